// SPDX-License-Identifier: GPL-3.0-or-later
#include "import_test_util.hpp"

namespace tactus::test {
namespace {

using namespace shorthand;

// lesson.docx was written by LibreOffice 7.4 from lesson.html (both committed).
TEST(DocxImport, DocumentWrittenByLibreOffice) {
    const auto doc = import_data_file("lesson.docx");
    const std::vector<document::Block> expected = {
        text_block(H, 1, {{"Weather Lesson"}}),
        text_block(P, 0,
                   {{"Today we learn about "}, {"clouds", B}, {" and "}, {"rain", I},
                    {", and the "}, {"water cycle", U}, {"."}}),
        text_block(H, 2, {{"Kinds of clouds"}}),
        text_block(LI, 1, {{"\u2022 Cumulus "}}),  // Word's bullet glyph becomes the bullet sign
        text_block(LI, 1, {{"\u2022 Stratus "}}),
        text_block(LI, 2, {{"\u2022 Nimbostratus"}}),
        text_block(LI, 1, {{"1. Look at the sky. "}}),
        text_block(LI, 1, {{"2. Write what you see. "}}),
        page_break("2"),
        text_block(P, 0, {{"今天的天气很好，我们一起去公园散步吧。"}}),
        text_block(H, 3, {{"Summary"}}),
        text_block(P, 0,
                   {{"Plain "}, {"bold italic", B | I}, {" end. A "}, {"strong", B},
                    {" and an "}, {"emphasised", I}, {" word."}}),
        table_row(false),
        text_block(C, 0, {{"Cloud"}}),
        text_block(C, 1, {{"雲"}}),
    };
    EXPECT_EQ(doc.blocks, expected);
    EXPECT_EQ(doc.encoding, "");
}

// features.docx is hand-made (see tests/data/import/README.md) to reach what
// LibreOffice did not write: renamed parts, style chains, numbering formats,
// section breaks, tracked changes.
TEST(DocxImport, StylesNumberingBreaksAndRevisions) {
    const auto doc = import_data_file("features.docx");
    const std::vector<document::Block> expected = {
        text_block(H, 1, {{"The Title"}}),  // bold of the Title style is not emphasis
        text_block(P, 0, {{"Tab\tand\nline kept"}}),  // lastRenderedPageBreak is no break
        text_block(P, 0, {{"styled", I | U}, {"link", B}}),  // a link's underline is print's, not emphasis
        text_block(LI, 1, {{"III. first"}}),
        text_block(LI, 2, {{"III.a) sub"}}),
        page_break("2"),
        text_block(LI, 1, {{"IV. second"}}),
        text_block(P, 0, {{"not a list"}}),
        page_break("3"),
        text_block(P, 0, {{"after break"}}),
        page_break("4"),  // pageBreakBefore from the style
        text_block(H, 1, {{"Chapter"}}),
        text_block(H, 2, {{"Sub"}}),  // continuous section break: no page
        text_block(P, 0, {{"end of section"}}),
        page_break("5"),  // section break (next page) after the paragraph
        text_block(H, 4, {{"Outline four"}}),
    };
    EXPECT_EQ(doc.blocks, expected);
}

TEST(DocxImport, TruncatedZipIsAClearError) {
    const auto e = import_data_file_error("truncated.docx");
    EXPECT_THAT(e.message, testing::HasSubstr("not a valid ZIP package"));
    EXPECT_EQ(e.where, import_data("truncated.docx").string());
}

TEST(DocxImport, MissingDocumentPartIsNamed) {
    const auto e = import_data_file_error("no_document.docx");
    EXPECT_THAT(e.message, testing::HasSubstr("missing part word/document.xml"));
    EXPECT_EQ(e.where, import_data("no_document.docx").string() + ":word/document.xml");
}

TEST(DocxImport, InvalidXmlNamesPartLineAndColumn) {
    const auto e = import_data_file_error("invalid_xml.docx");
    EXPECT_THAT(e.message, testing::HasSubstr("invalid XML"));
    EXPECT_THAT(e.where, testing::MatchesRegex(".*invalid_xml\\.docx:word/document\\.xml:2:[0-9]+"));
}

TEST(DocxImport, EmptyAndNonZipInputsAreErrors) {
    const auto empty = import::import_bytes("", "e.docx");
    ASSERT_FALSE(empty);
    EXPECT_THAT(empty.error().message, testing::HasSubstr("empty file"));
    const auto text = import::import_bytes("just words", "w.docx");
    ASSERT_FALSE(text);
    EXPECT_THAT(text.error().message, testing::HasSubstr("not a valid ZIP"));
}

}  // namespace
}  // namespace tactus::test

// A footnote or endnote nothing refers to (its reference deleted in Word)
// is kept, at the end of the
// document (a notes part gives it no place in the text), numbered on after the
// referenced notes, footnotes before endnotes; Word's separators are not notes.
TEST(DocxImport, NotesNothingRefersToAreKeptAtTheEnd) {
    const auto doc = tactus::test::import_data_file("unreferenced_notes.docx");
    std::string got;
    for (const auto& b : doc.blocks) {
        got += std::to_string(static_cast<int>(b.kind)) + ":";
        for (const auto& s : b.spans) got += s.note_reference ? "[" + s.text + "]" : s.text;
        got += "\n";
    }
    EXPECT_EQ(got,
              "1:Referred[1] here.\n"
              "7:[1] The referred note.\n"
              "1:Last paragraph.\n"
              "7:[2] A footnote whose reference was deleted.\n"
              "7:[3] An endnote nothing refers to.\n");
}

// pandoc's own test file: a link's underline (Word's Hyperlink style) is how
// print shows a link, not emphasis, and braille leaves it out (BANA).
TEST(DocxImport, LinksAreNotUnderlined) {
    const auto doc = tactus::test::import_data_file("pandoc_links.docx");
    std::string text;
    for (const auto& b : doc.blocks)
        for (const auto& s : b.spans) {
            text += s.text;
            EXPECT_EQ(s.emphasis & tactus::document::emphasis_underline, 0) << s.text;
        }
    EXPECT_NE(text.find("external link to a popular website."), std::string::npos) << text;
}
