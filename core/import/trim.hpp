// Leading and trailing ASCII white space (space, tab, CR, LF) cut from a
// view: the blanks around a Markdown line's text or a PEF attribute's value.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string_view>

namespace tactus::import::detail {

inline std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

}  // namespace tactus::import::detail
