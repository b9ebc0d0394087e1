// SPDX-License-Identifier: GPL-3.0-or-later
// Ready-made braille in the editor: a PEF opened in the editor keeps what its
// lines do not carry (edit::BrailleStructure: sections, volumes, the file's
// grid, its dc: metadata), lays out through the CLI's own call
// (layout::keep_braille_pages), and keeps the structure of the pages that are
// left when lines are edited, inserted or deleted (LiveLayout::replace).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "edit/editor_lines.hpp"
#include "edit/live_layout.hpp"
#include "export/export.hpp"
#include "import/import.hpp"
#include "layout/braille_pages.hpp"
#include "pipeline/pipeline.hpp"

using namespace tactus;

namespace {

const std::string kData = TACTUS_TEST_DATA "/pef/";

layout::LayoutOptions big_page() {
    layout::LayoutOptions o;
    o.geometry.cells_per_line = 40;
    o.geometry.lines_per_page = 30;
    o.geometry.interpoint = true;
    return o;
}

document::Document read(const std::string& path) {
    auto doc = import::import_file(path);
    if (!doc) throw std::runtime_error(doc.error().to_string());
    return *doc;
}

edit::LiveLayout open(const std::string& path, layout::LayoutOptions options = big_page()) {
    auto live = edit::LiveLayout::create("en-ueb-g2.ctb", options);
    if (!live) throw std::runtime_error(live.error().to_string());
    live->reset(read(path));
    return std::move(*live);
}

std::size_t line_of(const edit::LiveLayout& live, const std::string& text) {
    for (std::size_t i = 0; i < live.line_count(); ++i)
        if (live.line(i) == text) return i;
    throw std::runtime_error("no line " + text);
}

std::string pef(const layout::PagedDocument& paged) {
    auto bytes = exporter::to_pef(paged, exporter::pef_metadata(paged.metadata, "t", "2026-01-01"));
    if (!bytes) throw std::runtime_error(bytes.error().to_string());
    return *bytes;
}

// The PEF the CLI writes for `doc` (pipeline::lay_out, as tactus-cli layout does).
std::string cli_pef(const document::Document& doc, layout::LayoutOptions options = big_page()) {
    pipeline::PipelineOptions o;
    o.layout = options;
    auto paged = pipeline::lay_out(doc, o);
    if (!paged) throw std::runtime_error(paged.error().to_string());
    return pef(*paged);
}

std::size_t count(const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (auto i = s.find(what); i != std::string::npos; i = s.find(what, i + 1)) ++n;
    return n;
}

}  // namespace

// Opened and not edited: the same pages, sections, volumes and metadata as
// the CLI's pipeline gives, on interpoint and single-sided paper alike.
TEST(BrailleStructure, UneditedIsTheCliPipelinesLayout) {
    for (const auto* name : {"volumes.pef", "sections.pef", "single_sided_section.pef", "mixed_duplex.pef",
                             "real/book.pef", "real/margin-uneven.pef", "real/flow-in-header-footer4.pef",
                             "real/8-dot-chart.pef", "real/butterfly.pef"}) {
        for (const bool interpoint : {true, false}) {
            SCOPED_TRACE(std::string(name) + (interpoint ? " interpoint" : " single-sided"));
            auto options = big_page();
            options.geometry.interpoint = interpoint;
            const auto doc = read(kData + name);
            const auto live = open(kData + name, options);
            pipeline::PipelineOptions o;
            o.layout = options;
            const auto expected = pipeline::lay_out(doc, o);
            ASSERT_TRUE(expected) << expected.error().to_string();
            EXPECT_TRUE(live.paged().pages == expected->pages);
            EXPECT_EQ(live.paged().sections, expected->sections);
            EXPECT_EQ(live.paged().metadata, expected->metadata);
            EXPECT_EQ(live.paged().geometry, expected->geometry);
            // The same sections (the editor has a block a row, the importer a
            // block a page: where they start is compared as pages, above).
            const auto settings = [](std::vector<document::BrailleSection> sections) {
                for (auto& section : sections) section.first_block = 0;
                return sections;
            };
            EXPECT_EQ(settings(live.document().braille_sections), settings(doc.braille_sections));
            EXPECT_EQ(live.document().braille_grid, doc.braille_grid);
        }
    }
}

