// SPDX-License-Identifier: GPL-3.0-or-later
// --reflow on ready-made braille: a real BRF book (tests/data/layout/README.md)
// laid out again on narrower pages keeps every word whole and in order, drops
// the old page numbers, and breaks lines only between words.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../common/layout_options.hpp"
#include "document/cell.hpp"
#include "import/import.hpp"
#include "layout/braille_reflow.hpp"
#include "pipeline/pipeline.hpp"

using namespace tactus;

namespace {

const std::string kBook = std::string(TACTUS_TEST_DATA) + "/layout/aata-chapter-1.brf";

// The braille words (runs of non-blank cells) of some lines, as BRF.
// A compound broken after its hyphen at a line end ("well-" "known") is one word.
std::vector<std::string> words(const std::vector<document::BrailleLine>& lines) {
    std::vector<std::string> out;
    bool joined = false;  // the last word ended its line with a hyphen
    for (const auto& line : lines) {
        bool first = true;
        std::string word;
        for (const auto c : line) {
            if (c.blank()) {
                if (!word.empty()) {
                    if (first && joined) out.back() += word;
                    else out.push_back(word);
                    first = false;
                    joined = false;
                }
                word.clear();
            } else {
                word.push_back(document::cell_to_brf(c));
            }
        }
        if (!word.empty()) {
            if (first && joined) out.back() += word;
            else out.push_back(word);
            joined = word.back() == '-';
        } else if (!first || !line.empty()) {
            joined = false;
        }
    }
    return out;
}

std::vector<document::BrailleLine> source_lines(const document::Document& doc) {
    std::vector<document::BrailleLine> lines;
    for (const auto& b : doc.blocks)
        lines.insert(lines.end(), b.braille_lines.begin(), b.braille_lines.end());
    return lines;
}

std::vector<document::BrailleLine> body_lines(const layout::PagedDocument& paged) {
    std::vector<document::BrailleLine> lines;
    for (const auto& p : paged.pages) lines.insert(lines.end(), p.lines.begin(), p.lines.end());
    return lines;
}

}  // namespace

TEST(BrailleReflow, RealBookKeepsEveryWordWholeAndDropsPageNumbers) {
    const auto doc = import::import_file(kBook);
    ASSERT_TRUE(doc) << doc.error().to_string();
    // The book's own page numbers (12 to 15) end the last line of each page.
    auto expected = words(source_lines(*doc));
    for (const char* number : {"#AB", "#AC", "#AD", "#AE"}) {
        const auto at = std::find(expected.begin(), expected.end(), std::string(number));
        ASSERT_NE(at, expected.end()) << number;
        expected.erase(at);
    }
    for (const int width : {40, 32, 25}) {
        auto o = test::body_lines_options("en-ueb-g2.ctb", width);
        o.reflow_braille = true;
        const auto paged = pipeline::lay_out(*doc, o);
        ASSERT_TRUE(paged) << paged.error().to_string();
        const auto lines = body_lines(*paged);
        // Every word of the book, in order, none cut or joined, no old page number.
        EXPECT_EQ(words(lines), expected) << width;
        for (const auto& line : lines) EXPECT_LE(static_cast<int>(line.size()), width);
    }
}

// Running heads (the same first line on every page) and print page numbers at
// the end of the first line are the old pages' furniture, not text.
TEST(BrailleReflow, RunningHeadsAndPageNumbersGo) {
    const std::string brf =
        "      ,sea ,/ories       #a\n"
        "  ,! sea is deep1 wide &\n"
        "blue4\n"
        "      ,sea ,/ories\n"
        "& cold4\n"
        "\f      ,sea ,/ories       #c\n"
        "  ,fi% swim4\n";
    const auto doc = import::import_bytes(brf, "sea.brf");
    ASSERT_TRUE(doc) << doc.error().to_string();
    const auto blocks = layout::reflow_braille(*doc);
    std::vector<std::string> texts;
    for (const auto& b : blocks) {
        std::string t;
        for (const auto c : b.cells) t.push_back(document::cell_to_brf(c));
        texts.push_back(t);
    }
    // A centred line inside a page is a heading; a short line in cell 1 after
    // it ("& cold4") starts a paragraph; a long line's next goes on with it.
    EXPECT_EQ(texts, (std::vector<std::string>{",! SEA IS DEEP1 WIDE & BLUE4", ",SEA ,/ORIES", "& COLD4", ",FI% SWIM4"}));
}
