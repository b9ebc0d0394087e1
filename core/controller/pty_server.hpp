// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The simulated controller behind a pseudo-terminal, so any program can talk to
// it over a real tty (`tactus-cli sim --pty`). The line is paced at its baud
// rate in wall time; motion runs `time_scale` times faster than real time so a
// test does not wait for the paper.
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "common/result.hpp"
#include "controller/sim_controller.hpp"
#include "platform/sim_endpoint.hpp"

namespace tactus::controller {

struct PtyServerOptions {
    double baud = 115200;
    double time_scale = 1.0;
    double noise = 0;            // drop, flip and duplicate rate per byte, each
    std::uint64_t seed = 1;
    double disconnect_at_s = -1;  // line dead from this wall time (s after start) ...
    double disconnect_for_s = 0;  // ... for this long
    SimOptions sim;
};

class PtyServer {
public:
    static Result<PtyServer> open(const PtyServerOptions& options);
    PtyServer(PtyServer&&) noexcept;
    PtyServer& operator=(PtyServer&&) = delete;
    ~PtyServer();

    // The slave side a client opens (/dev/pts/N).
    [[nodiscard]] const std::string& path() const { return endpoint_.path(); }
    [[nodiscard]] SimController& controller() { return ctl_; }

    // Serves until `stop` is set. `on_strike` sees each strike as it is logged;
    // `on_tick` (optional) runs after every turn of the loop, to watch the controller.
    Result<void> serve(const std::atomic<bool>& stop,
                       const std::function<void(const LoggedStrike&)>& on_strike,
                       const std::function<void(const SimController&)>& on_tick = {});

private:
    explicit PtyServer(const PtyServerOptions& o) : options_(o), ctl_(o.sim) {}
    PtyServerOptions options_;
    SimController ctl_;
    platform::SimEndpoint endpoint_;  // its client's side is held open, so the line survives a client closing it
};

}  // namespace tactus::controller
