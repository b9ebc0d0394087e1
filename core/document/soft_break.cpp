// SPDX-License-Identifier: GPL-3.0-or-later
#include "document/soft_break.hpp"

namespace tactus::document {

std::string soft_breaks_as_spaces(std::string_view utf8) {
    if (utf8.find_first_of("\r\n") == std::string_view::npos) return std::string(utf8);
    std::string out;
    out.reserve(utf8.size());
    for (std::size_t i = 0; i < utf8.size(); ++i) {
        const char c = utf8[i];
        if (c != '\n' && c != '\r') {
            out += c;
            continue;
        }
        while (!out.empty() && (out.back() == ' ' || out.back() == '\t' || out.back() == '\v')) out.pop_back();
        while (i + 1 < utf8.size() && std::string_view(" \t\v\r\n").find(utf8[i + 1]) != std::string_view::npos) ++i;
        out += ' ';
    }
    return out;
}

}  // namespace tactus::document
