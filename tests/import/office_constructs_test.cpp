// SPDX-License-Identifier: GPL-3.0-or-later
// Every piece of text a reader needs, from DOCX and ODT made by LibreOffice
// and python-docx (tests/data/import/constructs, README there): content
// controls, text boxes as boxed material, picture descriptions as
// transcriber's notes, ruby, superscript and subscript, equations, ODT list
// numbering and multi-paragraph table cells. Golden files: the imported
// blocks (a readable dump) and the uncontracted UEB braille (unicode), under
// tests/data/import/constructs/expected; regenerate on purpose with
// TACTUS_UPDATE_GOLDEN=1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "common/file_io.hpp"
#include "export/export.hpp"
#include "import/import.hpp"
#include "import_test_util.hpp"
#include "pipeline/pipeline.hpp"

namespace tactus {
namespace {

namespace fs = std::filesystem;
using document::BlockKind;
using document::Position;

const fs::path kConstructs = fs::path(TACTUS_TEST_DATA) / "import" / "constructs";

document::Document load(const std::string& name, import::RubyGuide ruby = import::RubyGuide::after) {
    import::ImportOptions o;
    o.ruby = ruby;
    auto doc = import::import_file(kConstructs / name, o);
    EXPECT_TRUE(doc) << (doc ? "" : doc.error().to_string());
    return doc.value_or(document::Document{});
}

// One line per block: kind, level, box, then the spans with their marks
// (^ raised, _ lowered, TN transcriber's note, REF note reference).
std::string dump(const document::Document& doc) {
    std::string out;
    for (const auto& b : doc.blocks) {
        out += std::to_string(static_cast<int>(b.kind)) + "/" + std::to_string(b.level);
        if (b.box) out += " box" + std::to_string(b.box);
        out += ":";
        for (const auto& s : b.spans) {
            std::string text = s.text;
            for (std::size_t i = 0; (i = text.find('\n', i)) != std::string::npos;) text.replace(i, 1, "\\n");
            const std::string mark = s.transcriber_note                    ? "TN"
                                     : s.note_reference                    ? "REF"
                                     : s.position == Position::superscript ? "^"
                                     : s.position == Position::subscript   ? "_"
                                                                           : "";
            out += " [" + mark + (mark.empty() ? "" : ":") + text + "]";
        }
        out += "\n";
    }
    for (const auto& w : doc.warnings) out += "warning: " + w + "\n";
    return out;
}

std::string braille(const document::Document& doc) {
    pipeline::PipelineOptions o;
    o.tables = "en-ueb-g1.ctb";
    o.translation_workers = 1;
    auto paged = pipeline::lay_out(doc, o);
    EXPECT_TRUE(paged) << (paged ? "" : paged.error().to_string());
    if (!paged) return {};
    auto out = exporter::export_document(*paged, exporter::ExportFormat::unicode);
    EXPECT_TRUE(out);
    return out.value_or(std::string{});
}

void golden(const std::string& name, const std::string& actual) {
    const auto path = kConstructs / "expected" / name;
    if (std::getenv("TACTUS_UPDATE_GOLDEN")) {
        ASSERT_TRUE(write_file_atomic(path, actual));
        return;
    }
    const auto expected = read_file(path);
    ASSERT_TRUE(expected) << path;
    EXPECT_EQ(*expected, actual) << "differs from " << path;
}

// A box line across the default 27-cell line.
std::string line_of(const std::string& cell) {
    std::string out;
    for (int i = 0; i < 27; ++i) out += cell;
    return out;
}

const document::Block* find_block(const document::Document& doc, const std::string& text) {
    const auto it = std::ranges::find_if(doc.blocks, [&](const document::Block& b) {
        return b.text().find(text) != std::string::npos;
    });
    return it == doc.blocks.end() ? nullptr : &*it;
}

class Constructs : public ::testing::TestWithParam<std::string> {};

TEST_P(Constructs, MatchGoldenBlocksAndBraille) {
    const auto doc = load(GetParam());
    const auto stem = fs::path(GetParam()).stem().string() + "-" + fs::path(GetParam()).extension().string().substr(1);
    golden(stem + ".blocks.txt", dump(doc));
    golden(stem + ".txt", braille(doc));
}

INSTANTIATE_TEST_SUITE_P(OfficeConstructs, Constructs,
                         ::testing::Values("constructs.odt", "constructs.docx", "content_controls.docx"),
                         [](const auto& p) {
                             auto n = p.param;
                             std::ranges::replace(n, '.', '_');
                             return n;
                         });

class BothFormats : public ::testing::TestWithParam<std::string> {};

TEST_P(BothFormats, TextBoxIsBoxedMaterialAfterItsParagraph) {
    const auto doc = load(GetParam());
    const auto* before = find_block(doc, "Before the box.");
    const auto* name = find_block(doc, "Jane Doe");
    const auto* mail = find_block(doc, "jane@example.org");
    ASSERT_TRUE(before && name && mail);
    EXPECT_EQ(before->box, 0);
    EXPECT_NE(name->box, 0);
    EXPECT_EQ(name->box, mail->box);  // one box, two paragraphs
    EXPECT_LT(before, name);          // after the paragraph it is anchored in
    EXPECT_EQ(find_block(doc, "After the box.")->box, 0);
    const auto out = braille(doc);
    // BANA Braille Formats 2016 §7: top box line dots 2356, bottom dots 1245.
    EXPECT_NE(out.find("\n" + line_of("⠶") + "\n"), std::string::npos) << out;
    EXPECT_NE(out.find("\n" + line_of("⠛") + "\n"), std::string::npos) << out;
    EXPECT_LT(out.find("⠶⠶⠶"), out.find("⠚⠁⠝⠑"));  // "jane" inside the lines
    EXPECT_LT(out.find("⠚⠁⠝⠑"), out.find("⠛⠛⠛"));
}

TEST_P(BothFormats, PictureDescriptionIsATranscribersNoteAndAMissingOneIsOneWarning) {
    const auto doc = load(GetParam());
    const auto* p = find_block(doc, "A picture");
    ASSERT_TRUE(p);
    const auto note = std::ranges::find_if(p->spans, [](const auto& s) { return s.transcriber_note; });
    ASSERT_NE(note, p->spans.end());
    EXPECT_EQ(note->text, "A red square");
    ASSERT_EQ(doc.warnings.size(), 1u);
    EXPECT_NE(doc.warnings[0].find("1 picture has no description"), std::string::npos) << doc.warnings[0];
    EXPECT_NE(doc.warnings[0].find(GetParam().ends_with("odt") ? "content.xml:" : "word/document.xml:"),
              std::string::npos)
        << doc.warnings[0];
    // UEB transcriber's note indicators around the description.
    const auto out = braille(doc);
    EXPECT_NE(out.find("⠈⠨⠣⠠⠁⠀⠗⠑⠙"), std::string::npos) << out;
    EXPECT_NE(out.find("⠎⠟⠥⠁⠗⠑⠈⠨⠜"), std::string::npos) << out;
}

TEST_P(BothFormats, SuperscriptAndSubscriptDiffer) {
    const auto doc = load(GetParam());
    const auto* p = find_block(doc, "Area m");
    ASSERT_TRUE(p);
    const auto out = braille(doc);
    EXPECT_NE(out.find("⠍⠔⠼⠃⠀⠁⠝⠙⠀⠍⠁⠎⠎⠀⠍⠢⠼⠃"), std::string::npos) << out;  // m² and m₂ (UEB §3.24)
}

TEST_P(BothFormats, RubyKeepsItsBaseAndItsGuideByChoice) {
    const auto after = load(GetParam());
    const auto* p = find_block(after, "Read Tokyo");
    ASSERT_TRUE(p) << dump(after);
    ASSERT_EQ(p->spans.size(), 3u) << dump(after);
    EXPECT_TRUE(p->spans[1].transcriber_note);
    EXPECT_EQ(p->spans[1].text, "toh kyoh");
    const auto omit = load(GetParam(), import::RubyGuide::omit);
    const auto* q = find_block(omit, "Read Tokyo");
    ASSERT_TRUE(q);
    EXPECT_EQ(q->text(), "Read Tokyo aloud.");
}

TEST_P(BothFormats, AnEquationIsLinearTextInItsNumberedItem) {
    const auto doc = load(GetParam());
    const auto* item = find_block(doc, "The formula");
    ASSERT_TRUE(item) << dump(doc);
    EXPECT_EQ(item->kind, BlockKind::list_item);
    EXPECT_EQ(item->text().substr(0, 3), "1. ");
    EXPECT_NE(item->text().find("E=mc2 holds"), std::string::npos) << dump(doc);
    EXPECT_TRUE(std::ranges::any_of(item->spans, [](const auto& s) {
        return s.position == Position::superscript && s.text == "2";
    }));
}

TEST_P(BothFormats, ACellsParagraphsStayApart) {
    const auto doc = load(GetParam());
    const auto* cell = find_block(doc, "First line");
    ASSERT_TRUE(cell);
    EXPECT_EQ(cell->kind, BlockKind::table_cell);
    EXPECT_EQ(cell->text(), "First line\nSecond line");
}

TEST_P(BothFormats, ListsKeepTheirFormatsStartsAndContinuation) {
    // LibreOffice writes the ODT's start value as DOCX's w:startOverride.
    const auto doc = load(GetParam());
    std::vector<std::string> labels;
    for (const auto& b : doc.blocks)
        if (b.kind == BlockKind::list_item) labels.push_back(b.text().substr(0, b.text().find(' ')));
    EXPECT_EQ(labels, (std::vector<std::string>{"1.", "I.", "II.", "III.", "d)", "e)", "f)"}));
}

INSTANTIATE_TEST_SUITE_P(OfficeConstructs, BothFormats, ::testing::Values("constructs.odt", "constructs.docx"),
                         [](const auto& p) { return p.param.substr(p.param.find('.') + 1); });

TEST(OfficeConstructs, ContentControlsKeepTheirText) {
    const auto doc = load("content_controls.docx");
    for (const char* text : {"Annual report title", "A subtitle under it", "Pick one: Choose an item. then go on.",
                             "Jane Doe", "Author name", "Plain cell"})
        EXPECT_TRUE(find_block(doc, text)) << text << "\n" << dump(doc);
    EXPECT_EQ(find_block(doc, "Cell first paragraph")->text(), "Cell first paragraph\nCell second paragraph");
    const auto* fraction = find_block(doc, "(a+b)/2");
    ASSERT_TRUE(fraction) << dump(doc);
    EXPECT_EQ(fraction->text().substr(0, 3), "2. ");  // the item the equation alone holds keeps its number
}

TEST(OfficeConstructs, ADocumentOfOnlyUndescribedPicturesIsNotCalledEmpty) {
    const auto doc = load("pictures_only.docx");
    EXPECT_TRUE(doc.blocks.empty());
    ASSERT_EQ(doc.warnings.size(), 1u);
    EXPECT_NE(doc.warnings[0].find("2 pictures have no description"), std::string::npos) << doc.warnings[0];
    pipeline::PipelineOptions o;
    o.translation_workers = 1;
    auto paged = pipeline::lay_out(doc, o);
    ASSERT_FALSE(paged);
    EXPECT_EQ(paged.error().message.find("empty"), std::string::npos) << paged.error().to_string();
    EXPECT_NE(paged.error().message.find("no description"), std::string::npos) << paged.error().to_string();
}

TEST(OfficeConstructs, TheWarningReachesTheLaidOutDocument) {
    pipeline::PipelineOptions o;
    o.translation_workers = 1;
    auto paged = pipeline::lay_out(load("constructs.odt"), o);
    ASSERT_TRUE(paged);
    EXPECT_TRUE(std::ranges::any_of(paged->warnings, [](const std::string& w) {
        return w.find("picture has no description") != std::string::npos;
    }));
}

}  // namespace
}  // namespace tactus
