// SPDX-License-Identifier: GPL-3.0-or-later
// "Braille in, braille out": BRF and PEF keep their own pages, rows,
// page numbers, duplex and sections; a page the target cannot hold is refused
// unless the user asks for a reflow.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <tuple>

#include "../export/pef_checks.hpp"
#include "cells.hpp"
#include "export/export.hpp"
#include "import/import.hpp"
#include "layout/braille_pages.hpp"
#include "pipeline/pipeline.hpp"

using namespace tactus;
using namespace tactus::document;
using namespace tactus::pipeline;
using namespace tactus::layout;
using namespace tactus::exporter;
using namespace tactus::import;

namespace {

const std::filesystem::path kPef = std::filesystem::path(TACTUS_TEST_DATA) / "pef";

Document read_pef(const std::string& name) {
    auto doc = import_file(kPef / name);
    EXPECT_TRUE(doc) << doc.error().to_string();
    return doc ? std::move(*doc) : Document{};
}

PipelineOptions a4() {
    PipelineOptions o;  // 27 x 24 interpoint
    return o;
}

std::vector<std::string> rows(const Page& p) {
    std::vector<std::string> out;
    for (const auto& l : p.lines) out.push_back(brf(l));
    while (!out.empty() && out.back().empty()) out.pop_back();
    return out;
}

}  // namespace

TEST(BraillePages, PefImportReadsGridSectionsAndMetadata) {
    const auto doc = read_pef("sections.pef");
    ASSERT_TRUE(doc.braille_grid);
    EXPECT_EQ(doc.braille_grid->cols, 20);
    EXPECT_EQ(doc.braille_grid->rows, 6);
    ASSERT_EQ(doc.braille_sections.size(), 2u);
    EXPECT_TRUE(doc.braille_sections[0].duplex);
    EXPECT_TRUE(doc.braille_sections[1].duplex);
    ASSERT_GE(doc.metadata.size(), 7u);
    EXPECT_EQ(doc.metadata[0].name, "format");
    EXPECT_EQ(doc.metadata[2].name, "title");
    EXPECT_EQ(doc.metadata[2].value, "Two sections, interpoint");
    EXPECT_EQ(doc.metadata[4].name, "language");
}

// Five pages in two sections on interpoint paper: section 2 must not start on
// the back of section 1's last sheet, so a blank back is added after page 3.
TEST(BraillePages, PefPagesKeptAndSectionStartsANewSheet) {
    auto paged = lay_out(read_pef("sections.pef"), a4());
    ASSERT_TRUE(paged) << paged.error().to_string();
    EXPECT_EQ(paged->geometry.cells_per_line, 20);
    EXPECT_EQ(paged->geometry.lines_per_page, 6);
    EXPECT_TRUE(paged->geometry.interpoint);
    ASSERT_EQ(paged->pages.size(), 6u);
    EXPECT_EQ(rows(paged->pages[0]), (std::vector<std::string>{",TITLE ,PAGE", "", "", "", "", "                  #A"}));
    EXPECT_EQ(rows(paged->pages[1]), (std::vector<std::string>{",BACK OF SHEET #A"}));
    EXPECT_EQ(rows(paged->pages[2]).back(), "                  #C");  // its own number, nothing added
    EXPECT_TRUE(paged->pages[3].filler);
    EXPECT_TRUE(rows(paged->pages[3]).empty());
    EXPECT_EQ(rows(paged->pages[4]).front(), ",SEC;N #B");
    EXPECT_EQ(paged->sheet_count(), 3u);
    EXPECT_EQ(paged->sheet(3).front, &paged->pages[4]);
}

TEST(BraillePages, SingleSidedSectionGetsBlankBacks) {
    auto paged = lay_out(read_pef("mixed_duplex.pef"), a4());
    ASSERT_TRUE(paged) << paged.error().to_string();
    ASSERT_EQ(paged->pages.size(), 6u);
    EXPECT_EQ(rows(paged->pages[0]), std::vector<std::string>{"ONE"});
    EXPECT_EQ(rows(paged->pages[1]), std::vector<std::string>{"TWO"});
    EXPECT_EQ(rows(paged->pages[2]), std::vector<std::string>{"THREE"});
    EXPECT_TRUE(paged->pages[3].filler);
    EXPECT_EQ(rows(paged->pages[4]), std::vector<std::string>{"FOUR"});
    EXPECT_TRUE(paged->pages[5].filler);
}

