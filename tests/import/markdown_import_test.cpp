// SPDX-License-Identifier: GPL-3.0-or-later
#include "import_test_util.hpp"

#include "document/print_page.hpp"

namespace tactus::test {
namespace {

using namespace shorthand;

document::Document md(std::string_view text) {
    auto doc = import::import_bytes(text, "t.md");
    EXPECT_TRUE(doc) << (doc ? "" : doc.error().to_string());
    return doc.value_or(document::Document{});
}

TEST(MarkdownImport, LessonFileGivesTheExpectedBlocks) {
    const auto doc = import_data_file("lesson.md");
    const std::vector<document::Block> expected = {
        text_block(H, 1, {{"Weather Lesson"}}, 1),
        text_block(P, 0,
                   {{"Today we learn about "}, {"clouds", B}, {" and "}, {"rain", I},
                    {", and the water cycle & more."}},
                   3),
        text_block(H, 2, {{"Kinds of clouds"}}, 6),
        // Bullets are kept as the bullet sign (BANA keeps print's bullets).
        text_block(LI, 1, {{"\u2022 Cumulus"}}, 8),
        text_block(LI, 1, {{"\u2022 Stratus"}}, 9),
        text_block(LI, 2, {{"\u2022 Nimbostratus"}}, 10),
        text_block(LI, 3, {{"1. Low"}}, 11),
        text_block(LI, 3, {{"2. Grey"}}, 12),
        text_block(LI, 1, {{"3. Look at the sky."}}, 14),
        text_block(LI, 1, {{"4. Write what you see."}}, 15),
        page_break("2", 17),
        text_block(P, 0, {{"今天的天气很好。"}}, 19),
        page_break("3", 0),
        text_block(H, 3, {{"Summary"}}, 23),
        text_block(P, 0, {{"Plain "}, {"bold italic", B | I}, {" end."}}, 25),
    };
    EXPECT_EQ(doc.blocks, expected);
    EXPECT_EQ(doc.encoding, "UTF-8");
}

TEST(MarkdownImport, PageBreakCommentMayCarryThePrintedLabel) {
    const auto doc = md("one\n\n<!-- pagebreak: xii -->\n\ntwo\n\n<!-- just a note -->\n\nthree\n");
    const std::vector<document::Block> expected = {text_block(P, 0, {{"one"}}, 1), page_break("xii", 3, false),
                                         text_block(P, 0, {{"two"}}, 5),
                                         text_block(P, 0, {{"three"}}, 9)};
    EXPECT_EQ(doc.blocks, expected);
}

// "---" after <!-- pagebreak 10 --> is page 11, as the editor
// numbers it (one rule: document/print_page.hpp), not the importer's own count 3.
TEST(MarkdownImport, AnUnlabelledBreakCountsOnFromTheLabelBeforeIt) {
    const auto doc = md("one\n\n---\n\ntwo\n\n<!-- pagebreak 10 -->\n\nthree\n\n---\n\nfour\n\n"
                        "<!-- pagebreak xii -->\n\nfive\n\n---\n\nsix\n\n<!-- pagebreak Preface -->\n\nseven\n\n---\n\neight\n");
    std::vector<std::string> labels;
    for (const auto& b : doc.blocks)
        if (b.kind == document::BlockKind::print_page_break) labels.push_back(b.label);
    EXPECT_EQ(labels, (std::vector<std::string>{"2", "10", "11", "xii", "xiii", "Preface", ""}));
}

// A labelled break before any text says where the print pages start: it is kept
// (an unlabelled one would only add an empty page and is dropped).
TEST(MarkdownImport, ALabelledBreakBeforeTheTextSetsTheFirstPrintPage) {
    const auto doc = md("---\n\n<!-- pagebreak 10 -->\n\none\n\n---\n\ntwo\n");
    ASSERT_EQ(doc.blocks.size(), 4u);
    EXPECT_EQ(doc.blocks[0], page_break("10", 3, false));
    EXPECT_EQ(doc.blocks[2].label, "11");
}

TEST(PrintPage, NextPageByTheOneRule) {
    EXPECT_EQ(document::next_print_page("1"), "2");
    EXPECT_EQ(document::next_print_page("9"), "10");
    EXPECT_EQ(document::next_print_page("099"), "100");
    EXPECT_EQ(document::next_print_page("A-9"), "A-10");
    EXPECT_EQ(document::next_print_page("iv"), "v");
    EXPECT_EQ(document::next_print_page("XIX"), "XX");
    EXPECT_EQ(document::next_print_page("iiii"), "");
    EXPECT_EQ(document::next_print_page("Preface"), "");
    EXPECT_EQ(document::next_print_page(""), "");
    EXPECT_EQ(document::print_page_label("7", "3"), "7");
    EXPECT_EQ(document::print_page_label("", "3"), "4");
}

// The editor saves a forced braille page (e.g. a BRF form feed) as this comment.
TEST(MarkdownImport, BraillePageCommentIsABraillePageBreak) {
    const auto doc = md("one\n\n<!-- braillepage -->\n\ntwo\n");
    ASSERT_EQ(doc.blocks.size(), 3u);
    EXPECT_EQ(doc.blocks[1].kind, document::BlockKind::braille_page_break);
    EXPECT_EQ(doc.blocks[1].source_line, 3);
    EXPECT_EQ(doc.blocks[2].text(), "two");
}

TEST(MarkdownImport, FormFeedIsAPrintPageBreakAndLinesStayRight) {
    const auto doc = md("# A\n\nbefore\n\f\nafter\n");
    const std::vector<document::Block> expected = {text_block(H, 1, {{"A"}}, 1),
                                         text_block(P, 0, {{"before"}}, 3), page_break("2", 4),
                                         text_block(P, 0, {{"after"}}, 5)};
    EXPECT_EQ(doc.blocks, expected);
}

TEST(MarkdownImport, CodeBlockLinesArePlainParagraphs) {
    const auto doc = md("```\nint x = 1;\n\n  return *x;\n```\n");
    ASSERT_EQ(doc.blocks.size(), 2u);
    EXPECT_EQ(doc.blocks[0].text(), "int x = 1;");
    EXPECT_EQ(doc.blocks[1].text(), "  return *x;");
    EXPECT_EQ(doc.blocks[1].spans[0].emphasis, document::emphasis_none);
}

TEST(MarkdownImport, LooseListItemsWithSeveralParagraphsAndHardBreaks) {
    const auto doc = md("1. first\n\n   more of first\n2. second  \n   line two\n");
    const std::vector<document::Block> expected = {text_block(LI, 1, {{"1. first"}}, 1),
                                         text_block(LI, 1, {{"more of first"}}, 3),
                                         text_block(LI, 1, {{"2. second\nline two"}}, 4)};
    EXPECT_EQ(doc.blocks, expected);
}

TEST(MarkdownImport, EntitiesLinksImagesAndInlineHtml) {
    const auto doc = md("&eacute;&#233;&#x41;&copy; [site](http://x.org) ![a cat](c.png) <b>tag</b>\n");
    ASSERT_EQ(doc.blocks.size(), 1u);
    // &eacute; is not in the known set: kept literally rather than lost.
    EXPECT_EQ(doc.blocks[0].text(), "&eacute;éA© site a cat tag");
}

TEST(MarkdownImport, HtmlBlockKeepsItsTextWithoutTags) {
    const auto doc = md("<div class=\"x\">\nInside <em>div</em>\n</div>\n");
    ASSERT_EQ(doc.blocks.size(), 1u);
    EXPECT_EQ(doc.blocks[0].text(), "Inside div");
}

TEST(MarkdownImport, SetextHeadingIsNotAPageBreak) {
    const auto doc = md("Title\n-----\n\ntext\n");
    ASSERT_EQ(doc.blocks.size(), 2u);
    EXPECT_EQ(doc.blocks[0].kind, H);
    EXPECT_EQ(doc.blocks[0].level, 2);
}

TEST(MarkdownImport, LegacyEncodedMarkdownIsDecodedFirst) {
    // "# 標題" in Big5, with the encoding named.
    const auto doc = import::import_bytes("# \xBC\xD0\xC3\x44\n", "b.md", {import::SourceFormat::automatic, "Big5"});
    ASSERT_TRUE(doc) << doc.error().to_string();
    ASSERT_EQ(doc->blocks.size(), 1u);
    EXPECT_EQ(doc->blocks[0].text(), "標題");
    EXPECT_EQ(doc->encoding, "Big5");
}

}  // namespace
}  // namespace tactus::test

