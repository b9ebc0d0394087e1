// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/process_info.hpp"

#include <windows.h>

#include <cstdlib>

#include "platform/os_error_win.hpp"

namespace tactus::platform {

std::string host_name() {
    wchar_t name[MAX_COMPUTERNAME_LENGTH + 1] = {};
    DWORD n = MAX_COMPUTERNAME_LENGTH + 1;
    if (!GetComputerNameW(name, &n) || n == 0) return "localhost";
    return narrow(std::wstring_view(name, n));
}

std::int64_t current_process_id() { return static_cast<std::int64_t>(GetCurrentProcessId()); }

std::string user_name() {
    if (const wchar_t* u = _wgetenv(L"USERNAME"); u && *u) return narrow(u);
    wchar_t name[257] = {};
    DWORD n = 257;
    if (GetUserNameW(name, &n) && n > 1) return narrow(std::wstring_view(name, n - 1));
    return "user of process " + std::to_string(GetCurrentProcessId());
}

bool process_alive(std::int64_t pid) {
    if (pid <= 0 || pid > 0xffff'ffffLL) return false;
    if (static_cast<DWORD>(pid) == GetCurrentProcessId()) return true;
    const HANDLE h = OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, static_cast<DWORD>(pid));
    if (!h) return GetLastError() == ERROR_ACCESS_DENIED;  // there, but not ours to look at
    DWORD code = 0;
    const bool running = GetExitCodeProcess(h, &code) && code == STILL_ACTIVE;
    CloseHandle(h);
    return running;
}

bool running_as_root() {
    HANDLE token = nullptr;
    if (!OpenProcessToken(GetCurrentProcess(), TOKEN_QUERY, &token)) return false;
    TOKEN_ELEVATION elevation{};
    DWORD n = 0;
    const bool elevated = GetTokenInformation(token, TokenElevation, &elevation, sizeof elevation, &n) &&
                          elevation.TokenIsElevated != 0;
    CloseHandle(token);
    return elevated;
}

}  // namespace tactus::platform
