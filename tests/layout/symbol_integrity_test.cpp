// SPDX-License-Identifier: GPL-3.0-or-later
// "Never break inside a symbol": line breaks only where the print text
// allows them (a space, after a hyphen, between Chinese characters), checked
// against liblouis's own input positions; overlong words divided with a hyphen
// (UEB 10.13) or, inside a number, the line continuation indicator (UEB 6.10).
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "../common/layout_options.hpp"
#include "cells.hpp"
#include "common/utf8.hpp"
#include "louis_oracle.hpp"
#include "pipeline/pipeline.hpp"

using namespace tactus;
using namespace tactus::document;
using namespace tactus::pipeline;
using namespace tactus::layout;

namespace {

// Every body line of one paragraph laid out at `width` cells, no indent, no
// page numbers: the lines exactly as the line breaker made them.
std::vector<BrailleLine> lay_out_paragraph(const std::string& table, const std::string& text, int width,
                                           int indent = 0) {
    Document doc;
    Block b;
    b.kind = BlockKind::paragraph;
    b.spans.push_back(Span{text, emphasis_none});
    doc.blocks.push_back(b);
    auto o = test::body_lines_options(table, width);
    o.layout.paragraph_indent = indent;
    auto paged = lay_out(doc, o);
    EXPECT_TRUE(paged) << paged.error().to_string();
    std::vector<BrailleLine> lines;
    if (!paged) return lines;
    for (const auto& p : paged->pages)
        for (const auto& l : p.lines)
            if (!l.empty()) lines.push_back(l);
    return lines;
}

std::vector<std::string> brf_lines(const std::vector<BrailleLine>& lines) {
    std::vector<std::string> out;
    for (const auto& l : lines) out.push_back(brf(l));
    return out;
}

bool is_han(char32_t c) { return c >= 0x4E00 && c <= 0x9FFF; }
bool is_space(char32_t c) { return c == U' '; }
bool is_dash(char32_t c) { return c == U'-' || c == 0x2010 || c == 0x2013 || c == 0x2014; }
bool is_cjk_stop(char32_t c) { return c == 0xFF0C || c == 0x3002 || c == 0x3001; }  // ，。、

// What print allows before text[b], the first character of the next line (the
// characters from a to b gave no cells of their own): a stricter reading of
// UAX #14 than ICU's, for the characters the generators below use.
bool print_allows(const std::u32string& t, int a, int b) {
    (void)a;
    const char32_t x = t[static_cast<std::size_t>(b - 1)], y = t[static_cast<std::size_t>(b)];
    if (is_space(x) && !is_space(y)) return true;
    if (is_dash(x) && !is_dash(y) && !(y >= U'0' && y <= U'9')) return true;
    return (is_han(x) || is_cjk_stop(x)) && is_han(y);
}

// Walks the laid-out lines along liblouis's translation of the same text: the
// non-blank cells must be the same, in the same order (nothing lost), and every
// line must end where print allows a break and no print character's cells are
// split (no indicator cut from what it governs). Returns the problems found.
std::vector<std::string> check_breaks(const std::string& table, const std::string& utf8,
                                      const std::vector<BrailleLine>& lines) {
    std::vector<std::string> problems;
    const auto decoded = utf8_to_utf32(utf8);
    const std::u32string text = decoded.value();
    const auto oracle = louis_oracle(table, text);
    std::size_t o = 0;  // next oracle cell
    const auto skip_blanks = [&] {
        while (o < oracle.cells.size() && oracle.cells[o].blank()) ++o;
    };
    for (std::size_t l = 0; l < lines.size(); ++l) {
        const auto& line = lines[l];
        std::size_t c = 0;
        while (c < line.size() && line[c].blank()) ++c;
        if (l > 0) {
            // The break between the previous line and this one.
            const std::size_t end_of_prev = o;
            skip_blanks();
            if (o == end_of_prev && o < oracle.cells.size()) {
                const bool clean = oracle.clean_cut(o);
                int before = -1, after = static_cast<int>(text.size());
                for (std::size_t i = 0; i < o; ++i) before = std::max(before, oracle.source[i]);
                for (std::size_t i = o; i < oracle.cells.size(); ++i) after = std::min(after, oracle.source[i]);
                if (!clean)
                    problems.push_back("line " + std::to_string(l + 1) + " starts inside a print character's cells: " +
                                       brf(lines[l - 1]) + " | " + brf(line));
                else if (is_space(text[static_cast<std::size_t>(oracle.source[o - 1])]))
                    // UEB's numeric space (dot 5 in "84 2") ending a line reads as
                    // the line continuation indicator: 842.
                    problems.push_back("line " + std::to_string(l) + " ends with a space written as a sign: " +
                                       brf(lines[l - 1]) + " | " + brf(line));
                else if (!print_allows(text, before + 1, after))
                    problems.push_back("line " + std::to_string(l + 1) + " starts where print allows no break: " +
                                       brf(lines[l - 1]) + " | " + brf(line));
            }
        }
        for (; c < line.size(); ++c) {
            if (line[c].blank()) {
                if (o >= oracle.cells.size() || !oracle.cells[o].blank()) {
                    problems.push_back("line " + std::to_string(l + 1) + ": a space braille does not have");
                    return problems;
                }
                skip_blanks();
                continue;
            }
            if (o < oracle.cells.size() && oracle.cells[o].blank() && c > 0 && line[c - 1].blank()) skip_blanks();
            if (o >= oracle.cells.size() || oracle.cells[o] != line[c]) {
                problems.push_back("line " + std::to_string(l + 1) + " cell " + std::to_string(c + 1) +
                                   ": differs from liblouis's translation (lost or changed): " + brf(line));
                return problems;
            }
            ++o;
        }
    }
    skip_blanks();
    if (o != oracle.cells.size())
        problems.push_back("cells lost at the end: " + std::to_string(oracle.cells.size() - o));
    return problems;
}

std::string read_sample(const std::string& name) {
    std::ifstream f(std::string(TACTUS_RESOURCES_DIR) + "/samples/" + name, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

std::vector<std::string> paragraphs(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) out.push_back(line);
    return out;
}

}  // namespace

// `xxxxxxxxxxxxxxxxxxxxxxxx123456` used to break after the numeric indicator,
// so the next line read "abcdef". Now the word is divided with a hyphen before
// the number, which keeps its indicator.
TEST(SymbolIntegrity, NumericIndicatorStaysWithItsNumber) {
    const auto lines = brf_lines(lay_out_paragraph("en-ueb-g1.ctb", "xxxxxxxxxxxxxxxxxxxxxxxx123456", 27, 2));
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "  XXXXXXXXXXXXXXXXXXXXXXXX-");
    EXPECT_EQ(lines[1], "#ABCDEF");
}

