// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Maps a cursor between a line of print and its braille, word by word: braille
// words are runs of non-blank cells and contractions never cross a space, so the
// k-th print word is the k-th braille word. Inside a word, and for scripts
// without spaces (Chinese), the position is proportional.
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "document/cell.hpp"

namespace tactus::edit {

// `content` is the line as the reader sees it (without Markdown marks).
std::size_t print_to_braille(std::u32string_view content, std::size_t column, const document::BrailleLine& cells);
std::size_t braille_to_print(const document::BrailleLine& cells, std::size_t cell, std::u32string_view content);

// The braille of a paragraph written on several print lines (a hard-wrapped
// paragraph of a text file, brailled as its lines joined with one space) cut
// into each line's part, [begin, end) in `cells`: word by word, so a line
// shows the braille of its own words; in proportion to the lines' lengths when
// the words do not pair up.
std::vector<std::pair<std::size_t, std::size_t>> braille_of_lines(std::span<const std::u32string> lines,
                                                                  const document::BrailleLine& cells);

}  // namespace tactus::edit
