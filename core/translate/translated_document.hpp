// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The document after translation: the same block structure, each block's text
// now braille cells. Layout reads only this.
#include <cstddef>
#include <functional>
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"
#include "translate/line_breaks.hpp"
#include "translate/translator.hpp"

namespace tactus::translate {

struct TranslatedBlock {
    document::BlockKind kind = document::BlockKind::paragraph;
    int level = 0;
    document::BrailleLine cells;               // text kinds; words separated by blank cells
    LineBreaks breaks;               // one per cell of `cells`: where a line may end
    std::vector<document::BrailleLine> lines;  // braille: verbatim lines
    document::BrailleLine label;               // print_page_break: the page number in braille
    int source_line = 0;
    int span = 1;  // table_cell: the columns it covers (document::Block::span)
    int box = 0;   // document::Block::box: the box it is in, 0 = none
};

// Translates one block. Long paragraphs are cut at spaces into pieces liblouis
// handles in linear time; contractions never span a space, so the cut is invisible.
// `word_room` is the narrowest line the block's text may have to fit
// (layout::word_room()); a word longer than that is divided by the code's rules
// (translate/word_division.hpp). 0: no division (layout then cuts an overlong
// word between print characters, without a hyphen).
// `progress`, when given, hears the code points of the block done so far after
// each piece (a 50 MB paragraph takes a minute; the CLI shows how far it is).
Result<TranslatedBlock> translate_block(const document::Block& block, const Translator& translator,
                                        std::size_t word_room = 0,
                                        const std::function<void(std::size_t)>& progress = {});

}  // namespace tactus::translate
