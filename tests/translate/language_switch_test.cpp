// SPDX-License-Identifier: GPL-3.0-or-later
// Passages in another language translated with that language's table
// (translate/language_switch.hpp, translate/code_switch.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "common/utf8.hpp"
#include "document/document.hpp"
#include "export/zip_writer.hpp"
#include "import/import.hpp"
#include "pipeline/pipeline.hpp"
#include "translate/code_switch.hpp"
#include "translate/language_switch.hpp"
#include "translate/translated_document.hpp"
#include "translate/translator.hpp"

using namespace tactus;
using translate::TableSlot;

namespace {

namespace fs = std::filesystem;
const fs::path kImportData = fs::path(TACTUS_TEST_DATA) / "import";

translate::Translator open_mixed(const std::string& table, translate::LanguageSwitchOptions o = {}) {
    auto t = translate::open_translator(table, o);
    EXPECT_TRUE(t) << t.error().to_string();
    return std::move(*t);
}

translate::Translator open_one(const std::string& table) {
    auto t = translate::Translator::open(table);
    EXPECT_TRUE(t) << t.error().to_string();
    return std::move(*t);
}

// The runs as "slot:text" for readable failures.
std::vector<std::string> runs_of(const translate::Translator& tr, const std::u32string& text) {
    std::vector<std::string> out;
    for (const auto& r : tr.language_switch()->split(text))
        out.push_back(std::to_string(static_cast<int>(r.slot)) + ":" +
                      utf32_to_utf8(text.substr(r.begin, r.end - r.begin)));
    return out;
}

translate::TranslatedBlock paragraph(const translate::Translator& tr, const std::string& text, std::size_t room = 0) {
    document::Block b;
    b.spans.push_back(document::Span{text});
    auto tb = translate::translate_block(b, tr, room);
    EXPECT_TRUE(tb) << tb.error().to_string();
    return tb ? std::move(*tb) : translate::TranslatedBlock{};
}

document::BrailleLine cells_of(const translate::Translator& tr, const std::u32string& text) {
    auto c = tr.translate(text);
    EXPECT_TRUE(c) << c.error().to_string();
    return c ? *c : document::BrailleLine{};
}

bool has_dots_78(const document::BrailleLine& cells) {
    for (auto c : cells)
        if (c.has_dot(7) || c.has_dot(8)) return true;
    return false;
}

bool contains(const document::BrailleLine& hay, const document::BrailleLine& needle) {
    return std::search(hay.begin(), hay.end(), needle.begin(), needle.end()) != hay.end();
}

}  // namespace

TEST(LanguageSwitch, SplitsChineseOutOfEnglishByScript) {
    const auto tr = open_mixed("en-ueb-g2.ctb");
    EXPECT_EQ(runs_of(tr, U"the word 中文，好 means it."),
              (std::vector<std::string>{"0:the word ", "2:中文，好", "0: means it."}));
    EXPECT_EQ(runs_of(tr, U"plain English only, 42."), (std::vector<std::string>{"0:plain English only, 42."}));
}

// Unmarked Chinese in Simplified characters (汉, 语 have Traditional forms
// 漢, 語) goes to the mainland table; text with a Traditional character, or
// only characters both write alike, to Taiwan's.
TEST(LanguageSwitch, SimplifiedChineseGoesToTheMainlandTable) {
    const auto tr = open_mixed("en-ueb-g2.ctb");
    EXPECT_EQ(runs_of(tr, U"say 汉语 now"), (std::vector<std::string>{"0:say ", "3:汉语", "0: now"}));
    EXPECT_EQ(runs_of(tr, U"say 漢語 now"), (std::vector<std::string>{"0:say ", "2:漢語", "0: now"}));
    EXPECT_EQ(runs_of(tr, U"say 中文 now"), (std::vector<std::string>{"0:say ", "2:中文", "0: now"}));
    const auto cn = open_one("zhcn-g1.ctb");
    const auto tb = paragraph(tr, "say 汉语 now");
    EXPECT_TRUE(contains(tb.cells, cells_of(cn, U"汉语"))) << document::to_unicode_text(tb.cells);
}

