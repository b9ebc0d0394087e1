// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "cells.hpp"
#include "layout/line_breaker.hpp"

using namespace tactus;

namespace {
std::vector<std::string> wrap(std::string_view text, int width, int first = 0, int runover = 0) {
    std::vector<std::string> out;
    for (const auto& l : layout::break_lines(brf(text), width, first, runover)) out.push_back(brf(l));
    return out;
}
}  // namespace

TEST(LineBreaker, WrapsAtWordBoundaries) {
    EXPECT_EQ(wrap("AB CD EF GH", 5), (std::vector<std::string>{"AB CD", "EF GH"}));
    EXPECT_EQ(wrap("AB CD EF", 6), (std::vector<std::string>{"AB CD", "EF"}));
}

TEST(LineBreaker, FirstLineIndentAndRunover) {
    EXPECT_EQ(wrap("AAA BBB CCC", 8, 2, 1), (std::vector<std::string>{"  AAA", " BBB CCC"}));
}

TEST(LineBreaker, CollapsesRepeatedBlanks) {
    EXPECT_EQ(wrap("AB    CD", 10), (std::vector<std::string>{"AB CD"}));
}

TEST(LineBreaker, SplitsAWordLongerThanALine) {
    EXPECT_EQ(wrap("XY ABCDEFGHIJ Z", 4),
              (std::vector<std::string>{"XY", "ABCD", "EFGH", "IJ Z"}));
}

TEST(LineBreaker, EmptyInputGivesOneEmptyLine) {
    EXPECT_EQ(wrap("", 10), (std::vector<std::string>{""}));
    EXPECT_EQ(wrap("   ", 10), (std::vector<std::string>{""}));
}

// Property: for random text and widths, no line is too long and no non-blank
// cell is lost or reordered.
TEST(LineBreaker, NeverLosesACellNorOverflows) {
    std::mt19937 rng(42);
    const std::string alphabet = "ABCDEFGHIJ  ";
    for (int round = 0; round < 500; ++round) {
        std::string text;
        const auto len = std::uniform_int_distribution<int>(0, 300)(rng);
        for (int i = 0; i < len; ++i)
            text.push_back(alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)]);
        const int width = std::uniform_int_distribution<int>(4, 40)(rng);
        const int first = std::uniform_int_distribution<int>(0, width - 1)(rng);
        const int runover = std::uniform_int_distribution<int>(0, width - 1)(rng);
        std::string kept;
        for (const auto& l : layout::break_lines(brf(text), width, first, runover)) {
            ASSERT_LE(static_cast<int>(l.size()), width);
            for (auto c : l)
                if (!c.blank()) kept.push_back(document::cell_to_brf(c));
        }
        std::string expected;
        for (char c : text)
            if (c != ' ') expected.push_back(c);
        ASSERT_EQ(kept, expected) << "width " << width;
    }
}
