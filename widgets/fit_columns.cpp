// SPDX-License-Identifier: GPL-3.0-or-later
#include "fit_columns.hpp"

#include <QAbstractItemModel>
#include <QHeaderView>
#include <QScrollBar>
#include <QTableView>
#include <QTimer>
#include <algorithm>

namespace tactus::gui {
namespace {

void refit(QTableView* table) {
    auto* header = table->horizontalHeader();
    const QAbstractItemView* view = table;  // QTableView hides sizeHintForColumn
    int width = 0;
    for (int i = 0; i < header->count(); ++i) {
        if (header->isSectionHidden(i)) continue;
        width += std::max(header->sectionSizeHint(i), view->sizeHintForColumn(i));
    }
    if (table->verticalHeader()->isVisible()) width += table->verticalHeader()->sizeHint().width();
    table->setMinimumWidth(width + 2 * table->frameWidth() + table->verticalScrollBar()->sizeHint().width());
}

}  // namespace

void fit_columns_to_headings(QTableView* table) {
    auto* header = table->horizontalHeader();
    header->setSectionResizeMode(QHeaderView::ResizeToContents);
    header->setStretchLastSection(true);
    refit(table);
    auto* model = table->model();
    if (!model) return;
    // A table is filled a row at a time: measure once, after the last change.
    auto* again = new QTimer(table);
    again->setSingleShot(true);
    again->setInterval(0);
    QObject::connect(again, &QTimer::timeout, table, [table] { refit(table); });
    const auto later = [again] { again->start(); };
    QObject::connect(model, &QAbstractItemModel::rowsInserted, again, later);
    QObject::connect(model, &QAbstractItemModel::rowsRemoved, again, later);
    QObject::connect(model, &QAbstractItemModel::modelReset, again, later);
    QObject::connect(model, &QAbstractItemModel::dataChanged, again, later);
    QObject::connect(model, &QAbstractItemModel::layoutChanged, again, later);
    QObject::connect(model, &QAbstractItemModel::headerDataChanged, again, later);
}

}  // namespace tactus::gui