// YAML front matter (pandoc, Jekyll) is the document's metadata, not a heading
// and a paragraph; the text after it keeps its line numbers.
TEST(MarkdownImport, YamlFrontMatterIsMetadata) {
    const auto doc = tactus::import::import_bytes("---\n"
                                                  "title: \"Photosynthesis\"\n"
                                                  "author:\n"
                                                  "  - Ms. Lin\n"
                                                  "  - Mr. Chen\n"
                                                  "date: 2024-09-01\n"
                                                  "tags: [biology]\n"
                                                  "---\n"
                                                  "# Light\n"
                                                  "\n"
                                                  "Plants use light.\n",
                                                  "lesson.md");
    ASSERT_TRUE(doc) << doc.error().to_string();
    ASSERT_EQ(doc->blocks.size(), 2u);
    EXPECT_EQ(doc->blocks[0].kind, tactus::document::BlockKind::heading);
    EXPECT_EQ(doc->blocks[0].spans.at(0).text, "Light");
    EXPECT_EQ(doc->blocks[0].source_line, 9);
    EXPECT_EQ(doc->blocks[1].source_line, 11);
    EXPECT_EQ(doc->metadata, (std::vector<tactus::document::MetadataItem>{{"title", "Photosynthesis"},
                                                                          {"creator", "Ms. Lin"},
                                                                          {"creator", "Mr. Chen"},
                                                                          {"date", "2024-09-01"}}));
    // A rule at the top followed by Markdown is not front matter.
    const auto rule = tactus::import::import_bytes("---\nJust text.\n\n---\n", "rule.md");
    ASSERT_TRUE(rule);
    EXPECT_TRUE(rule->metadata.empty());
    EXPECT_FALSE(rule->blocks.empty());
}
