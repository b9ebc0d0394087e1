// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "cells.hpp"
#include "layout/paginator.hpp"

using namespace tactus;

namespace {

// Page numbers as "#" + digits in BRF, like UEB's number sign with letters a-j
// would be; a plain digit rendering is enough to check placement.
document::BrailleLine number(int n) {
    std::string s = "#";
    for (char d : std::to_string(n)) s.push_back(d == '0' ? 'J' : static_cast<char>('A' + (d - '1')));
    return brf(s);
}

translate::TranslatedBlock para(std::string_view text) {
    translate::TranslatedBlock b;
    b.kind = document::BlockKind::paragraph;
    b.cells = brf(text);
    return b;
}

translate::TranslatedBlock heading(std::string_view text, int level = 1) {
    translate::TranslatedBlock b;
    b.kind = document::BlockKind::heading;
    b.level = level;
    b.cells = brf(text);
    return b;
}

// A print page break labelled `label` (BRF).
translate::TranslatedBlock print_page(std::string_view label) {
    translate::TranslatedBlock b;
    b.kind = document::BlockKind::print_page_break;
    b.label = brf(label);
    return b;
}

layout::LayoutOptions small(int cells, int lines, bool interpoint) {
    layout::LayoutOptions o;
    o.geometry = {cells, lines, interpoint, false};
    return o;
}

std::vector<std::string> rows(const layout::Page& p) {
    std::vector<std::string> out;
    for (const auto& l : p.lines) out.push_back(brf(l));
    return out;
}

}  // namespace

TEST(Paginator, DefaultIsTheSourceEmbosserFormat) {
    layout::LayoutOptions o;
    EXPECT_EQ(o.geometry.cells_per_line, 27);
    EXPECT_EQ(o.geometry.lines_per_page, 24);
    EXPECT_TRUE(o.geometry.interpoint);
    EXPECT_TRUE(validate(o));
}

TEST(Paginator, ParagraphIndentAndBottomRightNumber) {
    layout::Paginator p(small(12, 4, false), number);
    p.add(para("ONE TWO THREE FOUR"));
    auto doc = std::move(p).finish();
    ASSERT_EQ(doc.pages.size(), 1u);
    EXPECT_EQ(rows(doc.pages[0]), (std::vector<std::string>{"  ONE TWO", "THREE FOUR", "", "          #A"}));
}

TEST(Paginator, FlowsOntoNewPagesAndNumbersThem) {
    layout::Paginator p(small(10, 3, false), number);  // 2 body lines per numbered page
    p.add(para("AA BB CC DD EE FF GG HH"));
    auto doc = std::move(p).finish();
    ASSERT_EQ(doc.pages.size(), 2u);
    EXPECT_EQ(rows(doc.pages[0]), (std::vector<std::string>{"  AA BB CC", "DD EE FF", "        #A"}));
    EXPECT_EQ(rows(doc.pages[1]), (std::vector<std::string>{"GG HH", "", "        #B"}));
}

TEST(Paginator, InterpointNumbersOnlyFronts) {
    layout::Paginator p(small(10, 3, true), number);
    for (int i = 0; i < 5; ++i) p.add(para("WORD"));
    auto doc = std::move(p).finish();
    // Front pages: 2 body lines + number; back pages: 3 body lines, no number.
    ASSERT_EQ(doc.pages.size(), 2u);
    EXPECT_EQ(rows(doc.pages[0]), (std::vector<std::string>{"  WORD", "  WORD", "        #A"}));
    EXPECT_EQ(rows(doc.pages[1]), (std::vector<std::string>{"  WORD", "  WORD", "  WORD"}));
    EXPECT_EQ(doc.sheet_count(), 1u);
    const auto sheet = doc.sheet(1);
    EXPECT_EQ(sheet.front, &doc.pages[0]);
    EXPECT_EQ(sheet.back, &doc.pages[1]);
}

TEST(Paginator, CentredHeadingWithBlankLineAfter) {
    layout::Paginator p(small(12, 6, false), number);
    p.add(heading("TITLE"));
    p.add(para("TEXT"));
    auto doc = std::move(p).finish();
    EXPECT_EQ(rows(doc.pages[0])[0], "   TITLE");
    EXPECT_EQ(rows(doc.pages[0])[1], "");
    EXPECT_EQ(rows(doc.pages[0])[2], "  TEXT");
}

TEST(Paginator, NoBlankLineAtTheTopOfAPage) {
    layout::Paginator p(small(10, 4, false), number);
    p.add(para("A"));
    p.add(para("B"));
    p.add(para("C"));
    p.add(heading("H", 2));  // blank line before would fall at the top of page 2
    auto doc = std::move(p).finish();
    ASSERT_EQ(doc.pages.size(), 2u);
    EXPECT_EQ(rows(doc.pages[1])[0], "    H");
}

TEST(Paginator, PrintPageIndicatorLine) {
    layout::Paginator p(small(10, 5, false), number);
    p.add(para("A"));
    p.add(print_page("#B"));
    p.add(para("B"));
    auto doc = std::move(p).finish();
    EXPECT_EQ(rows(doc.pages[0])[1], "--------#B");
    EXPECT_EQ(rows(doc.pages[0])[2], "  B");
}

