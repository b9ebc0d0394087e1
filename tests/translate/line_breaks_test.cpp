// SPDX-License-Identifier: GPL-3.0-or-later
// Line-break opportunities from liblouis's position mapping, and word division
// by the code's rules, checked on real tables.
#include <gtest/gtest.h>

#include <random>

#include "common/utf8.hpp"
#include "layout/line_breaker.hpp"
#include "translate/line_breaks.hpp"
#include "translate/translated_document.hpp"
#include "translate/translator.hpp"
#include "translate/word_division.hpp"

using namespace tactus;
using namespace tactus::document;
using namespace tactus::translate;
using namespace tactus::layout;

namespace {

std::u32string u32(std::string_view s) { return *utf8_to_utf32(s); }

std::string brf_of(const BrailleLine& cells) {
    std::string out;
    for (Cell c : cells) out.push_back(cell_to_brf(c));
    return out;
}

Translator open_table(const char* table) {
    auto t = Translator::open(table);
    EXPECT_TRUE(t) << t.error().to_string();
    return std::move(*t);
}

TranslatedBlock paragraph(const Translator& tr, std::string_view text, std::size_t room) {
    Block b;
    b.kind = BlockKind::paragraph;
    b.spans.push_back(Span{std::string(text), emphasis_none});
    auto tb = translate_block(b, tr, room);
    EXPECT_TRUE(tb) << tb.error().to_string();
    return tb ? std::move(*tb) : TranslatedBlock{};
}

}  // namespace

TEST(PrintBreaks, SpacesHyphensAndChineseCharacters) {
    const auto b = print_break_opportunities(u32("ab cd-ef"));
    // Before: a b _ c d - e f (end)
    EXPECT_EQ(b, (std::vector<bool>{true, false, false, true, false, false, true, false, true}));
    const auto z = print_break_opportunities(u32("床前明月光，疑"));
    // Between ideographs, never before the closing comma.
    EXPECT_EQ(z, (std::vector<bool>{true, true, true, true, true, false, true, true}));
}

TEST(MappedTranslation, EveryCellKnowsItsPrintCharacter) {
    const auto tr = open_table("en-ueb-g2.ctb");
    const auto m = tr.translate_mapped(u32("HELLO 12 knowing"));
    ASSERT_TRUE(m);
    ASSERT_EQ(m->cells.size(), m->source.size());
    EXPECT_EQ(brf_of(m->cells), ",,HELLO #AB \"K+");
    // The capitals-word indicator belongs to the H, the numeric indicator to the 1,
    // the "know" contraction to its first letter and "ing" to its i.
    EXPECT_EQ(m->source, (std::vector<std::uint32_t>{0, 0, 0, 1, 2, 3, 4, 5, 6, 6, 7, 8, 9, 9, 13}));
}

TEST(LineBreakKinds, IndicatorsAndSignsAreNeverCut) {
    const auto tr = open_table("en-ueb-g1.ctb");
    const auto text = u32("ab/cd 12 well-known");
    const auto m = tr.translate_mapped(text);
    ASSERT_TRUE(m);
    const auto br = find_line_breaks(text, m->cells, m->source);
    EXPECT_EQ(brf_of(m->cells), "AB_/CD #AB WELL-KNOWN");
    using B = BreakBefore;
    // A B _ / C D ' ' # A B ' ' W E L L - K N O W N
    EXPECT_EQ(br[3], B::never) << "inside the solidus";
    EXPECT_EQ(br[8], B::never) << "numeric indicator and its digit";
    EXPECT_EQ(br[9], B::between_chars) << "between digits";
    EXPECT_EQ(br[7], B::allowed);
    EXPECT_EQ(br[6], B::blank);
    EXPECT_EQ(br[16], B::allowed) << "after the hyphen";
    EXPECT_EQ(br[15], B::between_chars) << "no break before a hyphen";
}

TEST(LineBreakKinds, ChineseBreaksBetweenCharactersOnly) {
    for (const char* table : {"zh-tw.ctb", "zhcn-g2.ctb"}) {
        const auto tr = open_table(table);
        const auto text = u32(std::string(table) == "zh-tw.ctb" ? "點字是一種文字。" : "盲文是一种文字。");
        const auto m = tr.translate_mapped(text);
        ASSERT_TRUE(m);
        const auto br = find_line_breaks(text, m->cells, m->source);
        for (std::size_t i = 1; i < br.size(); ++i) {
            const bool new_char = m->source[i] != m->source[i - 1];
            if (!new_char && !m->cells[i].blank()) {
                EXPECT_EQ(br[i], BreakBefore::never) << table << " cell " << i;
            }
        }
    }
}

TEST(WordDivision, HyphenAtTheLineEndAndIndicatorsRepeated) {
    const auto tr = open_table("en-ueb-g1.ctb");
    auto pieces = divide_word(tr, u32("ABCDEFGHIJKLMNOP"), {}, 8);
    ASSERT_TRUE(pieces);
    ASSERT_GE(pieces->size(), 3u);
    for (std::size_t i = 0; i < pieces->size(); ++i) {
        const auto s = brf_of((*pieces)[i]);
        EXPECT_LE(s.size(), 8u) << s;
        EXPECT_TRUE(s.starts_with(",,")) << s;
        if (i + 1 < pieces->size()) {
            EXPECT_TRUE(s.ends_with("-")) << s;
        }
    }
}

