// SPDX-License-Identifier: GPL-3.0-or-later
#include "language_choice.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QVBoxLayout>
#include <algorithm>

#include "translate/catalogue.hpp"

namespace tactus::gui {
namespace {

// The interface language (main sets it as the default locale).
std::string interface_locale() { return QLocale().bcp47Name().toStdString(); }

}  // namespace

QString language_name(const QString& tag) {
    if (tag.isEmpty()) return {};
    return QString::fromStdString(translate::language_display_name(tag.toStdString(), interface_locale()));
}

QString language_status(const QString& tag) {
    return tag.isEmpty() ? QString() : QCoreApplication::translate("tactus::gui::LanguageChoice", "Language: %1").arg(language_name(tag));
}

QString language_set_text(const QString& tag) {
    return tag.isEmpty() ? QCoreApplication::translate("tactus::gui::LanguageChoice", "Language: document default") : language_status(tag);
}

std::optional<LanguageChoice> ask_language(QWidget* parent, const QString& current) {
    QDialog dialog(parent);
    dialog.setObjectName(QStringLiteral("languageDialog"));
    dialog.setWindowTitle(QCoreApplication::translate("tactus::gui::LanguageChoice", "Language"));
    auto* languages = new QComboBox(&dialog);
    languages->setObjectName(QStringLiteral("languageList"));
    languages->addItem(QCoreApplication::translate("tactus::gui::LanguageChoice", "Document default"), QString());
    for (const auto& l : translate::passage_languages(interface_locale()))
        languages->addItem(QString::fromStdString(l.name), QString::fromStdString(l.tag));
    // A passage marked in a language without a table of its own (from a
    // file) is shown as it is, so that OK keeps it.
    if (!current.isEmpty() && languages->findData(current) < 0) languages->addItem(language_name(current), current);
    languages->setCurrentIndex(std::max(0, languages->findData(current)));
    auto* paragraph = new QCheckBox(QCoreApplication::translate("tactus::gui::LanguageChoice", "The whole &paragraph"), &dialog);
    paragraph->setObjectName(QStringLiteral("languageParagraph"));
    auto* form = new QFormLayout;
    auto* label = new QLabel(QCoreApplication::translate("tactus::gui::LanguageChoice", "&Language:"), &dialog);
    label->setBuddy(languages);
    form->addRow(label, languages);
    form->addRow(paragraph);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    auto* layout = new QVBoxLayout(&dialog);
    layout->addLayout(form);
    layout->addWidget(buttons);
    languages->setFocus();
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    return LanguageChoice{languages->currentData().toString(), paragraph->isChecked()};
}

}  // namespace tactus::gui
