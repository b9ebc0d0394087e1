// SPDX-License-Identifier: GPL-3.0-or-later
// Lists, tables, notes and block quotes laid out by the rules
// docs/layout.md names (BANA Braille Formats), through real liblouis tables.
#include <gtest/gtest.h>

#include <tuple>

#include <random>

#include "../common/layout_options.hpp"
#include "cells.hpp"
#include "pipeline/pipeline.hpp"
#include "translate/translator.hpp"

using namespace tactus;
using namespace tactus::document;
using namespace tactus::pipeline;
using namespace tactus::layout;

namespace {

Block text_block(BlockKind kind, int level, std::vector<Span> spans) {
    Block b;
    b.kind = kind;
    b.level = level;
    b.spans = std::move(spans);
    return b;
}
Block text_block(BlockKind kind, int level, const std::string& text) {
    return text_block(kind, level, std::vector<Span>{Span{text}});
}
Span reference(const std::string& label) {
    Span s{label};
    s.note_reference = true;
    return s;
}
Block row(bool header) {
    Block b;
    b.kind = BlockKind::table_row;
    b.level = header ? 1 : 0;
    return b;
}

// Body lines (page numbers and print page lines off), blank lines kept.
std::vector<std::string> lay_out_lines(const std::vector<Block>& blocks, int width, const std::string& table = "en-ueb-g1.ctb") {
    Document doc;
    doc.blocks = blocks;
    auto paged = lay_out(doc, test::body_lines_options(table, width));
    EXPECT_TRUE(paged) << paged.error().to_string();
    std::vector<std::string> lines;
    if (!paged) return lines;
    for (const auto& p : paged->pages)
        for (const auto& l : p.lines) lines.push_back(brf(l));
    while (!lines.empty() && lines.back().empty()) lines.pop_back();
    return lines;
}

std::vector<Block> table_blocks(const std::vector<std::vector<std::string>>& rows, bool header) {
    std::vector<Block> out;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        out.push_back(row(header && r == 0));
        for (std::size_t c = 0; c < rows[r].size(); ++c)
            out.push_back(text_block(BlockKind::table_cell, static_cast<int>(c), rows[r][c]));
    }
    return out;
}

}  // namespace

TEST(StructureLayout, ListItemsHangAndNestTwoCellsDeeper) {
    const auto lines = lay_out_lines({text_block(BlockKind::list_item, 1, "\u2022 one two three four five six"),
                                      text_block(BlockKind::list_item, 2, "\u2022 seven eight nine ten eleven"),
                                      text_block(BlockKind::list_item, 1, "3. last")},
                                     20);
    const std::vector<std::string> expected{"_4 ONE TWO THREE",   // cell 1
                                            "  FOUR FIVE SIX",    // runover in cell 3
                                            "  _4 SEVEN EIGHT",   // level 2 in cell 3
                                            "    NINE TEN ELEVEN",  // its runover in cell 5
                                            "#C4 LAST"};
    EXPECT_EQ(lines, expected);
}

TEST(StructureLayout, SimpleTableHasColumnsGuideDotsAndASeparationLine) {
    auto blocks = table_blocks({{"Bird", "Seen"}, {"Heron", "3"}, {"Kingfisher", "12"}}, true);
    blocks.insert(blocks.begin(), text_block(BlockKind::paragraph, 0, "Birds:"));
    const auto lines = lay_out_lines(blocks, 27);
    const std::vector<std::string> expected{"  ,BIRDS3",
                                            "",
                                            ",BIRD        ,SEEN",
                                            "33333333333  33333",  // as wide as ",SEEN"
                                            ",HERON \"\"\"\"\" #C",
                                            ",KINGFISHER  #AB"};
    EXPECT_EQ(lines, expected);
}

TEST(StructureLayout, TableTooWideForTheLineIsListed) {
    const auto blocks = table_blocks({{"Plant", "Where it grows"}, {"Willow", "on the river bank"}}, true);
    EXPECT_EQ(lay_out_lines(blocks, 40), (std::vector<std::string>{",PLANT   ,WHERE IT GROWS",
                                                                   "3333333  33333333333333333",
                                                                   ",WILLOW  ON THE RIVER BANK"}));
    // At 16 cells the columns do not fit: one entry a line, the first in cell 1,
    // the others in cell 3, runovers in cell 5.
    EXPECT_EQ(lay_out_lines(blocks, 16), (std::vector<std::string>{",PLANT", "  ,WHERE IT", "    GROWS", ",WILLOW",
                                                                   "  ON THE RIVER", "    BANK"}));
}

