// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the system's own text services allow a line break in print (Unicode's
// line breaking rules, UAX #14). A build with ICU asks ICU instead
// (translate/line_breaks.cpp); this is for a Windows build made without it,
// where Uniscribe's ScriptBreak does the work. POSIX has no such service.
#include <string_view>
#include <vector>

#include "platform/os_error.hpp"

namespace tactus::platform {

// out[i] (0 <= i <= text.size()): a break is allowed before code point i.
// out[0] and out[text.size()] are true.
OsResult<std::vector<bool>> system_line_breaks(std::u32string_view text);

}  // namespace tactus::platform