TEST(WordDivision, NumbersUseTheContinuationIndicator) {
    const auto tr = open_table("en-ueb-g2.ctb");
    auto pieces = divide_word(tr, u32("1234567890123"), {}, 8);
    ASSERT_TRUE(pieces);
    std::vector<std::string> got;
    for (const auto& p : *pieces) got.push_back(brf_of(p));
    EXPECT_EQ(got, (std::vector<std::string>{"#ABCDEF\"", "GHIJABC"}));
}

TEST(WordDivision, PrefersSyllablesWhereTheLanguageHasADictionary) {
    const auto tr = open_table("en-ueb-g1.ctb");
    auto pieces = divide_word(tr, u32("transcription"), {}, 10);
    ASSERT_TRUE(pieces);
    ASSERT_EQ(pieces->size(), 2u);
    EXPECT_EQ(brf_of((*pieces)[0]), "TRANSCRIP-");
    EXPECT_EQ(brf_of((*pieces)[1]), "TION");
}

// Property: random text, overlong words included, in four tables at widths
// 10..40. Layout never makes a line longer than the width, never ends a line
// where the breaks say it may not, and keeps every cell of the translation;
// in uncontracted UEB the lines, read back with the division signs taken out,
// are the text again (so no indicator was separated from what it governs).
TEST(WordDivision, RandomTextIsDividedWithoutLoss) {
    std::mt19937 rng(2026);
    const std::u32string latin = U"abcdefghijklmnopqrstuvwxyzABCDEFGHIJ0123456789";
    // Characters each table knows (an unknown one is a long escape sequence,
    // the one thing cut at a line end).
    const std::u32string traditional = U"點字是一種讓視障者用手指閱讀的文";
    const std::u32string simplified = U"盲文是一种让视障者用手指阅读的字";
    for (const char* table : {"en-ueb-g1.ctb", "en-ueb-g2.ctb", "zh-tw.ctb", "zhcn-g2.ctb"}) {
        const auto tr = open_table(table);
        const bool english = std::string(table).starts_with("en");
        for (int width = 10; width <= 40; ++width) {
            std::u32string text;
            const int words = std::uniform_int_distribution<int>(1, 12)(rng);
            for (int w = 0; w < words; ++w) {
                if (w > 0) text.push_back(U' ');
                const int len = std::uniform_int_distribution<int>(1, english ? 60 : 30)(rng);
                const auto& alphabet = english ? latin
                                        : std::string(table) == "zh-tw.ctb" ? traditional
                                                                            : simplified;
                for (int i = 0; i < len; ++i)
                    text.push_back(alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)]);
            }
            const auto utf8 = utf32_to_utf8(text);
            const auto tb = paragraph(tr, utf8, static_cast<std::size_t>(width));
            ASSERT_EQ(tb.breaks.size(), tb.cells.size());
            const auto lines = break_lines(tb.cells, tb.breaks, width, 0, 0);
            std::size_t at = 0;  // index in tb.cells
            BrailleLine kept;
            for (std::size_t l = 0; l < lines.size(); ++l) {
                ASSERT_LE(static_cast<int>(lines[l].size()), width) << table << " " << utf8;
                // Find where this line starts in the block's cells. A blank cell
                // between the lines is a word space: the line may end there.
                bool word_space = false;
                while (at < tb.cells.size() && tb.cells[at].blank()) {
                    ++at;
                    word_space = true;
                }
                if (l > 0 && at < tb.cells.size() && !word_space) {
                    ASSERT_TRUE(is_line_break(tb.breaks[at]))
                        << table << " width " << width << ": line " << l + 1 << " starts at a "
                        << static_cast<int>(tb.breaks[at]) << " in \"" << utf8 << "\"";
                }
                for (Cell c : lines[l]) {
                    if (c.blank()) continue;
                    while (at < tb.cells.size() && tb.cells[at].blank()) ++at;
                    ASSERT_LT(at, tb.cells.size());
                    ASSERT_EQ(c, tb.cells[at]) << table << " " << utf8;
                    kept.push_back(c);
                    ++at;
                }
            }
            std::size_t non_blank = 0;
            for (Cell c : tb.cells) non_blank += c.blank() ? 0u : 1u;
            ASSERT_EQ(kept.size(), non_blank) << table << " " << utf8;
            if (std::string(table) == "en-ueb-g1.ctb") {
                // Read the lines as a reader does. A division hyphen at a line
                // end is not text, and the next piece is a word of its own. A line
                // continuation indicator (dot 5) is not text either, and the next
                // line goes on in numeric mode (UEB 6.10.5); the two-cell one
                // stands in for a numeric space, which stays.
                std::u32string read;
                BrailleLine segment;
                const auto flush = [&] {
                    const auto back = tr.back_translate(segment);
                    ASSERT_TRUE(back);
                    read += *back;
                    segment.clear();
                };
                const Cell hyphen{0x24}, dot5{0x10};
                for (std::size_t i = 0; i < tb.cells.size(); ++i) {
                    if (i > 0 && tb.breaks[i] == BreakBefore::forced && !segment.empty()) {
                        if (segment.back() == hyphen) {
                            segment.pop_back();
                            flush();
                        } else if (segment.back() == dot5) {
                            segment.pop_back();  // two cells: one stays as the numeric space
                        }
                    }
                    segment.push_back(tb.cells[i]);
                }
                flush();
                EXPECT_EQ(utf32_to_utf8(read), utf8) << "width " << width;
            }
        }
    }
}
