// SPDX-License-Identifier: GPL-3.0-or-later
// A word-processor file opened in the editor is shown as editor lines and
// saved from them: every construct the file's model holds (underline, raised
// and lowered text, boxes, a passage's language) must come back from the lines
// as it went in, for real files nobody here wrote (pandoc's, python-docx's,
// LibreOffice's) and for a document of every construct.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <sstream>

#include "../common/edit_fixtures.hpp"
#include "../common/office_files.hpp"
#include "document/soft_break.hpp"
#include "edit/editor_lines.hpp"
#include "edit/live_layout.hpp"
#include "export/office_export.hpp"
#include "import/import.hpp"
#include "pipeline/pipeline.hpp"

using namespace tactus;

namespace office_lines {

const std::filesystem::path data = TACTUS_TEST_DATA;

// Every field of the blocks but their source line, one block a line, so a
// difference reads as a diff.
std::string dump(const std::vector<document::Block>& blocks) {
    std::ostringstream o;
    for (const auto& b : blocks) {
        o << static_cast<int>(b.kind) << " level=" << b.level << " span=" << b.span << " align="
          << static_cast<int>(b.align) << " box=" << b.box << " label=" << b.label << (b.label_counted ? "+" : "")
          << " braille=" << b.braille_lines.size() << " images=" << b.images.size() << " [";
        for (const auto& s : b.spans)
            o << "('" << s.text << "' e" << int{s.emphasis} << " p" << static_cast<int>(s.position)
              << (s.note_reference ? " ref" : "") << (s.transcriber_note ? " tn" : "") << " " << s.language << ")";
        o << "]\n";
    }
    return o.str();
}

std::vector<document::Block> without_lines(std::vector<document::Block> blocks) {
    for (auto& b : blocks) b.source_line = 0;
    return blocks;
}

constexpr std::string_view kBullet = "\u2022 ";

bool marked_item(const document::Block& b) {
    if (b.spans.empty() || b.spans.front().note_reference) return false;
    const auto& t = b.spans.front().text;
    std::size_t digits = 0;
    while (digits < t.size() && digits < 9 && t[digits] >= '0' && t[digits] <= '9') ++digits;
    return t.starts_with(kBullet) ||
           (digits > 0 && digits + 1 < t.size() && (t[digits] == '.' || t[digits] == ')') && t[digits + 1] == ' ');
}

// The blocks as a line of the editor can hold them. What a line cannot say is
// named here, each with the warning a save to Markdown gives or the rule it
// follows; everything else must come back as it went in:
// - a soft line break inside a paragraph or cell is a space: one block, one
//   line (exporter::markdown_line);
// - spaces at a block's ends are no text, and a space at the edge of a bold or
//   italic run is plain (CommonMark: emphasis marks touch their words);
// - an image's description is plain text ("an image's description is written
//   as plain text", exporter::save_document);
// - a list item whose text starts with neither a bullet nor a number ("IV.
//   second", a Roman numeral) gets the bullet: every Markdown item has a mark
//   ("a list item without a bullet or number is written with a bullet");
// - a merged table cell is its columns, the first with the text ("a merged
//   cell is written as its columns"), and a row has as many cells as its
//   table's widest (empty ones at a row's end are left out here, on both sides);
// - a list item's label alone in a span before a passage in another language
//   ("• " then "text" in en-US) is in the passage's span: the line
//   "- <span lang=...>text</span>" gives the label to the text after it;
// - spans alike in every attribute are one span.
std::vector<document::Block> as_lines_hold(std::vector<document::Block> blocks) {
    std::vector<document::Block> cells_split;
    for (auto& b : blocks) {
        const int span = b.kind == document::BlockKind::table_cell ? b.span : 1;
        b.span = 1;
        cells_split.push_back(b);
        for (int c = 1; c < span; ++c) {
            document::Block empty;
            empty.kind = document::BlockKind::table_cell;
            empty.level = b.level + c;
            empty.align = b.align;
            empty.box = b.box;
            cells_split.push_back(std::move(empty));
        }
    }
    blocks.clear();
    for (std::size_t i = 0; i < cells_split.size(); ++i) {
        const auto& b = cells_split[i];
        if (b.kind == document::BlockKind::table_cell && b.spans.empty()) {
            auto j = i;
            while (j < cells_split.size() && cells_split[j].kind == document::BlockKind::table_cell &&
                   cells_split[j].spans.empty())
                ++j;
            if (j == cells_split.size() || cells_split[j].kind != document::BlockKind::table_cell) {
                i = j - 1;
                continue;
            }
        }
        blocks.push_back(b);
    }
    for (auto& b : blocks) {
        if (b.kind == document::BlockKind::list_item && !marked_item(b)) {
            if (!b.spans.empty() && !b.spans.front().note_reference && b.spans.front().emphasis == 0 &&
                b.spans.front().position == document::Position::baseline && b.spans.front().language.empty())
                b.spans.front().text.insert(0, kBullet);
            else
                b.spans.insert(b.spans.begin(), document::Span{std::string(kBullet)});
        }
        std::vector<document::Span> spans;
        for (auto s : b.spans) {
            s.text = document::soft_breaks_as_spaces(s.text);
            s.transcriber_note = false;
            // Split off the spaces at a bold or italic run's edges as plain.
            const auto plain_bits = static_cast<std::uint8_t>(document::emphasis_bold | document::emphasis_italic);
            std::vector<document::Span> pieces{s};
            if (!s.note_reference && (s.emphasis & plain_bits)) {
                const auto first = s.text.find_first_not_of(' ');
                if (first == std::string::npos) {
                    pieces.front().emphasis = static_cast<std::uint8_t>(s.emphasis & ~plain_bits);
                } else {
                    const auto last = s.text.find_last_not_of(' ');
                    auto lead = s, core = s, tail = s;
                    lead.text = s.text.substr(0, first);
                    lead.emphasis = static_cast<std::uint8_t>(s.emphasis & ~plain_bits);
                    core.text = s.text.substr(first, last + 1 - first);
                    tail.text = s.text.substr(last + 1);
                    tail.emphasis = lead.emphasis;
                    pieces = {lead, core, tail};
                }
            }
            for (auto& p : pieces) {
                if (p.text.empty() && !p.note_reference) continue;
                auto& back = spans;
                if (!back.empty() && !back.back().note_reference && !p.note_reference &&
                    back.back().emphasis == p.emphasis && back.back().position == p.position &&
                    back.back().language == p.language)
                    back.back().text += p.text;
                else
                    back.push_back(std::move(p));
            }
        }
        if (b.kind == document::BlockKind::list_item && spans.size() >= 2 && marked_item(b) &&
            spans[0].language.empty() && !spans[1].language.empty() && !spans[1].note_reference &&
            spans[0].emphasis == spans[1].emphasis && spans[0].position == spans[1].position &&
            (spans[0].text == kBullet || spans[0].text.find_first_not_of("0123456789.) ") == std::string::npos)) {
            spans[1].text.insert(0, spans[0].text);
            spans.erase(spans.begin());
        }
        // Spaces at the block's ends.
        if (!spans.empty() && !spans.front().note_reference) {
            auto& t = spans.front().text;
            t.erase(0, std::min(t.size(), t.find_first_not_of(' ')));
            if (t.empty()) spans.erase(spans.begin());
        }
        if (!spans.empty() && !spans.back().note_reference) {
            auto& t = spans.back().text;
            t.erase(std::min(t.size(), t.find_last_not_of(' ') + 1));
            if (t.empty()) spans.pop_back();
        }
        b.spans = std::move(spans);
        b.images.clear();
    }
    return without_lines(std::move(blocks));
}

// The document as the editor holds it: its lines, laid out, and the blocks
// the lines stand for (what Save writes).
document::Document through_lines(const document::Document& doc) {
    auto layout = test::live_layout(edit::render_editor_lines(doc), "en-ueb-g1.ctb");
    return layout.document();
}

}  // namespace office_lines

