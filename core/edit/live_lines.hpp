// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private to core/edit's LiveLayout files: how an editor line reads (a table
// line, verbatim braille, the pieces between form feeds) and how two section
// marks on one line merge.
#include <optional>
#include <string_view>

#include "document/document.hpp"
#include "edit/editor_lines.hpp"

namespace tactus::edit::live_lines {

// A line of a Markdown table (a row or the delimiter row).
inline bool starts_table_line(std::string_view line) {
    const auto t = line.find_first_not_of(" \t");
    return t != std::string_view::npos && line[t] == '|';
}

// A line of Unicode braille cells (with spaces around it) is verbatim braille in both dialects.
inline bool braille_text_line(std::string_view line) {
    const auto from = line.find_first_not_of(" \t");
    if (from == std::string_view::npos) return false;
    return is_braille_line(line.substr(from, line.find_last_not_of(" \t") + 1 - from));
}

// A text line's pieces between form feeds: the first continues a paragraph, the last may start one.
inline std::string_view first_piece(std::string_view line) { return line.substr(0, line.find('\f')); }
inline std::string_view last_piece(std::string_view line) {
    const auto ff = line.rfind('\f');
    return ff == std::string_view::npos ? line : line.substr(ff + 1);
}

// Two section marks meet on one line: the later one's section, a volume start if either had one.
inline void merge_mark(std::optional<document::BrailleSection>& onto, const document::BrailleSection& later) {
    const bool volume = (onto && onto->starts_volume) || later.starts_volume;
    onto = later;
    onto->starts_volume = volume;
}

}  // namespace tactus::edit::live_lines