// The structure is given back as it was given, by editor line.
TEST(BrailleStructure, GivenBackByLine) {
    const auto doc = read(kData + "volumes.pef");
    const auto live = open(kData + "volumes.pef");
    const auto s = live.braille_structure();
    EXPECT_EQ(s, edit::braille_structure(doc));
    ASSERT_EQ(s.sections.size(), 4u);
    // Volume 2 starts on the page break line before its first row.
    EXPECT_EQ(live.line(s.sections[2].first_block), "<!-- braillepage -->");
    EXPECT_EQ(live.line(s.sections[2].first_block + 1), "⠠⠧⠕⠇⠥⠍⠑⠀⠼⠃");
    EXPECT_TRUE(s.sections[2].starts_volume);
    EXPECT_FALSE(s.sections[1].starts_volume);
    EXPECT_FALSE(s.sections[1].duplex);
}

// A row edited in place, a line typed above everything: the sections stay.
TEST(BrailleStructure, EditingALineKeepsItsSection) {
    auto live = open(kData + "volumes.pef");
    const auto before = live.braille_structure();
    const auto v2 = before.sections[2].first_block;
    // The section's own first line replaced by an edited one (a page break typed again).
    live.replace(v2, 1, {"<!-- braillepage -->"});
    EXPECT_EQ(live.braille_structure(), before);
    // A line split in two (Enter in a row): the first part keeps its place.
    const auto v3 = before.sections[3].first_block;
    live.replace(v3 + 1, 1, {"⠠⠧⠕⠇⠥⠍⠑", "⠀⠼⠉"});
    EXPECT_EQ(live.braille_structure().sections.size(), 4u);
    EXPECT_EQ(live.braille_structure().sections[3].first_block, v3);
    // Rows typed in above the first row are in the first section.
    live.replace(0, 0, {"⠁⠃⠉"});
    const auto doc = live.document();
    ASSERT_EQ(doc.braille_sections.size(), 4u);
    EXPECT_EQ(doc.braille_sections[0].first_block, 0u);
    EXPECT_EQ(count(pef(live.paged()), "<volume "), 3u);
    EXPECT_NE(pef(live.paged()).find("<row>⠁⠃⠉</row>"), std::string::npos);
}

// Deleting the line a section starts on (its page break): the section starts
// at the line after it, its pages still on a new sheet; the file written
// again is the file with that page break gone, as the CLI writes that file.
TEST(BrailleStructure, DeletingASectionsFirstLineMovesItsStart) {
    auto live = open(kData + "volumes.pef");
    const auto v2 = live.braille_structure().sections[2].first_block;
    live.replace(v2, 1, {});
    const auto s = live.braille_structure();
    ASSERT_EQ(s.sections.size(), 4u);
    EXPECT_EQ(s.sections[2].first_block, v2);
    EXPECT_TRUE(s.sections[2].starts_volume);
    EXPECT_EQ(live.line(v2), "⠠⠧⠕⠇⠥⠍⠑⠀⠼⠃");
    const auto out = pef(live.paged());
    EXPECT_EQ(count(out, "<volume "), 3u);
    EXPECT_EQ(count(out, "<page"), 7u);
    // The same as the CLI gives for the PEF it wrote, read again.
    const auto again = import::import_bytes(out, "again.pef", {});
    ASSERT_TRUE(again);
    EXPECT_EQ(cli_pef(*again), out);
}

// Deleting a whole section (the single-sided one ending volume 1): it is gone,
// and the sections after it keep theirs. Deleting a volume's first section
// keeps the volume: its next section starts it.
TEST(BrailleStructure, DeletingWholeSectionsKeepsTheRest) {
    auto live = open(kData + "volumes.pef");
    auto s = live.braille_structure();
    const auto single = s.sections[1].first_block;
    live.replace(single, s.sections[2].first_block - single, {});
    s = live.braille_structure();
    ASSERT_EQ(s.sections.size(), 3u);
    EXPECT_TRUE(s.sections[1].starts_volume);
    EXPECT_EQ(live.line(s.sections[1].first_block + 1), "⠠⠧⠕⠇⠥⠍⠑⠀⠼⠃");
    auto out = pef(live.paged());
    EXPECT_EQ(count(out, "<volume "), 3u);
    EXPECT_EQ(count(out, "duplex=\"false\""), 1u);  // only volume 3's own
    EXPECT_EQ(out.find("⠎⠊⠝⠛⠇⠑"), std::string::npos);

    // A volume whose one section is deleted with the start of the next volume's
    // section: the later section wins, and a volume starts there.
    live.replace(s.sections[1].first_block, s.sections[2].first_block - s.sections[1].first_block + 1, {});
    s = live.braille_structure();
    ASSERT_EQ(s.sections.size(), 2u);
    EXPECT_TRUE(s.sections[1].starts_volume);
    EXPECT_FALSE(s.sections[1].duplex);  // volume 3's section
    out = pef(live.paged());
    EXPECT_EQ(count(out, "<volume "), 2u);
}

