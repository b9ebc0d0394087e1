// SPDX-License-Identifier: GPL-3.0-or-later
#include "import_test_util.hpp"

#include "document/main_language.hpp"
#include "export/zip_writer.hpp"
#include "import/office_language.hpp"
#include "../common/office_files.hpp"

namespace tactus::test {
namespace {

using namespace shorthand;

// lesson.docx was written by LibreOffice 7.4 from lesson.html (both committed).
TEST(DocxImport, DocumentWrittenByLibreOffice) {
    const auto doc = import_data_file("lesson.docx");
    const std::vector<document::Block> expected = {
        text_block(H, 1, {{"Weather Lesson"}}),
        text_block(P, 0,
                   {{"Today we learn about "}, {"clouds", B}, {" and "}, {"rain", I},
                    {", and the "}, {"water cycle", U}, {"."}}),
        text_block(H, 2, {{"Kinds of clouds"}}),
        text_block(LI, 1, {{"\u2022 Cumulus "}}),  // Word's bullet glyph becomes the bullet sign
        text_block(LI, 1, {{"\u2022 Stratus "}}),
        text_block(LI, 2, {{"\u2022 Nimbostratus"}}),
        text_block(LI, 1, {{"1. Look at the sky. "}}),
        text_block(LI, 1, {{"2. Write what you see. "}}),
        page_break("2"),
        text_block(P, 0, {{"今天的天气很好，我们一起去公园散步吧。"}}),
        text_block(H, 3, {{"Summary"}}),
        text_block(P, 0,
                   {{"Plain "}, {"bold italic", B | I}, {" end. A "}, {"strong", B},
                    {" and an "}, {"emphasised", I}, {" word."}}),
        table_row(false),
        text_block(C, 0, {{"Cloud"}}),
        text_block(C, 1, {{"雲"}}),
    };
    EXPECT_EQ(doc.blocks, expected);
    EXPECT_EQ(doc.encoding, "");
}

// features.docx is hand-made (see tests/data/import/README.md) to reach what
// LibreOffice did not write: renamed parts, style chains, numbering formats,
// section breaks, tracked changes.
TEST(DocxImport, StylesNumberingBreaksAndRevisions) {
    const auto doc = import_data_file("features.docx");
    const std::vector<document::Block> expected = {
        text_block(H, 1, {{"The Title"}}),  // bold of the Title style is not emphasis
        text_block(P, 0, {{"Tab\tand\nline kept"}}),  // lastRenderedPageBreak is no break
        text_block(P, 0, {{"styled", I | U}, {"link", B}}),  // a link's underline is print's, not emphasis
        text_block(LI, 1, {{"III. first"}}),
        text_block(LI, 2, {{"III.a) sub"}}),
        page_break("2"),
        text_block(LI, 1, {{"IV. second"}}),
        text_block(P, 0, {{"not a list"}}),
        page_break("3"),
        text_block(P, 0, {{"after break"}}),
        page_break("4"),  // pageBreakBefore from the style
        text_block(H, 1, {{"Chapter"}}),
        text_block(H, 2, {{"Sub"}}),  // continuous section break: no page
        text_block(P, 0, {{"end of section"}}),
        page_break("5"),  // section break (next page) after the paragraph
        text_block(H, 4, {{"Outline four"}}),
    };
    EXPECT_EQ(doc.blocks, expected);
}

// The per-script rule of DOCX and ODT languages (import/office_language.hpp)
// on its own, with a Taiwanese Word's defaults: each character takes the
// language of its script's class, a character of no script the class of
// the letter before it (else after it, else Latin), and only a language
// other than the document's own for that class is marked.
TEST(OfficeLanguage, EachCharacterTakesTheLanguageOfItsScript) {
    using import::detail::language_pieces;
    using import::detail::OfficeLanguages;
    const auto pieces = [](std::string_view text, const OfficeLanguages& run, const OfficeLanguages& doc) {
        std::vector<std::pair<std::string, std::string>> out;
        for (const auto& p : language_pieces(text, run, doc)) out.emplace_back(std::string(p.text), p.language);
        return out;
    };
    using Pieces = std::vector<std::pair<std::string, std::string>>;
    OfficeLanguages doc;
    doc.latin = "en-US";
    doc.east_asian = "zh-TW";
    doc.complex = "ar-SA";
    EXPECT_EQ(pieces("Hello 你好, world", doc, doc), (Pieces{{"Hello 你好, world", ""}}));
    auto mainland = doc;
    mainland.east_asian = "zh-CN";
    EXPECT_EQ(pieces("Hello 你好, world", mainland, doc),
              (Pieces{{"Hello ", ""}, {"你好, ", "zh-CN"}, {"world", ""}}));
    EXPECT_EQ(pieces("(2024) 中文。", mainland, doc), (Pieces{{"(2024) 中文。", "zh-CN"}}));
    EXPECT_EQ(pieces(" 2024\t", mainland, doc), (Pieces{{" 2024\t", ""}}));
    auto german = doc;
    german.latin = "de-DE";
    EXPECT_EQ(pieces("Guten Tag 中文", german, doc), (Pieces{{"Guten Tag ", "de-DE"}, {"中文", ""}}));
    // A run in one language for every class (as Tactus writes a passage) is
    // that language whatever its characters.
    OfficeLanguages english;
    english.latin = english.east_asian = english.complex = "en";
    EXPECT_EQ(pieces("A 中 \u0628 2", english, doc), (Pieces{{"A 中 \u0628 2", "en"}}));
    // Arabic letters, and every character of a right-to-left run, are complex script.
    auto hebrew = doc;
    hebrew.complex = "he-IL";
    EXPECT_EQ(pieces("abc \u05D0", hebrew, doc), (Pieces{{"abc ", ""}, {"\u05D0", "he-IL"}}));
    hebrew.complex_run = true;
    EXPECT_EQ(pieces("abc", hebrew, doc), (Pieces{{"abc", "he-IL"}}));
    // No defaults: every language a run names is marked.
    EXPECT_EQ(pieces("x", german, OfficeLanguages{}), (Pieces{{"x", "de-DE"}}));
    EXPECT_EQ(import::detail::language_tag("zh", "TW"), "zh-TW");
    EXPECT_EQ(import::detail::language_tag("zxx", "none"), "");
    EXPECT_EQ(import::detail::language_tag("fr", "none"), "fr");
}

// The text and its languages, span by span.
std::vector<std::pair<std::string, std::string>> languages_of(const document::Document& doc) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& b : doc.blocks)
        for (const auto& s : b.spans) out.emplace_back(s.text, s.language);
    return out;
}

