// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The simulated controller's end of a serial line that any program can open by
// name: a pseudo-terminal on POSIX (the client opens /dev/pts/N, raw), a named
// pipe on Windows (the client opens \\.\pipe\tactus-sim-PID-N). Either way the
// client's end stays valid when a client closes it and another comes.
#include <string>

#include "platform/channel.hpp"

namespace tactus::platform {

class SimEndpoint {
public:
    SimEndpoint() = default;
    // `nonblocking`: writes with no room (or no client) move nothing instead of waiting.
    static OsResult<SimEndpoint> open(bool nonblocking);

    // What a client opens.
    [[nodiscard]] const std::string& path() const { return path_; }
    // The simulator's side of the line.
    [[nodiscard]] Channel& line() { return line_; }

private:
    Channel line_;
    Channel keep_;  // the client's side held open, so the line outlives a client
    std::string path_;
};

}  // namespace tactus::platform
