// SPDX-License-Identifier: GPL-3.0-or-later
#include "fit_columns.hpp"

#include <QHeaderView>
#include <QScrollBar>
#include <QTableView>

namespace tactus::gui {

void fit_columns_to_headings(QTableView* table) {
    auto* header = table->horizontalHeader();
    header->setSectionResizeMode(QHeaderView::ResizeToContents);
    header->setStretchLastSection(true);
    int width = 0;
    for (int i = 0; i < header->count(); ++i) width += header->sectionSizeHint(i);
    if (table->verticalHeader()->isVisible()) width += table->verticalHeader()->sizeHint().width();
    table->setMinimumWidth(width + 2 * table->frameWidth() + table->verticalScrollBar()->sizeHint().width());
}

}  // namespace tactus::gui
