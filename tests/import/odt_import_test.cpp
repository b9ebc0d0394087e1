// SPDX-License-Identifier: GPL-3.0-or-later
#include "import_test_util.hpp"

#include "document/main_language.hpp"
#include "export/zip_writer.hpp"

namespace tactus::test {
namespace {

using namespace shorthand;

// lesson.odt is hand-made (tests/data/import/README.md) with the structure
// LibreOffice writes: automatic text styles, list styles, a page break from a
// paragraph style, soft page breaks, a note, a table.
TEST(OdtImport, TheSameLessonAsTheDocx) {
    const auto doc = import_data_file("lesson.odt");
    const std::vector<document::Block> expected = {
        text_block(H, 1, {{"Weather Lesson"}}),
        text_block(P, 0,
                   {{"Today we learn about "}, {"clouds", B}, {" and "}, {"rain", I}, {", and the "},
                    {"water cycle", U}, {"."}}),
        text_block(H, 2, {{"Kinds of clouds"}}),  // heading style bold is not emphasis
        text_block(LI, 1, {{"\u2022 Cumulus"}}),  // a bullet level: the bullet sign
        text_block(LI, 1, {{"\u2022 Stratus"}}),
        text_block(LI, 2, {{"\u2022 Nimbostratus"}}),
        text_block(LI, 1, {{"1. Look at the sky."}}),  // numbered: the label is text
        text_block(LI, 1, {{"2. Write what you see."}}),
        page_break("2"),  // fo:break-before="page"; the soft page break is none
        text_block(P, 0, {{"今天的天气很好，我们一起去公园散步吧。"}}),
        // A text style inherits its parent's bold; the note's reference is in
        // the text and the note follows the paragraph.
        text_block(P, 0, {{"Plain "}, {"bold italic", B | I}, {" end.\tTab\nand   spaces"}, reference("1"), {"."}}),
        text_block(N, 0, {reference("1"), {" A note"}}),
        table_row(false),
        text_block(C, 0, {{"Cloud"}}),
        text_block(C, 1, {{"雲"}}),
    };
    EXPECT_EQ(doc.blocks, expected);
}

// Languages from styles (hand-made, as LibreOffice writes them): the
// paragraph default style (English, Chinese (PRC) for Asian text), a common
// paragraph style for German, an automatic one based on it, and automatic
// text styles for Chinese (Taiwan) and, by style:rfc-language-tag, Serbian in
// Latin letters.
TEST(OdtImport, LanguagesComeFromStylesAndDefaults) {
    constexpr std::string_view ns =
        R"( xmlns:office="urn:oasis:names:tc:opendocument:xmlns:office:1.0")"
        R"( xmlns:style="urn:oasis:names:tc:opendocument:xmlns:style:1.0")"
        R"( xmlns:text="urn:oasis:names:tc:opendocument:xmlns:text:1.0")"
        R"( xmlns:fo="urn:oasis:names:tc:opendocument:xmlns:xsl-fo-compatible:1.0")";
    const std::string styles = std::string("<office:document-styles") + std::string(ns) + "><office:styles>" +
        R"(<style:default-style style:family="paragraph"><style:text-properties fo:language="en" fo:country="US")"
        R"( style:language-asian="zh" style:country-asian="CN" style:language-complex="hi" style:country-complex="IN"/>)"
        R"(</style:default-style>)"
        R"(<style:style style:name="Standard" style:family="paragraph"/>)"
        R"(<style:style style:name="Deutsch" style:family="paragraph" style:parent-style-name="Standard">)"
        R"(<style:text-properties fo:language="de" fo:country="DE"/></style:style>)"
        "</office:styles></office:document-styles>";
    const std::string content = std::string("<office:document-content") + std::string(ns) +
        "><office:automatic-styles>" +
        R"(<style:style style:name="P1" style:family="paragraph" style:parent-style-name="Deutsch"/>)"
        R"(<style:style style:name="T1" style:family="text"><style:text-properties style:language-asian="zh")"
        R"( style:country-asian="TW"/></style:style>)"
        R"(<style:style style:name="T2" style:family="text"><style:text-properties fo:language="sr")"
        R"( style:rfc-language-tag="sr-Latn"/></style:style>)"
        "</office:automatic-styles><office:body><office:text>" +
        R"(<text:p text:style-name="Standard">English 中文 <text:span text:style-name="T1">漢語 and words</text:span></text:p>)"
        R"(<text:p text:style-name="P1">Guten Tag 中文 <text:span text:style-name="T2">zdravo</text:span></text:p>)"
        "</office:text></office:body></office:document-content>";
    auto package = exporter::zip_package({{"mimetype", "application/vnd.oasis.opendocument.text", true},
                                          {"content.xml", content, false},
                                          {"styles.xml", styles, false}});
    ASSERT_TRUE(package) << package.error().to_string();
    auto doc = import::import_bytes(*package, "styles.odt");
    ASSERT_TRUE(doc) << doc.error().to_string();
    std::vector<std::pair<std::string, std::string>> got;
    for (const auto& b : doc->blocks)
        for (const auto& s : b.spans) got.emplace_back(s.text, s.language);
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"English 中文 ", ""}, {"漢語 ", "zh-TW"}, {"and words", ""},
        {"Guten Tag ", "de-DE"}, {"中文 ", ""}, {"zdravo", "sr-Latn"},
    };
    EXPECT_EQ(got, expected);
}