// A PEF written from these pages has the source's sections, duplex and dc:
// metadata again, and is valid PEF.
TEST(BraillePages, PefRoundTripKeepsPagesSectionsAndMetadata) {
    const auto source = read_pef("sections.pef");
    auto paged = lay_out(source, a4());
    ASSERT_TRUE(paged);
    const auto meta = pef_metadata(paged->metadata, "fallback title", "2030-01-01");
    const auto pef = to_pef(*paged, meta);
    ASSERT_TRUE(pef) << pef.error().to_string();
    EXPECT_EQ(validate_pef_schema(*pef), "");
    EXPECT_EQ(check_pef_schematron(*pef), "");
    auto again = import_bytes(*pef, "again.pef");
    ASSERT_TRUE(again) << again.error().to_string();
    EXPECT_EQ(again->metadata, source.metadata);
    EXPECT_EQ(again->braille_sections.size(), 2u);
    ASSERT_TRUE(again->braille_grid);
    EXPECT_EQ(again->braille_grid->cols, 20);
    EXPECT_EQ(again->braille_grid->rows, 6);
    auto paged_again = lay_out(*again, a4());
    ASSERT_TRUE(paged_again);
    ASSERT_EQ(paged_again->pages.size(), paged->pages.size());
    for (std::size_t p = 0; p < paged->pages.size(); ++p)
        EXPECT_EQ(rows(paged_again->pages[p]), rows(paged->pages[p])) << "page " << p + 1;
}

TEST(BraillePages, PageLargerThanThePrinterPageIsRefusedBeforeAnything) {
    const auto doc = read_pef("us_braille_40x25.pef");
    auto paged = lay_out(doc, a4());
    ASSERT_FALSE(paged);
    EXPECT_NE(paged.error().message.find("40"), std::string::npos) << paged.error().message;
    EXPECT_NE(paged.error().message.find("27"), std::string::npos) << paged.error().message;
    EXPECT_NE(paged.error().message.find("reflow"), std::string::npos) << paged.error().message;
    auto o = a4();
    o.reflow_braille = true;
    auto reflowed = lay_out(doc, o);
    ASSERT_TRUE(reflowed) << reflowed.error().to_string();
    EXPECT_EQ(reflowed->geometry.cells_per_line, 27);
    o.reflow_braille = false;
    o.layout.geometry = {40, 25, false, false};
    auto fits = lay_out(doc, o);
    ASSERT_TRUE(fits) << fits.error().to_string();
    EXPECT_EQ(fits->pages.size(), 2u);
    EXPECT_EQ(rows(fits->pages[0]).size(), 25u);
}

// The one rule the CLI's exit 5 and the app's question ask: the first page
// that does not fit, with the file's page and the printer's.
TEST(BraillePages, MisfitNamesThePageAndBothSizes) {
    const auto doc = read_pef("us_braille_40x25.pef");
    const auto m = find_braille_misfit(doc, a4().layout);
    ASSERT_TRUE(m);
    EXPECT_EQ(m->page, 1);
    EXPECT_EQ(m->file_cols, 40);
    EXPECT_EQ(m->file_rows, 25);
    EXPECT_EQ(m->target_cols, 27);
    EXPECT_EQ(m->target_rows, 24);
    EXPECT_GT(m->cols, 27);
    LayoutOptions big;
    big.geometry.cells_per_line = 40;
    big.geometry.lines_per_page = 25;
    EXPECT_FALSE(find_braille_misfit(doc, big));
    EXPECT_TRUE(check_braille_fits(doc, big));
}

// BRF written by layout and read back gives the same pages: no second page
// number, no page split in two (4 pages for 2 before).
TEST(BraillePages, BrfRoundTripIsPageForPage) {
    PipelineOptions o;
    o.layout.geometry.interpoint = false;
    auto doc = lay_out_file(std::filesystem::path(TACTUS_RESOURCES_DIR) / "samples" / "welcome.md", o);
    ASSERT_TRUE(doc);
    const auto brf_text = to_brf(*doc);
    ASSERT_TRUE(brf_text);
    auto imported = import_bytes(*brf_text, "welcome.brf");
    ASSERT_TRUE(imported) << imported.error().to_string();
    auto again = lay_out(*imported, o);
    ASSERT_TRUE(again) << again.error().to_string();
    ASSERT_EQ(again->pages.size(), doc->pages.size());
    EXPECT_EQ(to_brf(*again).value(), *brf_text);
}