// pandoc's i18n_blocks.docx (tests/data/import/public), made by a Russian
// Word: its defaults say Russian (w:docDefaults w:lang w:val="ru-RU"), and
// every run is set to English (w:lang w:val="en-US"). So each block's text is
// an English passage in a Russian document; a list item's bullet, which the
// importer adds, is the document's.
TEST(DocxImport, LanguagesOfARealDocument) {
    const auto doc = import_data_file("public/pandoc-i18n_blocks.docx");
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"This is Heading 1", "en-US"}, {"This is Heading 2", "en-US"},  {"This is Quote", "en-US"},
        {"This is Block Text", "en-US"}, {"\u2022 ", ""},                 {"This is list item 1", "en-US"},
        {"\u2022 ", ""},                  {"This is list item 2", "en-US"},
    };
    EXPECT_EQ(languages_of(doc), expected);
}

// Every other real DOCX and ODT of the test data is written in the languages
// its defaults name (LibreOffice's ODTs: German, French or English in the
// paragraph default style; pandoc-unicode.docx's Japanese is only its
// paragraph mark's, w:pPr/w:rPr, not its text's): no span is marked.
TEST(OfficeLanguage, RealDocumentsInTheirDefaultLanguagesCarryNoMarks) {
    int files = 0;
    for (const auto& path : real_office_files(std::filesystem::path(TACTUS_TEST_DATA))) {
        // Made to have passages in other languages: tested on their own.
        if (path.filename() == "pandoc-i18n_blocks.docx" || path.filename() == "table_language.docx") continue;
        auto doc = import::import_file(path);
        if (!doc) continue;  // the importer's own error files
        ++files;
        for (const auto& [text, language] : languages_of(*doc))
            EXPECT_EQ(language, "") << path.filename().string() << ": '" << text << "'";
    }
    EXPECT_GE(files, 40);
}

