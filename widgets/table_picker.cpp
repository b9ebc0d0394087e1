// SPDX-License-Identifier: GPL-3.0-or-later
#include "table_picker.hpp"

#include <QLocale>

#include "translate/catalogue.hpp"

namespace tactus::gui {
namespace {

// liblouis names its tables in English only. For another interface language the
// name is built from the table's metadata with translated words, so that a
// Chinese reader sees "英文 — 統一英文點字，縮寫" and not English.
QString braille_code(const translate::TableInfo& t) {
    QStringList parts;
    if (t.system == "ueb") parts << TablePicker::tr("Unified English Braille");
    else if (t.system == "ebae") parts << TablePicker::tr("English Braille American Edition");
    else if (t.system == "cmn-bopomofo") parts << TablePicker::tr("Taiwanese braille (bopomofo)");
    else if (t.system == "cmn-traditional") parts << TablePicker::tr("current Chinese braille");
    else if (t.system == "cmn-two-cell") parts << TablePicker::tr("two-cell Chinese braille");
    if (t.contraction == "no") parts << TablePicker::tr("uncontracted");
    else if (t.contraction == "partial") parts << TablePicker::tr("partly contracted");
    else if (t.contraction == "full") parts << TablePicker::tr("contracted");
    else if (!t.grade.empty()) parts << TablePicker::tr("grade %1").arg(QString::fromStdString(t.grade));
    if (parts.isEmpty()) return QString::fromStdString(t.name.empty() ? t.file : t.name);
    return parts.join(TablePicker::tr(", ", "list separator")) + QStringLiteral(" (%1)").arg(QString::fromStdString(t.file));
}

}  // namespace

TablePicker::TablePicker(QWidget* parent) : QComboBox(parent) {
    setObjectName(QStringLiteral("tablePicker"));
    setAccessibleName(tr("Braille table"));
    setAccessibleDescription(tr("The language and braille code the print is translated with"));
    setToolTip(accessibleDescription());
    // The window says "Braille table: ..." for each change (MainWindow::set_table).
    setProperty("announcesChange", true);
    const QLocale ui;  // the interface language (main sets it as the default)
    const bool english = ui.language() == QLocale::English || ui.language() == QLocale::C;
    for (const auto& t : translate::table_catalogue(ui.bcp47Name().toStdString())) {
        const auto language = QString::fromStdString(t.language.empty() ? t.language_tag : t.language);
        const auto name = english ? QString::fromStdString(t.name.empty() ? t.file : t.name) : braille_code(t);
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
