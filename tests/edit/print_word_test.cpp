// SPDX-License-Identifier: GPL-3.0-or-later
// The print word that produced a cell (the preview says "in the word ..."): the
// word as the author wrote it, never a back-translation of its braille, which
// read "FRIDAY," as "friday," and Chinese as unrelated ideographs.
#include "edit/print_word.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace tactus;

TEST(PrintWord, EveryCellNamesTheWordAsWritten) {
    auto l = edit::LiveLayout::create("en-ueb-g2.ctb", {});
    ASSERT_TRUE(l.has_value());
    l->reset({"See you on FRIDAY, at noon."});
    const auto cells = l->braille_of(0);
    ASSERT_FALSE(cells.empty());
    const std::vector<std::u32string> words{U"See", U"you", U"on", U"FRIDAY,", U"at", U"noon."};
    std::vector<std::u32string> seen;
    for (std::size_t k = 0; k < cells.size(); ++k) {
        if (cells[k].blank()) continue;
        const auto word = edit::print_word_at(*l, l->position_of(0, k));
        EXPECT_NE(std::find(words.begin(), words.end(), word), words.end()) << "cell " << k;
        if (seen.empty() || seen.back() != word) seen.push_back(word);
    }
    EXPECT_EQ(seen, words);
}

TEST(PrintWord, ChineseNamesTheCharacterWritten) {
    auto l = edit::LiveLayout::create("zh-tw.ctb", {});
    ASSERT_TRUE(l.has_value());
    const std::u32string line = U"今天星期五";
    l->reset({"今天星期五"});
    const auto cells = l->braille_of(0);
    std::u32string heard;
    for (std::size_t k = 0; k < cells.size(); ++k) {
        if (cells[k].blank()) continue;
        const auto word = edit::print_word_at(*l, l->position_of(0, k));
        ASSERT_EQ(word.size(), 1u);  // one ideograph of the line, never another one
        EXPECT_NE(line.find(word), std::u32string::npos);
        if (heard.empty() || heard.back() != word.front()) heard += word;
    }
    EXPECT_EQ(heard, line);
}

TEST(PrintWord, NothingForABlankOrABrailleLine) {
    auto l = edit::LiveLayout::create("en-ueb-g1.ctb", {});
    ASSERT_TRUE(l.has_value());
    l->reset({"\u2813\u2811"});  // a paragraph written in braille has no print word
    EXPECT_TRUE(edit::print_word_at(*l, l->position_of(0, 0)).empty());
    EXPECT_TRUE(edit::print_word_at(*l, edit::PagePosition{99, 0, 0}).empty());
}
