// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/sim_endpoint.hpp"

#include <windows.h>

#include <atomic>

#include "platform/os_error_win.hpp"

namespace tactus::platform {

OsResult<SimEndpoint> SimEndpoint::open(bool) {
    // Byte mode, one client at a time, PIPE_NOWAIT: reads and writes never
    // wait, like the POSIX side's non-blocking pty master. The name is unique
    // per process and per endpoint.
    static std::atomic<unsigned> serial{0};
    SimEndpoint s;
    s.path_ = "\\\\.\\pipe\\tactus-sim-" + std::to_string(GetCurrentProcessId()) + "-" + std::to_string(serial++);
    const HANDLE h = CreateNamedPipeW(widen(s.path_).c_str(), PIPE_ACCESS_DUPLEX | FILE_FLAG_FIRST_PIPE_INSTANCE,
                                      PIPE_TYPE_BYTE | PIPE_READMODE_BYTE | PIPE_NOWAIT |
                                          PIPE_REJECT_REMOTE_CLIENTS,
                                      1, 64 * 1024, 64 * 1024, 0, nullptr);
    if (h == INVALID_HANDLE_VALUE) return os_fail("cannot create the named pipe " + s.path_ + ": " + last_error().what);
    s.line_ = Channel(reinterpret_cast<std::intptr_t>(h));
    ConnectNamedPipe(h, nullptr);  // listening; PIPE_NOWAIT returns at once
    return s;
}

}  // namespace tactus::platform
