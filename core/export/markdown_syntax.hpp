// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The few facts about Markdown's line syntax that both the Markdown writer
// (export) and the editor's line dialect (edit) read and write: which
// characters are escaped, the bullet sign core's importers write, and the
// ordinal that starts a numbered item ("12." or "3)"). One place, so the
// writer and the editor can never disagree on what a line means.
#include <cstddef>
#include <string_view>

namespace tactus::exporter::markdown {

// Characters a Markdown writer escapes inside text.
inline constexpr std::string_view kInlineSpecials = "\\*_[]<>`&~";
// The bullet sign, as core's importers write it before a list item's text.
inline constexpr std::string_view kBullet = "\u2022 ";

inline bool is_space(char c) { return c == ' ' || c == '\t'; }
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Without spaces, tabs and line ends at either edge.
inline std::string_view trim(std::string_view s) {
    while (!s.empty() && (is_space(s.front()) || s.front() == '\r')) s.remove_prefix(1);
    while (!s.empty() && (is_space(s.back()) || s.back() == '\r' || s.back() == '\n')) s.remove_suffix(1);
    return s;
}

// Length of "12." / "3)" at the start of s (at most 9 digits, as CommonMark),
// 0 when there is none.
inline std::size_t ordinal_length(std::string_view s) {
    std::size_t i = 0;
    while (i < s.size() && i < 9 && is_digit(s[i])) ++i;
    if (i == 0 || i >= s.size() || (s[i] != '.' && s[i] != ')')) return 0;
    return i + 1;
}

}  // namespace tactus::exporter::markdown