// Languages from styles (hand-made, as Word writes them): the document
// defaults (English, Chinese (Taiwan) for East Asian text), a paragraph
// style based on one that sets German, a character style that sets
// Chinese (PRC) for East Asian text, and direct formatting over both.
TEST(DocxImport, LanguagesComeFromStylesAndDefaults) {
    constexpr std::string_view w = R"( xmlns:w="http://schemas.openxmlformats.org/wordprocessingml/2006/main")";
    const std::string styles = std::string("<w:styles") + std::string(w) +
        R"(><w:docDefaults><w:rPrDefault><w:rPr><w:lang w:val="en-US" w:eastAsia="zh-TW" w:bidi="ar-SA"/></w:rPr>)"
        R"(</w:rPrDefault></w:docDefaults>)"
        R"(<w:style w:type="paragraph" w:default="1" w:styleId="Normal"><w:name w:val="Normal"/></w:style>)"
        R"(<w:style w:type="paragraph" w:styleId="German"><w:name w:val="German"/><w:basedOn w:val="Normal"/>)"
        R"(<w:rPr><w:lang w:val="de-DE"/></w:rPr></w:style>)"
        R"(<w:style w:type="paragraph" w:styleId="GermanQuote"><w:name w:val="German quote"/><w:basedOn w:val="German"/></w:style>)"
        R"(<w:style w:type="character" w:styleId="Mainland"><w:name w:val="Mainland"/>)"
        R"(<w:rPr><w:lang w:eastAsia="zh-CN"/></w:rPr></w:style></w:styles>)";
    const std::string body = std::string("<w:document") + std::string(w) + "><w:body>" +
        R"(<w:p><w:r><w:t xml:space="preserve">English 中文 </w:t></w:r>)"
        R"(<w:r><w:rPr><w:rStyle w:val="Mainland"/></w:rPr><w:t>汉语 and words</w:t></w:r></w:p>)"
        R"(<w:p><w:pPr><w:pStyle w:val="GermanQuote"/></w:pPr><w:r><w:t xml:space="preserve">Guten Tag 中文 </w:t></w:r>)"
        R"(<w:r><w:rPr><w:lang w:val="en-US"/></w:rPr><w:t>hello</w:t></w:r></w:p>)"
        "</w:body></w:document>";
    constexpr std::string_view rels = "http://schemas.openxmlformats.org/officeDocument/2006/relationships";
    const std::string head = R"(<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">)";
    auto package = exporter::zip_package(
        {{"_rels/.rels", head + R"(<Relationship Id="r1" Type=")" + std::string(rels) +
                             R"(/officeDocument" Target="word/document.xml"/></Relationships>)", false},
         {"word/_rels/document.xml.rels", head + R"(<Relationship Id="r1" Type=")" + std::string(rels) +
                                              R"(/styles" Target="styles.xml"/></Relationships>)", false},
         {"word/document.xml", body, false},
         {"word/styles.xml", styles, false}});
    ASSERT_TRUE(package) << package.error().to_string();
    auto doc = import::import_bytes(*package, "styles.docx");
    ASSERT_TRUE(doc) << doc.error().to_string();
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"English 中文 ", ""}, {"汉语 ", "zh-CN"}, {"and words", ""},
        {"Guten Tag ", "de-DE"}, {"中文 hello", ""},
    };
    EXPECT_EQ(languages_of(*doc), expected);
}

// A table style's language is its text's (Word's order: the document
// defaults, the table style, the paragraph style, the run): python-docx's
// "Light Grid Accent 1" given French for Latin and Chinese (Taiwan) for East
// Asian text (constructs/make_table_language.py), a run in it set to English
// directly (the document's own), and a table in a style without a language.
TEST(DocxImport, ATableStyleGivesItsTextItsLanguage) {
    const auto doc = import_data_file("constructs/table_language.docx");
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"A paragraph before the tables.", ""}, {"Bonjour le monde", "fr-FR"}, {"中文字", "zh-TW"},
        {"Au revoir", "fr-FR"}, {"Hello", ""}, {"Plain words", ""}, {"A paragraph after the tables.", ""},
    };
    EXPECT_EQ(languages_of(doc), expected);
    EXPECT_EQ(document::main_language(doc), "en-US");
}

// The main language is the document's own language of the script class most
// of its unmarked text is in; without text, the first class that names one.
TEST(OfficeLanguage, TheMainLanguageIsThatOfMostOfTheText) {
    using import::detail::main_language;
    import::detail::OfficeLanguages own;
    own.latin = "en-US";
    own.east_asian = "zh-TW";
    own.complex = "ar-SA";
    const auto doc_of = [](std::vector<document::Span> spans) {
        document::Document d;
        d.blocks.push_back(document::Block{});
        d.blocks.back().spans = std::move(spans);
        return d;
    };
    EXPECT_EQ(main_language(own, doc_of({{.text = "我住在台北市的中心區, in Taipei."}})), "zh-TW");
    EXPECT_EQ(main_language(own, doc_of({{.text = "I live in 台北."}})), "en-US");
    EXPECT_EQ(main_language(own, doc_of({{.text = "مرحبا"}})), "ar-SA");
    // A passage in its own language does not count.
    EXPECT_EQ(main_language(own, doc_of({{.text = "Hi "}, {.text = "我住在台北", .language = "zh-CN"}})), "en-US");
    EXPECT_EQ(main_language(own, document::Document{}), "en-US");
    import::detail::OfficeLanguages asian_only;
    asian_only.east_asian = "ja-JP";
    EXPECT_EQ(main_language(asian_only, doc_of({{.text = "Latin words"}})), "ja-JP");
    EXPECT_EQ(main_language({}, doc_of({{.text = "Latin words"}})), "");
}