TEST(Paginator, PrintPageAtTopOfPageNeedsNoSeparator) {
    layout::Paginator p(small(10, 3, false), number);
    p.add(para("A"));
    p.add(para("B"));
    p.add(print_page("#C"));
    p.add(para("C"));
    auto doc = std::move(p).finish();
    ASSERT_EQ(doc.pages.size(), 2u);
    EXPECT_EQ(rows(doc.pages[1])[0], "  C");
    EXPECT_EQ(doc.pages[1].print_page, document::to_unicode_text(brf("#C")));
}

TEST(Paginator, BraillePageBreakStartsNewPage) {
    layout::Paginator p(small(10, 5, false), number);
    p.add(para("A"));
    translate::TranslatedBlock br;
    br.kind = document::BlockKind::braille_page_break;
    p.add(br);
    p.add(br);  // a second break on an empty page adds no blank page
    p.add(para("B"));
    auto doc = std::move(p).finish();
    ASSERT_EQ(doc.pages.size(), 2u);
    EXPECT_EQ(rows(doc.pages[1])[0], "  B");
}

TEST(Paginator, VerbatimBrailleKeepsSpacingAndCutsLongLines) {
    layout::Paginator p(small(6, 5, false), number);
    translate::TranslatedBlock b;
    b.kind = document::BlockKind::braille;
    b.lines = {brf("A  B"), brf(""), brf("ABCDEFGH")};
    p.add(b);
    auto doc = std::move(p).finish();
    EXPECT_EQ(rows(doc.pages[0]), (std::vector<std::string>{"A  B", "", "ABCDEF", "GH", "    #A"}));
}

TEST(Paginator, MarginsAndTopNumber) {
    auto o = small(12, 4, false);
    o.left_margin = 2;
    o.right_margin = 1;
    o.page_numbers = layout::PageNumberPosition::top_right;
    layout::Paginator p(o, number);
    p.add(para("AAA BBB"));
    auto doc = std::move(p).finish();
    EXPECT_EQ(rows(doc.pages[0]), (std::vector<std::string>{"         #A", "    AAA BBB", "", ""}));
}

TEST(Paginator, ListItemsHangingIndentByLevel) {
    layout::Paginator p(small(9, 6, false), number);
    translate::TranslatedBlock li;
    li.kind = document::BlockKind::list_item;
    li.level = 2;
    li.cells = brf("AA BB CC");
    p.add(li);
    auto doc = std::move(p).finish();
    EXPECT_EQ(rows(doc.pages[0])[0], "  AA BB");
    EXPECT_EQ(rows(doc.pages[0])[1], "    CC");
}

TEST(Paginator, SixDotLayoutStripsDots78WithAWarning) {
    layout::Paginator p(small(10, 4, false), number);
    auto b = para("A");
    b.source_line = 3;
    b.cells.push_back(document::Cell{0xC1});
    p.add(b);
    auto doc = std::move(p).finish();
    ASSERT_EQ(doc.warnings.size(), 1u);
    EXPECT_NE(doc.warnings[0].find("line 3"), std::string::npos);
    EXPECT_EQ(rows(doc.pages[0])[0], "  AA");
}

// One warning a source line, not one a braille line: a paragraph whose every
// line has an escape said "line 3: ..." once per braille line (a Chinese text
// under an English table printed it hundreds of times).
TEST(Paginator, SixDotWarningOnceForASourceLineOverSeveralBrailleLines) {
    layout::Paginator p(small(10, 12, false), number);
    auto b = para("A");
    b.source_line = 3;
    b.breaks.assign(b.cells.size(), translate::BreakBefore::never);
    for (int i = 0; i < 4; ++i) {
        b.cells.push_back(document::Cell{});
        b.breaks.push_back(translate::BreakBefore::blank);
        for (int k = 0; k < 5; ++k) {
            b.cells.push_back(document::Cell{0xC1});
            b.breaks.push_back(k == 0 ? translate::BreakBefore::allowed : translate::BreakBefore::never);
        }
    }
    p.add(b);
    auto doc = std::move(p).finish();
    ASSERT_GE(doc.pages[0].lines.size(), 4u);
    ASSERT_EQ(doc.warnings.size(), 1u);
    EXPECT_NE(doc.warnings[0].find("line 3"), std::string::npos);
}

TEST(LayoutOptions, RejectsImpossibleGeometry) {
    layout::LayoutOptions o;
    o.geometry.cells_per_line = 2;
    EXPECT_EQ(validate(o).error().where, "cells_per_line");
    o = {};
    o.left_margin = 20;
    o.right_margin = 5;
    EXPECT_EQ(validate(o).error().where, "margins");
}

// BANA Braille Formats, headings: the main heading centred with a blank line
// before and after; level 2 a cell-5 heading and level 3 a cell-7 heading, both
// blocked (runover lines in the same cell), a blank line before, none after.
TEST(Paginator, HeadingLevelsCentredCellFiveCellSeven) {
    layout::Paginator p(small(14, 12, false), number);
    p.add(heading("TITLE", 1));
    p.add(heading("SECTION NAME", 2));
    p.add(para("TEXT"));
    p.add(heading("SUB PARTS", 3));
    p.add(para("MORE"));
    auto doc = std::move(p).finish();
    const auto r = rows(doc.pages[0]);
    EXPECT_EQ(std::vector<std::string>(r.begin(), r.begin() + 9),
              (std::vector<std::string>{"    TITLE", "", "    SECTION", "    NAME", "  TEXT", "", "      SUB",
                                        "      PARTS", "  MORE"}));
}
