// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tab and Shift+Tab through the controls a user can see. With docks stacked as
// tabs, Qt's focus chain also walked the controls of the tabs that are not
// raised (about 45 stops for Motion, Vibration, Profile and Printer while the
// Preview is shown): the focus went where neither a sighted nor a blind user
// could follow it.
class QDockWidget;
class QWidget;

namespace tactus::gui {

// Remembers whether the dock's tab is raised (QDockWidget::visibilityChanged).
void track_dock_page(QDockWidget* dock);
// True when `w` is inside a dock of `window` whose tab is not raised.
[[nodiscard]] bool on_hidden_page(const QWidget* w, const QWidget* window);
// Moves the focus of `window` to the next (or previous) control that takes Tab
// focus, is enabled, shown and not on a hidden page. False when there is none.
bool focus_next_visible(QWidget* window, bool next);

}  // namespace tactus::gui
