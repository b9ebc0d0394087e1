// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Table columns that never cut their headings. Stretched columns share the
// table's width evenly, so "Versus lower bound" or a longer translation was
// cut off in a narrow dock (issue 14 item 4). Columns take at least their
// heading's width, the last one takes what is left, and the table asks its
// layout for the room the headings need.
class QTableView;

namespace tactus::gui {

void fit_columns_to_headings(QTableView* table);

}  // namespace tactus::gui
