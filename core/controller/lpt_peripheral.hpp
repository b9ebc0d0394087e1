// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The controller's side of the parallel port, as its firmware runs it: latch a
// byte on each nStrobe with Busy/nAck (compatibility mode), show paper-out,
// fault and online on the status lines, and answer IEEE 1284 nibble-mode
// negotiation to send its reply frames back four bits at a time.
// tick() is one pass of the firmware's port poll: it reacts to the host's lines.
// The reference firmware runs the same state machine (firmware/src/lpt.c);
// tests/firmware/lpt_firmware_test.cpp drives both with the host's LptPort.
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include "transport/lpt_port.hpp"

namespace tactus::controller {

class LptPeripheral {
public:
    void set_data(std::uint8_t d) { data_ = d; }
    void set_control(const transport::LptControl& c) { ctl_ = c; }
    void tick();
    [[nodiscard]] transport::LptStatus status() const { return st_; }

    // Bytes latched from the host so far (and clears them).
    std::vector<std::uint8_t> take_received();
    // Queues bytes for the host to read in nibble mode.
    void send(std::span<const std::uint8_t> bytes);
    void set_condition(bool paper_out, bool fault, bool online);

private:
    enum class Mode { compat, negotiating, idle, low_shown, low_done, high_shown, term_ack, term_done };
    void show_condition();
    void show_nibble(unsigned nibble);
    transport::LptControl ctl_, prev_;
    transport::LptStatus st_;
    std::uint8_t data_ = 0;
    Mode mode_ = Mode::compat;
    int ack_phase_ = 0;
    bool saw_strobe_low_ = false;
    bool paper_out_ = false, fault_ = false, online_ = true;
    std::vector<std::uint8_t> received_;
    std::deque<std::uint8_t> outgoing_;
};

}  // namespace tactus::controller