TEST(BraillePages, ImpossiblePefAttributesAreRefusedWithTheLine) {
    for (const auto& [file, what] : {std::pair{"bad_cols.pef", "cols"}, std::pair{"bad_rows.pef", "rows"},
                                     std::pair{"bad_duplex.pef", "duplex"}}) {
        auto doc = import_file(kPef / file);
        ASSERT_FALSE(doc) << file;
        EXPECT_NE(doc.error().message.find(what), std::string::npos) << doc.error().message;
        EXPECT_EQ(doc.error().where, (kPef / file).string() + ":11") << file;
    }
    // rowgap is a non-negative whole number wherever it stands (volume, section,
    // page, row); the old importer did not look at it.
    for (const auto& [file, line] : {std::pair{"bad_rowgap.pef", ":11"}, std::pair{"bad_row_rowgap.pef", ":14"}}) {
        auto doc = import_file(kPef / file);
        ASSERT_FALSE(doc) << file;
        EXPECT_NE(doc.error().message.find("rowgap"), std::string::npos) << doc.error().message;
        EXPECT_EQ(doc.error().where, (kPef / file).string() + line) << file;
    }
    auto rows_over = import_file(kPef / "too_many_rows.pef");
    ASSERT_FALSE(rows_over);
    EXPECT_NE(rows_over.error().message.find("3 rows"), std::string::npos) << rows_over.error().message;
}

// Volumes of different page sizes (volume_grids.pef: 12 x 5, 20 x 8, 16 x 6
// with a 10 x 4 section): each section keeps its own grid through
// keep_braille_pages, and the PEF written from it is the file again, valid
// PEF with each volume's own cols/rows/rowgap (before: the largest, 20 x 8,
// rowgap 0, for every volume).
TEST(BraillePages, EachVolumeKeepsItsOwnGrid) {
    const auto doc = read_pef("volume_grids.pef");
    ASSERT_EQ(doc.braille_sections.size(), 5u);
    EXPECT_EQ(doc.braille_sections[4].cols, 10);
    EXPECT_EQ(doc.braille_sections[4].rows, 4);
    EXPECT_EQ(doc.braille_sections[3].rowgap, 1);
    auto paged = lay_out(doc, a4());
    ASSERT_TRUE(paged) << paged.error().to_string();
    EXPECT_EQ(paged->geometry.cells_per_line, 20);  // the sheets hold the largest page
    EXPECT_EQ(paged->geometry.lines_per_page, 8);
    ASSERT_EQ(paged->sections.size(), 5u);
    const auto grid = [](const PageSection& s) { return std::tuple{s.cols, s.rows, s.rowgap, s.duplex, s.starts_volume}; };
    EXPECT_EQ(grid(paged->sections[0]), std::tuple(12, 5, 0, true, true));
    EXPECT_EQ(grid(paged->sections[1]), std::tuple(12, 5, 0, false, false));
    EXPECT_EQ(grid(paged->sections[2]), std::tuple(20, 8, 0, false, true));
    EXPECT_EQ(grid(paged->sections[3]), std::tuple(16, 6, 1, true, true));
    EXPECT_EQ(grid(paged->sections[4]), std::tuple(10, 4, 1, false, false));
    const auto pef = to_pef(*paged, pef_metadata(paged->metadata, "fallback", "2030-01-01"));
    ASSERT_TRUE(pef) << pef.error().to_string();
    EXPECT_EQ(validate_pef_schema(*pef), "");
    EXPECT_EQ(check_pef_schematron(*pef), "");
    std::ifstream in(kPef / "volume_grids.pef", std::ios::binary);
    const std::string source((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(*pef, source);
}

// Each volume's own page is what the printer's page must hold, even where
// its rows are shorter: volume 2 declares 20 cells (its longest row is 19),
// so a 19-cell printer cannot emboss it page for page; before, only the rows
// were measured, so it was kept, on sheets of 20 cells the printer has not.
// The misfit names the file's page volume by volume.
TEST(BraillePages, EachVolumesOwnPageIsCheckedAgainstThePrinters) {
    const auto doc = read_pef("volume_grids.pef");
    LayoutOptions printer;
    printer.geometry.cells_per_line = 19;
    printer.geometry.lines_per_page = 8;
    const auto m = find_braille_misfit(doc, printer);
    ASSERT_TRUE(m);
    EXPECT_EQ(m->page, 5);  // volume 2's first page
    EXPECT_EQ(m->cols, 19);
    EXPECT_EQ(m->file_cols, 20);
    EXPECT_EQ(m->file_rows, 8);
    EXPECT_EQ(m->volumes, (std::vector<VolumePage>{{1, 12, 5, true}, {2, 20, 8, false}, {3, 16, 6, true}}));
    EXPECT_FALSE(keep_braille_pages(doc, printer));
    printer.geometry.cells_per_line = 20;
    EXPECT_FALSE(find_braille_misfit(doc, printer));
    // A BRF (no declared page) is measured by its rows, as before.
    const auto brf = import_bytes(",A\n,B\f", "two.brf");
    ASSERT_TRUE(brf) << brf.error().to_string();
    printer.geometry = {4, 3, false, false};
    EXPECT_FALSE(find_braille_misfit(*brf, printer));
}