// The document's main language: the default style's where it names one
// (as LibreOffice writes it), else meta.xml's dc:language.
TEST(OdtImport, TheMainLanguageComesFromTheDefaultStyleElseTheMeta) {
    constexpr std::string_view ns =
        R"( xmlns:office="urn:oasis:names:tc:opendocument:xmlns:office:1.0")"
        R"( xmlns:style="urn:oasis:names:tc:opendocument:xmlns:style:1.0")"
        R"( xmlns:text="urn:oasis:names:tc:opendocument:xmlns:text:1.0")"
        R"( xmlns:fo="urn:oasis:names:tc:opendocument:xmlns:xsl-fo-compatible:1.0")"
        R"( xmlns:dc="http://purl.org/dc/elements/1.1/")";
    const std::string content = "<office:document-content" + std::string(ns) +
        "><office:body><office:text><text:p>我住在台北。</text:p></office:text></office:body></office:document-content>";
    const std::string meta = "<office:document-meta" + std::string(ns) +
        "><office:meta><dc:language> zh-TW </dc:language></office:meta></office:document-meta>";
    const std::string styles = "<office:document-styles" + std::string(ns) +
        R"(><office:styles><style:default-style style:family="paragraph"><style:text-properties)"
        R"( fo:language="en" fo:country="US" style:language-asian="zh" style:country-asian="HK"/>)"
        "</style:default-style></office:styles></office:document-styles>";
    const auto main_language_of = [&](bool with_styles) {
        std::vector<exporter::ZipPart> parts = {{"mimetype", "application/vnd.oasis.opendocument.text", true},
                                                {"content.xml", content, false},
                                                {"meta.xml", meta, false}};
        if (with_styles) parts.push_back({"styles.xml", styles, false});
        auto package = exporter::zip_package(parts);
        EXPECT_TRUE(package);
        auto doc = import::import_bytes(package.value_or(std::string()), "language.odt");
        EXPECT_TRUE(doc) << doc.error().to_string();
        return doc ? document::main_language(*doc) : std::string("?");
    };
    EXPECT_EQ(main_language_of(false), "zh-TW");
    // The styles' language for Han text (the text's script), not the Latin one.
    EXPECT_EQ(main_language_of(true), "zh-HK");
}

TEST(OdtImport, DetectedByExtensionAndContent) {
    const auto bytes = read_data("lesson.odt");
    EXPECT_EQ(import::detect_source_format(bytes, "lesson.odt"), import::SourceFormat::odt);
    EXPECT_EQ(import::detect_source_format(bytes, "no-extension"), import::SourceFormat::odt);
    EXPECT_EQ(import::parse_source_format("ODT").value(), import::SourceFormat::odt);
}

TEST(OdtImport, AMissingContentPartIsNamed) {
    const auto e = import_data_file_error("no_content.odt");
    EXPECT_NE(e.message.find("missing part content.xml"), std::string::npos) << e.to_string();
    EXPECT_NE(e.where.find("no_content.odt"), std::string::npos) << e.to_string();
}

TEST(OdtImport, AnotherOpenDocumentKindIsRefused) {
    // A spreadsheet saved under an .odt name: its mimetype entry says so.
    const auto e = import_data_file_error("spreadsheet.odt");
    EXPECT_NE(e.message.find("not an OpenDocument text but application/vnd.oasis.opendocument.spreadsheet"),
              std::string::npos)
        << e.to_string();
}

}  // namespace
}  // namespace tactus::test
