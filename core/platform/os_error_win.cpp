// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/os_error.hpp"

#include <windows.h>

#include "platform/os_error_win.hpp"

namespace tactus::platform {

std::wstring widen(std::string_view utf8) {
    if (utf8.empty()) return {};
    const int n = MultiByteToWideChar(CP_UTF8, 0, utf8.data(), static_cast<int>(utf8.size()), nullptr, 0);
    std::wstring out(static_cast<std::size_t>(n), L'\0');
    MultiByteToWideChar(CP_UTF8, 0, utf8.data(), static_cast<int>(utf8.size()), out.data(), n);
    return out;
}

std::string narrow(std::wstring_view utf16) {
    if (utf16.empty()) return {};
    const int n = WideCharToMultiByte(CP_UTF8, 0, utf16.data(), static_cast<int>(utf16.size()), nullptr, 0,
                                      nullptr, nullptr);
    std::string out(static_cast<std::size_t>(n), '\0');
    WideCharToMultiByte(CP_UTF8, 0, utf16.data(), static_cast<int>(utf16.size()), out.data(), n, nullptr, nullptr);
    return out;
}

OsError os_error_from_code(unsigned long code) {
    OsErrorKind kind = OsErrorKind::other;
    switch (code) {
        case ERROR_FILE_NOT_FOUND:
        case ERROR_PATH_NOT_FOUND:
        case ERROR_INVALID_NAME:
        case ERROR_DEV_NOT_EXIST: kind = OsErrorKind::not_found; break;
        case ERROR_ACCESS_DENIED: kind = OsErrorKind::permission; break;
        case ERROR_SHARING_VIOLATION:
        case ERROR_LOCK_VIOLATION:
        case ERROR_PIPE_BUSY: kind = OsErrorKind::busy; break;
        case ERROR_NOT_SUPPORTED:
        case ERROR_CALL_NOT_IMPLEMENTED: kind = OsErrorKind::unsupported; break;
        default: break;
    }
    wchar_t* text = nullptr;
    const DWORD n = FormatMessageW(FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM |
                                       FORMAT_MESSAGE_IGNORE_INSERTS,
                                   nullptr, code, 0, reinterpret_cast<wchar_t*>(&text), 0, nullptr);
    std::string what = n > 0 ? narrow(std::wstring_view(text, n)) : "system error " + std::to_string(code);
    if (text) LocalFree(text);
    while (!what.empty() && (what.back() == '\n' || what.back() == '\r' || what.back() == '.')) what.pop_back();
    return OsError{std::move(what), kind};
}

OsError last_error() { return os_error_from_code(GetLastError()); }

}  // namespace tactus::platform
