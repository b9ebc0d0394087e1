// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <vector>

#include "document/cell.hpp"

namespace tactus::layout {

// Fills lines of `width` cells with the words of `cells` (words are runs of
// non-blank cells). The first line starts after `first_indent` blank cells, the
// others after `runover_indent`. A word longer than a line is cut across lines,
// so no cell is ever dropped.
std::vector<document::BrailleLine> break_lines(const document::BrailleLine& cells, int width, int first_indent,
                                     int runover_indent);

}  // namespace tactus::layout
