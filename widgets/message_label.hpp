// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The status bar's message, shown whole. QStatusBar::showMessage paints one
// line under the permanent widgets, so a long message (a table warning, a
// printer fault) ran into the position indicator and was cut. This label sits
// beside the position, wraps, and is as tall as its text needs; a message
// clears itself after a while, like showMessage's timeout. It is not what a
// screen reader hears first: the announcer speaks the message; the label keeps
// it on screen (and in reach of a screen reader's review).
#include <QLabel>

class QTimer;

namespace tactus::gui {

class MessageLabel : public QLabel {
    Q_OBJECT
public:
    explicit MessageLabel(QWidget* parent = nullptr);
    // Shows `text` for `timeout_ms` (0: until the next message).
    void show_message(const QString& text, int timeout_ms);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void fit_height();
    QTimer* clear_ = nullptr;
};

}  // namespace tactus::gui
