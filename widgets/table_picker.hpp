// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Braille tables by language name ("English - Unified English contracted braille"),
// recommended tables first; the liblouis file name is the item data.
#include <QComboBox>

namespace tactus::gui {

class TablePicker : public QComboBox {
    Q_OBJECT
public:
    explicit TablePicker(QWidget* parent = nullptr);
    [[nodiscard]] QString table() const;
    // Selects the table with this file name; adds it when it is not catalogued.
    void set_table(const QString& file);

Q_SIGNALS:
    void table_chosen(const QString& file);
};

}  // namespace tactus::gui
