// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An open stream of bytes owned here: a pseudo-terminal's or a named pipe's
// server side, a FIFO. Reads and writes move what they can now; waiting is
// wait_readable's job, over one channel or several.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "platform/os_error.hpp"

namespace tactus::platform {

class Channel {
public:
    Channel() = default;
    explicit Channel(std::intptr_t handle) : handle_(handle) {}
    Channel(Channel&& o) noexcept : handle_(o.release()) {}
    Channel& operator=(Channel&& o) noexcept;
    ~Channel() { close(); }

    [[nodiscard]] bool is_open() const { return handle_ != -1; }
    // Up to buffer.size() bytes: 0 when none can be read now (nothing waiting,
    // or an interrupted call).
    OsResult<std::size_t> read_some(std::span<std::uint8_t> buffer);
    // What the channel takes now: 0 when a non-blocking channel is full or has no reader.
    OsResult<std::size_t> write_some(std::span<const std::uint8_t> bytes);
    void close() noexcept;
    [[nodiscard]] std::intptr_t native() const { return handle_; }

private:
    std::intptr_t release() noexcept {
        const auto h = handle_;
        handle_ = -1;
        return h;
    }
    std::intptr_t handle_ = -1;
};

// Waits up to `timeout` until one of `channels` has bytes to read; which ones
// have (all false on a timeout or an interrupted wait).
OsResult<std::vector<bool>> wait_readable(std::span<Channel* const> channels, std::chrono::nanoseconds timeout);

// A TCP connection to this machine's loopback address: a local program's
// console (s51 serves one with -Z). Blocking; TCP_NODELAY, as a console's
// lines are short and each waits for its answer.
OsResult<Channel> connect_loopback(std::uint16_t port);
// A TCP port on the loopback address nobody listens on at this moment (another
// program may take it before it is used: the user retries).
OsResult<std::uint16_t> unused_loopback_port();

// Makes a FIFO at `path` and opens it both ways, so opening it elsewhere
// never waits for this side. POSIX only: Windows has no FIFO in its file system.
OsResult<Channel> open_fifo(const std::filesystem::path& path);

}  // namespace tactus::platform
