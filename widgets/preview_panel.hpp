// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The preview dock: the sheet view in a scroll area with its side, page, zoom and
// contrast controls, each an action with a shortcut so all of it works by keyboard.
#include <QWidget>

#include "sheet_preview.hpp"

class QAction;
class QActionGroup;
class QComboBox;
class QLabel;
class QScrollArea;

namespace tactus::gui {

class BookView;

class PreviewPanel : public QWidget {
    Q_OBJECT
public:
    explicit PreviewPanel(QWidget* parent = nullptr);
    [[nodiscard]] SheetPreview* preview() const { return preview_; }
    [[nodiscard]] QList<QAction*> view_actions() const;
    QAction* front_action() const { return front_; }
    QAction* back_action() const { return back_; }
    QAction* both_action() const { return both_; }
    QAction* high_contrast_action() const { return contrast_; }
    QAction* pdf_action() const { return pdf_; }
    QAction* next_volume_action() const { return next_volume_; }
    QAction* previous_volume_action() const { return previous_volume_; }
    // The book whose volumes the panel moves by and names ("Volume 2 of 3,
    // page p1"); the panel reads it again when it changes.
    void set_book(const BookView* book);
    // The volume (0-based) the shown sheet is in.
    [[nodiscard]] std::size_t volume() const;
    // Shows the first sheet of volume `volume` (0-based) and says where it is.
    void go_to_volume(std::size_t volume);
    [[nodiscard]] QString label_text() const;

Q_SIGNALS:
    void print_pdf_requested();
    // Something to say now (a move to another volume).
    void announce(const QString& text);

private:
    void update_label();
    void update_volumes();
    SheetPreview* preview_;
    QScrollArea* scroll_;
    QLabel* label_;
    QAction *front_, *back_, *both_, *next_, *previous_, *zoom_in_, *zoom_out_, *contrast_, *pdf_;
    QAction *next_volume_, *previous_volume_;
    QComboBox* volume_box_;
    QAction* volume_box_action_ = nullptr;
    const BookView* book_ = nullptr;
};

}  // namespace tactus::gui
