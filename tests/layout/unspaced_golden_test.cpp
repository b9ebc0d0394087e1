// SPDX-License-Identifier: GPL-3.0-or-later
// Text without spaces is laid out several times
// faster (word division translates one line ahead instead of four), and its
// lines must stay exactly what they were. The expected file was written by the
// division as it was before the change (commit 7c54b89) and is compared line
// for line: unspaced letters, base64-like ASCII longer than one 4096-character
// translation piece, runs of capitals, digits and punctuation, Chinese, and
// spaced text with overlong words, in four tables at seven widths.
// TACTUS_UPDATE_GOLDEN=1 rewrites it (review the diff: it must not change).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "../common/layout_options.hpp"
#include "cells.hpp"
#include "common/file_io.hpp"
#include "common/utf8.hpp"
#include "pipeline/pipeline.hpp"

using namespace tactus;
using namespace tactus::document;

namespace {

const std::filesystem::path kExpected =
    std::filesystem::path(TACTUS_TEST_DATA) / "layout" / "unspaced-lines.brf";

// Characters drawn from `alphabet` by a generator whose output the standard
// fixes (mt19937's, not a distribution's), so the text is the same everywhere.
std::u32string draw(std::mt19937& rng, std::u32string_view alphabet, std::size_t n) {
    std::u32string s;
    for (std::size_t i = 0; i < n; ++i) s.push_back(alphabet[rng() % alphabet.size()]);
    return s;
}

std::u32string runs(std::mt19937& rng, std::size_t n, bool spaces) {
    static const std::u32string_view kinds[] = {U"abcdefghijklmnopqrstuvwxyz", U"ABCDEFGHIJKLMNOPQRSTUVWXYZ",
                                                U"0123456789", U".,;:'!?/()\"&*-", U"ingtheandation", U"  -"};
    std::u32string s;
    const std::size_t nkinds = spaces ? std::size(kinds) : std::size(kinds) - 1;
    while (s.size() < n) {
        // In this order, which the golden file was made with: as two arguments
        // of one call, the compiler chose which was drawn first (GCC and clang
        // differ).
        const std::size_t length = 1 + rng() % 30;
        const auto kind = kinds[rng() % nkinds];
        s += draw(rng, kind, length);
    }
    s.resize(n);
    return s;
}

std::u32string sample_han(const char* name) {
    std::ifstream in(std::string(TACTUS_RESOURCES_DIR) + "/samples/" + name);
    std::stringstream ss;
    ss << in.rdbuf();
    std::u32string han;
    if (const auto u = utf8_to_utf32(ss.str()))
        for (char32_t c : *u)
            if (c >= 0x4E00 && c <= 0x9FFF) han.push_back(c);
    return han;
}

struct Case {
    std::string name;
    std::string table;
    std::u32string text;
    std::vector<int> widths;
};

std::vector<Case> cases() {
    std::mt19937 rng(2026);
    const std::vector<int> widths{10, 14, 19, 25, 27, 33, 40};
    const std::u32string base64 = U"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<Case> out;
    // Longer than one 4096-character piece: divided as one word from end to end.
    out.push_back({"base64", "en-ueb-g1.ctb", draw(rng, base64, 4300), {10, 27, 40}});
    out.push_back({"letters", "en-ueb-g1.ctb", draw(rng, U"abcdefghijklmnopqrstuvwxyz", 700), widths});
    out.push_back({"letters", "en-ueb-g2.ctb", draw(rng, U"abcdefghijklmnopqrstuvwxyz", 700), widths});
    out.push_back({"runs", "en-ueb-g1.ctb", runs(rng, 700, false), widths});
    out.push_back({"runs", "en-ueb-g2.ctb", runs(rng, 700, false), widths});
    out.push_back({"runs", "en-us-g2.ctb", runs(rng, 700, false), widths});
    out.push_back({"spaced", "en-ueb-g2.ctb", runs(rng, 700, true), widths});
    out.push_back({"han", "zh-tw.ctb", draw(rng, sample_han("chinese-tw.txt"), 250), widths});
    return out;
}

std::string render() {
    std::string out;
    for (const auto& c : cases()) {
        for (int width : c.widths) {
            Document doc;
            Block b;
            b.kind = BlockKind::paragraph;
            b.spans.push_back(Span{utf32_to_utf8(c.text), emphasis_none});
            doc.blocks.push_back(std::move(b));
            auto paged = pipeline::lay_out(doc, test::body_lines_options(c.table, width));
            EXPECT_TRUE(paged) << paged.error().to_string();
            if (!paged) continue;
            out += "== " + c.name + " " + c.table + " width " + std::to_string(width) + "\n";
            for (const auto& p : paged->pages)
                for (const auto& l : p.lines)
                    if (!l.empty()) out += brf(l) + "\n";
        }
    }
    return out;
}

}  // namespace

TEST(GoldenUnspaced, LinesAreWhatTheDivisionGaveBeforeTheSpeedUp) {
    const auto actual = render();
    if (std::getenv("TACTUS_UPDATE_GOLDEN")) {
        ASSERT_TRUE(write_file_atomic(kExpected, actual));
        GTEST_SKIP() << "updated " << kExpected;
    }
    const auto expected = read_file(kExpected);
    ASSERT_TRUE(expected) << expected.error().to_string();
    // Line by line, so a difference names its case and line.
    std::istringstream a(actual), e(*expected);
    std::string la, le, heading;
    for (int n = 1; std::getline(e, le); ++n) {
        ASSERT_TRUE(std::getline(a, la)) << "lines missing from line " << n << " (" << heading << ")";
        if (le.starts_with("== ")) heading = le;
        ASSERT_EQ(la, le) << "line " << n << " of " << kExpected.filename() << " (" << heading << ")";
    }
    EXPECT_FALSE(std::getline(a, la)) << "more lines than expected";
}
