// SPDX-License-Identifier: GPL-3.0-or-later
#include "import_test_util.hpp"

namespace tactus::test {
namespace {

std::vector<std::string> unicode_lines(const document::Block& b) {
    std::vector<std::string> out;
    for (const auto& line : b.braille_lines) out.push_back(document::to_unicode_text(line));
    return out;
}

TEST(BrfImport, PagesBecomeBrailleBlocksSeparatedByBraillePageBreaks) {
    const auto doc = import_data_file("lesson.brf");
    ASSERT_EQ(kinds(doc), (std::vector<document::BlockKind>{document::BlockKind::braille, document::BlockKind::braille_page_break,
                                                  document::BlockKind::braille}));
    // ",WEA!R ,LES/N" etc. in Braille ASCII; the blank line is kept as a line.
    EXPECT_EQ(unicode_lines(doc.blocks[0]),
              (std::vector<std::string>{"⠠⠺⠑⠁⠮⠗⠀⠠⠇⠑⠎⠌⠝", "", "⠠⠞⠕⠙⠐⠁⠀⠺⠑⠀⠇⠜⠝"}));
    EXPECT_EQ(unicode_lines(doc.blocks[2]), (std::vector<std::string>{"⠠⠏⠁⠛⠑⠀⠼⠃", "⠁⠃⠀⠉⠙"}));
    EXPECT_EQ(doc.blocks[0].source_line, 1);
    EXPECT_EQ(doc.blocks[1].source_line, 4);
    EXPECT_EQ(doc.blocks[2].source_line, 4);  // the form feed starts line 4
}

TEST(BrfImport, LfAndCrLfGiveTheSameBraille) {
    const auto lf = import::import_bytes("AB\nCD\n\fEF\n", "a.brf");
    const auto crlf = import::import_bytes("AB\r\nCD\r\n\f\r\nEF\r\n", "a.brf");
    ASSERT_TRUE(lf && crlf);
    ASSERT_EQ(lf->blocks.size(), 3u);
    ASSERT_EQ(crlf->blocks.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(lf->blocks[i].braille_lines, crlf->blocks[i].braille_lines) << i;
}

TEST(BrfImport, LowerCaseMapsLikeUpperCase) {
    const auto upper = import::import_bytes("ABC{|}~`\n", "u.brf");
    const auto lower = import::import_bytes("abc[\\]^@\n", "l.brf");
    ASSERT_TRUE(upper && lower);
    EXPECT_EQ(upper->blocks, lower->blocks);
}

TEST(BrfImport, FormFeedAtEndOfLineAndBlankPages) {
    // "A\f" ends page 1; the second form feed makes page 2 blank.
    const auto doc = import::import_bytes("A\f\fB", "p.brf");
    ASSERT_TRUE(doc);
    ASSERT_EQ(doc->blocks.size(), 5u);
    EXPECT_EQ(doc->blocks[2].kind, document::BlockKind::braille);
    EXPECT_TRUE(doc->blocks[2].braille_lines.empty());
    EXPECT_EQ(unicode_lines(doc->blocks[4]), std::vector<std::string>{"⠃"});
}

TEST(BrfImport, CharacterOutsideBrailleAsciiNamesLineAndColumn) {
    const auto e = import_data_file_error("bad_char.brf");
    EXPECT_THAT(e.message, testing::HasSubstr("byte 0x09 is not Braille ASCII"));
    EXPECT_EQ(e.where, import_data("bad_char.brf").string() + ":2:4");
    const auto utf8 = import::import_bytes("AB\nC\xC3\xA9\n", "u.brf");
    ASSERT_FALSE(utf8);
    EXPECT_EQ(utf8.error().where, "u.brf:2:2");
}

TEST(BrfImport, EmptyFileAndDosEofMarker) {
    const auto empty = import::import_bytes("", "e.brf");
    ASSERT_TRUE(empty);
    EXPECT_TRUE(empty->blocks.empty());
    const auto dos = import::import_bytes("AB\r\n\x1A", "d.brf");
    ASSERT_TRUE(dos) << dos.error().to_string();
    ASSERT_EQ(dos->blocks.size(), 1u);
    EXPECT_EQ(dos->blocks[0].braille_lines.size(), 1u);
}

}  // namespace
}  // namespace tactus::test
