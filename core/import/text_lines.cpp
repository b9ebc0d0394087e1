// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/text_lines.hpp"

namespace tactus::import {

bool is_blank_text_line(std::string_view s) { return s.find_first_not_of(" \t\v") == std::string_view::npos; }

std::vector<std::string> split_text_lines(std::string_view utf8) {
    std::vector<std::string> lines;
    for_each_text_line(utf8, [&](std::string_view line, int) {
        lines.emplace_back(line);
        return true;
    });
    if (utf8.empty() || utf8.back() == '\n' || utf8.back() == '\r') lines.emplace_back();
    return lines;
}

std::string line_ending_of(std::string_view utf8) {
    const auto end = utf8.find_first_of("\r\n");
    if (end == std::string_view::npos || utf8[end] == '\n') return "\n";
    return end + 1 < utf8.size() && utf8[end + 1] == '\n' ? "\r\n" : "\r";
}

bool ParagraphBreaks::line(std::string_view line) {
    if (found_) return true;
    if (is_blank_text_line(line)) {
        blank_after_text_ = seen_text_;
    } else {
        if (blank_after_text_) found_ = true;
        seen_text_ = true;
    }
    return found_;
}

}  // namespace tactus::import
