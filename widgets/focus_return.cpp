// SPDX-License-Identifier: GPL-3.0-or-later
#include "focus_return.hpp"

#include <QApplication>

namespace tactus::gui {

void return_focus(QWidget* window, QWidget* target) {
    if (!window || !window->isVisible()) return;
    window->raise();
    window->activateWindow();
    if (target && target->isVisible() && target->isEnabled() && target->window() == window)
        target->setFocus(Qt::OtherFocusReason);
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
