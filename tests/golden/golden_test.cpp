// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../export/pef_checks.hpp"
#include "common/file_io.hpp"
#include "export/export.hpp"
#include "import/import.hpp"
#include "pipeline/pipeline.hpp"

using namespace tactus;
namespace fs = std::filesystem;

namespace {

const fs::path kSamples = fs::path(TACTUS_RESOURCES_DIR) / "samples";
// One document as Markdown, DOCX and ODT (make_office.py writes the last two):
// headings, a note, bullets and numbers, a nested list, a block quote, a table
// that fits the line and one that does not.
const fs::path kStructure = fs::path(TACTUS_GOLDEN_DIR) / ".." / "structure";

struct GoldenCase {
    std::string name;     // expected file name
    std::string input;    // under resources/samples, or tests/golden/structure for structure*
    std::string tables;
    bool interpoint;
    exporter::ExportFormat format;
};

std::string render(const GoldenCase& c) {
    pipeline::PipelineOptions o;
    o.tables = c.tables;
    o.layout.geometry.interpoint = c.interpoint;
    const auto dir = c.input.starts_with("structure") ? kStructure
                     : c.input.starts_with("mixed/") ? fs::path(TACTUS_GOLDEN_DIR) / ".."
                     : c.input.starts_with("public/") ? fs::path(TACTUS_TEST_DATA) / "import"
                                                     : kSamples;
    auto doc = pipeline::lay_out_file(dir / c.input, o);
    EXPECT_TRUE(doc) << doc.error().to_string();
    if (!doc) return {};
    exporter::PefMetadata meta;
    meta.title = c.input;
    meta.date = "2026-01-01";
    auto out = exporter::export_document(*doc, c.format, meta);
    EXPECT_TRUE(out) << out.error().to_string();
    return out ? *out : std::string{};
}

class Golden : public ::testing::TestWithParam<GoldenCase> {};

}  // namespace

TEST_P(Golden, MatchesExpectedBytes) {
    const auto& c = GetParam();
    const auto actual = render(c);
    const auto path = fs::path(TACTUS_GOLDEN_DIR) / c.name;
    if (std::getenv("TACTUS_UPDATE_GOLDEN")) {
        ASSERT_TRUE(write_file_atomic(path, actual));
        GTEST_SKIP() << "updated " << path;
    }
    const auto expected = read_file(path);
    ASSERT_TRUE(expected) << expected.error().to_string();
    EXPECT_EQ(actual, *expected) << "golden mismatch for " << c.name
                                 << " (TACTUS_UPDATE_GOLDEN=1 regenerates; review the diff)";
    if (c.format == exporter::ExportFormat::pef) {
        EXPECT_EQ(validate_pef_schema(actual), "");
        EXPECT_EQ(check_pef_schematron(actual), "");
    }
}