TEST(StructureLayout, NoteFollowsItsParagraphInSevenFive) {
    const auto lines =
        lay_out_lines({text_block(BlockKind::paragraph, 0, {Span{"We saw herons."}, reference("1"), Span{" Then rain."}}),
                       text_block(BlockKind::note, 0, {reference("1"), Span{" The walk took an hour and more."}}),
                       text_block(BlockKind::paragraph, 0, "Next.")},
                      24);
    // The reference (UEB's superscript indicator, dots 35, then the number:
    // uncontracted, no grade 1 indicator) stays on its word; the note starts in
    // cell 7 with the same reference, its runovers in cell 5.
    ASSERT_GE(lines.size(), 5u);
    EXPECT_EQ(lines[0], "  ,WE SAW HERONS49#A");
    EXPECT_EQ(lines[2].substr(0, 9), "      9#A");
    EXPECT_TRUE(lines[3].starts_with("    ") && lines[3][4] != ' ') << lines[3];
    EXPECT_EQ(lines.back(), "  ,NEXT4");
}

TEST(StructureLayout, BlockQuoteHasABlankLineBeforeAndAfter) {
    const auto lines = lay_out_lines({text_block(BlockKind::paragraph, 0, "Before."),
                                      text_block(BlockKind::quote, 1, "Quoted one."),
                                      text_block(BlockKind::quote, 1, "Quoted two."),
                                      text_block(BlockKind::paragraph, 0, "After.")},
                                     27);
    EXPECT_EQ(lines, (std::vector<std::string>{"  ,BEFORE4", "", "  ,QUOTED ONE4", "  ,QUOTED TWO4", "", "  ,AFTER4"}));
}

// Random tables at widths 12 to 40: a table laid out as columns has one line a
// row, every entry starting in its column's cell; a listed one has every entry
// in row order with the listed indents. Either way nothing is lost.
TEST(StructureLayout, RandomTablesAreColumnsOrListsAndLoseNothing) {
    std::mt19937 rng(13);
    const std::vector<std::string> words{"a", "heron", "kingfisher", "3", "reed", "river bank", "of", "willow",
                                         "sun", "12", "wet soil"};
    int simple = 0, listed = 0;
    for (int round = 0; round < 200; ++round) {
        const int width = 12 + static_cast<int>(rng() % 29);
        const auto cols = 1 + rng() % 4, rows = 1 + rng() % 4;
        std::vector<std::vector<std::string>> t(rows, std::vector<std::string>(cols));
        for (auto& r : t)
            for (auto& c : r) c = words[rng() % words.size()];
        const bool header = rng() % 2;
        const auto lines = lay_out_lines(table_blocks(t, header), width);
        SCOPED_TRACE("width " + std::to_string(width) + " round " + std::to_string(round));
        // Each entry alone, as its own one-cell table would show it.
        std::vector<std::vector<std::string>> entries(rows, std::vector<std::string>(cols));
        for (std::size_t r = 0; r < rows; ++r)
            for (std::size_t c = 0; c < cols; ++c) {
                const auto one = lay_out_lines({row(false), text_block(BlockKind::table_cell, 0, t[r][c])}, 200);
                ASSERT_EQ(one.size(), 1u);
                entries[r][c] = one[0];
            }
        // The rule: columns when every column, as wide as its widest entry, fits
        // with two cells between columns, and no entry needs dividing (longer
        // than a listed runover line, width - 4).
        std::vector<std::size_t> start(cols, 0), widest(cols, 0);
        bool divided = false;
        for (std::size_t c = 0; c < cols; ++c)
            for (std::size_t r = 0; r < rows; ++r) {
                widest[c] = std::max(widest[c], entries[r][c].size());
                divided = divided || entries[r][c].size() > static_cast<std::size_t>(width - 4);
            }
        for (std::size_t c = 1; c < cols; ++c) start[c] = start[c - 1] + widest[c - 1] + 2;
        const bool as_columns = !divided && start[cols - 1] + widest[cols - 1] <= static_cast<std::size_t>(width);
        if (as_columns) {
            ++simple;
            ASSERT_EQ(lines.size(), rows + (header ? 1 : 0));
            for (std::size_t r = 0, l = 0; r < rows; ++r, ++l) {
                for (std::size_t c = 0; c < cols; ++c)
                    EXPECT_EQ(lines[l].substr(start[c], entries[r][c].size()), entries[r][c]) << lines[l];
                EXPECT_LE(lines[l].size(), static_cast<std::size_t>(width));
                if (r == 0 && header) ++l;  // the separation line
            }
        } else {
            ++listed;
            // Joined back, the lines hold each entry in order.
            std::string all;
            for (const auto& l : lines) {
                ASSERT_FALSE(l.empty());
                const auto indent = l.find_first_not_of(' ');
                EXPECT_TRUE(indent == 0 || indent == 2 || indent == 4) << l;
                all += l.substr(indent) + " ";
            }
            std::size_t at = 0;
            for (std::size_t r = 0; r < rows; ++r)
                for (std::size_t c = 0; c < cols; ++c) {
                    // A divided word loses its division hyphen when joined; compare word by word.
                    const auto& e = entries[r][c];
                    const auto first_word = e.substr(0, e.find(' '));
                    const auto found = all.find(first_word.substr(0, std::min<std::size_t>(first_word.size(), 4)), at);
                    ASSERT_NE(found, std::string::npos) << e << " in " << all;
                    at = found;
                }
        }
    }
    EXPECT_GT(simple, 20);
    EXPECT_GT(listed, 20);
}

