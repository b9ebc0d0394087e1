// SPDX-License-Identifier: GPL-3.0-or-later
#include "import_test_util.hpp"

namespace tactus::test {
namespace {

const auto BR = document::BlockKind::braille;
const auto BREAK = document::BlockKind::braille_page_break;

std::vector<std::string> unicode_lines(const document::Block& b) {
    std::vector<std::string> out;
    for (const auto& line : b.braille_lines) out.push_back(document::to_unicode_text(line));
    return out;
}

TEST(PefImport, PagesOfAllSectionsBecomeBrailleBlocks) {
    const auto doc = import_data_file("lesson.pef");
    ASSERT_EQ(kinds(doc), (std::vector<document::BlockKind>{BR, BREAK, BR, BREAK, BR, BREAK, BR}));
    EXPECT_EQ(unicode_lines(doc.blocks[0]), (std::vector<std::string>{"⠠⠺⠑⠁⠮⠗", "", "⠁⠃"}));
    EXPECT_EQ(unicode_lines(doc.blocks[2]), std::vector<std::string>{"⠼⠃"});
    EXPECT_TRUE(doc.blocks[4].braille_lines.empty());  // <page/>: a blank page
    // Eight-dot cells survive: U+28FF is all eight dots.
    ASSERT_EQ(doc.blocks[6].braille_lines.size(), 1u);
    EXPECT_EQ(doc.blocks[6].braille_lines[0][0].dots, 0xFF);
    EXPECT_EQ(doc.blocks[0].source_line, 12);
    EXPECT_EQ(doc.blocks[2].source_line, 17);
}

TEST(PefImport, NonBrailleCharacterInARowNamesTheLine) {
    const auto e = import_data_file_error("bad_row.pef");
    EXPECT_THAT(e.message, testing::HasSubstr("row character 2 is U+0042"));
    EXPECT_EQ(e.where, import_data("bad_row.pef").string() + ":18");
}

TEST(PefImport, WrongNamespaceIsRefused) {
    const auto e = import_data_file_error("wrong_namespace.pef");
    EXPECT_THAT(e.message, testing::HasSubstr("not a PEF 2008-1 document"));
    EXPECT_THAT(e.message, testing::HasSubstr("http://example.com/not-pef"));
    EXPECT_EQ(e.where, import_data("wrong_namespace.pef").string() + ":2");
}

TEST(PefImport, InvalidXmlNamesLineAndColumn) {
    const auto e = import_data_file_error("invalid_xml.pef");
    EXPECT_THAT(e.message, testing::HasSubstr("invalid XML"));
    EXPECT_THAT(e.where, testing::MatchesRegex(".*invalid_xml\\.pef:20:[0-9]+"));
}

TEST(PefImport, PrefixedNamespaceIsAccepted) {
    const auto doc = import::import_bytes(
        "<p:pef xmlns:p='http://www.daisy.org/ns/2008/pef' version='2008-1'><p:head/>"
        "<p:body><p:volume cols='2' rows='1' rowgap='0' duplex='false'><p:section><p:page>"
        "<p:row>\u2801</p:row></p:page></p:section></p:volume></p:body></p:pef>",
        "x.pef");
    ASSERT_TRUE(doc) << doc.error().to_string();
    ASSERT_EQ(doc->blocks.size(), 1u);
    EXPECT_EQ(unicode_lines(doc->blocks[0]), std::vector<std::string>{"⠁"});
}

// A row broken over lines and indented, as a pretty-printing XML writer
// leaves it: the white space is layout, the cells are the braille characters.
TEST(PefImport, WhiteSpaceInsideARowIsLayout) {
    const auto doc = import::import_bytes(
        "<pef xmlns='http://www.daisy.org/ns/2008/pef' version='2008-1'><head/>"
        "<body><volume cols='4' rows='2' rowgap='0' duplex='false'><section><page>"
        "<row>\n      \u2801\u2803\n      \u2800\u2809\r\n    </row><row>\t\u2811 </row>"
        "</page></section></volume></body></pef>",
        "pretty.pef");
    ASSERT_TRUE(doc) << doc.error().to_string();
    ASSERT_EQ(doc->blocks.size(), 1u);
    EXPECT_EQ(unicode_lines(doc->blocks[0]), (std::vector<std::string>{"⠁⠃⠀⠉", "⠑"}));
}

TEST(PefImport, MissingBodyAndEmptyInput) {
    const auto nobody = import::import_bytes("<pef xmlns='http://www.daisy.org/ns/2008/pef'/>", "n.pef");
    ASSERT_FALSE(nobody);
    EXPECT_THAT(nobody.error().message, testing::HasSubstr("no <body>"));
    const auto empty = import::import_bytes("", "e.pef");
    ASSERT_FALSE(empty);
    EXPECT_THAT(empty.error().message, testing::HasSubstr("empty file"));
}

}  // namespace
}  // namespace tactus::test