TEST(LanguageSwitch, SplitsEnglishOutOfChineseByScript) {
    const auto tr = open_mixed("zh-tw.ctb");
    EXPECT_EQ(runs_of(tr, U"我喜歡apple和New York。"),
              (std::vector<std::string>{"0:我喜歡", "1:apple", "0:和", "1:New York", "0:。"}));
    // Closing punctuation the English table writes goes with the English;
    // CJK punctuation never does (en-ueb knows no 」).
    EXPECT_EQ(runs_of(tr, U"老師說：「Please sit down.」"),
              (std::vector<std::string>{"0:老師說：「", "1:Please sit down.", "0:」"}));
}

TEST(LanguageSwitch, MarkedLanguagesPickTheirTableFromTheCatalogue) {
    const auto tr = open_mixed("en-ueb-g2.ctb");
    const auto* sw = tr.language_switch();
    EXPECT_EQ(sw->slot_for_language("zh-TW"), TableSlot::chinese_tw);
    EXPECT_EQ(sw->slot_for_language("zh-Hant"), TableSlot::chinese_tw);
    EXPECT_EQ(sw->slot_for_language("zh-CN"), TableSlot::chinese_cn);
    EXPECT_EQ(sw->slot_for_language("zh-Hans"), TableSlot::chinese_cn);
    EXPECT_EQ(sw->slot_for_language("zh-Latn-pinyin"), TableSlot::primary);
    EXPECT_EQ(sw->slot_for_language("en-GB"), TableSlot::primary);
    EXPECT_EQ(sw->slot_for_language("fr"), TableSlot::primary);
    auto cn = sw->translator(TableSlot::chinese_cn);
    ASSERT_TRUE(cn) << cn.error().to_string();
    EXPECT_EQ((*cn)->tables(), "zhcn-g1.ctb");
    auto tw = sw->translator(TableSlot::chinese_tw);
    ASSERT_TRUE(tw);
    EXPECT_EQ((*tw)->tables(), "zh-tw.ctb");
    const auto zh = open_mixed("zh-tw.ctb");
    auto en = zh.language_switch()->translator(TableSlot::english);
    ASSERT_TRUE(en);
    EXPECT_EQ((*en)->tables(), "en-ueb-g1.ctb");
    translate::LanguageSwitchOptions g2;
    g2.english_grade = "2";
    auto en2 = open_mixed("zh-tw.ctb", g2).language_switch()->translator(TableSlot::english);
    ASSERT_TRUE(en2);
    EXPECT_EQ((*en2)->tables(), "en-ueb-g2.ctb");
}

TEST(LanguageSwitch, ABadSecondTableIsAnErrorWhenOpened) {
    translate::LanguageSwitchOptions o;
    o.second_table = "no-such-table.ctb";
    auto t = translate::open_translator("en-ueb-g2.ctb", o);
    ASSERT_FALSE(t);
    EXPECT_EQ(t.error().where, "--second-table");
}

// UEB §14.3.1: ⠘⠷ before a Chinese word in English, ended by the space after
// it; the Chinese is zh-tw.ctb's own braille, no dots 7-8 escapes.
TEST(LanguageSwitch, ChineseWordInUebHasTheNonUebWordIndicator) {
    const auto tr = open_mixed("en-ueb-g2.ctb");
    const auto zh = open_one("zh-tw.ctb");
    const auto tb = paragraph(tr, "the word 中文 means");
    EXPECT_FALSE(has_dots_78(tb.cells));
    document::BrailleLine expected = cells_of(tr, U"the word ");
    expected.insert(expected.end(), std::begin(translate::kNonUebWord), std::end(translate::kNonUebWord));
    const auto chinese = cells_of(zh, U"中文");
    expected.insert(expected.end(), chinese.begin(), chinese.end());
    const auto rest = cells_of(tr, U" means");
    expected.insert(expected.end(), rest.begin(), rest.end());
    EXPECT_EQ(document::to_unicode_text(tb.cells), document::to_unicode_text(expected));
    ASSERT_EQ(tb.breaks.size(), tb.cells.size());
    // The indicator starts the word: a line may end before it, never inside it.
    const auto at = cells_of(tr, U"the word ").size();
    EXPECT_EQ(tb.breaks[at], translate::BreakBefore::allowed);
    EXPECT_EQ(tb.breaks[at + 1], translate::BreakBefore::never);
    EXPECT_EQ(tb.breaks[at + 2], translate::BreakBefore::never);
}

