// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The book layout's rules and title page, as the CLI's --volumes options set
// them (pipeline::BookOptions, docs/layout.md "Books"): sheets per volume, the
// heading level a volume may start at, the title page, the contents and its
// depth, running heads; the title page's lines. The rules are the user's
// (kept in the settings, for every book); the title page's lines belong to one
// document (empty: from its metadata), so they are never saved.
#include <QDialog>

#include "pipeline/book_layout.hpp"

class QCheckBox;
class QLineEdit;
class QSettings;
class QSpinBox;

namespace tactus::gui {

class BookSettingsDialog : public QDialog {
    Q_OBJECT
public:
    explicit BookSettingsDialog(const pipeline::BookOptions& current, QWidget* parent = nullptr);
    [[nodiscard]] pipeline::BookOptions options() const;
    // Shows these options.
    void show_options(const pipeline::BookOptions& options);

private:
    // Only the rules ("Restore Defaults" leaves the title page's lines).
    void show_rules(const pipeline::BookOptions& options);

    QSpinBox* sheets_;
    QSpinBox* split_level_;
    QCheckBox* title_page_;
    QCheckBox* contents_;
    QSpinBox* contents_depth_;
    QCheckBox* running_heads_;
    QLineEdit* title_;
    QLineEdit* author_;
    QLineEdit* publisher_;
    QLineEdit* year_;
    QLineEdit* transcriber_;
};

// The rules as the settings keep them (group "book"); what is not there has
// the rules' default. The title page's lines are left empty.
[[nodiscard]] pipeline::BookOptions load_book_rules(const QSettings& settings);
void save_book_rules(QSettings& settings, const pipeline::BookOptions& options);
// The options with the title page's lines emptied: another document's.
[[nodiscard]] pipeline::BookOptions without_title_lines(pipeline::BookOptions options);

}  // namespace tactus::gui
