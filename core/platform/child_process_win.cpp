// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/child_process.hpp"

#include <windows.h>

#include <utility>

#include "platform/os_error_win.hpp"

namespace tactus::platform {
namespace {

HANDLE handle_of(std::intptr_t h) { return reinterpret_cast<HANDLE>(h); }
std::intptr_t stored(HANDLE h) { return reinterpret_cast<std::intptr_t>(h); }

// One argument as CommandLineToArgvW reads it back: quoted, with the
// backslashes before a quote doubled.
std::wstring quoted(const std::wstring& arg) {
    if (!arg.empty() && arg.find_first_of(L" \t\"") == std::wstring::npos) return arg;
    std::wstring out = L"\"";
    std::size_t backslashes = 0;
    for (const wchar_t ch : arg) {
        if (ch == L'\\') {
            ++backslashes;
            continue;
        }
        out.append(ch == L'"' ? backslashes * 2 + 1 : backslashes, L'\\');
        backslashes = 0;
        out.push_back(ch);
    }
    out.append(backslashes * 2, L'\\');
    out.push_back(L'"');
    return out;
}

}  // namespace

OsResult<ChildProcess> ChildProcess::spawn(const ChildOptions& o) {
    if (o.args.empty()) return os_fail("no program to run");
    ChildProcess c;
    SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
    const HANDLE log = CreateFileW(o.log.c_str(), GENERIC_WRITE, FILE_SHARE_READ, &inherit, CREATE_ALWAYS,
                                   FILE_ATTRIBUTE_NORMAL, nullptr);
    if (log == INVALID_HANDLE_VALUE) return std::unexpected(last_error());
    HANDLE in_read = nullptr, in_write = nullptr;
    if (o.idle_input) {
        if (!CreatePipe(&in_read, &in_write, &inherit, 0)) {
            const auto e = last_error();
            CloseHandle(log);
            return std::unexpected(e);
        }
        SetHandleInformation(in_write, HANDLE_FLAG_INHERIT, 0);  // only the read end goes to the child
        c.input_[0] = stored(in_read);
        c.input_[1] = stored(in_write);
    }
    std::wstring command;
    for (const auto& a : o.args) command += (command.empty() ? L"" : L" ") + quoted(widen(a));
    STARTUPINFOW si{};
    si.cb = sizeof si;
    si.dwFlags = STARTF_USESTDHANDLES;
    si.hStdInput = o.idle_input ? in_read : GetStdHandle(STD_INPUT_HANDLE);
    si.hStdOutput = log;
    si.hStdError = log;
    PROCESS_INFORMATION pi{};
    const DWORD flags = CREATE_UNICODE_ENVIRONMENT | CREATE_NO_WINDOW |
                        (o.lower_priority ? BELOW_NORMAL_PRIORITY_CLASS : 0);
    const BOOL ok = CreateProcessW(nullptr, command.data(), nullptr, nullptr, TRUE, flags, nullptr,
                                   o.dir.empty() ? nullptr : o.dir.c_str(), &si, &pi);
    const auto e = ok ? OsError{} : last_error();
    CloseHandle(log);
    if (!ok) return std::unexpected(e);
    CloseHandle(pi.hThread);
    c.process_ = stored(pi.hProcess);
    c.id_ = static_cast<std::int64_t>(pi.dwProcessId);
    return c;
}

ChildProcess::ChildProcess(ChildProcess&& o) noexcept
    : process_(std::exchange(o.process_, -1)),
      input_{std::exchange(o.input_[0], -1), std::exchange(o.input_[1], -1)},
      id_(o.id_) {}

bool ChildProcess::running() {
    if (process_ == -1) return false;
    if (WaitForSingleObject(handle_of(process_), 0) == WAIT_OBJECT_0) {
        CloseHandle(handle_of(process_));
        process_ = -1;
        return false;
    }
    return true;
}

int ChildProcess::wait() {
    if (process_ == -1) return -1;
    const HANDLE h = handle_of(std::exchange(process_, -1));
    WaitForSingleObject(h, INFINITE);
    DWORD code = 0;
    const bool known = GetExitCodeProcess(h, &code);
    CloseHandle(h);
    return known ? static_cast<int>(code) : -1;
}

void ChildProcess::stop() {
    if (process_ != -1) {
        // A console program has no SIGTERM to catch: it is ended outright.
        const HANDLE h = handle_of(std::exchange(process_, -1));
        TerminateProcess(h, 1);
        WaitForSingleObject(h, 1000);
        CloseHandle(h);
    }
    for (auto& h : input_) {
        if (h != -1 && h != 0) CloseHandle(handle_of(h));
        h = -1;
    }
}

bool find_in_path(const std::string& program) {
    wchar_t found[MAX_PATH] = {};
    return SearchPathW(nullptr, widen(program).c_str(), L".exe", MAX_PATH, found, nullptr) > 0;
}

}  // namespace tactus::platform