// Undo of a deletion is an insertion reported over the line the deletion left
// (as the editor widget reports it): the deleted lines come back with the
// structure they had.
TEST(BrailleStructure, UndoingADeletionGivesTheStructureBack) {
    auto live = open(kData + "volumes.pef");
    const auto before = live.braille_structure();
    const auto original = pef(live.paged());
    const auto v2 = before.sections[2].first_block;
    const std::vector<std::string> deleted = {live.line(v2), live.line(v2 + 1)};
    const auto after = live.line(v2 + 2);
    live.replace(v2, 2, {});
    EXPECT_NE(pef(live.paged()), original);
    live.replace(v2, 1, {deleted[0], deleted[1], after});
    EXPECT_EQ(live.braille_structure(), before);
    EXPECT_EQ(pef(live.paged()), original);
}

// The page before a section start deleted and the deletion undone: the
// section start stays where it was (the lines come back above it, before the
// section), as the editor reports the undo.
TEST(BrailleStructure, UndoingADeletionBeforeASectionKeepsItsStart) {
    auto live = open(kData + "volumes.pef");
    const auto before = live.braille_structure();
    const auto original = pef(live.paged());
    const auto v3 = before.sections[3].first_block;  // volume 3's page break line
    const std::vector<std::string> deleted = {live.line(v3 - 2), live.line(v3 - 1)};
    ASSERT_EQ(deleted[1], "⠋⠊⠧⠑");
    live.replace(v3 - 2, 3, {live.line(v3)});  // as the editor reports deleting whole lines above it
    EXPECT_EQ(count(pef(live.paged()), "<page"), 6u);
    live.replace(v3 - 2, 1, {deleted[0], deleted[1], live.line(v3 - 2)});
    EXPECT_EQ(live.braille_structure(), before);
    EXPECT_EQ(pef(live.paged()), original);
}

// Enter at the start or end of a section's first line: the line that is the
// same keeps the mark.
TEST(BrailleStructure, ABlankLineBesideASectionStartLeavesItThere) {
    auto live = open(kData + "volumes.pef");
    const auto v2 = live.braille_structure().sections[2].first_block;
    const auto text = live.line(v2);
    live.replace(v2, 1, {"", text});
    EXPECT_EQ(live.braille_structure().sections[2].first_block, v2 + 1);
    live.replace(v2 + 1, 1, {text, ""});
    EXPECT_EQ(live.braille_structure().sections[2].first_block, v2 + 1);
}

// Print text typed into a PEF: it is no longer ready-made braille, so it is
// laid out by the paginator on the options' page, as one section; its
// metadata is still written. Taken out again, the sections are back.
TEST(BrailleStructure, PrintTextLaysOutAgainAndTheStructureComesBackWithoutIt) {
    auto live = open(kData + "single_sided_section.pef");
    const auto original = pef(live.paged());
    const auto three = line_of(live, "⠞⠓⠗⠑⠑");
    live.replace(three + 1, 0, {"Some print text."});
    EXPECT_TRUE(live.paged().sections.empty());
    EXPECT_EQ(live.paged().geometry.cells_per_line, 40);
    EXPECT_EQ(live.paged().metadata, live.document().metadata);
    EXPECT_NE(pef(live.paged()).find("org.example.tactus.single-sided-section"), std::string::npos);
    live.replace(three + 1, 1, {});
    EXPECT_EQ(pef(live.paged()), original);
}

