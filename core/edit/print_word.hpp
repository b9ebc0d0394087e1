// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The print word that produced a cell on paper. The preview said "in the word …"
// with a back-translation of the braille word, which is not what the author
// wrote: Chinese came back as unrelated ideographs and "FRIDAY," as "friday,".
// This finds the editor line the cell came from and the print word
// under it, with the same word-by-word map the cursor uses (cursor_map).
#include <string>

#include "edit/live_layout.hpp"

namespace tactus::edit {

// Empty when the cell is not part of a print paragraph (a page number, a blank,
// or a line written in braille).
[[nodiscard]] std::u32string print_word_at(const LiveLayout& layout, const PagePosition& where);

}  // namespace tactus::edit
