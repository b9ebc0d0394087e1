// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The in-process simulator as a byte stream: a serial line of a given baud rate
// in each direction, the simulated controller at the far end, and virtual time,
// in which every byte, timeout and step happens at the moment it would on the
// real machine. The wall clock paces it (SimLineOptions::speed): the plan's own
// speed for a technician, as fast as the host can go for tests. Line faults
// (lost, flipped and duplicated bytes, a pulled cable) are injected here.
#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "controller/line_end.hpp"
#include "controller/sim_controller.hpp"
#include "transport/byte_stream.hpp"
#include "transport/device.hpp"

namespace tactus::controller {

struct LineNoise {
    double drop = 0;  // probability per byte
    double flip = 0;  // one bit inverted
    double dup = 0;   // byte delivered twice
    std::uint64_t seed = 1;
};

struct SimLineOptions {
    double baud = 115200;
    int bits_per_byte = 10;  // 8N1
    LineNoise noise;
    // How fast simulated time may run against the wall clock: 0 (the default
    // for test rigs) as fast as the host can go; N > 0 at most N times real
    // time, so a technician sees the job take as long as on the machine (the
    // `sim` device's default is 1: docs/transports.md).
    double speed = 0;
};

// The line of a `sim?...` device string (transport::sim_settings).
SimLineOptions line_options(const transport::SimSettings& settings);

class SimTransport final : public transport::ByteStream {
public:
    SimTransport(std::shared_ptr<controller::SimController> controller, SimLineOptions options);
    // Any other far end (the reference firmware's C compiled natively).
    SimTransport(std::shared_ptr<LineEnd> end, SimLineOptions options);

    Result<void> write(std::span<const std::uint8_t> bytes) override;
    Result<std::size_t> read(std::span<std::uint8_t> buffer,
                             std::chrono::microseconds timeout) override;
    Result<void> reopen() override;
    [[nodiscard]] double now() const override { return now_; }
    void sleep(std::chrono::microseconds duration) override;
    [[nodiscard]] double bytes_per_second() const override;
    [[nodiscard]] std::string describe() const override { return "sim"; }

    // The cable is pulled for [from, to): reads and writes fail, reopen fails.
    void unplug_between(double from, double to) { unplugged_ = {from, to}; }
    // The line goes dead for [from, to): bytes are lost but the port stays open.
    void silence_between(double from, double to) { silent_ = {from, to}; }
    // The line's noise from now on (the app's technician turns it on and off).
    void set_noise(const LineNoise& noise) { options_.noise = noise; }
    // A watchdog reset (RAM kept) or power loss of the controller at time t.
    void reset_controller_at(double t, bool keep_ram) { reset_ = {t, keep_ram}; }
    // The pace from now on (0: as fast as possible); the wall clock is
    // re-anchored here, so the time before does not count.
    void set_speed(double speed);
    void set_baud(double baud) { options_.baud = baud; }
    // Reads, writes and sleeps wait for the wall clock themselves (the
    // default), or leave it to the caller, who sleeps until due() (the app's
    // simulator, which must not sleep holding its lock).
    void set_self_paced(bool on) { self_paced_ = on; }
    // The wall-clock moment the simulated clock's present is due at this
    // speed; nullopt at full speed. When the wall clock is more than a tenth
    // of a second past it (the line lay idle, or the host was slow), the
    // simulated clock does not race to catch up: the clock is re-anchored.
    [[nodiscard]] std::optional<std::chrono::steady_clock::time_point> due();

    // The C++ simulated controller at the far end (only when it is one).
    [[nodiscard]] controller::SimController& controller() { return *sim_; }
    [[nodiscard]] std::size_t line_bytes_to_controller() const { return tx_count_; }
    [[nodiscard]] std::size_t bytes_corrupted() const { return corrupted_; }

private:
    struct Timed {
        double at;
        std::uint8_t byte;
    };
    void run_until(double t);
    // Waits (wall time) until due(), when self-paced.
    void pace();
    void send_line(std::deque<Timed>& line, double& line_free, double from,
                   std::span<const std::uint8_t> bytes);
    void collect_output(double at);
    [[nodiscard]] bool in(const std::pair<double, double>& w, double t) const {
        return t >= w.first && t < w.second;
    }

    std::shared_ptr<LineEnd> controller_;
    controller::SimController* sim_ = nullptr;
    SimLineOptions options_;
    std::mt19937_64 rng_;
    double now_ = 0;
    // Simulated time anchor_sim_ was (or is due) at wall time anchor_wall_.
    std::chrono::steady_clock::time_point anchor_wall_ = std::chrono::steady_clock::now();
    double anchor_sim_ = 0;
    bool self_paced_ = true;
    double tx_free_ = 0, rx_free_ = 0;
    std::deque<Timed> to_controller_, to_host_;
    std::pair<double, double> unplugged_{-1, -1}, silent_{-1, -1};
    std::optional<std::pair<double, bool>> reset_;
    std::size_t tx_count_ = 0;
    std::size_t corrupted_ = 0;
};

}  // namespace tactus::controller
