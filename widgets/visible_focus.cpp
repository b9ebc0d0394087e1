// SPDX-License-Identifier: GPL-3.0-or-later
#include "visible_focus.hpp"

#include <QDockWidget>
#include <QVariant>

namespace tactus::gui {
namespace {
constexpr const char* kShown = "tactusDockShown";
}

void track_dock_page(QDockWidget* dock) {
    dock->setProperty(kShown, true);
    QObject::connect(dock, &QDockWidget::visibilityChanged, dock, [dock](bool shown) { dock->setProperty(kShown, shown); });
}

bool on_hidden_page(const QWidget* w, const QWidget* window) {
    for (auto* p = w; p && p != window; p = p->parentWidget())
        if (qobject_cast<const QDockWidget*>(p)) {
            const auto shown = p->property(kShown);
            if (shown.isValid() && !shown.toBool()) return true;
        }
    return false;
}

bool focus_next_visible(QWidget* window, bool next) {
    QWidget* start = window->focusWidget() ? window->focusWidget() : window;
    // The chain is a ring of every widget in the window: at most one lap.
    for (QWidget* w = next ? start->nextInFocusChain() : start->previousInFocusChain(); w != start;
         w = next ? w->nextInFocusChain() : w->previousInFocusChain()) {
        if (w->window() != window || w->focusProxy()) continue;
        if ((w->focusPolicy() & Qt::TabFocus) != Qt::TabFocus) continue;
        if (!w->isEnabled() || !w->isVisibleTo(window) || on_hidden_page(w, window)) continue;
        w->setFocus(next ? Qt::TabFocusReason : Qt::BacktabFocusReason);
        return true;
    }
    return false;
}

}  // namespace tactus::gui