// BANA Braille Formats §8: a blank line before and after a list; none under a
// heading (its own rule), none inside the list.
TEST(StructureLayout, AListHasABlankLineBeforeAndAfter) {
    const auto lines = lay_out_lines({text_block(BlockKind::paragraph, 0, "Before."),
                                      text_block(BlockKind::list_item, 1, "\u2022 one"),
                                      text_block(BlockKind::list_item, 2, "\u2022 two"),
                                      text_block(BlockKind::paragraph, 0, "After."),
                                      text_block(BlockKind::heading, 2, "Steps"),
                                      text_block(BlockKind::list_item, 1, "1. first")},
                                     27);
    EXPECT_EQ(lines, (std::vector<std::string>{"  ,BEFORE4", "", "_4 ONE", "  _4 TWO", "", "  ,AFTER4", "",
                                               "    ,STEPS", "#A4 FIRST"}));
}

// A table that runs on to a new page repeats its column headings and their
// separation line at the top of it (BANA §11).
TEST(StructureLayout, ATableContinuedOnANewPageRepeatsItsHeadings) {
    std::vector<std::vector<std::string>> rows{{"Bird", "Seen"}};
    for (int i = 1; i <= 8; ++i) rows.push_back({"Heron", std::to_string(i)});
    Document doc;
    doc.blocks = table_blocks(rows, true);
    PipelineOptions o;
    o.tables = "en-ueb-g1.ctb";
    o.translation_workers = 1;
    o.layout.geometry = {27, 6, false, false};
    o.layout.page_numbers = PageNumberPosition::none;
    const auto paged = lay_out(doc, o);
    ASSERT_TRUE(paged) << paged.error().to_string();
    ASSERT_GE(paged->pages.size(), 2u);
    for (std::size_t p = 0; p < paged->pages.size(); ++p) {
        SCOPED_TRACE(p);
        EXPECT_EQ(brf(paged->pages[p].lines[0]), ",BIRD   ,SEEN");
        EXPECT_EQ(brf(paged->pages[p].lines[1]), "333333  33333");
    }
    int herons = 0;
    for (const auto& p : paged->pages)
        for (const auto& l : p.lines) herons += brf(l).starts_with(",HERON");
    EXPECT_EQ(herons, 8);
}

// The note reference indicator is UEB's (⠰⠔) and EBAE's (⠶⠶) (see
// TheNoteReferenceIndicatorIsTheCodesOwn): Chinese writes the number in
// parentheses as its table writes them (no 8-dot escapes).
TEST(StructureLayout, ChineseHasNoNoteReferenceIndicator) {
    const std::vector<Block> blocks{
        text_block(BlockKind::paragraph, 0, {Span{"\u4eca\u5929"}, reference("1")}),
        text_block(BlockKind::note, 0, {reference("1"), Span{" \u8a3b"}})};
    const auto zh = lay_out_lines(blocks, 27, "zh-tw.ctb");
    ASSERT_FALSE(zh.empty());
    auto tr = translate::Translator::open("zh-tw.ctb");
    ASSERT_TRUE(tr);
    EXPECT_FALSE(tr->is_ueb());
    const auto one = tr->translate(U"1");
    ASSERT_TRUE(one);
    for (const auto& l : zh) EXPECT_EQ(l.find("77" + brf(*one)), std::string::npos) << l;
    const auto bracketed = tr->translate(U"(1)");
    ASSERT_TRUE(bracketed);
    for (const auto c : *bracketed) EXPECT_EQ(c.dots & 0xC0, 0);  // the table knows the marks
    EXPECT_NE(zh[0].find(brf(*bracketed)), std::string::npos) << zh[0] << " / " << brf(*bracketed);
    auto ueb = translate::Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(ueb);
    EXPECT_TRUE(ueb->is_ueb());
}

