// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Find and replace in the print text. Replacements go through the print document,
// so they re-translate only the lines they change and undo like typing.
#include <QDialog>

class QCheckBox;
class QLabel;
class QLineEdit;
class QTextEdit;

namespace tactus::gui {

class FindReplaceDialog : public QDialog {
    Q_OBJECT
public:
    FindReplaceDialog(QTextEdit* editor, QWidget* parent = nullptr);
    void set_find_text(const QString& text);

public Q_SLOTS:
    bool find_next();
    bool find_previous();
    bool replace_one();
    int replace_all();

Q_SIGNALS:
    void message(const QString& text);

private:
    bool find(bool backward);
    QTextEdit* editor_;
    QLineEdit* find_;
    QLineEdit* replace_;
    QCheckBox* case_;
    QCheckBox* words_;
    QLabel* status_;
};

}  // namespace tactus::gui
