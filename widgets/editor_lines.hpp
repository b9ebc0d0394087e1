// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The editor shows a document as lines of light Markdown, one block per line:
// "# Heading", "  - nested item", "3. numbered item", "<!-- pagebreak 12 -->",
// a paragraph with *italic* and **bold**, or a line of Unicode braille cells kept
// verbatim. One line is one block, so an edit touches exactly the blocks of the
// lines it changed; the file on disk is ordinary Markdown that core imports again.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "document/document.hpp"

namespace tactus::gui {

// The block a line stands for; empty for a blank line. A page break without a
// label gets an empty label (the caller numbers it from the previous one).
std::optional<document::Block> parse_editor_line(std::string_view utf8);

// One editor line per block, escaped so that parse_editor_line gives the block back.
std::vector<std::string> render_editor_lines(const document::Document& document);
std::string render_editor_line(const document::Block& block);

// The text a reader sees: without the heading marks, bullet and emphasis marks.
// Used to map the cursor between print and braille word by word.
std::string editor_line_content(std::string_view utf8);

// True when the line is nothing but Unicode braille cells (U+2800..U+28FF).
bool is_braille_line(std::string_view utf8);

}  // namespace tactus::gui