// Braille Formats 2016, Appendix C "Blank Lines": a blank line before but not
// after a cell-5 or cell-7 heading; only columned material (a table) gets one
// after it. A block quote under such a heading follows it directly, as a list
// does (docs/layout.md, "Blank lines").
TEST(StructureLayout, NoBlankLineUnderACellFiveOrSevenHeadingBeforeAQuoteOrAList) {
    const auto lines = lay_out_lines({text_block(BlockKind::paragraph, 0, "Before."),
                                      text_block(BlockKind::heading, 2, "Saying"),
                                      text_block(BlockKind::quote, 1, "Quoted."),
                                      text_block(BlockKind::heading, 3, "Steps"),
                                      text_block(BlockKind::list_item, 1, "1. first"),
                                      text_block(BlockKind::heading, 3, "Birds"),
                                      row(true), text_block(BlockKind::table_cell, 0, "Bird"),
                                      row(false), text_block(BlockKind::table_cell, 0, "Heron")},
                                     27);
    EXPECT_EQ(lines, (std::vector<std::string>{"  ,BEFORE4", "", "    ,SAYING", "  ,QUOTED4", "", "      ,STEPS",
                                               "#A4 FIRST", "", "      ,BIRDS", "", ",BIRD", "333333", ",HERON"}));
}

// A note placed after the block that refers to it stays inside that block's
// structure: no blank line before it, and the block after the note is
// separated as if it followed the note's block (the blank line after a list or
// a quote is kept; a quote goes on after a note inside it).
TEST(StructureLayout, ANoteInsideAListOrAQuoteKeepsTheirBlankLines) {
    const auto lines = lay_out_lines(
        {text_block(BlockKind::list_item, 1, {Span{"\u2022 one"}, reference("1")}),
         text_block(BlockKind::note, 0, {reference("1"), Span{" Note."}}),
         text_block(BlockKind::paragraph, 0, "After."),
         text_block(BlockKind::quote, 1, {Span{"Quoted"}, reference("2")}),
         text_block(BlockKind::note, 0, {reference("2"), Span{" Source."}}),
         text_block(BlockKind::quote, 1, "More."),
         text_block(BlockKind::paragraph, 0, "End.")},
        27, "en-ueb-g1.ctb");
    EXPECT_EQ(lines, (std::vector<std::string>{"_4 ONE9#A", "      9#A ,NOTE4", "", "  ,AFTER4", "",
                                               "  ,QUOTED9#B", "      9#B ,SOURCE4", "  ,MORE4", "", "  ,END4"}));
}

// A note reference with print text straight after it ("clarion[^1]and"):
// the number and that text are translated together, so the code's own rule
// for what follows a number holds. In UEB a letter a-j after a number takes
// the grade 1 indicator (liblouis: "1and" is ⠼⠁⠰⠁⠝⠙); translated apart, the
// text read ⠼⠁⠯, "1" and a sign, and "1b" read as the number 12.
TEST(StructureLayout, TextStraightAfterANoteReferenceFollowsTheNumbersRule) {
    for (const auto& [table, text, want] :
         {std::tuple<std::string, std::string, std::string>{"en-ueb-g2.ctb", "and more", ";9#A;AND M"},
          {"en-ueb-g1.ctb", "b and c", "9#A;B AND C"},
          {"en-ueb-g2.ctb", "k", ";9#AK"}}) {
        SCOPED_TRACE(table + " / " + text);
        const std::vector<Block> blocks{
            text_block(BlockKind::paragraph, 0, {Span{"clarion"}, reference("1"), Span{text}}),
            text_block(BlockKind::note, 0, {reference("1"), Span{" A note."}})};
        const auto lines = lay_out_lines(blocks, 40, table);
        ASSERT_FALSE(lines.empty());
        EXPECT_NE(lines[0].find(want), std::string::npos) << lines[0] << " | " << (lines.size() > 1 ? lines[1] : "");
        // The same as liblouis writes the number and the text as one.
        auto tr = translate::Translator::open(table);
        ASSERT_TRUE(tr);
        std::u32string joined = U"1";
        for (const char c : text) joined += static_cast<char32_t>(c);
        const auto cells = tr->translate(joined);
        ASSERT_TRUE(cells);
        EXPECT_NE(lines[0].find(brf(*cells)), std::string::npos) << lines[0] << " / " << brf(*cells);
    }
}