// Real documents' main languages, as each format names it: DOCX's
// w:docDefaults, ODT's default style, EPUB's first dc:language, HTML's lang.
TEST(OfficeLanguage, TheMainLanguageOfRealDocuments) {
    for (const auto& [file, language] : std::vector<std::pair<std::string, std::string>>{
             {"public/pandoc-i18n_blocks.docx", "ru-RU"},
             {"public/python-docx-tbl-having-applied-style.docx", "en-US"},
             {"public/pandoc-headers.docx", "en-US"},  // its default paragraph style's
             {"public/pandoc-unicode.odt", "en-US"},
             {"public/odfdo-table.odt", "fr-FR"},
             {"public/pandoc-footnote.odt", "de-DE"},
             {"public/pandoc-img_no_cover.epub", "en"},
             {"lesson.html", "en"},
         })
        EXPECT_EQ(document::main_language(import_data_file(file)), language) << file;
}

TEST(DocxImport, TruncatedZipIsAClearError) {
    const auto e = import_data_file_error("truncated.docx");
    EXPECT_THAT(e.message, testing::HasSubstr("not a valid ZIP package"));
    EXPECT_EQ(e.where, import_data("truncated.docx").string());
}

TEST(DocxImport, MissingDocumentPartIsNamed) {
    const auto e = import_data_file_error("no_document.docx");
    EXPECT_THAT(e.message, testing::HasSubstr("missing part word/document.xml"));
    EXPECT_EQ(e.where, import_data("no_document.docx").string() + ":word/document.xml");
}

TEST(DocxImport, InvalidXmlNamesPartLineAndColumn) {
    const auto e = import_data_file_error("invalid_xml.docx");
    EXPECT_THAT(e.message, testing::HasSubstr("invalid XML"));
    EXPECT_THAT(e.where, testing::MatchesRegex(".*invalid_xml\\.docx:word/document\\.xml:2:[0-9]+"));
}

TEST(DocxImport, EmptyAndNonZipInputsAreErrors) {
    const auto empty = import::import_bytes("", "e.docx");
    ASSERT_FALSE(empty);
    EXPECT_THAT(empty.error().message, testing::HasSubstr("empty file"));
    const auto text = import::import_bytes("just words", "w.docx");
    ASSERT_FALSE(text);
    EXPECT_THAT(text.error().message, testing::HasSubstr("not a valid ZIP"));
}

}  // namespace
}  // namespace tactus::test

// A footnote or endnote nothing refers to (its reference deleted in Word)
// is kept, at the end of the
// document (a notes part gives it no place in the text), numbered on after the
// referenced notes, footnotes before endnotes; Word's separators are not notes.
TEST(DocxImport, NotesNothingRefersToAreKeptAtTheEnd) {
    const auto doc = tactus::test::import_data_file("unreferenced_notes.docx");
    std::string got;
    for (const auto& b : doc.blocks) {
        got += std::to_string(static_cast<int>(b.kind)) + ":";
        for (const auto& s : b.spans) got += s.note_reference ? "[" + s.text + "]" : s.text;
        got += "\n";
    }
    EXPECT_EQ(got,
              "1:Referred[1] here.\n"
              "7:[1] The referred note.\n"
              "1:Last paragraph.\n"
              "7:[2] A footnote whose reference was deleted.\n"
              "7:[3] An endnote nothing refers to.\n");
}

// pandoc's own test file: a link's underline (Word's Hyperlink style) is how
// print shows a link, not emphasis, and braille leaves it out (BANA).
TEST(DocxImport, LinksAreNotUnderlined) {
    const auto doc = tactus::test::import_data_file("pandoc_links.docx");
    std::string text;
    for (const auto& b : doc.blocks)
        for (const auto& s : b.spans) {
            text += s.text;
            EXPECT_EQ(s.emphasis & tactus::document::emphasis_underline, 0) << s.text;
        }
    EXPECT_NE(text.find("external link to a popular website."), std::string::npos) << text;
}
