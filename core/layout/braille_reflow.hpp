// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Ready-made braille (BRF, PEF) laid out again on other pages (--reflow): the
// old pages' furniture is taken away and the text's paragraphs are joined so
// the paginator can break them again where braille may break.
//
// - Page numbers: a number (the numeric indicator and digits a-j, with a
//   letter or two before it, p12 or t3) at the end of a page's first or last
//   line, three or more blank cells after the text (BANA Braille Formats:
//   braille page numbers at the right of the last line, print page numbers at
//   the right of the first), is removed; a line left blank by it goes too.
// - Running heads: a first line that is the same on at least half the pages
//   (and on two or more) is removed.
// - Paragraphs: a line that starts in cell 1 goes on with the paragraph
//   before it, across page ends too; a blank line, a line indented by one or
//   two cells (a paragraph's first line, cell 3) starts a new paragraph, and a
//   line indented by three or more (a centred heading) is a heading of its own.
//   Lines are joined with one blank cell, or with none after a line that ends
//   in a hyphen.
// - Breaks: the joined cells may break again only at a blank cell or after a
//   hyphen, never inside a word, a number or an indicator (a braille word's
//   cells are never cut; a word longer than the line is the paginator's).
#include <vector>

#include "document/document.hpp"
#include "translate/translated_document.hpp"

namespace tactus::layout {

std::vector<translate::TranslatedBlock> reflow_braille(const document::Document& doc);

}  // namespace tactus::layout