// The note reference indicator is the code's: dots 2356 2356 before the number
// in EBAE (BANA Braille Formats 2011 §16.1.3, "77#a numbered"), read from
// en-us-g2.ctb, which has no metadata of its own but includes en-us-g1.ctb
// (#+system:ebae). In UEB ⠶⠶ is the double prime (Rules of UEB 2013 §3.11,
// §3.15): a note reference is print's superscript number, ⠰⠔ (grade 1 and
// superscript indicators) before it in contracted braille, ⠔ alone in
// uncontracted (§3.24.1, §11.4.2, §5.11.1). Not ⠶⠶⠼⠁ for
// UEB, which a UEB reader reads as ″1. Chinese has none Tactus knows: the
// number in parentheses.
TEST(StructureLayout, TheNoteReferenceIndicatorIsTheCodesOwn) {
    const auto blocks = [](const std::string& text) {
        return std::vector<Block>{text_block(BlockKind::paragraph, 0, {Span{text}, reference("1")}),
                                  text_block(BlockKind::note, 0, {reference("1"), Span{" " + text}})};
    };
    for (const std::string table : {"en-us-g2.ctb", "en-us-g1.ctb"}) {
        SCOPED_TRACE(table);
        auto tr = translate::Translator::open(table);
        ASSERT_TRUE(tr);
        EXPECT_EQ(tr->braille_system(), "ebae");
        const auto lines = lay_out_lines(blocks("We saw herons."), 27, table);
        ASSERT_GE(lines.size(), 2u);
        EXPECT_TRUE(lines[0].ends_with("477#A")) << lines[0];
        EXPECT_TRUE(lines[1].starts_with("      77#A ")) << lines[1];
    }
    for (const auto& [table, reference] : {std::pair<std::string, std::string>{"en-ueb-g2.ctb", ";9#A"},
                                           {"en-ueb-g1.ctb", "9#A"}}) {
        SCOPED_TRACE(table);
        auto tr = translate::Translator::open(table);
        ASSERT_TRUE(tr);
        EXPECT_TRUE(tr->is_ueb());
        const auto lines = lay_out_lines(blocks("We saw herons."), 27, table);
        ASSERT_GE(lines.size(), 2u);
        EXPECT_TRUE(lines[0].ends_with("4" + reference)) << lines[0];
        EXPECT_TRUE(lines[1].starts_with("      " + reference + " ")) << lines[1];
        // Not the table's double prime, which is ⠶⠶ in UEB.
        const auto double_prime = tr->translate(U"″");
        ASSERT_TRUE(double_prime);
        EXPECT_EQ(brf(*double_prime), "77");
        EXPECT_EQ(lines[0].find("77"), std::string::npos) << lines[0];
    }
    {
        // liblouis's contracted UEB table writes a superscript two the same way
        // (en-ueb-chardefs.uti: ² is 56-35-3456-12), an independent source.
        auto tr = translate::Translator::open("en-ueb-g2.ctb");
        ASSERT_TRUE(tr);
        const auto squared = tr->translate(U"²");
        ASSERT_TRUE(squared);
        const auto& indicator = tr->note_reference_indicator();
        ASSERT_GE(squared->size(), indicator.size());
        EXPECT_TRUE(std::equal(indicator.begin(), indicator.end(), squared->begin()))
            << brf(*squared) << " / " << brf(indicator);
    }
    for (const std::string table : {"zhcn-g2.ctb", "zh-tw.ctb"}) {
        SCOPED_TRACE(table);
        auto tr = translate::Translator::open(table);
        ASSERT_TRUE(tr);
        EXPECT_TRUE(tr->note_reference_indicator().empty());
        const auto bracketed = tr->translate(U"(1)");
        ASSERT_TRUE(bracketed);
        const auto lines = lay_out_lines(blocks("\u4eca\u5929"), 27, table);
        ASSERT_GE(lines.size(), 2u);
        EXPECT_TRUE(lines[0].ends_with(brf(*bracketed))) << lines[0] << " / " << brf(*bracketed);
        EXPECT_TRUE(lines[1].starts_with("      " + brf(*bracketed))) << lines[1];
    }
}
