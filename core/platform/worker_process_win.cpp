// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/worker_process.hpp"

#include <windows.h>

#include <utility>

namespace tactus::platform {
namespace {

HANDLE handle_of(std::intptr_t h) { return reinterpret_cast<HANDLE>(h); }

}  // namespace

bool WorkerOutput::write_all(const void* data, std::size_t n) {
    const auto* p = static_cast<const char*>(data);
    while (n > 0) {
        DWORD wrote = 0;
        const auto chunk = static_cast<DWORD>(n > 0x1'0000u ? 0x1'0000u : n);
        if (!WriteFile(handle_of(handle_), p, chunk, &wrote, nullptr) || wrote == 0) return false;
        p += wrote;
        n -= wrote;
    }
    return true;
}

bool WorkerProcess::supported() { return false; }

OsResult<WorkerProcess> WorkerProcess::start(const std::function<int(WorkerOutput&)>&,
                                             std::span<const WorkerProcess>) {
    return os_fail("worker processes are copies of this process (fork), which Windows cannot make",
                   OsErrorKind::unsupported);
}

int WorkerProcess::read_all(void* data, std::size_t n) {
    auto* p = static_cast<char*>(data);
    std::size_t done = 0;
    while (done < n) {
        DWORD got = 0;
        const auto chunk = static_cast<DWORD>(n - done > 0x1'0000u ? 0x1'0000u : n - done);
        if (!ReadFile(handle_of(read_end_), p + done, chunk, &got, nullptr) || got == 0)
            return done == 0 && GetLastError() == ERROR_BROKEN_PIPE ? 0 : -1;
        done += got;
    }
    return 1;
}

std::string WorkerProcess::wait_for_end() {
    if (pid_ <= 0) return "exit status unknown";
    const HANDLE h = OpenProcess(SYNCHRONIZE | PROCESS_QUERY_LIMITED_INFORMATION, FALSE, static_cast<DWORD>(pid_));
    pid_ = -1;
    if (!h) return "exit status unknown";
    WaitForSingleObject(h, INFINITE);
    DWORD code = 0;
    GetExitCodeProcess(h, &code);
    CloseHandle(h);
    return "exit status " + std::to_string(code);
}

void WorkerProcess::stop() {
    if (read_end_ != -1) CloseHandle(handle_of(read_end_));
    read_end_ = -1;
    if (pid_ > 0) {
        if (const HANDLE h = OpenProcess(PROCESS_TERMINATE | SYNCHRONIZE, FALSE, static_cast<DWORD>(pid_))) {
            TerminateProcess(h, 1);
            WaitForSingleObject(h, INFINITE);
            CloseHandle(h);
        }
    }
    pid_ = -1;
}

}  // namespace tactus::platform
