// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Footnotes in Markdown, a small extension md4c does not have (docs/import.md,
// "Footnotes"): a definition is a line `[^id]: text` (up to three spaces in
// front) and the indented lines after it; a reference is `[^id]` with a defined
// id. Before md4c parses the text, definitions are blanked out (their line ends
// stay, so line numbers hold) and each reference becomes one private-use
// character that md4c passes through as text.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tactus::import {

// The id of a note reference "[^id]" at `at` in `text` (an id has no space,
// tab or bracket), or none: nothing of the kind there, or its "[" escaped
// (after an odd run of backslashes: "\[^1]" is text, "\\[^1]" a backslash
// and a reference). The one reading of a reference, for the importer and the
// editor's line dialect.
std::optional<std::string_view> note_reference_id(std::string_view text, std::size_t at);

}  // namespace tactus::import

namespace tactus::import::detail {

struct MarkdownFootnote {
    std::string id;
    std::string text;  // the definition's Markdown, continuation lines joined
    int line = 0;      // 1-based line of the definition
};

struct PreparedMarkdown {
    std::string text;                      // the source with the changes above
    std::vector<MarkdownFootnote> notes;   // in order of definition
};

PreparedMarkdown prepare_footnotes(std::string_view markdown);

// The reference character for note `index` (an index into `notes`), and back.
std::string footnote_marker(std::size_t index);
// If `s` starts with a marker: the note's index and the marker's length in bytes.
std::optional<std::pair<std::size_t, std::size_t>> read_footnote_marker(std::string_view s);

}  // namespace tactus::import::detail
