// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <span>
#include <vector>

#include "document/cell.hpp"
#include "translate/line_breaks.hpp"

namespace tactus::layout {

// Fills lines of `width` cells with `cells`. A line ends only where `breaks`
// allows it (translate/line_breaks.hpp): at a blank cell, which is dropped at the
// line end, after a hyphen or between Chinese characters, and always before a
// forced break (a divided word's next piece). The first line starts after
// `first_indent` blank cells, the others after `runover_indent`; a paragraph
// break (the next paragraph of a table cell) ends the line and starts the next
// one after `runover_indent`, under its entry. Runs of blank
// cells become one. A unit longer than a line (only braille without the
// translator's division) is cut between print characters; no cell is dropped.
std::vector<document::BrailleLine> break_lines(const document::BrailleLine& cells, std::span<const translate::BreakBefore> breaks,
                                     int width, int first_indent, int runover_indent);

// Without break information: words are runs of non-blank cells (typed braille).
std::vector<document::BrailleLine> break_lines(const document::BrailleLine& cells, int width, int first_indent,
                                     int runover_indent);

}  // namespace tactus::layout
