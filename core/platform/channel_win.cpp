// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/channel.hpp"

#include <windows.h>


#include "platform/os_error_win.hpp"

namespace tactus::platform {
namespace {

HANDLE handle_of(std::intptr_t h) { return reinterpret_cast<HANDLE>(h); }

// A named pipe's server end whose client left: it disconnects and listens for
// the next client (PIPE_NOWAIT: ConnectNamedPipe returns at once), as a
// serial line takes the next cable.
void listen_again(HANDLE h) {
    DisconnectNamedPipe(h);
    ConnectNamedPipe(h, nullptr);
}

}  // namespace

Channel& Channel::operator=(Channel&& o) noexcept {
    if (this != &o) {
        close();
        handle_ = o.release();
    }
    return *this;
}

void Channel::close() noexcept {
    if (handle_ != -1) CloseHandle(handle_of(handle_));
    handle_ = -1;
}

OsResult<std::size_t> Channel::read_some(std::span<std::uint8_t> buffer) {
    const HANDLE h = handle_of(handle_);
    DWORD got = 0;
    if (ReadFile(h, buffer.data(), static_cast<DWORD>(buffer.size()), &got, nullptr)) return std::size_t{got};
    switch (const DWORD code = GetLastError()) {
        case ERROR_NO_DATA:           // nothing waiting (a PIPE_NOWAIT pipe)
        case ERROR_PIPE_LISTENING:    // no client yet
        case ERROR_PIPE_NOT_CONNECTED: return std::size_t{0};
        case ERROR_BROKEN_PIPE: listen_again(h); return std::size_t{0};
        default: return std::unexpected(os_error_from_code(code));
    }
}

OsResult<std::size_t> Channel::write_some(std::span<const std::uint8_t> bytes) {
    const HANDLE h = handle_of(handle_);
    DWORD wrote = 0;
    if (WriteFile(h, bytes.data(), static_cast<DWORD>(bytes.size()), &wrote, nullptr)) return std::size_t{wrote};
    // No client: the bytes are lost, as on a line with no cable.
    switch (const DWORD code = GetLastError()) {
        case ERROR_PIPE_LISTENING:
        case ERROR_PIPE_NOT_CONNECTED: return std::size_t{0};
        case ERROR_NO_DATA:  // on a write: the client is closing its end
        case ERROR_BROKEN_PIPE: listen_again(h); return std::size_t{0};
        default: return std::unexpected(os_error_from_code(code));
    }
}

OsResult<std::vector<bool>> wait_readable(std::span<Channel* const> channels, std::chrono::nanoseconds timeout) {
    // Pipes cannot be waited on for data without overlapped reads; peeking
    // each millisecond keeps the channels' plain non-blocking reads.
    const auto until = std::chrono::steady_clock::now() + timeout;
    std::vector<bool> ready(channels.size(), false);
    for (;;) {
        bool any = false;
        for (std::size_t i = 0; i < channels.size(); ++i) {
            const HANDLE h = handle_of(channels[i]->native());
            ConnectNamedPipe(h, nullptr);  // a server end waiting for its client
            DWORD avail = 0;
            if (PeekNamedPipe(h, nullptr, 0, nullptr, &avail, nullptr)) {
                if (avail > 0) ready[i] = any = true;
            } else if (GetLastError() == ERROR_BROKEN_PIPE) {
                listen_again(h);
            }
        }
        if (any || std::chrono::steady_clock::now() >= until) return ready;
        Sleep(1);
    }
}

OsResult<Channel> connect_loopback(std::uint16_t) {
    return os_fail("a console over TCP is not wired up on Windows", OsErrorKind::unsupported);
}

OsResult<std::uint16_t> unused_loopback_port() {
    return os_fail("a console over TCP is not wired up on Windows", OsErrorKind::unsupported);
}

OsResult<Channel> open_fifo(const std::filesystem::path&) {
    return os_fail("Windows has no FIFO in its file system", OsErrorKind::unsupported);
}

}  // namespace tactus::platform
