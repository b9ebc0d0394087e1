// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "common/utf8.hpp"
#include "document/document.hpp"
#include "translate/translated_document.hpp"
#include "translate/translator.hpp"

using namespace tactus;

namespace {

std::string unicode(const Result<document::BrailleLine>& r) {
    EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().to_string());
    return r ? document::to_unicode_text(*r) : std::string{};
}

std::u32string u32(std::string_view s) { return *utf8_to_utf32(s); }

}  // namespace

TEST(Translator, UebGrade2ContractsWords) {
    auto t = translate::Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(t);
    // "the" and "and" are whole-word contractions in UEB grade 2.
    EXPECT_EQ(unicode(t->translate(u32("the cat and dog"))), "⠮⠀⠉⠁⠞⠀⠯⠀⠙⠕⠛");
}

TEST(Translator, UebGrade1SpellsOut) {
    auto t = translate::Translator::open("en-ueb-g1.ctb");
    ASSERT_TRUE(t);
    EXPECT_EQ(unicode(t->translate(u32("the"))), "⠞⠓⠑");
}

TEST(Translator, CapitalAndNumberIndicators) {
    auto t = translate::Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(t);
    EXPECT_EQ(unicode(t->translate(u32("Hi 42"))), "⠠⠓⠊⠀⠼⠙⠃");
}

TEST(Translator, EmphasisBecomesIndicators) {
    auto t = translate::Translator::open("en-ueb-g1.ctb");
    ASSERT_TRUE(t);
    const auto text = u32("a big b");
    std::vector<std::uint8_t> emph(text.size(), document::emphasis_none);
    emph[2] = emph[3] = emph[4] = document::emphasis_bold;
    const auto plain = unicode(t->translate(text));
    const auto bold = unicode(t->translate(text, emph));
    // UEB bold word indicator is dots 45, 2 before the word.
    EXPECT_EQ(bold, "⠁⠀⠘⠂⠃⠊⠛⠀⠃");
    EXPECT_NE(plain, bold);
}

TEST(Translator, ChineseTaiwanAndMainland) {
    auto tw = translate::Translator::open("zh-tw.ctb");
    auto cn = translate::Translator::open("zhcn-g1.ctb");
    ASSERT_TRUE(tw);
    ASSERT_TRUE(cn);
    const auto tw_cells = tw->translate(u32("我們"));
    const auto cn_cells = cn->translate(u32("我们"));
    ASSERT_TRUE(tw_cells && cn_cells);
    EXPECT_FALSE(tw_cells->empty());
    EXPECT_FALSE(cn_cells->empty());
    // Different braille systems: bopomofo-based vs. mainland current braille.
    EXPECT_NE(document::to_unicode_text(*tw_cells), document::to_unicode_text(*cn_cells));
    for (document::Cell c : *tw_cells) EXPECT_FALSE(c.dots & 0xC0) << "6-dot expected";
}

TEST(Translator, BackTranslationRoundTrip) {
    auto t = translate::Translator::open("en-ueb-g1.ctb");
    ASSERT_TRUE(t);
    const auto cells = t->translate(u32("Braille is read by touch."));
    ASSERT_TRUE(cells);
    const auto back = t->back_translate(*cells);
    ASSERT_TRUE(back);
    EXPECT_EQ(utf32_to_utf8(*back), "Braille is read by touch.");
}

TEST(Translator, BrfDisplayTable) {
    auto t = translate::Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(t);
    const auto brf = t->translate_with_display(u32("Hello"), "en-us-brf.dis");
    ASSERT_TRUE(brf);
    EXPECT_EQ(utf32_to_utf8(*brf), ",HELLO");
}

TEST(Translator, UnknownTableIsAClearError) {
    auto t = translate::Translator::open("no-such-table.ctb");
    ASSERT_FALSE(t);
    EXPECT_NE(t.error().message.find("no-such-table.ctb"), std::string::npos);
    EXPECT_EQ(t.error().where, "--table");
}

TEST(Translator, BrokenTableIsAClearError) {
    const auto path = std::filesystem::temp_directory_path() / "tactus-broken-table.ctb";
    {
        std::ofstream(path) << "this is not a liblouis opcode\n";
    }
    auto t = translate::Translator::open(path.string());
    ASSERT_FALSE(t);
    EXPECT_NE(t.error().message.find("broken"), std::string::npos);
    std::filesystem::remove(path);
}

TEST(Translator, LongTextIsNotTruncated) {
    auto t = translate::Translator::open("en-ueb-g1.ctb");
    ASSERT_TRUE(t);
    std::u32string text;
    for (int i = 0; i < 3000; ++i) text += U"word ";
    const auto cells = t->translate(text);
    ASSERT_TRUE(cells);
    // Every "word" is 4 cells plus one blank, except the trailing space.
    EXPECT_GE(cells->size(), 3000u * 5 - 1);
}