// The cursor's place on paper: a row's page counts the blank backs before it.
TEST(BrailleStructure, PositionsCountBlankBacks) {
    const auto live = open(kData + "single_sided_section.pef");
    // Pages: one, two, three, (blank), four, (blank), five, (blank).
    const auto four = line_of(live, "⠋⠕⠥⠗");
    const auto five = line_of(live, "⠋⠊⠧⠑");
    EXPECT_EQ(live.position_of(four, 2).page, 4u);
    EXPECT_EQ(live.position_of(four, 2).line, 0);
    EXPECT_EQ(live.position_of(four, 2).cell, 2);
    EXPECT_EQ(live.position_of(five).page, 6u);
    EXPECT_EQ(live.line_at(6, 0), five);
    EXPECT_TRUE(live.paged().pages[5].filler);
}

// Random edits (cells typed and erased in rows, rows split, joined, deleted,
// page breaks typed): after each, the live pages are exactly what the CLI's
// call, layout::keep_braille_pages, gives for the document the lines stand
// for (the editor changes a row in place when nothing else can change; in
// volume_grids.pef a row is within its own section's cols, not the file's largest).
TEST(BrailleStructure, RandomEditsGiveTheCoreCallsPages) {
    for (const auto* name : {"volumes.pef", "volume_grids.pef", "real/book.pef", "real/margin-uneven.pef"}) {
        SCOPED_TRACE(name);
        auto live = open(kData + name);
        std::mt19937 rng(13);
        const auto pick = [&rng](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
        const std::vector<std::string> cells = {"⠁", "⠃", "⠉", "⠀", "⠿"};
        for (int step = 0; step < 300; ++step) {
            const auto i = pick(live.line_count());
            auto line = live.line(i);
            switch (pick(10)) {
                case 0: live.replace(i, 1, {line, "⠙⠑"}); break;                      // a row added
                case 1: if (live.line_count() > 3) live.replace(i, 1, {}); break;  // a line deleted
                case 2: live.replace(i, 0, {"<!-- braillepage -->"}); break;     // a page break typed
                case 3:
                    if (i + 1 < live.line_count() && edit::is_braille_line(line) && edit::is_braille_line(live.line(i + 1)))
                        live.replace(i, 2, {line + live.line(i + 1)});  // two rows joined
                    break;
                default:
                    if (!edit::is_braille_line(line)) break;
                    // A cell typed at the end or the last one erased (3 bytes each).
                    if (pick(2) == 0 || line.size() <= 3) line += cells[pick(cells.size())];
                    else line.resize(line.size() - 3);
                    live.replace(i, 1, {line});
            }
            const auto doc = live.document();
            const auto expected = layout::keep_braille_pages(doc, big_page());
            if (!expected) {
                EXPECT_FALSE(live.pages_kept());
                continue;
            }
            ASSERT_TRUE(live.pages_kept()) << "step " << step;
            ASSERT_TRUE(live.paged().pages == expected->pages) << "step " << step;
            ASSERT_EQ(live.paged().sections, expected->sections) << "step " << step;
            ASSERT_EQ(live.paged().geometry, expected->geometry) << "step " << step;
            ASSERT_EQ(live.paged().metadata, expected->metadata) << "step " << step;
        }
    }
}

// A row of volume_grids.pef's first volume (12 cols; 8 cells) typed to 13 cells,
// within the file's largest cols (20): its section's page grows to 13 cells,
// as keep_braille_pages says, and is written so. Before, the row was changed
// in place, measured against the file's largest cols, and the section kept
// 12 cols, so the PEF written from the pages was refused (a row longer than
// cols).
TEST(BrailleStructure, ARowTypedPastItsSectionsColsGrowsThatSection) {
    auto live = open(kData + "volume_grids.pef");
    std::size_t row = 0;
    while (row < live.line_count() && live.line(row) != "⠕⠝⠑⠀⠏⠁⠛⠑") ++row;
    ASSERT_LT(row, live.line_count());
    auto line = live.line(row);
    for (const auto* cell : {"⠁", "⠃", "⠉", "⠙", "⠑"}) {
        line += cell;
        live.replace(row, 1, {line});
    }
    const auto expected = layout::keep_braille_pages(live.document(), big_page());
    ASSERT_TRUE(expected) << expected.error().to_string();
    ASSERT_TRUE(live.pages_kept());
    EXPECT_EQ(expected->sections.front().cols, 13);
    EXPECT_EQ(live.paged().sections, expected->sections);
    EXPECT_TRUE(live.paged().pages == expected->pages);
    EXPECT_TRUE(exporter::to_pef(live.paged(), exporter::pef_metadata(live.paged().metadata, "t", "2030-01-01")));
}
