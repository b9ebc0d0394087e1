// SPDX-License-Identifier: GPL-3.0-or-later
#include "table_picker.hpp"

#include "translate/catalogue.hpp"

namespace tactus::gui {

TablePicker::TablePicker(QWidget* parent) : QComboBox(parent) {
    setObjectName(QStringLiteral("tablePicker"));
    setAccessibleName(tr("Braille table"));
    setAccessibleDescription(tr("The language and braille code the print is translated with"));
    setToolTip(accessibleDescription());
    for (const auto& t : translate::table_catalogue()) {
        const auto language = QString::fromStdString(t.language.empty() ? t.language_tag : t.language);
        const auto name = QString::fromStdString(t.name.empty() ? t.file : t.name);
        addItem(QStringLiteral("%1 \u2014 %2").arg(language, name), QString::fromStdString(t.file));
        setItemData(count() - 1, QString::fromStdString(t.file), Qt::ToolTipRole);
    }
    set_table(QString::fromLatin1(translate::kDefaultTable));
    connect(this, &QComboBox::activated, this, [this](int) { Q_EMIT table_chosen(table()); });
}

QString TablePicker::table() const { return currentData().toString(); }

void TablePicker::set_table(const QString& file) {
    int i = findData(file);
    if (i < 0) {
        addItem(file, file);
        i = count() - 1;
    }
    setCurrentIndex(i);
}

}  // namespace tactus::gui
