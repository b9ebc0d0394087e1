// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The reference firmware's own C (firmware/src: link.c, decoder.c, crc16.c,
// exec.c, and the generated ramp_tables.c), compiled natively and run at the
// far end of the in-process serial line (controller::SimTransport) on virtual
// time, so the host's real link drives the firmware's real frame decoder,
// sessions, window, DATA check and executor over a noisy line: hundreds of
// seeds in seconds, where s51 runs one in real time.
//
// What is the chip's and what is modelled here:
// * every rule of the link and the executor is the firmware's code;
// * the main loop is main.c's (received bytes, compact, exec_poll,
//   fw_poll_paper, fw_report_room), run after each byte and each event;
// * the step interrupt and motion.c are modelled: a phase ends when the
//   firmware's timer schedule says (docs/protocol.md "Timing": a move's first
//   step start_gap + T[0] after the last timer event, its last step the
//   table's move time later; the settle, the hammer pulse; a phase the main
//   loop comes to late starts when given), as controller::SimController does;
// * the UART sends the replies byte by byte as fw_reply_byte() builds them
//   (one character time each), as the serial interrupt does; the receive
//   side is never late (the main loop keeps up: firmware/README.md "Main
//   loop"), so no byte is dropped by a full queue;
// * the sensors: paper present, the hammers home, the limit switch closes
//   when homing reaches step 0 (the emulator build's rule).
//
// The firmware's state is its global variables: one instance at a time.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "controller/line_end.hpp"
#include "controller/sim_controller.hpp"
#include "machine/firmware_tables.hpp"

namespace tactus::test {

struct NativeFirmwareOptions {
    // The tables the firmware's ramp_tables.c was generated with (the same
    // build's ramp.json): the modelled step interrupt times moves with them.
    machine::FirmwareTables tables;
    double baud = 9600;  // the reply line's pace (the firmware's build: BAUD=9600)
    bool paper_present = true;
    // Every phase ends when it starts (the link-efficiency benchmark: the
    // line and the ring are the only limits).
    bool instant_motion = false;
};

class NativeFirmware final : public controller::LineEnd {
public:
    explicit NativeFirmware(NativeFirmwareOptions options = {});
    ~NativeFirmware() override;
    NativeFirmware(const NativeFirmware&) = delete;
    NativeFirmware& operator=(const NativeFirmware&) = delete;

    void receive(std::span<const std::uint8_t> bytes, double now) override;
    void advance(double now) override;
    [[nodiscard]] std::optional<double> next_event() const override;
    std::vector<std::uint8_t> take_output() override;
    void warm_reset(double now) override;
    void power_loss(double now) override;

    // The strikes the hammers made, in the C++ controller's form (sheet, side
    // and hammer, carriage and feed step, read from the firmware's counters
    // when the hammer comes down).
    [[nodiscard]] const std::vector<controller::LoggedStrike>& strike_log() const { return log_; }
    // Each time the executor waited for data (state *waiting*: a job under
    // way, its next op or strike entry not in the ring): when, how long.
    [[nodiscard]] const std::vector<controller::SimController::Wait>& waits() const { return waits_; }

    // Called by the native motion layer (native_firmware.cpp).
    [[nodiscard]] const machine::FirmwareTables& tables() const { return options_.tables; }
    void phase(std::uint64_t first_ticks, std::uint64_t total_ticks);
    void hammer_down(std::uint8_t pins);
    void tx_kick();
    void stop();

private:
    void main_loop();
    void boot(bool warm);

    NativeFirmwareOptions options_;
    double now_ = 0;
    double last_event_ = 0;  // the timer's last event (a phase's end)
    bool phase_busy_ = false;
    double phase_end_ = 0;
    bool tx_busy_ = false;
    double tx_next_ = 0;
    std::vector<std::uint8_t> out_;
    std::vector<controller::LoggedStrike> log_;
    std::vector<controller::SimController::Wait> waits_;
    double waiting_since_ = -1;
};

}  // namespace tactus::test
