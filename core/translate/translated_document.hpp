// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The document after translation: the same block structure, each block's text
// now braille cells. Layout reads only this.
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"
#include "translate/translator.hpp"

namespace tactus {

struct TranslatedBlock {
    BlockKind kind = BlockKind::paragraph;
    int level = 0;
    BrailleLine cells;               // heading, paragraph, list_item; words separated by blank cells
    std::vector<BrailleLine> lines;  // braille: verbatim lines
    BrailleLine label;               // print_page_break: the page number in braille
    int source_line = 0;
};

// Translates one block. Long paragraphs are cut at spaces into pieces liblouis
// handles in linear time; contractions never span a space, so the cut is invisible.
Result<TranslatedBlock> translate_block(const Block& block, const Translator& translator);

}  // namespace tactus
