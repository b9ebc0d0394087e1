// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The units a screen reader reads text by (character, word, sentence, line,
// paragraph), for the app's own accessible text interfaces. Qt's fallback
// (QAccessibleTextInterface::textAtOffset) loops for ever on a text with no
// word in it, such as a line of braille cells, and takes a whole braille
// paragraph for one word; these rules know that a blank braille cell (U+2800)
// separates words as a space does, and always end.
#include <QAccessible>
#include <QString>
#include <functional>

namespace tactus::gui {

// [start, end) in UTF-16 offsets of the text.
struct TextUnit {
    int start = 0;
    int end = 0;
};

// A space, a blank braille cell, a tab or a line break.
bool is_word_gap(QChar c);

// Where the next word starts after `offset` (the text's length when none), and
// where the word before `offset` starts (0 when none): Ctrl+Right and Ctrl+Left.
int next_word_start(const QString& text, int offset);
int previous_word_start(const QString& text, int offset);

// The line a caller lays out itself (a text pane's wrapped lines); without one,
// a line is a paragraph.
using LineUnits = std::function<TextUnit(int offset)>;

// The unit of `boundary` that holds `offset`. Units tile the text: a word is the
// word and the gap after it (a gap before the first word is a unit of its own),
// so the unit before and after always exist or are empty at the ends.
TextUnit text_unit_at(const QString& text, int offset, QAccessible::TextBoundaryType boundary,
                      const LineUnits& lines = {});

// QAccessibleTextInterface's three reads over those units.
QString text_at_offset(const QString& text, int offset, QAccessible::TextBoundaryType boundary, int* start,
                       int* end, const LineUnits& lines = {});
QString text_before_offset(const QString& text, int offset, QAccessible::TextBoundaryType boundary, int* start,
                           int* end, const LineUnits& lines = {});
QString text_after_offset(const QString& text, int offset, QAccessible::TextBoundaryType boundary, int* start,
                          int* end, const LineUnits& lines = {});

}  // namespace tactus::gui
