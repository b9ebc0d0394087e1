// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Dividing a word too long for a braille line, by the braille code's rules
// rather than by counting cells:
//  - the word is divided in print, between syllables where the table's language
//    has a hyphenation dictionary (UEB 10.13: divide between syllables), else
//    between any two print characters;
//  - each piece is translated again on its own with a hyphen at its end, so every
//    piece carries its own indicators (a capitals-word indicator is repeated, as
//    after any hyphen in UEB) and no contraction bridges the division;
//  - UEB 6.10: a number is divided between digits with the one-cell line
//    continuation indicator (dot 5) at the line end and no numeric indicator on
//    the next line, since the continuation does not end numeric mode.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "document/cell.hpp"
#include "translate/translator.hpp"

namespace tactus::translate {

// Pieces of at most `room` cells whose concatenation reads as `word`; every piece
// but the last ends with the code's division sign. `emphasis` is empty or one
// entry per code point of `word`.
Result<std::vector<document::BrailleLine>> divide_word(const Translator& translator, std::u32string_view word,
                                             std::span<const std::uint8_t> emphasis,
                                             std::size_t room);

// The same, each line handed to `sink` as it is made, so a word of many
// megabytes (a text without spaces) is not held twice, once as its lines
// (a 50 MB word held as lines takes 140 MB).
using PieceSink = std::function<void(document::BrailleLine&&)>;
Result<void> divide_word(const Translator& translator, std::u32string_view word, std::span<const std::uint8_t> emphasis,
                         std::size_t room, const PieceSink& sink);

}  // namespace tactus::translate