TEST(LanguageSwitch, UnspacedTextAfterTheWordGetsTheTerminator) {
    const auto tr = open_mixed("en-ueb-g2.ctb");
    const auto tb = paragraph(tr, "say 你好, then");
    EXPECT_TRUE(contains(tb.cells, document::BrailleLine(std::begin(translate::kNonUebWordEnd),
                                                         std::end(translate::kNonUebWordEnd))));
}

// UEB §14.3.2: three or more symbols-sequences take the passage indicators.
TEST(LanguageSwitch, ThreeSequencesTakeThePassageIndicators) {
    const auto tr = open_mixed("en-ueb-g2.ctb");
    const auto tb = paragraph(tr, "read 我們 明天 見 aloud");
    const document::BrailleLine open(std::begin(translate::kNonUebOpen), std::end(translate::kNonUebOpen));
    const document::BrailleLine close(std::begin(translate::kNonUebClose), std::end(translate::kNonUebClose));
    EXPECT_TRUE(contains(tb.cells, open));
    EXPECT_TRUE(contains(tb.cells, close));
    EXPECT_FALSE(contains(tb.cells, document::BrailleLine(std::begin(translate::kNonUebWord),
                                                          std::end(translate::kNonUebWord))));
}

// English words in Chinese text: UEB braille, not zh-tw.ctb's 8-dot computer
// braille (capital letters with dot 7).
TEST(LanguageSwitch, EnglishInTaiwaneseTextIsUebNotComputerBraille) {
    const auto tr = open_mixed("zh-tw.ctb");
    const auto one = open_one("zh-tw.ctb");
    EXPECT_TRUE(has_dots_78(paragraph(one, "大家說Good morning。").cells));
    const auto tb = paragraph(tr, "大家說Good morning。");
    EXPECT_FALSE(has_dots_78(tb.cells));
    const auto g1 = open_one("en-ueb-g1.ctb");
    EXPECT_TRUE(contains(tb.cells, cells_of(g1, U"Good")));
}

TEST(LanguageSwitch, MainlandTextPutsTheLetterSignBeforeUnspacedLatin) {
    const auto tr = open_mixed("zhcn-g2.ctb");
    const auto tb = paragraph(tr, "我喜欢apple和你");
    const auto g1 = open_one("en-ueb-g1.ctb");
    document::BrailleLine signed_word(std::begin(translate::kLetterSign), std::end(translate::kLetterSign));
    const auto apple = cells_of(g1, U"apple");
    signed_word.insert(signed_word.end(), apple.begin(), apple.end());
    signed_word.push_back(document::Cell{});  // the space before the Chinese after it
    EXPECT_TRUE(contains(tb.cells, signed_word)) << document::to_unicode_text(tb.cells);
}

TEST(LanguageSwitch, IndicatorsCanBeTurnedOff) {
    translate::LanguageSwitchOptions o;
    o.indicators = translate::SwitchIndicators::none;
    const auto tr = open_mixed("en-ueb-g2.ctb", o);
    const auto zh = open_one("zh-tw.ctb");
    const auto tb = paragraph(tr, "the word 中文 means");
    document::BrailleLine expected = cells_of(tr, U"the word ");
    const auto chinese = cells_of(zh, U"中文");
    expected.insert(expected.end(), chinese.begin(), chinese.end());
    const auto rest = cells_of(tr, U" means");
    expected.insert(expected.end(), rest.begin(), rest.end());
    EXPECT_EQ(document::to_unicode_text(tb.cells), document::to_unicode_text(expected));
}

