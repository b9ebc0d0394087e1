// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/worker_process.hpp"

#include <windows.h>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <utility>
#include <vector>

#include "platform/program_file.hpp"

namespace tactus::platform {
namespace {

// The hidden first argument of a worker, then its input and output handles
// (inherited, so their values are the same in both processes).
constexpr std::string_view kWorkerArgument = "--tactus-worker";

HANDLE handle_of(std::intptr_t h) { return reinterpret_cast<HANDLE>(h); }
std::intptr_t stored(HANDLE h) { return reinterpret_cast<std::intptr_t>(h); }

void close_handle(std::intptr_t& h) {
    if (h != -1) CloseHandle(handle_of(h));
    h = -1;
}

std::wstring handle_argument(HANDLE h) { return std::to_wstring(reinterpret_cast<std::uintptr_t>(h)); }

bool parse_handle(const char* text, HANDLE& h) {
    std::uintptr_t value = 0;
    const auto end = text + std::strlen(text);
    const auto [p, ec] = std::from_chars(text, end, value);
    if (ec != std::errc{} || p != end || value == 0) return false;
    h = reinterpret_cast<HANDLE>(value);
    return true;
}

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

bool WorkerProcess::supported() { return true; }

WorkerStart WorkerProcess::how() { return WorkerStart::program; }

OsResult<WorkerProcess> WorkerProcess::start(const std::function<int(WorkerOutput&)>&,
                                             std::span<const WorkerProcess>) {
    return os_fail("Windows cannot copy a process (fork): a worker is the program started again (start_program)",
                   OsErrorKind::unsupported);
}

OsResult<WorkerProcess> WorkerProcess::start_program() {
    auto program = program_file();
    if (!program) return std::unexpected(program.error());
    SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
    HANDLE in_read = nullptr, in_write = nullptr, out_read = nullptr, out_write = nullptr;
    if (!CreatePipe(&in_read, &in_write, &inherit, 0)) return std::unexpected(last_error());
    if (!CreatePipe(&out_read, &out_write, &inherit, 0)) {
        const auto e = last_error();
        CloseHandle(in_read);
        CloseHandle(in_write);
        return std::unexpected(e);
    }
    // The parent's ends are its own: no child inherits them.
    SetHandleInformation(in_write, HANDLE_FLAG_INHERIT, 0);
    SetHandleInformation(out_read, HANDLE_FLAG_INHERIT, 0);
    std::wstring command = L"\"" + program->wstring() + L"\" " +
                           std::wstring(kWorkerArgument.begin(), kWorkerArgument.end()) + L" " +
                           handle_argument(in_read) + L" " + handle_argument(out_write);

    // Only the worker's two ends are inherited, not whatever else another
    // thread has made inheritable at the moment (a sibling's pipe, a log file).
    STARTUPINFOEXW si{};
    si.StartupInfo.cb = sizeof si;
    SIZE_T size = 0;
    InitializeProcThreadAttributeList(nullptr, 1, 0, &size);
    std::vector<char> storage(size);
    auto* list = reinterpret_cast<LPPROC_THREAD_ATTRIBUTE_LIST>(storage.data());
    HANDLE inherited[2] = {in_read, out_write};
    const bool listed = size > 0 && InitializeProcThreadAttributeList(list, 1, 0, &size) &&
                        UpdateProcThreadAttribute(list, 0, PROC_THREAD_ATTRIBUTE_HANDLE_LIST, inherited,
                                                  sizeof inherited, nullptr, nullptr);
    if (listed) si.lpAttributeList = list;
    PROCESS_INFORMATION pi{};
    // No console window: a worker started by the app (which has no console) shows nothing.
    const DWORD flags = CREATE_NO_WINDOW | (listed ? EXTENDED_STARTUPINFO_PRESENT : 0);
    const BOOL ok = CreateProcessW(program->c_str(), command.data(), nullptr, nullptr, TRUE, flags, nullptr,
                                   nullptr, &si.StartupInfo, &pi);
    const auto e = ok ? OsError{} : last_error();
    if (listed) DeleteProcThreadAttributeList(list);
    CloseHandle(in_read);
    CloseHandle(out_write);
    if (!ok) {
        CloseHandle(in_write);
        CloseHandle(out_read);
        return std::unexpected(e);
    }
    CloseHandle(pi.hThread);
    WorkerProcess w(static_cast<std::int64_t>(pi.dwProcessId), stored(out_read));
    w.write_end_ = stored(in_write);
    w.process_ = stored(pi.hProcess);
    return w;
}

OsResult<void> WorkerProcess::send_input(std::string_view input) {
    if (write_end_ == -1) return os_fail("the worker's input was sent already");
    WorkerOutput to_worker(write_end_);
    const bool ok = to_worker.write_all(input.data(), input.size());
    const auto e = ok ? OsError{} : last_error();
    close_handle(write_end_);
    if (!ok) return std::unexpected(e);
    return {};
}

std::optional<OsResult<WorkerSide>> WorkerProcess::worker_side(int argc, char** argv) {
    if (argc < 2 || argv[1] != kWorkerArgument) return std::nullopt;
    // A worker that crashes shows no dialog waiting for a click: its parent
    // sees its pipe end and reports how it ended.
    SetErrorMode(SEM_FAILCRITICALERRORS | SEM_NOGPFAULTERRORBOX);
    HANDLE in = nullptr, out = nullptr;
    if (argc != 4 || !parse_handle(argv[2], in) || !parse_handle(argv[3], out))
        return os_fail("a worker is started with the handles of its two pipes");
    std::string input;
    std::vector<char> buffer(0x1'0000);
    for (;;) {
        DWORD got = 0;
        if (!ReadFile(in, buffer.data(), static_cast<DWORD>(buffer.size()), &got, nullptr)) {
            if (GetLastError() == ERROR_BROKEN_PIPE) break;  // the whole input
            const auto e = last_error();
            CloseHandle(in);
            return std::unexpected(e);
        }
        if (got == 0) break;
        input.append(buffer.data(), got);
    }
    CloseHandle(in);
    return WorkerSide{std::move(input), WorkerOutput(stored(out))};
}

int WorkerProcess::read_all(void* data, std::size_t n) {
    auto* p = static_cast<char*>(data);
    std::size_t done = 0;
    while (done < n) {
        if (ahead_at_ == ahead_.size()) {
            ahead_.resize(0x1'0000);
            ahead_at_ = 0;
            DWORD got = 0;
            const BOOL ok = ReadFile(handle_of(read_end_), ahead_.data(), static_cast<DWORD>(ahead_.size()), &got,
                                     nullptr);
            const DWORD why = ok ? ERROR_SUCCESS : GetLastError();
            ahead_.resize(ok ? got : 0);
            if (!ok || got == 0) return done == 0 && why == ERROR_BROKEN_PIPE ? 0 : -1;
        }
        const auto take = std::min(n - done, ahead_.size() - ahead_at_);
        std::memcpy(p + done, ahead_.data() + ahead_at_, take);
        ahead_at_ += take;
        done += take;
    }
    return 1;
}

std::string WorkerProcess::wait_for_end() {
    pid_ = -1;
    if (process_ == -1) return "exit status unknown";
    WaitForSingleObject(handle_of(process_), INFINITE);
    DWORD code = 0;
    GetExitCodeProcess(handle_of(process_), &code);
    close_handle(process_);
    // A crash ends a process with its exception's code (0xC0000005, an
    // access violation), which Windows shows in hexadecimal.
    if (code >= 0xC000'0000u) {
        char hex[16];
        const auto [end, ec] = std::to_chars(hex, hex + sizeof hex, code, 16);
        return "exception 0x" + std::string(hex, end);
    }
    return "exit status " + std::to_string(code);
}

void WorkerProcess::stop() {
    close_handle(read_end_);
    ahead_.clear();
    ahead_at_ = 0;
    close_handle(write_end_);
    if (process_ != -1) {
        TerminateProcess(handle_of(process_), 1);
        WaitForSingleObject(handle_of(process_), INFINITE);
        close_handle(process_);
    }
    pid_ = -1;
}

}  // namespace tactus::platform
