// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/user_dirs.hpp"

#include <windows.h>

#include <cstdlib>

namespace tactus::platform {

std::optional<std::filesystem::path> user_data_home() {
    // %LOCALAPPDATA%: this machine's data for this user (not roaming: a spool
    // database belongs to the printers of one machine).
    if (const wchar_t* v = _wgetenv(L"LOCALAPPDATA"); v && *v) return std::filesystem::path(v);
    if (const wchar_t* v = _wgetenv(L"USERPROFILE"); v && *v)
        return std::filesystem::path(v) / L"AppData" / L"Local";
    return std::nullopt;
}

}  // namespace tactus::platform
