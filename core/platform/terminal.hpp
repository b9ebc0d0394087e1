// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A serial line opened by its name and driven directly: on POSIX a terminal
// device through termios (pseudo-terminals, which libserialport refuses), on
// Windows a COM port through its DCB or the simulator's named pipe. Opened
// exclusively (two senders on one line would interleave frames) and raw.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "platform/os_error.hpp"

namespace tactus::platform {

struct LineSettings {
    int baud = 115200;
    char parity = 'n';  // n, o, e
    int stop_bits = 1;
    enum class Flow : std::uint8_t { none, rtscts, xonxoff } flow = Flow::none;
};

class Terminal {
public:
    // The error says what is wrong in the user's words (no such device,
    // permission denied, busy, not a terminal, unsupported baud rate).
    static OsResult<Terminal> open(const std::string& path, const LineSettings& line);
    Terminal(Terminal&& o) noexcept : handle_(o.release()) {}
    Terminal& operator=(Terminal&& o) noexcept;
    ~Terminal();

    // Every byte, waiting up to a second at a time for a blocked line.
    OsResult<void> write_all(std::span<const std::uint8_t> bytes);
    // What arrives within `timeout`: 0 bytes when nothing did. An error when
    // the other end is gone.
    OsResult<std::size_t> read(std::span<std::uint8_t> buffer, std::chrono::microseconds timeout);

private:
    explicit Terminal(std::intptr_t h) : handle_(h) {}
    std::intptr_t release() noexcept {
        const auto h = handle_;
        handle_ = -1;
        return h;
    }
    std::intptr_t handle_ = -1;
};

}  // namespace tactus::platform
