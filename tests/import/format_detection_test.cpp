// SPDX-License-Identifier: GPL-3.0-or-later
#include "import_test_util.hpp"

namespace tactus::test {
namespace {

TEST(FormatDetection, ExtensionDecidesFirst) {
    EXPECT_EQ(detect_source_format("", "a.TXT"), SourceFormat::text);
    EXPECT_EQ(detect_source_format("", "dir.v2/a.md"), SourceFormat::markdown);
    EXPECT_EQ(detect_source_format("", "a.markdown"), SourceFormat::markdown);
    EXPECT_EQ(detect_source_format("", "a.docx"), SourceFormat::docx);
    EXPECT_EQ(detect_source_format("", "a.brf"), SourceFormat::brf);
    EXPECT_EQ(detect_source_format("", "a.pef"), SourceFormat::pef);
    // A .txt file stays text even when it starts like a ZIP.
    EXPECT_EQ(detect_source_format("PK\x03\x04", "a.txt"), SourceFormat::text);
}

TEST(FormatDetection, ContentWhenTheExtensionSaysNothing) {
    EXPECT_EQ(detect_source_format(read_data("lesson.docx"), "upload"), SourceFormat::docx);
    EXPECT_EQ(detect_source_format(read_data("lesson.pef"), "upload.xml"), SourceFormat::pef);
    EXPECT_EQ(detect_source_format("\xEF\xBB\xBF<!-- c --><x:pef xmlns:x='y'>", "f"),
              SourceFormat::pef);
    EXPECT_EQ(detect_source_format("<html><pef/></html>", "f"), SourceFormat::text);
    EXPECT_EQ(detect_source_format("hello", "README"), SourceFormat::text);
}

TEST(FormatDetection, ImportOfARenamedFileUsesItsContent) {
    const auto bytes = read_data("lesson.docx");
    const auto doc = import_bytes(bytes, "lesson.download");
    ASSERT_TRUE(doc) << doc.error().to_string();
    EXPECT_EQ(doc->blocks.at(0).text(), "Weather Lesson");
}

TEST(FormatDetection, ForcedFormatWinsOverTheExtension) {
    const auto doc = import_bytes("# Not a heading\n", "a.md", {SourceFormat::text, {}});
    ASSERT_TRUE(doc);
    EXPECT_EQ(doc->blocks.at(0).kind, BlockKind::paragraph);
    EXPECT_EQ(doc->blocks.at(0).text(), "# Not a heading");
}

TEST(FormatDetection, ParseSourceFormatNames) {
    EXPECT_EQ(parse_source_format("txt"), SourceFormat::text);
    EXPECT_EQ(parse_source_format("TEXT"), SourceFormat::text);
    EXPECT_EQ(parse_source_format("md"), SourceFormat::markdown);
    EXPECT_EQ(parse_source_format("Markdown"), SourceFormat::markdown);
    EXPECT_EQ(parse_source_format("docx"), SourceFormat::docx);
    EXPECT_EQ(parse_source_format("brf"), SourceFormat::brf);
    EXPECT_EQ(parse_source_format("pef"), SourceFormat::pef);
    EXPECT_EQ(parse_source_format("auto"), SourceFormat::automatic);
    const auto bad = parse_source_format("rtf");
    ASSERT_FALSE(bad);
    EXPECT_THAT(bad.error().message, testing::HasSubstr("unknown input format 'rtf'"));
    for (auto f : {SourceFormat::text, SourceFormat::markdown, SourceFormat::docx,
                   SourceFormat::brf, SourceFormat::pef, SourceFormat::automatic})
        EXPECT_EQ(parse_source_format(source_format_name(f)), f);
}

TEST(FormatDetection, MissingFileNamesThePath) {
    const auto doc = import_file(import_data("does-not-exist.txt"));
    ASSERT_FALSE(doc);
    EXPECT_THAT(doc.error().where, testing::HasSubstr("does-not-exist.txt"));
}

}  // namespace
}  // namespace tactus::test