TEST(OfficeLines, RealOfficeFilesComeBackFromTheEditorLines) {
    int files = 0;
    for (const auto& path : test::real_office_files(office_lines::data)) {
        auto doc = import::import_file(path);
        if (!doc) continue;  // the importer's own error files (truncated, invalid XML)
        ++files;
        SCOPED_TRACE(path.filename().string());
        const auto back = office_lines::through_lines(*doc);
        EXPECT_EQ(office_lines::dump(office_lines::as_lines_hold(back.blocks)),
                  office_lines::dump(office_lines::as_lines_hold(doc->blocks)));
    }
    EXPECT_GE(files, 40);
}

// Pictures through the editor: every real DOCX and ODT opened with its
// pictures (as the app opens it) is lines with a picture's mark where each
// described picture stood, and the document the lines stand for has the same
// pictures (bytes and type), each after the same description, on the same
// blocks; an edit of another line keeps them.
TEST(OfficeLines, RealOfficeFilesKeepTheirPicturesThroughTheEditorLines) {
    const auto pictures = [](const document::Document& d) {
        std::ostringstream o;
        for (const auto& b : d.blocks) {
            if (b.images.empty()) continue;
            o << b.text() << ":";
            std::size_t next = 0;
            for (const auto& s : b.spans)
                if (s.transcriber_note && next < b.images.size()) {
                    const auto& image = b.images[next++];
                    o << " [" << s.text << " " << image.media_type << " " << std::hash<std::string>{}(image.bytes) << "]";
                }
            for (; next < b.images.size(); ++next) o << " [undescribed " << b.images[next].bytes.size() << "]";
            o << "\n";
        }
        return o.str();
    };
    import::ImportOptions options;
    options.images = true;
    options.picture_marks = true;
    int files = 0, with_pictures = 0;
    for (const auto& path : test::real_office_files(office_lines::data)) {
        auto doc = import::import_file(path, options);
        if (!doc) continue;
        ++files;
        SCOPED_TRACE(path.filename().string());
        auto layout = edit::LiveLayout::create("en-ueb-g1.ctb", {});
        ASSERT_TRUE(layout);
        layout->reset(*doc);
        const auto expected = pictures(*doc);
        if (!expected.empty()) ++with_pictures;
        EXPECT_EQ(pictures(layout->document()), expected);
        EXPECT_TRUE(layout->document().warnings.empty());
        // The lines show marks, never the bytes; a line added at the top keeps the pictures.
        for (std::size_t i = 0; i < layout->line_count(); ++i) EXPECT_LT(layout->line(i).size(), 4096u);
        layout->replace(0, 0, {"An edit above."});
        EXPECT_EQ(pictures(layout->document()), expected);
    }
    EXPECT_GE(files, 40);
    EXPECT_GE(with_pictures, 4);  // inline_images, image_vml, image.odt, textbox_image, ...
}