INSTANTIATE_TEST_SUITE_P(
    Samples, Golden,
    ::testing::Values(
        GoldenCase{"welcome.brf", "welcome.md", "en-ueb-g2.ctb", false, exporter::ExportFormat::brf},
        GoldenCase{"welcome-interpoint.brf", "welcome.md", "en-ueb-g2.ctb", true, exporter::ExportFormat::brf},
        GoldenCase{"welcome-g1.pef", "welcome.md", "en-ueb-g1.ctb", true, exporter::ExportFormat::pef},
        GoldenCase{"chinese-tw.brf", "chinese-tw.txt", "zh-tw.ctb", true, exporter::ExportFormat::brf},
        // Passages in another language (docs/translation.md): English in
        // Taiwanese braille, Chinese in UEB contracted, HTML lang spans.
        GoldenCase{"mixed-zh-tw-english.brf", "mixed/zh-tw-english.md", "zh-tw.ctb", false, exporter::ExportFormat::brf},
        GoldenCase{"mixed-ueb-chinese.brf", "mixed/ueb-chinese.md", "en-ueb-g2.ctb", false, exporter::ExportFormat::brf},
        GoldenCase{"mixed-lang-spans.brf", "mixed/lang-spans.html", "en-ueb-g2.ctb", false, exporter::ExportFormat::brf},
        GoldenCase{"chinese-cn.txt", "chinese-cn.txt", "zhcn-g2.ctb", false, exporter::ExportFormat::unicode},
        GoldenCase{"structure-md.brf", "structure.md", "en-ueb-g2.ctb", true, exporter::ExportFormat::brf},
        GoldenCase{"structure-docx.brf", "structure.docx", "en-ueb-g2.ctb", true, exporter::ExportFormat::brf},
        GoldenCase{"structure-odt.brf", "structure.odt", "en-ueb-g2.ctb", true, exporter::ExportFormat::brf},
        GoldenCase{"structure-md.pef", "structure.md", "en-ueb-g1.ctb", true, exporter::ExportFormat::pef},
        // A table over two pages: its headings repeated on the second.
        GoldenCase{"structure-long-table.brf", "structure-long-table.md", "en-ueb-g2.ctb", true,
                   exporter::ExportFormat::brf},
        // A listed table over three pages: its headings (the header row, listed)
        // repeated at the top of each page it runs on to, rows kept whole.
        GoldenCase{"structure-long-listed-table.brf", "structure-long-listed-table.md", "en-ueb-g2.ctb", true,
                   exporter::ExportFormat::brf},
        // Merged cells: a simple table with headings over two rows and two
        // columns, and a listed one. The two files are one document.
        GoldenCase{"structure-spans-docx.brf", "structure-spans.docx", "en-ueb-g2.ctb", true,
                   exporter::ExportFormat::brf},
        GoldenCase{"structure-spans-odt.brf", "structure-spans.odt", "en-ueb-g2.ctb", true,
                   exporter::ExportFormat::brf},
        // Blank lines by Braille Formats 2016 Appendix C (a quote and a list
        // right under a cell-5 or cell-7 heading, a table after a blank line),
        // notes inside a quote and a list; the note reference indicator of UEB
        // and of EBAE (en-us-g2.ctb), and the parentheses of a code without
        // one (zh-tw.ctb).
        // Real files whose table cells hold several paragraphs or a list: each
        // paragraph of an entry on a line of its own, in listed format.
        GoldenCase{"cell-paragraphs-docx.brf", "public/pandoc-tables.docx", "en-ueb-g2.ctb", false,
                   exporter::ExportFormat::brf},
        GoldenCase{"cell-paragraphs-list-docx.brf", "public/pandoc-table_with_list_cell.docx", "en-ueb-g2.ctb", false,
                   exporter::ExportFormat::brf},
        GoldenCase{"cell-paragraphs-odt.brf", "public/odfdo-table.odt", "en-ueb-g2.ctb", false,
                   exporter::ExportFormat::brf},
        GoldenCase{"cell-paragraphs-html.brf", "public/pandoc-table_with_list_cell.html", "en-ueb-g2.ctb", false,
                   exporter::ExportFormat::brf},
        GoldenCase{"structure-formats.brf", "structure-formats.md", "en-ueb-g2.ctb", true,
                   exporter::ExportFormat::brf},
        GoldenCase{"structure-formats-ebae.brf", "structure-formats.md", "en-us-g2.ctb", true,
                   exporter::ExportFormat::brf},
        GoldenCase{"structure-notes-zh.brf", "structure-notes-zh.md", "zh-tw.ctb", true,
                   exporter::ExportFormat::brf}),
    [](const auto& param_info) {
        std::string n = param_info.param.name;
        for (auto& ch : n)
            if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        return n;
    });

// BRF written by Tactus and read back lays out to the same pages.
TEST(RoundTrip, BrfExportImportLayout) {
    pipeline::PipelineOptions o;
    o.layout.geometry.interpoint = true;
    auto doc = pipeline::lay_out_file(kSamples / "welcome.md", o);
    ASSERT_TRUE(doc);
    const auto brf = exporter::to_brf(*doc);
    ASSERT_TRUE(brf);
    auto imported = import::import_bytes(*brf, "welcome.brf");
    ASSERT_TRUE(imported) << imported.error().to_string();
    // Page numbers are already in the BRF text: lay it out without adding more.
    o.layout.page_numbers = layout::PageNumberPosition::none;
    auto again = pipeline::lay_out(*imported, o);
    ASSERT_TRUE(again) << again.error().to_string();
    EXPECT_EQ(exporter::to_brf(*again).value(), *brf);
}

TEST(RoundTrip, PefExportImportLayout) {
    pipeline::PipelineOptions o;
    o.tables = "zh-tw.ctb";
    o.layout.geometry.interpoint = true;
    auto doc = pipeline::lay_out_file(kSamples / "chinese-tw.txt", o);
    ASSERT_TRUE(doc);
    const auto pef = exporter::to_pef(*doc);
    ASSERT_TRUE(pef);
    auto imported = import::import_bytes(*pef, "x.pef");
    ASSERT_TRUE(imported) << imported.error().to_string();
    o.layout.page_numbers = layout::PageNumberPosition::none;
    auto again = pipeline::lay_out(*imported, o);
    ASSERT_TRUE(again);
    ASSERT_EQ(again->pages.size(), doc->pages.size());
    for (std::size_t p = 0; p < doc->pages.size(); ++p)
        EXPECT_EQ(again->pages[p].lines, doc->pages[p].lines) << "page " << p + 1;
}

// The DOCX and the ODT with merged cells are one document: the same braille.
TEST(Golden, MergedCellsLayOutAlikeFromDocxAndOdt) {
    const auto docx = read_file(fs::path(TACTUS_GOLDEN_DIR) / "structure-spans-docx.brf");
    const auto odt = read_file(fs::path(TACTUS_GOLDEN_DIR) / "structure-spans-odt.brf");
    ASSERT_TRUE(docx && odt);
    EXPECT_EQ(*docx, *odt);
}
