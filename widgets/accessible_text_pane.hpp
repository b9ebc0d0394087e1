// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QAccessibleInterface;
class QPlainTextEdit;
class QTextEdit;

namespace tactus::gui {

// The accessible text of the app's text panes, for its accessibility factory:
// Qt's interface for a text edit, but with the units of text_units.hpp, the
// same in every pane. A word runs to the start of the next one, its trailing
// gap included, as AT-SPI's word-start boundary says: Orca presents a word
// move as the word it passed only when the word before the caret reaches it,
// so with Qt's own units ("has" without its space) the first Ctrl+Right in the
// print text was silent.

// The braille pane and read-only plain texts (logs). A blank cell (U+2800) is
// shown as the space it is: Orca takes the word passed by Ctrl+Right to start
// after the last space or letter before the caret, and a braille cell is
// neither, so the first word move said the blank cell alone. Same length, so
// every offset stays the pane's own.
QAccessibleInterface* make_accessible_plain_text(QPlainTextEdit* pane);

// The print text: a rich text edit.
QAccessibleInterface* make_accessible_rich_text(QTextEdit* pane);

}  // namespace tactus::gui