// The lines themselves: HTML a Markdown reader shows as such, and the
// document they stand for is the one they were made from.
TEST(OfficeLines, UnderlineRaisedTextLanguagesAndBoxesAreLines) {
    document::Document doc;
    const auto span = [](std::string text, std::uint8_t emphasis = document::emphasis_none,
                         document::Position position = document::Position::baseline, std::string language = {}) {
        document::Span s{std::move(text), emphasis};
        s.position = position;
        s.language = std::move(language);
        return s;
    };
    document::Block p;
    p.spans = {span("An "), span("underlined", document::emphasis_underline), span(" and "),
               span("bold underlined", document::emphasis_underline | document::emphasis_bold), span(" word, m"),
               span("2", 0, document::Position::superscript), span(", H"), span("2", 0, document::Position::subscript),
               span("O, "), span("Guten Tag", document::emphasis_italic, document::Position::baseline, "de"),
               span(" and <u>not a tag</u>.")};
    doc.blocks.push_back(p);
    document::Block boxed;
    boxed.kind = document::BlockKind::heading;
    boxed.level = 2;
    boxed.box = 1;
    boxed.spans = {span("In a box")};
    doc.blocks.push_back(boxed);
    boxed.kind = document::BlockKind::paragraph;
    boxed.level = 0;
    boxed.spans = {span("Its text, "), span("underlined", document::emphasis_underline), span(".")};
    doc.blocks.push_back(boxed);
    document::Block after;
    after.spans = {span("After the box.")};
    doc.blocks.push_back(after);
    boxed.box = 2;
    doc.blocks.push_back(boxed);

    const auto lines = edit::render_editor_lines(doc);
    const std::vector<std::string> expected{
        "An <u>underlined</u> and <u>**bold underlined**</u> word, m<sup>2</sup>, H<sub>2</sub>O, "
        "<span lang=\"de\">*Guten Tag*</span> and \\<u>not a tag\\</u>.",
        "<!-- box -->",
        "## In a box",
        "Its text, <u>underlined</u>.",
        "<!-- /box -->",
        "After the box.",
        "<!-- box -->",
        "Its text, <u>underlined</u>.",
        "<!-- /box -->"};
    EXPECT_EQ(lines, expected);
    const auto back = office_lines::through_lines(doc);
    EXPECT_EQ(office_lines::dump(office_lines::without_lines(back.blocks)),
              office_lines::dump(office_lines::without_lines(doc.blocks)));
    // The file saved from the lines reads back the same, and as DOCX and ODT.
    auto layout = test::live_layout(lines, "en-ueb-g1.ctb");
    for (const auto* name : {"saved.md", "saved.docx", "saved.odt"}) {
        SCOPED_TRACE(name);
        auto bytes = edit::file_bytes(lines, edit::Dialect::markdown, layout.document(), name);
        ASSERT_TRUE(bytes) << bytes.error().to_string();
        auto reopened = import::import_bytes(*bytes, name);
        ASSERT_TRUE(reopened) << reopened.error().to_string();
        EXPECT_EQ(office_lines::dump(office_lines::without_lines(reopened->blocks)),
                  office_lines::dump(office_lines::without_lines(doc.blocks)));
    }
}

