// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The desktop app's built-in simulated embosser: one simulated 89C52 and one
// line for the app's whole life, so the controller keeps its job count across
// connections as a real machine does (the spool's reconciliation reads it).
// Each connection (the printer panel's Connect, the app's spool runner) gets a
// stream onto that line; only one is used at a time. A technician injects
// faults from another thread (the GUI's) while a runner thread streams: every
// call goes through one mutex, and a fault takes effect at the line's next
// moment in simulated time. Each connection brings the options of its device
// string (`sim?speed=10`, transport::sim_settings, the same rule as
// `tactus-cli`'s `sim`): by default the job takes the plan's own time, so a
// technician can pause it mid-sheet. The wall clock is waited for outside the
// mutex, so a fault button or a status read never waits for the machine.
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "common/result.hpp"
#include "controller/sim_controller.hpp"
#include "controller/sim_transport.hpp"
#include "transport/byte_stream.hpp"
#include "transport/device.hpp"

namespace tactus::controller {

class BuiltInSimulator {
public:
    explicit BuiltInSimulator(SimOptions options = default_options(), SimLineOptions line = {});

    // A simulated operator loads paper 5 s after it runs out.
    static SimOptions default_options();

    // A new connection to the same controller, with a `sim?...` device
    // string's options (speed, baud, noise, paper-reload; the default
    // SimSettings: the plan's own speed).
    std::unique_ptr<transport::ByteStream> connect(const transport::SimSettings& settings);
    // The same for a printer whose profile makes `tables`
    // (profile::make_firmware_tables; nullopt when it cannot): the controller
    // speaks protocol 3 with them unless the settings say protocol=2, as the
    // reference firmware built from that profile does. When that is not the
    // firmware it runs, it is flashed with it first, a power cycle (RAM and
    // the job count lost), as a technician would reflash the chip. Refused
    // for protocol=3 without tables.
    Result<std::unique_ptr<transport::ByteStream>> connect(const transport::SimSettings& settings,
                                                           const std::optional<machine::FirmwareTables>& tables);
    // The protocol the controller speaks now (2, or 3 with ramp tables).
    [[nodiscard]] std::uint8_t protocol() const;
    [[nodiscard]] std::optional<machine::FirmwareTables> firmware() const;

    // Faults, at the simulated moment the line is next used:
    void paper_out();                      // the feeder runs empty (the operator reloads it)
    void pull_cable(double seconds);       // reads, writes and reopen fail for this long
    void noise(double seconds, double per_byte);  // bytes lost, flipped and doubled for this long
    void reset_controller();               // a watchdog reset: registers lost, RAM (the count) kept

    [[nodiscard]] std::vector<LoggedStrike> strikes() const;
    // What the last CONFIGURE set (zeros before any).
    [[nodiscard]] machine::ControllerConfig config() const;
    [[nodiscard]] encode::Status status() const;
    // The simulated clock (seconds since the simulator was made).
    [[nodiscard]] double now() const;

private:
    class Stream;
    struct Pending {
        bool paper_out = false;
        std::optional<double> unplug_s;
        std::optional<std::pair<double, double>> noise;  // seconds, rate
        bool reset = false;
    };
    // Applies pending faults and ends a noise burst that is over; mutex held.
    void apply_pending();

    mutable std::mutex mutex_;
    std::shared_ptr<SimController> controller_;
    SimTransport line_;
    Pending pending_;
    double noise_until_ = -1;
    LineNoise base_noise_;  // the device string's, back after an injected burst
    double paper_reload_s_;  // the simulated operator's delay when the device string names none
};

}  // namespace tactus::controller
