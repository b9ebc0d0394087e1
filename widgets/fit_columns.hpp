// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Table columns that never cut their headings or their cells. Stretched
// columns share the table's width evenly, so "Versus lower bound" or a longer
// translation was cut off in a narrow dock. Columns take at
// least the width of their heading and their widest cell, the last one takes
// what is left, and the table asks its layout for the room that needs. The
// room is measured again whenever the table's rows change: a cell such as
// "Jerk-limited (7 segments)" arrives only once a plan exists.
class QTableView;

namespace tactus::gui {

void fit_columns_to_headings(QTableView* table);

}  // namespace tactus::gui
