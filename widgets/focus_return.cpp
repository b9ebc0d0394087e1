// SPDX-License-Identifier: GPL-3.0-or-later
#include "focus_return.hpp"

#include <QApplication>
#include <QTimer>

namespace tactus::gui {

void return_focus(QWidget* window, QWidget* target) {
    if (!window || !window->isVisible()) return;
    window->raise();
    window->activateWindow();
    if (target && target->isVisible() && target->isEnabled() && target->window() == window)
        target->setFocus(Qt::OtherFocusReason);
    // The window manager handles the closed dialog's window asynchronously and can
    // leave no window focused after our request: ask again while none of the
    // app's windows is active (never taking the focus from another of its windows).
    QPointer<QWidget> w(window);
    for (const int ms : {50, 250, 1000})
        QTimer::singleShot(ms, window, [w] {
            if (w && w->isVisible() && !QApplication::activeWindow()) {
                w->raise();
                w->activateWindow();
                // When the window manager already gave our window the input focus
                // (so the request above changes nothing), Qt never hears of it and
                // keeps the window inactive: tell Qt directly.
                QApplication::setActiveWindow(w);
            }
        });
}

FocusReturn::FocusReturn(QWidget* window, QWidget* fallback)
    : window_(window), previous_(QApplication::focusWidget()), fallback_(fallback) {
    if (previous_ && previous_->window() != window) previous_ = nullptr;
}

FocusReturn::~FocusReturn() { restore(); }

void FocusReturn::restore() {
    if (done_) return;
    done_ = true;
    return_focus(window_, previous_ ? previous_.data() : fallback_.data());
}

}  // namespace tactus::gui
