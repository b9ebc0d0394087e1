// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The document after translation: the same block structure, each block's text
// now braille cells. Layout reads only this.
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"
#include "translate/translator.hpp"

namespace tactus::translate {

struct TranslatedBlock {
    document::BlockKind kind = document::BlockKind::paragraph;
    int level = 0;
    document::BrailleLine cells;               // heading, paragraph, list_item; words separated by blank cells
    std::vector<document::BrailleLine> lines;  // braille: verbatim lines
    document::BrailleLine label;               // print_page_break: the page number in braille
    int source_line = 0;
};

// Translates one block. Long paragraphs are cut at spaces into pieces liblouis
// handles in linear time; contractions never span a space, so the cut is invisible.
Result<TranslatedBlock> translate_block(const document::Block& block, const Translator& translator);

}  // namespace tactus::translate
