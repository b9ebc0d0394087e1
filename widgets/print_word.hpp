// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The print word that produced a cell on paper. The preview said "in the word …"
// with a back-translation of the braille word, which is not what the author
// wrote: Chinese came back as unrelated ideographs and "FRIDAY," as "friday,"
// (issue 14). This finds the editor line the cell came from and the print word
// under it, with the same word-by-word map the cursor uses (cursor_map).
#include <QString>

#include "edit/live_layout.hpp"

namespace tactus::gui {

// Empty when the cell is not part of a print paragraph (a page number, a blank,
// or a line written in braille).
[[nodiscard]] QString print_word_at(const edit::LiveLayout& layout, const edit::PagePosition& where);

}  // namespace tactus::gui
