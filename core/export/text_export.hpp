// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The document as print text files: Markdown and plain text, beside the braille
// formats (export.hpp). Escaping is the Markdown writer's business only: the
// plain text writer writes the text as it is. Both write what core's importers
// read back to the same blocks (tests/export/text_export_test.cpp,
// tests/edit/round_trip_test.cpp).
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"

#include "document/document.hpp"

namespace tactus::exporter {

// ---- Markdown ----

// One block as one line of Markdown, escaped so that core's Markdown importer
// (and the editor's line dialect) reads the block back: "## Heading", "  - item",
// "3. item", "> quote", "[^1]: note", "<!-- pagebreak 12 -->" (a label counted on
// from the page before is left out: "<!-- pagebreak -->"), a paragraph with
// *italic* and **bold**. Table blocks give "" (see markdown_lines).
std::string markdown_line(const document::Block& block);

// A table row and its cells as one GitHub pipe-table row: "| a | b \| c |".
// Each cell in its column (Block::level); a merged cell's other columns are
// empty entries (Markdown has no merged cells).
std::string markdown_table_row(std::span<const document::Block> cells);

// The columns of the pipe table a run of table lines is written as: as many
// as its widest row (cells split at unescaped pipes), delimiter rows not
// counted (join_markdown_lines writes them anew), at least one. The importer
// gives every row that many cells; the editor's live layout pads its rows to
// it the same way (one rule for both, so a table opened and saved keeps its
// columns).
std::size_t markdown_table_width(std::span<const std::string> lines);

// The column alignments a pipe table's delimiter row gives: "|:--|:-:|--:|---|"
// -> left, centre, right, none. The Markdown importer reads them (md4c), the
// writer writes them back (join_markdown_lines keeps the editor's row's).
std::vector<document::Align> markdown_table_alignments(std::string_view delimiter);

// True for a pipe table's delimiter row: "|---|:--:|".
bool is_markdown_table_delimiter(std::string_view line);

// The document as Markdown lines, one block a line: a table is its rows, one
// line each, with the delimiter row after the header row (a table without a
// header row gets an empty one, which the importer reads as none, as Pandoc
// writes it); a braille block is its lines of Unicode braille.
std::vector<std::string> markdown_lines(const document::Document& document);

// Markdown lines, one block each, as a file: a blank line between blocks (none
// between the rows of a table), lines without text dropped. A run of table rows
// without a header row and delimiter gets an empty header, and every row of a
// table as many cells as its widest row (GitHub tables take their width from
// the header).
std::string join_markdown_lines(std::span<const std::string> lines);

// The YAML front matter a Markdown file starts with for what the blocks do
// not hold: the document's main language ("lang: zh-TW", which the importer
// and pandoc read), else "" (no front matter).
std::string markdown_front_matter(const document::Document& document);

// The front matter, then the blocks (join_markdown_lines).
std::string to_markdown(const document::Document& document);

// ---- Plain text ----

// One block as the line of plain text it is: its text as written (no escapes,
// no marks; a note reference as "[1]"), a print or braille page break as a form
// feed, braille as its Unicode cells.
std::string text_line(const document::Block& block);

// The document as plain text lines: the blocks one a line (a paragraph with soft
// line breaks, document/soft_break.hpp, is its lines, as one entry with "\n" in it),
// with a blank line between two blocks whose source lines are apart (or unknown),
// so a file opened and saved keeps its own paragraph breaks; and between every
// two paragraphs once the text has any blank line, because then the importer
// joins adjacent lines into one paragraph. A table's cells are one line each.
std::vector<std::string> text_lines(const document::Document& document);

// text_lines as a file, each line ended by LF.
std::string to_text(const document::Document& document);

// ---- Encodings ----

// UTF-8 text as the bytes of a file in `encoding` (an ICU name, as the
// importer records it in Document::encoding: "UTF-8", "UTF-16LE", "BIG5",
// "GB18030", "WINDOWS-1252", ...; empty = UTF-8), with the encoding's
// byte-order mark first when `byte_order_mark`. A text file opened and saved
// is the same bytes. Nothing is ever replaced: a character the encoding
// cannot hold fails (ErrorKind::input) naming it and its line:column, so the
// caller can ask the user (save as UTF-8, or not at all); see
// is_unrepresentable_error.
Result<std::string> encode_text(std::string_view utf8, std::string_view encoding, bool byte_order_mark = false);

// True for the error encode_text gives for a character the encoding cannot
// hold (as opposed to an unknown encoding name).
bool is_unrepresentable_error(const Error& error);

}  // namespace tactus::exporter
