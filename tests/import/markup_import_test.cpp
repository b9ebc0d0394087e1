// SPDX-License-Identifier: GPL-3.0-or-later
// HTML, EPUB and DTBook: the blocks each gives (docs/import.md "HTML, EPUB and
// DTBook"). The inputs are small hand-made files in tests/data/import/markup
// (the EPUBs written by make_epubs.py there); real books are read in
// book_import_test.cpp.
#include <algorithm>
#include <string>

#include "import_test_util.hpp"

namespace tactus::test {
namespace {

using namespace shorthand;

document::Span lang(std::string text, std::string language, std::uint8_t emphasis = 0) {
    document::Span s{std::move(text), emphasis};
    s.language = std::move(language);
    return s;
}

// Blocks without source lines, for comparing structure.
std::vector<document::Block> without_lines(std::vector<document::Block> blocks) {
    for (auto& b : blocks) b.source_line = 0;
    return blocks;
}

std::string metadata(const document::Document& doc, const std::string& name) {
    for (const auto& m : doc.metadata)
        if (m.name == name) return m.value;
    return {};
}

document::Block cell(int column, std::vector<document::Span> spans, int span = 1) {
    auto b = text_block(C, column, std::move(spans));
    b.span = span;
    return b;
}

TEST(HtmlImport, StructureOfAnHtml5Page) {
    const auto doc = import_data_file("markup/structure.html");
    const std::vector<document::Block> expected = {
        text_block(H, 1, {{"Weather"}}),
        text_block(P, 0, {{"Today we learn about "}, {"clouds", B}, {" and "}, {"rain", I}, {", and the "}, {"water cycle", U}, {"."}}),
        // The reference brings its note (an aside further on) after its paragraph.
        text_block(P, 0, {{"Unclosed paragraph, as HTML allows"}, reference("1"), {"."}}),
        text_block(N, 0, {reference("1"), {" Clouds are water."}}),
        text_block(H, 2, {{"Kinds"}}),
        text_block(LI, 1, {{"\u2022 Cumulus"}}),
        text_block(LI, 1, {{"\u2022 Stratus"}}),
        text_block(LI, 2, {{"\u2022 Nimbostratus"}}),
        text_block(LI, 1, {{"3. Look."}}),
        text_block(LI, 1, {{"4. Write."}}),
        page_break("12", 0, false),
        text_block(document::BlockKind::quote, 1, {{"A quoted line."}}),
        text_block(P, 0, {lang("Il pleut, ", "fr"), lang("pluvia", "la", I), lang(".", "fr")}),
        text_block(P, 0, {{"Clouds"}}),
        table_row(true),
        cell(0, {{"Name"}}),
        cell(1, {{"Height"}}),
        table_row(false),
        cell(0, {{"Cirrus"}}),
        cell(1, {{"High"}}, 2),
        text_block(P, 0, {{"Image: A cumulus cloud over a hill"}}),
        text_block(P, 0, {{"Area: a/2 m."}}),
    };
    EXPECT_EQ(without_lines(doc.blocks), expected);
    EXPECT_EQ(metadata(doc, "title"), "Weather Book");
    EXPECT_EQ(metadata(doc, "creator"), "A. Teacher");
    EXPECT_EQ(metadata(doc, "language"), "en");
    // Left out, and said so: the image without a description, the video.
    ASSERT_EQ(doc.warnings.size(), 2u) << ::testing::PrintToString(doc.warnings);
    EXPECT_THAT(doc.warnings[0], ::testing::HasSubstr("image with no description"));
    EXPECT_THAT(doc.warnings[0], ::testing::StartsWith("21: "));  // its line
    EXPECT_THAT(doc.warnings[1], ::testing::HasSubstr("<video> left out"));
}

// A table cell's paragraphs, list items and <br>s stay apart, a line break
// between them (document/cell_paragraphs.hpp); inline elements and white
// space run on. pandoc's HTML of its own table_with_list_cell.docx.
TEST(HtmlImport, TableCellParagraphsStayApart) {
    const auto doc = import_data_file("public/pandoc-table_with_list_cell.html");
    std::vector<std::string> cells;
    for (const auto& b : doc.blocks)
        if (b.kind == C) cells.push_back(b.text());
    EXPECT_EQ(cells, (std::vector<std::string>{"Cell with text", "Cell with text", "\u2022 Cell with\n\u2022 A\n\u2022 Bullet list",
                                                "1. Cell with\n2. A\n3. Numbered list."}));
    const auto small = import::import_bytes(
        "<table><tr><td><p>One <em>two</em></p><p>three</p></td><td>four<br>five <b>six</b></td>"
        "<td><ol start=\"3\"><li>x</li><li><p>y</p></li></ol></td></tr></table>",
        "cells.html");
    ASSERT_TRUE(small) << small.error().to_string();
    std::vector<std::string> texts;
    for (const auto& b : small->blocks)
        if (b.kind == C) texts.push_back(b.text());
    EXPECT_EQ(texts, (std::vector<std::string>{"One two\nthree", "four\nfive six", "3. x\n4. y"}));
}

TEST(MarkdownImport, BrInAPipeTableCellIsALineBreak) {
    const auto doc = import::import_bytes("| a | b |\n|---|---|\n| one<br>two | x<BR/>*y* |\n", "t.md");
    ASSERT_TRUE(doc) << doc.error().to_string();
    std::vector<std::string> texts;
    for (const auto& b : doc->blocks)
        if (b.kind == C) texts.push_back(b.text());
    EXPECT_EQ(texts, (std::vector<std::string>{"a", "b", "one\ntwo", "x\ny"}));
}

TEST(HtmlImport, BlocksKeepTheirSourceLines) {
    const auto doc = import_data_file("markup/structure.html");
    ASSERT_FALSE(doc.blocks.empty());
    EXPECT_EQ(doc.blocks[0].source_line, 5);  // <h1>Weather</h1>
}

TEST(HtmlImport, NestingDeeperThanTheLimitIsAnErrorNamingWhere) {
    std::string html = "<html><body>";
    for (int i = 0; i < 1000; ++i) html += "<div>";
    html += "deep";
    const auto doc = import::import_bytes(html, "deep.html");
    ASSERT_FALSE(doc);
    EXPECT_THAT(doc.error().message, ::testing::HasSubstr("nested more than"));
    EXPECT_THAT(doc.error().to_string(), ::testing::StartsWith("deep.html"));
    // The same in XHTML, read by the XML parser.
    std::string xhtml = "<html xmlns=\"http://www.w3.org/1999/xhtml\"><body>";
    for (int i = 0; i < 1000; ++i) xhtml += "<span>";
    xhtml += "deep";
    for (int i = 0; i < 1000; ++i) xhtml += "</span>";
    xhtml += "</body></html>";
    const auto x = import::import_bytes(xhtml, "deep.xhtml");
    ASSERT_FALSE(x);
    // Refused by the XML parser's depth limit (common/nesting.hpp), with its
    // line, and not read again as HTML.
    EXPECT_THAT(x.error().to_string(), ::testing::StartsWith("deep.xhtml:1"));
    EXPECT_THAT(x.error().message, ::testing::HasSubstr("nested more than"));
}

TEST(HtmlImport, AMillionOpenTagsAreRefusedBeforeParsing) {
    std::string html(5'000'000, ' ');
    for (std::size_t i = 0; i + 5 <= html.size(); i += 5) html.replace(i, 5, "<div>");
    const auto doc = import::import_bytes(html, "tower.html");
    ASSERT_FALSE(doc);
    EXPECT_THAT(doc.error().message, ::testing::HasSubstr("nested more than"));
}

TEST(EpubImport, Epub3SpineOrderNotesAcrossFilesPagesAndMath) {
    const auto doc = import_data_file("markup/water-cycle.epub");
    const std::vector<document::Block> expected = {
        text_block(H, 2, {{"Evaporation"}}),
        text_block(P, 0, {{"The sun warms the sea"}, reference("1"), {", and water rises."}}),
        // The endnote, from another file, after the paragraph; its back link is not text.
        text_block(N, 0, {reference("1"), {" Mostly the oceans."}}),
        page_break("2", 0, false),
        text_block(P, 0, {{"It rises as "}, {"vapour", I}, {"."}}),
        text_block(H, 2, {{"Rain"}}),
        text_block(P, 0, {{"Drops fall"}, reference("2"), {". A drop weighs r^3 units."}}),
        text_block(N, 0, {reference("2"), {" As rain or snow."}}),
        text_block(P, 0, {lang("Es regnet.", "de")}),
        text_block(H, 2, {{"Endnotes"}}),
    };
    EXPECT_EQ(without_lines(doc.blocks), expected);
    EXPECT_EQ(metadata(doc, "title"), "The Water Cycle");
    EXPECT_EQ(metadata(doc, "creator"), "C. Author");
    EXPECT_EQ(metadata(doc, "publisher"), "Tactus Test Press");
    EXPECT_EQ(metadata(doc, "date"), "2024");
    ASSERT_EQ(doc.warnings.size(), 1u) << ::testing::PrintToString(doc.warnings);
    EXPECT_THAT(doc.warnings[0], ::testing::HasSubstr("OEBPS/images/sun.png: a spine item of type image/png left out"));
}

TEST(EpubImport, Epub2WithHtmlThatIsNotXml) {
    const auto doc = import_data_file("markup/snow-epub2.epub");
    const std::vector<document::Block> expected = {
        text_block(H, 1, {{"Snow"}}),
        text_block(P, 0, {{"Snow\u00a0falls in winter."}}),
        text_block(P, 0, {{"It is cold."}}),
    };
    EXPECT_EQ(without_lines(doc.blocks), expected);
    EXPECT_EQ(metadata(doc, "creator"), "D. Author");
}

TEST(EpubImport, BrokenPackagesAreClearErrors) {
    EXPECT_THAT(import::import_bytes("PK\x03\x04junk", "x.epub").error().message, ::testing::HasSubstr("not an EPUB"));
    // A DOCX is a ZIP without META-INF/container.xml.
    const auto docx = read_data("lesson.docx");
    const auto e = import::import_bytes(docx, "lesson.epub");
    ASSERT_FALSE(e);
    EXPECT_THAT(e.error().to_string(), ::testing::HasSubstr("missing part META-INF/container.xml"));
    EXPECT_FALSE(import::import_bytes("", "x.epub"));
}

TEST(DtbookImport, LevelsPagesNotesAndImages) {
    const auto doc = import_data_file("markup/book.dtbook.xml");
    const std::vector<document::Block> expected = {
        text_block(H, 1, {{"Rivers"}}),  // doctitle
        text_block(P, 0, {{"B. Writer"}}),
        // Page 1 before any text starts the numbering, as a label does.
        page_break("1", 0, false),
        text_block(H, 1, {{"Rivers"}}),
        text_block(P, 0, {{"A river runs"}, reference("1"), {" to the "}, {"sea", I}, {"."}}),
        text_block(N, 0, {reference("1"), {" Or flows."}}),
        text_block(H, 2, {{"Long rivers"}}),
        text_block(LI, 1, {{"1. Nile"}}),
        text_block(LI, 1, {{"2. Amazon"}}),
        page_break("2", 0, false),
        text_block(H, 3, {{"Deltas"}}),  // <hd> in a level3
        text_block(P, 0, {{"Deltas "}, {"grow", B}, {"."}}),
        text_block(P, 0, {{"Image: A river delta from above"}}),
        text_block(P, 0, {{"The delta"}}),
        text_block(H, 1, {{"Notes"}}),
    };
    EXPECT_EQ(without_lines(doc.blocks), expected);
    EXPECT_EQ(metadata(doc, "title"), "Rivers");
    EXPECT_EQ(metadata(doc, "publisher"), "School Press");
    EXPECT_TRUE(doc.warnings.empty()) << ::testing::PrintToString(doc.warnings);
}

TEST(DtbookImport, AnotherXmlRootIsNotDtbook) {
    const auto e = import::import_bytes("<?xml version=\"1.0\"?><book/>", "x.xml", {import::SourceFormat::dtbook, {}});
    ASSERT_FALSE(e);
    EXPECT_THAT(e.error().message, ::testing::HasSubstr("not a DTBook document"));
}

TEST(MarkupFormats, DetectedByExtensionAndContent) {
    using import::SourceFormat;
    EXPECT_EQ(import::detect_source_format("", "a.html"), SourceFormat::html);
    EXPECT_EQ(import::detect_source_format("", "a.XHTML"), SourceFormat::html);
    EXPECT_EQ(import::detect_source_format("", "a.epub"), SourceFormat::epub);
    const auto dtbook = read_data("markup/book.dtbook.xml");
    EXPECT_EQ(import::detect_source_format(dtbook, "book.xml"), SourceFormat::dtbook);
    EXPECT_EQ(import::detect_source_format("<!DOCTYPE html>\n<!-- x --><html><p>x", "page"), SourceFormat::html);
    EXPECT_EQ(import::detect_source_format(read_data("markup/water-cycle.epub"), "book"), SourceFormat::epub);
    EXPECT_EQ(import::parse_source_format("epub").value(), SourceFormat::epub);
    EXPECT_EQ(import::parse_source_format("dtbook").value(), SourceFormat::dtbook);
    EXPECT_EQ(import::parse_source_format("htm").value(), SourceFormat::html);
}

}  // namespace
}  // namespace tactus::test