// A number longer than a line is divided between digits with the line
// continuation indicator (dot 5) and no new numeric indicator (UEB 6.10.3-5).
TEST(SymbolIntegrity, LongNumberUsesTheLineContinuationIndicator) {
    const auto lines = brf_lines(lay_out_paragraph("en-ueb-g1.ctb", "12345678901234567890", 12));
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "#ABCDEFGHIJ\"");
    EXPECT_EQ(lines[1], "ABCDEFGHIJ");
}

// The capitals-word indicator is two cells; neither may end a line without its
// word, and the continued line repeats it (the division hyphen ends capitals mode).
TEST(SymbolIntegrity, CapitalWordIndicatorIsNotSplit) {
    const auto lines = brf_lines(lay_out_paragraph("en-ueb-g1.ctb", "xxxxxxxxxxxxxxxxxxxxxxxxABCDEF", 27, 2));
    ASSERT_GE(lines.size(), 2u);
    for (const auto& l : lines) {
        EXPECT_FALSE(l.ends_with(",")) << l;
        EXPECT_FALSE(l.ends_with(",-")) << l;
    }
    EXPECT_TRUE(lines[0].ends_with("-")) << lines[0];
    EXPECT_TRUE(lines.back().ends_with(",,ABCDEF")) << lines.back();
}

TEST(SymbolIntegrity, CapitalWordGetsItsIndicatorAgainAfterADivision) {
    const auto lines = brf_lines(lay_out_paragraph("en-ueb-g1.ctb", "ABCDEFGHIJKLMNOPQRSTUVWXYZ", 12));
    ASSERT_GE(lines.size(), 3u);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        EXPECT_TRUE(lines[i].starts_with(",,")) << i << ": " << lines[i];
        EXPECT_LE(lines[i].size(), 12u);
        if (i + 1 < lines.size()) {
            EXPECT_TRUE(lines[i].ends_with("-")) << lines[i];
        }
    }
}

// The solidus is the two cells `_/` in UEB: never one on each line.
TEST(SymbolIntegrity, TwoCellSignIsNotSplit) {
    for (const char* table : {"en-ueb-g1.ctb", "en-ueb-g2.ctb"}) {
        const auto lines = brf_lines(lay_out_paragraph(table, "xxxxxxxxxxxxxxxxxxxxxxxx/yyyy", 27, 2));
        for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
            EXPECT_FALSE(lines[i].ends_with("_")) << table << ": " << lines[i] << " | " << lines[i + 1];
            EXPECT_FALSE(lines[i + 1].starts_with("/")) << table << ": " << lines[i] << " | " << lines[i + 1];
        }
    }
}

// Words joined by a hyphen break after the hyphen, which stays at the line end.
TEST(SymbolIntegrity, BreaksAfterAHyphen) {
    const auto lines = brf_lines(lay_out_paragraph("en-ueb-g1.ctb", "well-known", 8));
    EXPECT_EQ(lines, (std::vector<std::string>{"WELL-", "KNOWN"}));
}