// liblouis is not thread-safe; the translator serialises calls, so concurrent
// use must give exactly the single-threaded result.
TEST(Translator, ConcurrentCallsGiveTheSameResult) {
    auto t = translate::Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(t);
    const auto text = u32("The quick brown fox jumps over the lazy dog, and then some.");
    const auto expected = unicode(t->translate(text));
    std::vector<std::thread> threads;
    std::atomic<int> mismatches{0};
    for (int k = 0; k < 4; ++k)
        threads.emplace_back([&] {
            for (int i = 0; i < 200; ++i)
                if (document::to_unicode_text(*t->translate(text)) != expected) ++mismatches;
        });
    for (auto& th : threads) th.join();
    EXPECT_EQ(mismatches.load(), 0);
}

TEST(TranslateBlock, LongParagraphCutAtSpacesMatchesWholeTranslation) {
    auto t = translate::Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(t);
    std::string text;
    for (int i = 0; i < 900; ++i) text += "and the children ";
    document::Block b;
    b.spans = {document::Span{text, document::emphasis_none}};
    const auto chunked = translate::translate_block(b, *t);
    ASSERT_TRUE(chunked);
    // The block's last space is print's, not braille (a block's edge spaces are left out).
    const auto whole = t->translate(u32(text.substr(0, text.size() - 1)));
    ASSERT_TRUE(whole);
    EXPECT_EQ(document::to_unicode_text(chunked->cells), document::to_unicode_text(*whole));
}

TEST(TranslateBlock, InvalidUtf8NamesTheLine) {
    auto t = translate::Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(t);
    document::Block b;
    b.source_line = 7;
    b.spans = {document::Span{"ok \xC3", document::emphasis_none}};
    const auto r = translate::translate_block(b, *t);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().where, "line 7:byte 3");
}

// English words are divided between syllables (UEB 10.13), which needs
// liblouis's hyphenation dictionary for the table's language. The build looked
// for the dictionaries in "/liblouis/tables" (liblouis.pc has `tablesdir`, not
// `datadir`), so none was ever found and words were cut anywhere.
TEST(Translator, EnglishWordsHaveSyllableBreaksFromLiblouisDictionary) {
    auto tr = translate::Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(tr);
    const std::u32string word = U"hyphenation";
    const auto points = tr->hyphenation_points(word);
    ASSERT_EQ(points.size(), word.size() + 1);  // true before character i
    std::string marked;
    for (std::size_t i = 0; i < word.size(); ++i) {
        if (points[i]) marked += '-';
        marked += static_cast<char>(word[i]);
    }
    EXPECT_EQ(marked, "hy-phen-ation");
}

// A paragraph is decoded straight into the translator's text
// (no whole copy on the side); a bad byte leaves what was there.
TEST(Utf8, AppendUtf32AddsToTheEndOrNothing) {
    std::u32string text = U"ab";
    ASSERT_TRUE(tactus::append_utf32(text, "c\xE4\xB8\xAD\xF0\x9F\x98\x80"));
    EXPECT_EQ(text, U"abc\u4E2D\U0001F600");
    const auto bad = tactus::append_utf32(text, "x\xC3");
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().where, "byte 1");
    EXPECT_EQ(text, U"abc\u4E2D\U0001F600");
}

// Word division looks one line ahead instead of
// four only in tables that write a word locally. en-us-g2.ctb (through
// en-us-g1.ctb) has `compbrl`, which puts a whole word in computer braille when
// "://", ".com", "()" and the like appear anywhere in it; the UEB and Chinese
// tables have none.
TEST(Translator, KnowsWhichTablesHaveWordWideRules) {
    for (const auto& [table, wide] : {std::pair{"en-us-g2.ctb", true}, std::pair{"en-us-g1.ctb", true},
                                      std::pair{"en-ueb-g1.ctb", false}, std::pair{"en-ueb-g2.ctb", false},
                                      std::pair{"zh-tw.ctb", false}, std::pair{"zhcn-g2.ctb", false}}) {
        auto tr = translate::Translator::open(table);
        ASSERT_TRUE(tr) << table;
        EXPECT_EQ(tr->has_word_wide_rules(), wide) << table;
    }
    // The rule's effect, which is why the window must stay long there: the
    // start of the word changes with its end.
    auto ebae = translate::Translator::open("en-us-g2.ctb");
    ASSERT_TRUE(ebae);
    const auto plain = ebae->translate(U"OHZIBTKngtte");
    const auto url = ebae->translate(U"OHZIBTKngtte.com");
    ASSERT_TRUE(plain && url);
    EXPECT_EQ(tactus::document::cell_to_brf((*plain)[0]), ',');   // capital sign
    EXPECT_EQ(tactus::document::cell_to_brf((*url)[0]), '_');     // computer braille begins
}
