// SPDX-License-Identifier: GPL-3.0-or-later
#include "find_replace.hpp"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QTextEdit>
#include <QPushButton>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <QVBoxLayout>

#include "entry_focus.hpp"

namespace tactus::gui {

FindReplaceDialog::FindReplaceDialog(QTextEdit* editor, QWidget* parent)
    : QDialog(parent), editor_(editor) {
    setObjectName(QStringLiteral("findReplace"));
    setWindowTitle(tr("Find and Replace"));
    setAccessibleName(windowTitle());
    find_ = new QLineEdit(this);
    find_->setAccessibleName(tr("Find"));
    replace_ = new QLineEdit(this);
    replace_->setAccessibleName(tr("Replace with"));
    speak_entry_on_focus(find_);
    speak_entry_on_focus(replace_);
    case_ = new QCheckBox(tr("&Match case"), this);
    words_ = new QCheckBox(tr("&Whole words"), this);
    status_ = new QLabel(this);
    status_->setAccessibleName(tr("Search result"));
    auto* form = new QFormLayout;
    form->addRow(tr("F&ind:"), find_);
    form->addRow(tr("Re&place with:"), replace_);
    form->addRow(case_);
    form->addRow(words_);
    auto* buttons = new QDialogButtonBox(this);
    auto* next = buttons->addButton(tr("Find &Next"), QDialogButtonBox::ActionRole);
    auto* previous = buttons->addButton(tr("Find Pre&vious"), QDialogButtonBox::ActionRole);
    auto* one = buttons->addButton(tr("&Replace"), QDialogButtonBox::ActionRole);
    auto* all = buttons->addButton(tr("Replace &All"), QDialogButtonBox::ActionRole);
    buttons->addButton(QDialogButtonBox::Close);
    next->setDefault(true);
    connect(next, &QPushButton::clicked, this, &FindReplaceDialog::find_next);
    connect(previous, &QPushButton::clicked, this, &FindReplaceDialog::find_previous);
    connect(one, &QPushButton::clicked, this, &FindReplaceDialog::replace_one);
    connect(all, &QPushButton::clicked, this, &FindReplaceDialog::replace_all);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::hide);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(status_);
    layout->addWidget(buttons);
}

void FindReplaceDialog::set_find_text(const QString& text) {
    find_->setText(text);
    find_->selectAll();
}

bool FindReplaceDialog::find(bool backward) {
    QTextDocument::FindFlags flags;
    if (backward) flags |= QTextDocument::FindBackward;
    if (case_->isChecked()) flags |= QTextDocument::FindCaseSensitively;
    if (words_->isChecked()) flags |= QTextDocument::FindWholeWords;
    const auto needle = find_->text();
    if (needle.isEmpty()) return false;
    auto* doc = editor_->document();
    auto found = doc->find(needle, editor_->textCursor(), flags);
    if (found.isNull()) {  // wrap around once
        QTextCursor from(doc);
        if (backward) from.movePosition(QTextCursor::End);
        found = doc->find(needle, from, flags);
    }
    if (found.isNull()) {
        status_->setText(tr("\u201c%1\u201d not found").arg(needle));
        Q_EMIT message(status_->text());
        return false;
    }
    editor_->setTextCursor(found);
    status_->setText(tr("Found on line %1").arg(found.blockNumber() + 1));
    Q_EMIT message(status_->text());
    return true;
}

bool FindReplaceDialog::find_next() { return find(false); }
bool FindReplaceDialog::find_previous() { return find(true); }

bool FindReplaceDialog::replace_one() {
    auto c = editor_->textCursor();
    const auto cs = case_->isChecked() ? Qt::CaseSensitive : Qt::CaseInsensitive;
    if (c.hasSelection() && c.selectedText().compare(find_->text(), cs) == 0) {
        c.insertText(replace_->text());
        editor_->setTextCursor(c);
    }
    return find_next();
}

int FindReplaceDialog::replace_all() {
    QTextDocument::FindFlags flags;
    if (case_->isChecked()) flags |= QTextDocument::FindCaseSensitively;
    if (words_->isChecked()) flags |= QTextDocument::FindWholeWords;
    if (find_->text().isEmpty()) return 0;
    auto* doc = editor_->document();
    QTextCursor edit(doc);
    edit.beginEditBlock();  // one undo step
    int n = 0;
    QTextCursor at(doc);
    while (true) {
        at = doc->find(find_->text(), at, flags);
        if (at.isNull()) break;
        at.insertText(replace_->text());
        ++n;
    }
    edit.endEditBlock();
    status_->setText(tr("%n replaced", nullptr, n));
    Q_EMIT message(status_->text());
    return n;
}

}  // namespace tactus::gui
