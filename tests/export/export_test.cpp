// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "../layout/cells.hpp"
#include "export/export.hpp"
#include "pef_checks.hpp"

using namespace tactus;

namespace {

layout::PagedDocument two_pages(bool interpoint) {
    layout::PagedDocument d;
    d.geometry = {6, 3, interpoint, false};
    layout::Page a;
    a.braille_number = 1;
    a.lines = {brf(",HI"), {}, brf("    #A")};
    layout::Page b;
    b.braille_number = 2;
    b.lines = {brf("BYE"), {}, {}};
    d.pages = {a, b};
    return d;
}

}  // namespace

TEST(BrfExport, CrlfLinesAndFormFeedAfterEveryPage) {
    const auto brf_text = exporter::to_brf(two_pages(true));
    ASSERT_TRUE(brf_text);
    EXPECT_EQ(*brf_text, ",HI\r\n\r\n    #A\r\n\fBYE\r\n\f");
}

TEST(BrfExport, EightDotCellsAreRefusedWithTheirPlace) {
    auto d = two_pages(false);
    d.pages[1].lines[0][1].dots |= 0x80;
    const auto r = exporter::to_brf(d);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().where, "page 2 line 1");
}

TEST(UnicodeExport, LinesAndFormFeedsBetweenPages) {
    EXPECT_EQ(exporter::to_unicode(two_pages(false)), "⠠⠓⠊\n\n⠀⠀⠀⠀⠼⠁\n\f⠃⠽⠑\n");
}

TEST(PefExport, ValidatesAgainstTheSchemaAndSchematronRules) {
    for (bool duplex : {false, true}) {
        exporter::PefMetadata meta;
        meta.title = "Test & <escape>";
        meta.language = "en";
        meta.date = "2026-11-21";
        const auto pef = exporter::to_pef(two_pages(duplex), meta);
        ASSERT_TRUE(pef);
        EXPECT_EQ(validate_pef_schema(*pef), "");
        EXPECT_EQ(check_pef_schematron(*pef), "");
        EXPECT_NE(pef->find(duplex ? "duplex=\"true\"" : "duplex=\"false\""), std::string::npos);
        EXPECT_NE(pef->find("<row>⠠⠓⠊</row>"), std::string::npos);
        EXPECT_NE(pef->find("Test &amp; &lt;escape&gt;"), std::string::npos);
    }
}

// A book's own metadata (EPUB, DTBook) as it comes: two titles (a subtitle),
// a timestamp and a bare year as dates. PEF allows one title and one
// YYYY-MM-DD date: the first title and the timestamp's day are written.
TEST(PefExport, SourceMetadataKeepsTheSchemasSingleElementsSingle) {
    exporter::PefMetadata meta;
    meta.source = {{"title", "Frankenstein"}, {"title", "Or, The Modern Prometheus"}, {"creator", "Mary Shelley"},
                   {"date", "2015-05-12T00:01:00Z"}, {"date", "1818"}, {"language", "en-GB"}};
    const auto pef = exporter::to_pef(two_pages(true), meta);
    ASSERT_TRUE(pef);
    EXPECT_EQ(validate_pef_schema(*pef), "");
    EXPECT_NE(pef->find("<dc:title>Frankenstein</dc:title>"), std::string::npos);
    EXPECT_EQ(pef->find("Prometheus"), std::string::npos);
    EXPECT_NE(pef->find("<dc:date>2015-05-12</dc:date>"), std::string::npos);
    EXPECT_EQ(pef->find("1818"), std::string::npos);
}

// A document whose metadata is its main language alone (a DOCX's, an ODT's)
// has no head of its own: the PEF gets the one made for the export, with its
// title, date and the braille's language; any other item makes it the source's.
TEST(PefExport, AMainLanguageAloneIsNotTheSourcesHead) {
    const auto made = exporter::pef_metadata({{"language", "zh-TW"}}, "lesson.docx", "2030-01-01", "en");
    EXPECT_TRUE(made.source.empty());
    const auto pef = exporter::to_pef(two_pages(true), made);
    ASSERT_TRUE(pef);
    EXPECT_NE(pef->find("<dc:title>lesson.docx</dc:title>"), std::string::npos);
    EXPECT_NE(pef->find("<dc:language>en</dc:language>"), std::string::npos);
    EXPECT_NE(pef->find("<dc:date>2030-01-01</dc:date>"), std::string::npos);
    const auto own = exporter::pef_metadata({{"language", "zh-TW"}, {"title", "A book"}}, "x", "2030-01-01", "en");
    EXPECT_EQ(own.source.size(), 2u);
}

TEST(PefExport, IdentifierIsStableAndContentDerived) {
    const auto a = exporter::to_pef(two_pages(true));
    const auto b = exporter::to_pef(two_pages(true));
    auto other = two_pages(true);
    other.pages[1].lines[0] = brf("BYF");
    const auto c = exporter::to_pef(other);
    ASSERT_TRUE(a && b && c);
    EXPECT_EQ(*a, *b);
    EXPECT_NE(*a, *c);
}

TEST(PefChecks, DetectViolations) {
    // The checks themselves must be able to fail.
    const std::string too_long =
        R"(<pef xmlns="http://www.daisy.org/ns/2008/pef"><body><volume cols="2" rows="1" rowgap="0" duplex="false"><section><page><row>⠁⠁⠁</row></page></section></volume></body></pef>)";
    EXPECT_NE(check_pef_schematron(too_long), "");
    const std::string too_many =
        R"(<pef xmlns="http://www.daisy.org/ns/2008/pef"><body><volume cols="2" rows="1" rowgap="0" duplex="false"><section><page><row>⠁</row><row>⠁</row></page></section></volume></body></pef>)";
    EXPECT_NE(check_pef_schematron(too_many), "");
    EXPECT_NE(validate_pef_schema("<pef/>"), "");
}

TEST(ExportFormat, ParsesNamesAndRejectsOthers) {
    EXPECT_EQ(*exporter::parse_export_format("pef"), exporter::ExportFormat::pef);
    EXPECT_FALSE(exporter::parse_export_format("docx"));
}
