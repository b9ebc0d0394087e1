// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The editor shows a document in one of two line dialects, one block per line,
// so an edit touches exactly the blocks of the lines it changed:
// - Markdown (a .md, .docx, ...): "# Heading", "  - nested item", "3. numbered
//   item", "<!-- pagebreak 12 -->" or "---", "| a | b |" (a table row; the
//   delimiter row "|---|---|" under it makes it the header row), a paragraph
//   with *italic* and **bold**, <u>underline</u>, <sup>raised</sup> and
//   <sub>lowered</sub> text, <span lang="de">a passage's language</span>,
//   "![description](name)" a picture (edit/editor_pictures.hpp),
//   "<!-- box -->" ... "<!-- /box -->" lines around a box's blocks (the HTML
//   core's Markdown writer and importer share, document/markdown_html.hpp);
//   the lines are core's Markdown writer's
//   (export/text_export.hpp), which core's importer reads again.
// - Text (a .txt): the file's own lines, as the author wrote them, with no
//   escapes and no marks; blank lines separate paragraphs, whose lines run on
//   (a hard-wrapped paragraph, brailled as one), or each line is a paragraph
//   when no blank line separates any two (import/text_lines.hpp, the
//   importer's rules); a form feed is a print page break.
// In both, a line of Unicode braille cells is braille kept verbatim.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"

namespace tactus::edit {

enum class Dialect { markdown, text };

// The dialect a file is shown in: text for .txt and .text, else Markdown.
Dialect dialect_for(std::string_view file_name);

// The block a line stands for; empty for a blank line (and for a table's
// delimiter row). A page break without a label gets an empty label (the caller
// numbers it: document/print_page.hpp). A table row gives its table_row block;
// its cells are parse_table_cells's.
std::optional<document::Block> parse_editor_line(std::string_view utf8, Dialect dialect = Dialect::markdown);

// A box line (document/markdown_html.hpp, "<!-- box -->" and "<!-- /box -->"):
// +1 starts a box, -1 ends one, 0 for any other line. It stands for no block;
// the blocks between a box's lines are the box (LiveLayout::document()).
int box_line(std::string_view utf8, Dialect dialect = Dialect::markdown);

// The cells of a table row line ("| a | *b* |"), one table_cell block each.
std::vector<document::Block> parse_table_cells(std::string_view utf8);
// True for a Markdown table's delimiter row ("|---|---|").
bool is_table_delimiter(std::string_view utf8);

// The editor's lines for a document, so that parse_editor_line gives its blocks
// back: Markdown through core's Markdown writer, text the lines of the file
// core's text writer writes (a text file opened is shown as its own lines,
// import/text_lines.hpp split_text_lines).
std::vector<std::string> render_editor_lines(const document::Document& document,
                                             Dialect dialect = Dialect::markdown);
std::string render_editor_line(const document::Block& block, Dialect dialect = Dialect::markdown);

// The editor's lines as the file they are saved as, in the file's format (by
// its name's extension: .txt and .text are plain text, anything else Markdown).
// `blocks` are the lines' blocks with their print pages numbered
// (LiveLayout::document()); when the lines are in the file's own dialect they
// are written as they are (made whole, for a Markdown table; a text file's
// lines byte for byte), else the blocks are written by core's writer for that
// format; every line ends with `line_ending`, the file's own (a text or
// Markdown file's first, Document::line_ending).
std::string file_text(std::span<const std::string> lines, Dialect dialect, const document::Document& blocks,
                      std::string_view file_name, std::string_view line_ending = "\n");

// file_text as the file's bytes, text (.txt, .text) and Markdown alike, in the
// encoding the document was opened with (`blocks.encoding`, with its
// byte-order mark when `blocks.byte_order_mark`: exporter::encode_text; empty,
// as for a new document or a DOCX, is UTF-8), so a file opened and saved is the
// same bytes. Fails, writing nothing, when the text holds a character that
// encoding cannot (exporter::is_unrepresentable_error).
// A .docx or .odt name gives the blocks as that word-processor file
// (exporter::to_office), with what it does not keep added to `warnings`.
Result<std::string> file_bytes(std::span<const std::string> lines, Dialect dialect, const document::Document& blocks,
                               std::string_view file_name, std::string_view line_ending = "\n",
                               std::vector<std::string>* warnings = nullptr);

// The text a reader sees: without the heading marks, bullet and emphasis marks.
// Used to map the cursor between print and braille word by word.
std::string editor_line_content(std::string_view utf8, Dialect dialect = Dialect::markdown);

// True when the line is nothing but Unicode braille cells (U+2800..U+28FF).
bool is_braille_line(std::string_view utf8);

}  // namespace tactus::edit
