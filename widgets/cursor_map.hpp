// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Maps a cursor between a line of print and its braille, word by word: braille
// words are runs of non-blank cells and contractions never cross a space, so the
// k-th print word is the k-th braille word. Inside a word, and for scripts
// without spaces (Chinese), the position is proportional.
#include <cstddef>
#include <string_view>

#include "document/cell.hpp"

namespace tactus::gui {

// `content` is the line as the reader sees it (without Markdown marks).
std::size_t print_to_braille(std::u32string_view content, std::size_t column, const document::BrailleLine& cells);
std::size_t braille_to_print(const document::BrailleLine& cells, std::size_t cell, std::u32string_view content);

}  // namespace tactus::gui
