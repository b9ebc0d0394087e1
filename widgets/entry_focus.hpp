// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A text entry that Orca names when Tab or a shortcut reaches it. Then
// QLineEdit selects its
// whole text as it takes the focus, and tells assistive technology that the
// selection and the caret moved before QWidget::setFocus sends the accessible
// focus event. Orca takes the object of a selection or caret event as the
// focus, silently, so the focus event after it changes nothing and the entry
// is reached in silence (its name is never said). Here the entry takes the
// focus as if not by Tab, so the focus event comes alone and is spoken, and
// selects its text just after, as a Tab would have (what is typed then
// replaces the old text).
class QLineEdit;

namespace tactus::gui {

// Installs this on `entry` (owned by it; removed with it).
void speak_entry_on_focus(QLineEdit* entry);

}  // namespace tactus::gui