// The live layout draws a box's lines as the CLI does (the pages of the
// document the lines stand for), and keeps doing so through edits that add,
// move and take away box lines and type inside a box.
TEST(OfficeLines, BoxesLayOutLiveAsTheCliAndThroughEdits) {
    std::vector<std::string> lines;
    for (int i = 0; i < 60; ++i) {
        if (i % 7 == 2) lines.emplace_back("<!-- box -->");
        lines.push_back("Paragraph " + std::to_string(i) + " with a few words to fill a braille line or two of text.");
        if (i % 7 == 4) lines.emplace_back("<!-- /box -->");
        if (i % 14 == 4) lines.emplace_back("<!-- box -->");  // a box right after a box
        if (i % 14 == 5) lines.emplace_back("<!-- /box -->");
    }
    layout::LayoutOptions options;
    auto live = test::live_layout(lines, "en-ueb-g1.ctb", options);
    const auto same_as_cli = [&options](const edit::LiveLayout& l) {
        pipeline::PipelineOptions p;
        p.tables = "en-ueb-g1.ctb";
        p.layout = options;
        auto expected = pipeline::lay_out(l.document(), p);
        if (!expected) return testing::AssertionFailure() << expected.error().to_string();
        if (!(l.paged().pages == expected->pages)) return testing::AssertionFailure() << "pages differ";
        return testing::AssertionSuccess();
    };
    ASSERT_TRUE(same_as_cli(live));
    const auto boxes = [](const document::Document& d) {
        int n = 0;
        for (const auto& b : d.blocks) n = std::max(n, b.box);
        return n;
    };
    EXPECT_EQ(boxes(live.document()), 13);
    std::mt19937 rng(7);
    for (int step = 0; step < 60; ++step) {
        const auto at = std::uniform_int_distribution<std::size_t>(0, lines.size() - 1)(rng);
        std::vector<std::string> replacement;
        switch (step % 4) {
            case 0: replacement = {"<!-- box -->", lines[at]}; break;
            case 1: replacement = {lines[at], "<!-- /box -->"}; break;
            case 2: replacement = {lines[at] + " typed"}; break;
            case 3: replacement = {}; break;
        }
        live.replace(at, 1, replacement);
        lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(at));
        lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at), replacement.begin(), replacement.end());
        const auto fresh = test::live_layout(lines, "en-ueb-g1.ctb", options);
        ASSERT_TRUE(live.paged().pages == fresh.paged().pages) << "step " << step << " at line " << at;
        ASSERT_TRUE(same_as_cli(live)) << "step " << step;
    }
}