// The bundled Tang-poem style samples at the default 27 cells: every Chinese
// character's cells stay on one line (10 broken characters with zh-tw.ctb and
// 36 with zhcn-g2.ctb before).
TEST(SymbolIntegrity, ChineseCharactersAreNeverCut) {
    for (const auto& [table, sample] : {std::pair{"zh-tw.ctb", "chinese-tw.txt"},
                                        std::pair{"zhcn-g2.ctb", "chinese-cn.txt"},
                                        std::pair{"zhcn-g1.ctb", "chinese-cn.txt"}}) {
        for (const auto& para : paragraphs(read_sample(sample))) {
            for (int width : {20, 27, 33}) {
                const auto problems = check_breaks(table, para, lay_out_paragraph(table, para, width));
                EXPECT_TRUE(problems.empty()) << table << " width " << width << ": " << problems.front();
            }
        }
    }
}

namespace {

std::string random_english(std::mt19937& rng) {
    static const std::vector<std::string> words = {
        "a", "the", "and", "of", "cat", "dog", "ing", "know", "ea", "ch", "sh", "be", "con",
        "dis", "ment", "ness", "in", "en", "st", "ar", "ed", "er", "ou", "ow", "gh", "th", "wh"};
    std::string out;
    const int n = std::uniform_int_distribution<int>(5, 60)(rng);
    for (int i = 0; i < n; ++i) {
        if (i > 0) out += std::uniform_int_distribution<int>(0, 9)(rng) == 0 ? "-" : " ";
        const int kind = std::uniform_int_distribution<int>(0, 9)(rng);
        if (kind == 0) {  // a number
            const int digits = std::uniform_int_distribution<int>(1, 4)(rng);
            for (int d = 0; d < digits; ++d) out += static_cast<char>('0' + std::uniform_int_distribution<int>(0, 9)(rng));
            if (out.size() > static_cast<std::size_t>(digits) && out[out.size() - 1 - static_cast<std::size_t>(digits)] == '-')
                out[out.size() - 1 - static_cast<std::size_t>(digits)] = ' ';  // "-5" is a minus sign
            continue;
        }
        std::string w = words[std::uniform_int_distribution<std::size_t>(0, words.size() - 1)(rng)];
        if (w.size() < 4 && std::uniform_int_distribution<int>(0, 2)(rng) == 0)
            w += words[std::uniform_int_distribution<std::size_t>(0, words.size() - 1)(rng)].substr(0, 2);
        if (kind == 1)
            for (auto& ch : w) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        else if (kind == 2)
            w[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(w[0])));
        out += w;
        if (kind == 3) out += ",";
        if (kind == 4) out += ".";
    }
    return out;
}

std::string random_chinese(std::mt19937& rng, const std::string& sample) {
    std::u32string han;
    const auto decoded = utf8_to_utf32(sample);
    for (char32_t c : decoded.value())
        if (is_han(c)) han.push_back(c);
    std::u32string out;
    const int n = std::uniform_int_distribution<int>(5, 120)(rng);
    for (int i = 0; i < n; ++i) {
        out.push_back(han[std::uniform_int_distribution<std::size_t>(0, han.size() - 1)(rng)]);
        const int p = std::uniform_int_distribution<int>(0, 11)(rng);
        if (p == 0 && i + 1 < n) out.push_back(0xFF0C);
        if (p == 1 && i + 1 < n) out.push_back(0x3002);
    }
    return utf32_to_utf8(out);
}

}  // namespace

// Property: random text in four tables at every width from 10 to 40 cells. The
// laid-out lines hold exactly liblouis's cells (nothing lost or changed), and
// every line starts where print allows a break and no character's cells are
// split. Words stay shorter than the narrowest line, so no division is needed.
TEST(SymbolIntegrity, RandomTextBreaksOnlyWherePrintAllows) {
    std::mt19937 rng(13);
    const auto tw = read_sample("chinese-tw.txt");
    const auto cn = read_sample("chinese-cn.txt");
    for (const char* table : {"en-ueb-g1.ctb", "en-ueb-g2.ctb", "zh-tw.ctb", "zhcn-g2.ctb"}) {
        const std::string t = table;
        for (int width = 10; width <= 40; ++width) {
            for (int round = 0; round < 3; ++round) {
                const auto text = t.starts_with("en") ? random_english(rng)
                                  : t == "zh-tw.ctb"  ? random_chinese(rng, tw)
                                                      : random_chinese(rng, cn);
                const auto lines = lay_out_paragraph(t, text, width);
                for (const auto& l : lines) ASSERT_LE(static_cast<int>(l.size()), width);
                const auto problems = check_breaks(t, text, lines);
                ASSERT_TRUE(problems.empty()) << t << " width " << width << " text \"" << text << "\": "
                                              << problems.front();
            }
        }
    }
}