// Property: a text in the table's own language alone translates to the same
// cells and the same line breaks with the switch as without it. Every block
// of a real book (Jekyll and Hyde, English) and of the Chinese samples.
TEST(LanguageSwitch, OneLanguageTextIsUnchanged) {
    struct Case {
        fs::path file;
        std::string table;
    };
    const std::vector<Case> cases = {
        {kImportData / "books" / "jekyll-and-hyde.epub", "en-ueb-g2.ctb"},
        {fs::path(TACTUS_RESOURCES_DIR) / "samples" / "chinese-tw.txt", "zh-tw.ctb"},
        {fs::path(TACTUS_RESOURCES_DIR) / "samples" / "chinese-cn.txt", "zhcn-g2.ctb"},
    };
    for (const auto& c : cases) {
        auto doc = import::import_file(c.file, {});
        ASSERT_TRUE(doc) << doc.error().to_string();
        const auto mixed = open_mixed(c.table);
        const auto one = open_one(c.table);
        std::size_t blocks = 0;
        for (const auto& b : doc->blocks) {
            if (!document::is_text_kind(b.kind)) continue;
            for (std::size_t room : {std::size_t{0}, std::size_t{12}}) {
                auto a = translate::translate_block(b, mixed, room);
                auto e = translate::translate_block(b, one, room);
                ASSERT_TRUE(a && e);
                ASSERT_EQ(a->cells, e->cells) << c.file << " " << c.table << " block " << b.text();
                ASSERT_EQ(a->breaks, e->breaks) << c.file << " " << c.table << " block " << b.text();
            }
            ++blocks;
        }
        EXPECT_GT(blocks, 2u) << c.file;
    }
}

// Line breaks stay sound across a change of table: one per cell, a line may
// end only at a word space or where print allows, and every line the
// layout's breaker makes fits, at every width.
TEST(LanguageSwitch, BreaksStayIndexedAcrossTheSwitch) {
    const auto tr = open_mixed("zh-tw.ctb");
    const std::string text =
        "老師說：「Please open your books to page twelve.」大家一起念Good morning，然後寫extraordinarily在黑板上。";
    for (std::size_t room : {std::size_t{0}, std::size_t{8}, std::size_t{15}, std::size_t{30}}) {
        const auto tb = paragraph(tr, text, room);
        ASSERT_EQ(tb.breaks.size(), tb.cells.size());
        ASSERT_FALSE(tb.cells.empty());
        EXPECT_EQ(tb.breaks[0], translate::BreakBefore::never);
        for (std::size_t i = 0; i < tb.cells.size(); ++i) {
            if (tb.breaks[i] == translate::BreakBefore::blank) {
                EXPECT_TRUE(tb.cells[i].blank()) << i;
            }
        }
        if (room == 0) continue;
        // A divided word's lines are at most `room` cells between forced breaks.
        std::size_t line = 0;
        for (std::size_t i = 0; i < tb.cells.size(); ++i) {
            if (translate::is_line_break(tb.breaks[i])) line = 0;
            ++line;
            EXPECT_LE(line, room + 4) << "room " << room << " at cell " << i;  // indicators ride on their word
        }
    }
}

// lesson.md's Chinese line under the English table: with the switch it is
// zh-tw.ctb's braille, so the dots 7-8 warning (escape codes) is gone; with
// one table it is still there.
TEST(LanguageSwitch, LessonChineseLineGivesNoDotsSevenEightWarning) {
    const auto dots_warnings = [](bool enabled) {
        pipeline::PipelineOptions o;
        o.tables = "en-ueb-g2.ctb";
        o.language_switch.enabled = enabled;
        o.translation_workers = 1;
        auto paged = pipeline::lay_out_file(kImportData / "lesson.md", o);
        EXPECT_TRUE(paged) << paged.error().to_string();
        std::size_t n = 0;
        if (paged) {
            for (const auto& w : paged->warnings) n += w.find("dots 7-8") != std::string::npos;
        }
        return n;
    };
    EXPECT_EQ(dots_warnings(true), 0u);
    EXPECT_EQ(dots_warnings(false), 1u);
}

