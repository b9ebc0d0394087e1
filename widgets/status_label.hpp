// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Status that a screen reader must hear with its caption: the controller status,
// a standing fault, the motion time estimates, the natural frequencies, the
// position ("Sheet 1 of 1 ..."). Qt names a QLabel by its text unless it has an
// accessible name, and then the text is never heard: a fixed name such as
// "Controller status" hid the status itself. A status label keeps no fixed name;
// its accessible name is "caption: text", and a new text is announced as a name
// change the way Qt does for any unnamed label.
#include <QString>

class QAccessibleInterface;
class QLabel;

namespace tactus::gui {

// Makes `label` a status label with this caption (its accessible description too).
void expose_status(QLabel* label, const QString& caption);
// The caption given with expose_status(), or empty for other labels.
[[nodiscard]] QString status_caption(const QLabel* label);
// "caption: text" (plain text, one line); the caption alone while the text is empty.
[[nodiscard]] QString status_accessible_name(const QLabel* label);
// The accessible interface of a status label (used by install_accessibility()).
QAccessibleInterface* make_accessible_status(QLabel* label);

}  // namespace tactus::gui
