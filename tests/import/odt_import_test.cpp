// SPDX-License-Identifier: GPL-3.0-or-later
#include "import_test_util.hpp"

namespace tactus::test {
namespace {

using namespace shorthand;

// lesson.odt is hand-made (tests/data/import/README.md) with the structure
// LibreOffice writes: automatic text styles, list styles, a page break from a
// paragraph style, soft page breaks, a note, a table.
TEST(OdtImport, TheSameLessonAsTheDocx) {
    const auto doc = import_data_file("lesson.odt");
    const std::vector<document::Block> expected = {
        text_block(H, 1, {{"Weather Lesson"}}),
        text_block(P, 0,
                   {{"Today we learn about "}, {"clouds", B}, {" and "}, {"rain", I}, {", and the "},
                    {"water cycle", U}, {"."}}),
        text_block(H, 2, {{"Kinds of clouds"}}),  // heading style bold is not emphasis
        text_block(LI, 1, {{"\u2022 Cumulus"}}),  // a bullet level: the bullet sign
        text_block(LI, 1, {{"\u2022 Stratus"}}),
        text_block(LI, 2, {{"\u2022 Nimbostratus"}}),
        text_block(LI, 1, {{"1. Look at the sky."}}),  // numbered: the label is text
        text_block(LI, 1, {{"2. Write what you see."}}),
        page_break("2"),  // fo:break-before="page"; the soft page break is none
        text_block(P, 0, {{"今天的天气很好，我们一起去公园散步吧。"}}),
        // A text style inherits its parent's bold; the note's reference is in
        // the text and the note follows the paragraph.
        text_block(P, 0, {{"Plain "}, {"bold italic", B | I}, {" end.\tTab\nand   spaces"}, reference("1"), {"."}}),
        text_block(N, 0, {reference("1"), {" A note"}}),
        table_row(false),
        text_block(C, 0, {{"Cloud"}}),
        text_block(C, 1, {{"雲"}}),
    };
    EXPECT_EQ(doc.blocks, expected);
}

TEST(OdtImport, DetectedByExtensionAndContent) {
    const auto bytes = read_data("lesson.odt");
    EXPECT_EQ(import::detect_source_format(bytes, "lesson.odt"), import::SourceFormat::odt);
    EXPECT_EQ(import::detect_source_format(bytes, "no-extension"), import::SourceFormat::odt);
    EXPECT_EQ(import::parse_source_format("ODT").value(), import::SourceFormat::odt);
}

TEST(OdtImport, AMissingContentPartIsNamed) {
    const auto e = import_data_file_error("no_content.odt");
    EXPECT_NE(e.message.find("missing part content.xml"), std::string::npos) << e.to_string();
    EXPECT_NE(e.where.find("no_content.odt"), std::string::npos) << e.to_string();
}

TEST(OdtImport, AnotherOpenDocumentKindIsRefused) {
    // A spreadsheet saved under an .odt name: its mimetype entry says so.
    const auto e = import_data_file_error("spreadsheet.odt");
    EXPECT_NE(e.message.find("not an OpenDocument text but application/vnd.oasis.opendocument.spreadsheet"),
              std::string::npos)
        << e.to_string();
}

}  // namespace
}  // namespace tactus::test
