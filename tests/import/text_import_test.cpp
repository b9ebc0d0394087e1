// SPDX-License-Identifier: GPL-3.0-or-later
#include <unistd.h>

#include <fstream>

#include "import_test_util.hpp"

namespace tactus::test {
namespace {

const auto P = document::BlockKind::paragraph;

// A hard-wrapped paragraph keeps its lines, a soft line break between them
// (document/soft_break.hpp: braille reads it as a space).
TEST(TextImport, ParagraphsKeepWrappedLinesAndFormFeedIsPrintPageBreak) {
    const auto doc = import_data_file("utf8.txt");
    const std::vector<document::Block> expected = {
        text_block(P, 0, {{"Braille Lesson"}}, 1),
        text_block(P, 0, {{"Braille is read by touch.\nEach cell has six dots."}}, 3),
        text_block(P, 0, {{"盲文是一种触摸阅读的文字。"}}, 6),
        page_break("2", 7),
        text_block(P, 0, {{"Page two starts here."}}, 7),
    };
    EXPECT_EQ(doc.blocks, expected);
    EXPECT_EQ(doc.encoding, "UTF-8");
    EXPECT_EQ(doc.source_name, import_data("utf8.txt").string());
}

TEST(TextImport, CrLfAndLoneCrEndLinesLikeLf) {
    const auto lf = import::import_bytes("a\nb\n\nc\n", "x.txt");
    const auto crlf = import::import_bytes("a\r\nb\r\n\r\nc\r\n", "x.txt");
    const auto cr = import::import_bytes("a\rb\r\rc\r", "x.txt");
    ASSERT_TRUE(lf && crlf && cr);
    EXPECT_EQ(lf->blocks, crlf->blocks);
    EXPECT_EQ(lf->blocks, cr->blocks);
    ASSERT_EQ(lf->blocks.size(), 2u);
    EXPECT_EQ(lf->blocks[0].text(), "a\nb");
    EXPECT_EQ(lf->blocks[1].source_line, 4);
}

// A text without a single blank line between lines (verse per line, a list of
// words) has no paragraph marks but its line ends: each line is a paragraph.
TEST(TextImport, WithoutAnyBlankLineEachLineIsAParagraph) {
    const auto doc = import::import_bytes("Ge1:1 In the beginning.\nGe1:2 And the earth.\n\n", "kjv.txt");
    ASSERT_TRUE(doc);
    ASSERT_EQ(doc->blocks.size(), 2u);
    EXPECT_EQ(doc->blocks[0].text(), "Ge1:1 In the beginning.");
    EXPECT_EQ(doc->blocks[1].text(), "Ge1:2 And the earth.");
    EXPECT_EQ(doc->blocks[1].source_line, 2);
    // One blank line anywhere between text switches to blank-line paragraphs.
    const auto wrapped = import::import_bytes("a\nb\n\nc\n", "x.txt");
    ASSERT_TRUE(wrapped);
    EXPECT_EQ(wrapped->blocks.size(), 2u);
}

TEST(TextImport, FormFeedInsideALineSplitsTheParagraphAndPagesAreNumbered) {
    const auto doc = import::import_bytes("one\ftwo\n\fthree\n", "x.txt");
    ASSERT_TRUE(doc);
    const std::vector<document::Block> expected = {
        text_block(P, 0, {{"one"}}, 1), page_break("2", 1), text_block(P, 0, {{"two"}}, 1),
        page_break("3", 2), text_block(P, 0, {{"three"}}, 2)};
    EXPECT_EQ(doc->blocks, expected);
}

// Before any content an unlabelled break would only add an empty page; after
// all of it a break is kept, so saving and reopening loses none.
TEST(TextImport, PageBreaksBeforeAllContentAreDroppedAndAfterItKept) {
    const auto doc = import::import_bytes("\f\fbody\n\f\n\f", "x.txt");
    ASSERT_TRUE(doc);
    ASSERT_EQ(doc->blocks.size(), 3u);
    EXPECT_EQ(doc->blocks[0].text(), "body");
    EXPECT_EQ(doc->blocks[1], page_break("2", 2));
    EXPECT_EQ(doc->blocks[2], page_break("3", 3));
}

// A paragraph's spaces at its ends are kept as written: a .txt is verbatim
// (braille leaves them out, the translator's rule).
TEST(TextImport, WhitespaceOnlyLinesSeparateParagraphsAndEdgeSpacesAreKept) {
    const auto doc = import::import_bytes("   first\t \n  \t \n\tsecond  \n", "x.txt");
    ASSERT_TRUE(doc);
    ASSERT_EQ(doc->blocks.size(), 2u);
    EXPECT_EQ(doc->blocks[0].text(), "   first\t ");
    EXPECT_EQ(doc->blocks[1].text(), "\tsecond  ");
}

TEST(TextImport, EmptyInputIsAnEmptyDocument) {
    for (const std::string_view input : {"", "\xEF\xBB\xBF", "\n\n  \n", "\f"}) {
        const auto doc = import::import_bytes(input, "empty.txt");
        ASSERT_TRUE(doc) << doc.error().to_string();
        EXPECT_TRUE(doc->blocks.empty());
    }
}

TEST(TextImport, NulBytesAreRejectedWithTheirOffset) {
    const auto doc = import::import_file(import_data("junk.bin"), {import::SourceFormat::text, {}});
    ASSERT_FALSE(doc);
    EXPECT_THAT(doc.error().message, testing::HasSubstr("not text: NUL byte"));
    const auto junk = read_data("junk.bin");
    const auto nul = junk.find('\0');
    EXPECT_EQ(doc.error().where, import_data("junk.bin").string() + ":byte " + std::to_string(nul));
}

TEST(TextImport, ControlCharactersAreRejectedWithLineAndColumn) {
    const auto doc = import::import_bytes("fine\nab\x01" "c\n", "ctl.txt");
    ASSERT_FALSE(doc);
    EXPECT_EQ(doc.error().where, "ctl.txt:2:3");
    EXPECT_THAT(doc.error().message, testing::HasSubstr("U+0001"));
}

TEST(TextImport, ManyTinyParagraphsStayCorrect) {
    std::string input;
    for (int i = 0; i < 10000; ++i) input += "p" + std::to_string(i) + "\n\n";
    const auto doc = import::import_bytes(input, "many.txt");
    ASSERT_TRUE(doc);
    ASSERT_EQ(doc->blocks.size(), 10000u);
    EXPECT_EQ(doc->blocks[9999].text(), "p9999");
    EXPECT_EQ(doc->blocks[9999].source_line, 19999);
}

TEST(TextImport, FileAboveTheSizeLimitIsRefusedBeforeReading) {
    // A sparse file: its size is above the limit but it occupies no disk space.
    const auto path = std::filesystem::temp_directory_path() /
                      ("tactus_import_huge_" + std::to_string(::getpid()) + ".txt");
    { std::ofstream(path).put('a'); }
    std::filesystem::resize_file(path, import::max_import_bytes + 1);
    const auto doc = import::import_file(path);
    std::filesystem::remove(path);
    ASSERT_FALSE(doc);
    EXPECT_THAT(doc.error().message, testing::HasSubstr("above the limit"));
    EXPECT_EQ(doc.error().where, path.string());
}

}  // namespace
}  // namespace tactus::test
