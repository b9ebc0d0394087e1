// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/text_breaks.hpp"

namespace tactus::platform {

OsResult<std::vector<bool>> system_line_breaks(std::u32string_view) {
    return os_fail("this system has no line-breaking service (ICU provides it)", OsErrorKind::unsupported);
}

}  // namespace tactus::platform