// A Word document with an English paragraph holding a passage marked Chinese
// (Taiwan) for East Asian text (w:eastAsia="zh-TW"), the rest English by the
// document defaults, as Word writes them. The package is made here, part by
// part: no real file marks a Chinese passage. The passage is in Simplified
// characters, which unmarked would go to the mainland table (see
// SimplifiedChineseGoesToTheMainlandTable): marked, it is laid out with
// Taiwan's table, the braille of the passage alone in zh-tw.ctb.
TEST(LanguageSwitch, DocxPassageMarkedChineseIsLaidOutWithItsTable) {
    constexpr std::string_view w = R"( xmlns:w="http://schemas.openxmlformats.org/wordprocessingml/2006/main")";
    const std::string document_xml =
        std::string(R"(<?xml version="1.0" encoding="UTF-8"?><w:document)") + std::string(w) +
        R"(><w:body><w:p><w:r><w:t xml:space="preserve">Say </w:t></w:r>)"
        R"(<w:r><w:rPr><w:lang w:eastAsia="zh-TW"/></w:rPr><w:t>汉语</w:t></w:r>)"
        R"(<w:r><w:t xml:space="preserve"> now.</w:t></w:r></w:p></w:body></w:document>)";
    const std::string styles_xml =
        std::string(R"(<?xml version="1.0" encoding="UTF-8"?><w:styles)") + std::string(w) +
        R"(><w:docDefaults><w:rPrDefault><w:rPr><w:lang w:val="en-US" w:eastAsia="en-US" w:bidi="ar-SA"/>)"
        R"(</w:rPr></w:rPrDefault></w:docDefaults></w:styles>)";
    constexpr std::string_view rels = "http://schemas.openxmlformats.org/officeDocument/2006/relationships";
    const std::string package_rels =
        std::string(R"(<?xml version="1.0" encoding="UTF-8"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">)") +
        R"(<Relationship Id="rId1" Type=")" + std::string(rels) + R"(/officeDocument" Target="word/document.xml"/></Relationships>)";
    const std::string document_rels =
        std::string(R"(<?xml version="1.0" encoding="UTF-8"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">)") +
        R"(<Relationship Id="rId1" Type=")" + std::string(rels) + R"(/styles" Target="styles.xml"/></Relationships>)";
    auto package = exporter::zip_package({{"_rels/.rels", package_rels, false},
                                          {"word/document.xml", document_xml, false},
                                          {"word/_rels/document.xml.rels", document_rels, false},
                                          {"word/styles.xml", styles_xml, false}});
    ASSERT_TRUE(package) << package.error().to_string();
    auto doc = import::import_bytes(*package, "passage.docx");
    ASSERT_TRUE(doc) << doc.error().to_string();
    std::vector<std::pair<std::string, std::string>> spans;
    for (const auto& b : doc->blocks)
        for (const auto& s : b.spans) spans.emplace_back(s.text, s.language);
    EXPECT_EQ(spans, (std::vector<std::pair<std::string, std::string>>{{"Say ", ""}, {"汉语", "zh-TW"}, {" now.", ""}}));

    pipeline::PipelineOptions o;
    o.tables = "en-ueb-g2.ctb";
    o.translation_workers = 1;
    auto paged = pipeline::lay_out(*doc, o);
    ASSERT_TRUE(paged) << paged.error().to_string();
    document::BrailleLine all;
    for (const auto& page : paged->pages)
        for (const auto& line : page.lines) all.insert(all.end(), line.begin(), line.end());
    const auto tw = cells_of(open_one("zh-tw.ctb"), U"汉语");
    const auto cn = cells_of(open_one("zhcn-g1.ctb"), U"汉语");
    ASSERT_NE(tw, cn);
    EXPECT_FALSE(has_dots_78(tw)) << "zh-tw.ctb writes the passage";
    EXPECT_TRUE(contains(all, tw)) << document::to_unicode_text(all);
    EXPECT_FALSE(contains(all, cn)) << document::to_unicode_text(all);
}
