// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Inside the Windows implementations only: a GetLastError code as an OsError,
// and UTF-8 <-> UTF-16 for the wide (W) API.
#include <string>
#include <string_view>

#include "platform/os_error.hpp"

namespace tactus::platform {

OsError os_error_from_code(unsigned long code);
std::wstring widen(std::string_view utf8);
std::string narrow(std::wstring_view utf16);

}  // namespace tactus::platform
