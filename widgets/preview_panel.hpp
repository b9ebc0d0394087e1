// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The preview dock: the sheet view in a scroll area with its side, page, zoom and
// contrast controls, each an action with a shortcut so all of it works by keyboard.
#include <QWidget>

#include "sheet_preview.hpp"

class QAction;
class QActionGroup;
class QLabel;
class QScrollArea;

namespace tactus::gui {

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

Q_SIGNALS:
    void print_pdf_requested();

private:
    void update_label();
    SheetPreview* preview_;
    QScrollArea* scroll_;
    QLabel* label_;
    QAction *front_, *back_, *both_, *next_, *previous_, *zoom_in_, *zoom_out_, *contrast_, *pdf_;
};

}  // namespace tactus::gui
