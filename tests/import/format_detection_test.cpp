// SPDX-License-Identifier: GPL-3.0-or-later
#include "import_test_util.hpp"

namespace tactus::test {
namespace {

TEST(FormatDetection, ExtensionDecidesFirst) {
    EXPECT_EQ(import::detect_source_format("", "a.TXT"), import::SourceFormat::text);
    EXPECT_EQ(import::detect_source_format("", "dir.v2/a.md"), import::SourceFormat::markdown);
    EXPECT_EQ(import::detect_source_format("", "a.markdown"), import::SourceFormat::markdown);
    EXPECT_EQ(import::detect_source_format("", "a.docx"), import::SourceFormat::docx);
    EXPECT_EQ(import::detect_source_format("", "a.brf"), import::SourceFormat::brf);
    EXPECT_EQ(import::detect_source_format("", "a.pef"), import::SourceFormat::pef);
    // A .txt file stays text even when it starts like a ZIP.
    EXPECT_EQ(import::detect_source_format("PK\x03\x04", "a.txt"), import::SourceFormat::text);
}

TEST(FormatDetection, ContentWhenTheExtensionSaysNothing) {
    EXPECT_EQ(import::detect_source_format(read_data("lesson.docx"), "upload"), import::SourceFormat::docx);
    EXPECT_EQ(import::detect_source_format(read_data("lesson.pef"), "upload.xml"), import::SourceFormat::pef);
    EXPECT_EQ(import::detect_source_format("\xEF\xBB\xBF<!-- c --><x:pef xmlns:x='y'>", "f"),
              import::SourceFormat::pef);
    // The root decides: a <pef> inside <html> is an HTML page, not PEF.
    EXPECT_EQ(import::detect_source_format("<html><pef/></html>", "f"), import::SourceFormat::html);
    EXPECT_EQ(import::detect_source_format("hello", "README"), import::SourceFormat::text);
}

// A ZIP signature with less than a local header after it (found by
// fuzz_front_half): told as a package, then refused by its reader with the
// reason, where reading the stored type past the end used to throw.
TEST(FormatDetection, AZipSignatureCutShortIsRefusedNotACrash) {
    for (const std::string_view bytes :
         {std::string_view("PK\x03\x04"), std::string_view("PK\x03\x04\xE6\x88\x91 short root\x82\n"),
          std::string_view("PK\x03\x04\x14\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00"
                           "\x00\x00\x08\x00\x00\x00mimety")}) {
        EXPECT_EQ(import::detect_source_format(bytes, "upload"), import::SourceFormat::docx);
        const auto doc = import::import_bytes(bytes, "upload");
        ASSERT_FALSE(doc);
        EXPECT_FALSE(doc.error().message.empty());
    }
}

TEST(FormatDetection, ImportOfARenamedFileUsesItsContent) {
    const auto bytes = read_data("lesson.docx");
    const auto doc = import::import_bytes(bytes, "lesson.download");
    ASSERT_TRUE(doc) << doc.error().to_string();
    EXPECT_EQ(doc->blocks.at(0).text(), "Weather Lesson");
}

TEST(FormatDetection, ForcedFormatWinsOverTheExtension) {
    const auto doc = import::import_bytes("# Not a heading\n", "a.md", {import::SourceFormat::text, {}});
    ASSERT_TRUE(doc);
    EXPECT_EQ(doc->blocks.at(0).kind, document::BlockKind::paragraph);
    EXPECT_EQ(doc->blocks.at(0).text(), "# Not a heading");
}

TEST(FormatDetection, ParseSourceFormatNames) {
    EXPECT_EQ(import::parse_source_format("txt"), import::SourceFormat::text);
    EXPECT_EQ(import::parse_source_format("TEXT"), import::SourceFormat::text);
    EXPECT_EQ(import::parse_source_format("md"), import::SourceFormat::markdown);
    EXPECT_EQ(import::parse_source_format("Markdown"), import::SourceFormat::markdown);
    EXPECT_EQ(import::parse_source_format("docx"), import::SourceFormat::docx);
    EXPECT_EQ(import::parse_source_format("brf"), import::SourceFormat::brf);
    EXPECT_EQ(import::parse_source_format("pef"), import::SourceFormat::pef);
    EXPECT_EQ(import::parse_source_format("auto"), import::SourceFormat::automatic);
    const auto bad = import::parse_source_format("rtf");
    ASSERT_FALSE(bad);
    EXPECT_THAT(bad.error().message, testing::HasSubstr("unknown input format 'rtf'"));
    for (auto f : {import::SourceFormat::text, import::SourceFormat::markdown, import::SourceFormat::docx,
                   import::SourceFormat::brf, import::SourceFormat::pef, import::SourceFormat::automatic})
        EXPECT_EQ(import::parse_source_format(source_format_name(f)), f);
}

TEST(FormatDetection, MissingFileNamesThePath) {
    const auto doc = import::import_file(import_data("does-not-exist.txt"));
    ASSERT_FALSE(doc);
    EXPECT_THAT(doc.error().where, testing::HasSubstr("does-not-exist.txt"));
}

}  // namespace
}  // namespace tactus::test
