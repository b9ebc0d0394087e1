// SPDX-License-Identifier: GPL-3.0-or-later
// The editor's line format: every block of every sample survives render -> parse,
// and Markdown-looking print text is escaped rather than reinterpreted.
#include "edit/editor_lines.hpp"

#include <gtest/gtest.h>

#include "../common/edit_fixtures.hpp"
#include "export/text_export.hpp"
#include "import/import.hpp"

using namespace tactus;

TEST(EditorLines, SamplesRoundTrip) {
    for (const std::string file : {"welcome.md", "chinese-tw.txt", "chinese-cn.txt"}) {
        SCOPED_TRACE(file);
        auto doc = import::import_file(test::sample_path(file));
        ASSERT_TRUE(doc.has_value());
        const auto lines = edit::render_editor_lines(*doc);
        // The lines' blocks, their print pages numbered by the one rule.
        const auto parsed = test::document_of(lines).blocks;
        std::vector<document::Block> expected;
        for (auto b : doc->blocks) {
            b.source_line = 0;
            expected.push_back(b);
        }
        ASSERT_EQ(parsed.size(), expected.size());
        for (std::size_t i = 0; i < parsed.size(); ++i) {
            ASSERT_EQ(static_cast<int>(parsed[i].kind), static_cast<int>(expected[i].kind));
            ASSERT_EQ(parsed[i].level, expected[i].level);
            ASSERT_EQ(std::string(parsed[i].text()), std::string(expected[i].text()));
            ASSERT_EQ(parsed[i].label, expected[i].label);
            ASSERT_EQ(parsed[i].label_counted, expected[i].label_counted);
            ASSERT_TRUE(parsed[i].spans == expected[i].spans) << lines[i].c_str();
        }
    }
}

TEST(EditorLines, KindsFromMarks) {
    auto h = edit::parse_editor_line("## Reading tips");
    ASSERT_TRUE(h && h->kind == document::BlockKind::heading && h->level == 2 &&
                h->text() == "Reading tips");
    auto nested = edit::parse_editor_line("  - Beginners");
    ASSERT_TRUE(nested && nested->kind == document::BlockKind::list_item && nested->level == 2);
    auto numbered = edit::parse_editor_line("3. Preview");
    ASSERT_TRUE(numbered && numbered->kind == document::BlockKind::list_item &&
                numbered->text() == "3. Preview");
    auto brk = edit::parse_editor_line("<!-- pagebreak 12 -->");
    ASSERT_TRUE(brk && brk->kind == document::BlockKind::print_page_break && brk->label == "12");
    auto rule = edit::parse_editor_line("---");
    ASSERT_TRUE(rule && rule->kind == document::BlockKind::print_page_break && rule->label.empty());
    ASSERT_TRUE(!edit::parse_editor_line("   "));
    auto emph = edit::parse_editor_line("a **bold** and *italic* word");
    ASSERT_TRUE(emph && emph->spans.size() == 5);
    ASSERT_EQ(int(emph->spans[1].emphasis), int(document::emphasis_bold));
    ASSERT_EQ(int(emph->spans[3].emphasis), int(document::emphasis_italic));
}

TEST(EditorLines, BrailleLinesAreVerbatim) {
    auto b = edit::parse_editor_line("\u2813\u2811\u2800\u2807");
    ASSERT_TRUE(b && b->kind == document::BlockKind::braille);
    ASSERT_EQ(b->braille_lines.size(), std::size_t{1});
    ASSERT_EQ(document::dot_numbers(b->braille_lines[0][0]), std::string("1-2-5"));
    ASSERT_TRUE(b->braille_lines[0][2].blank());
}

TEST(EditorLines, PrintThatLooksLikeMarkdownIsEscaped) {
    for (const std::string text :
         {"# not a heading", "1. not a list", "- not a bullet", "5 * 3 = 15",
          "<!-- pagebreak 3 -->", "a_b_c and \\ backslash", "---"}) {
        document::Block b;
        b.spans = {document::Span{text}};
        const auto line = edit::render_editor_line(b);
        const auto back = edit::parse_editor_line(line);
        ASSERT_TRUE(back.has_value()) << line.c_str();
        ASSERT_EQ(int(back->kind), int(document::BlockKind::paragraph));
        ASSERT_EQ(std::string(back->text()), std::string(text));
    }
}

// Block quotes, notes, note references and bullets are lines of the
// dialect, and survive parse -> render and save -> reopen.
TEST(EditorLines, QuotesNotesAndBulletsRoundTrip) {
    const std::vector<std::string> lines{"Our trip[^1] was long.", "[^1]: It took an *hour*.", "> Quoted *words*.",
                                         "> > Deeper.", "- A bullet", "  - nested", "\\[^2\\] is text"};
    for (const auto& l : lines) {
        const auto b = edit::parse_editor_line(l);
        ASSERT_TRUE(b) << l;
        EXPECT_EQ(edit::render_editor_line(*b), l);
    }
    const auto ref = edit::parse_editor_line(lines[0]);
    ASSERT_GE(ref->spans.size(), 3u);
    EXPECT_TRUE(ref->spans[1].note_reference);
    EXPECT_EQ(ref->text(), "Our trip1 was long.");  // the space after the reference is kept
    const auto note = edit::parse_editor_line(lines[1]);
    EXPECT_EQ(note->kind, document::BlockKind::note);
    EXPECT_TRUE(note->spans.front().note_reference);
    EXPECT_EQ(edit::parse_editor_line(lines[3])->level, 2);
    EXPECT_EQ(edit::parse_editor_line(lines[4])->text(), "\u2022 A bullet");  // as core's importers give it
    EXPECT_FALSE(edit::parse_editor_line(lines[6])->spans.front().note_reference);

    const auto reopened = import::import_bytes(exporter::join_markdown_lines(lines), "saved.md");
    ASSERT_TRUE(reopened.has_value()) << reopened.error().to_string();
    EXPECT_EQ(edit::render_editor_lines(*reopened), lines);
}
