// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A table cell's paragraphs (document.hpp, table_cell): its text cut at each
// line break. The one place that reads the rule; the translator lays each
// paragraph on a line of its own, the DOCX and ODT writers write each as a
// paragraph of the cell.
#include <span>
#include <vector>

#include "document/document.hpp"

namespace tactus::document {

// The spans of each paragraph, in order, the line breaks left out; a span
// with no line break stays whole, one that has some is cut there. A note
// reference or a transcriber's note is never cut. Always at least one
// paragraph (empty for an empty cell); an empty paragraph (two breaks in a
// row, a break at an end) is kept as an empty entry.
std::vector<std::vector<Span>> cell_paragraphs(std::span<const Span> spans);

// True when the cell's text has a line break, i.e. more than one paragraph.
bool has_cell_paragraphs(std::span<const Span> spans);

}  // namespace tactus::document
