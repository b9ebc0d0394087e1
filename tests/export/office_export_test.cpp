// SPDX-License-Identifier: GPL-3.0-or-later
// The DOCX and ODT writers (core/export/office_export): a document written
// and opened again is the same blocks, for a document of every construct the
// editor shows, for real files (pandoc's and python-docx's test documents,
// LibreOffice's), and for random documents; the packages are well-formed;
// what a format cannot hold is named in a warning.
#include "export/office_export.hpp"

#include <gtest/gtest.h>
#include <pugixml.hpp>
#include <zip.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>

#include "document/main_language.hpp"
#include "export/document_save.hpp"
#include "export/picture_size.hpp"
#include "export/text_export.hpp"
#include "import/import.hpp"
#include "../common/process.hpp"
#include "../common/office_files.hpp"

using namespace tactus;
using document::Block;
using document::BlockKind;
using document::Span;

namespace {

const std::filesystem::path data = TACTUS_TEST_DATA;

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<Block> blocks_of(const document::Document& d) {
    auto blocks = d.blocks;
    for (auto& b : blocks) b.source_line = 0;
    return blocks;
}

// Every field of the blocks, one a line, so a difference reads as a diff.
std::string dump(const std::vector<Block>& blocks) {
    std::ostringstream o;
    for (const auto& b : blocks) {
        o << static_cast<int>(b.kind) << " level=" << b.level << " span=" << b.span << " align="
          << static_cast<int>(b.align) << " box=" << b.box << " label=" << b.label << (b.label_counted ? "+" : "")
          << " braille=" << b.braille_lines.size() << " [";
        for (const auto& s : b.spans)
            o << "('" << s.text << "' e" << int{s.emphasis} << " p" << static_cast<int>(s.position)
              << (s.note_reference ? " ref" : "") << (s.transcriber_note ? " tn" : "") << " " << s.language << ")";
        o << "]";
        for (const auto& i : b.images) o << " <" << i.media_type << " " << i.bytes.size() << " bytes " << i.name << ">";
        o << "\n";
    }
    return o.str();
}

#define EXPECT_SAME_BLOCKS(a, b)           \
    do {                                   \
        const auto& a_ = (a);              \
        const auto& b_ = (b);              \
        EXPECT_EQ(dump(a_), dump(b_));     \
        EXPECT_TRUE(a_ == b_);             \
    } while (false)

document::Document reopen(const document::Document& doc, exporter::OfficeFormat format) {
    auto file = exporter::to_office(doc, format);
    if (!file) throw std::runtime_error(file.error().to_string());
    auto back = import::import_bytes(file->bytes, format == exporter::OfficeFormat::docx ? "saved.docx" : "saved.odt");
    if (!back) throw std::runtime_error(back.error().to_string());
    return std::move(*back);
}

Span text(std::string t, std::uint8_t emphasis = document::emphasis_none) {
    Span s;
    s.text = std::move(t);
    s.emphasis = emphasis;
    return s;
}

Block block(BlockKind kind, int level, std::vector<Span> spans) {
    Block b;
    b.kind = kind;
    b.level = level;
    b.spans = std::move(spans);
    return b;
}

Span reference(std::string label) {
    Span s;
    s.text = std::move(label);
    s.note_reference = true;
    return s;
}

// Every construct the editor shows, as the office importers give them.
document::Document every_construct() {
    document::Document d;
    auto& b = d.blocks;
    for (int level = 1; level <= 6; ++level)
        b.push_back(block(BlockKind::heading, level, {text("Heading " + std::to_string(level))}));
    b.push_back(block(BlockKind::paragraph, 0,
                      {text("Plain, "), text("bold", document::emphasis_bold), text(", "),
                       text("italic", document::emphasis_italic), text(", "),
                       text("underlined", document::emphasis_underline), text(" and "),
                       text("all", document::emphasis_bold | document::emphasis_italic | document::emphasis_underline),
                       text(" & <markup> \"quoted\"  two  spaces\ta tab")}));
    Span raised = text("2");
    raised.position = document::Position::superscript;
    Span lowered = text("2");
    lowered.position = document::Position::subscript;
    b.push_back(block(BlockKind::paragraph, 0, {text("E = mc"), raised, text(" and H"), lowered, text("O.")}));
    b.push_back(block(BlockKind::paragraph, 0, {text("A line\nand the next.")}));
    // Lists: bullets, nested numbers, a list that does not start at 1.
    b.push_back(block(BlockKind::list_item, 1, {text("\u2022 first bullet")}));
    b.push_back(block(BlockKind::list_item, 2, {text("1. nested one")}));
    b.push_back(block(BlockKind::list_item, 2, {text("2. nested "), text("two", document::emphasis_bold)}));
    b.push_back(block(BlockKind::list_item, 1, {text("\u2022 second bullet")}));
    b.push_back(block(BlockKind::paragraph, 0, {text("Between lists.")}));
    b.push_back(block(BlockKind::list_item, 1, {text("4. four")}));
    b.push_back(block(BlockKind::list_item, 1, {text("5. five")}));
    b.push_back(block(BlockKind::list_item, 1, {text("7) seven")}));
    b.push_back(block(BlockKind::list_item, 1, {text("iv. a roman label kept as text")}));
    b.push_back(block(BlockKind::quote, 1, {text("A quotation.")}));
    // A note.
    b.push_back(block(BlockKind::paragraph, 0, {text("Noted"), reference("1"), text(" text.")}));
    b.push_back(block(BlockKind::note, 0, {reference("1"), text(" The note, "), text("emphasised", document::emphasis_italic)}));
    // A page break, then a table with a header row and a merged cell.
    Block page;
    page.kind = BlockKind::print_page_break;
    page.label = "2";
    page.label_counted = true;
    b.push_back(page);
    b.push_back(block(BlockKind::paragraph, 0, {text("On page two.")}));
    Block header;
    header.kind = BlockKind::table_row;
    header.level = 1;
    b.push_back(header);
    for (int c = 0; c < 3; ++c) b.push_back(block(BlockKind::table_cell, c, {text("H" + std::to_string(c))}));
    Block row;
    row.kind = BlockKind::table_row;
    b.push_back(row);
    auto merged = block(BlockKind::table_cell, 0, {text("two columns")});
    merged.span = 2;
    b.push_back(merged);
    b.push_back(block(BlockKind::table_cell, 2, {}));
    b.push_back(row);
    b.push_back(block(BlockKind::table_cell, 0, {text("a\nb")}));
    b.push_back(block(BlockKind::table_cell, 1, {text("c", document::emphasis_bold)}));
    b.push_back(block(BlockKind::table_cell, 2, {text("d")}));
    // An image's description, and a box.
    Span description;
    description.text = "A red square.";
    description.transcriber_note = true;
    b.push_back(block(BlockKind::paragraph, 0, {text("See "), description, text(" here.")}));
    b.push_back(block(BlockKind::paragraph, 0, {text("Before the box.")}));
    auto boxed = block(BlockKind::paragraph, 0, {text("Boxed text.")});
    boxed.box = 1;
    b.push_back(boxed);
    auto boxed_heading = block(BlockKind::heading, 2, {text("Boxed heading")});
    boxed_heading.box = 1;
    b.push_back(boxed_heading);
    b.push_back(page);
    b.back().label = "3";
    b.push_back(block(BlockKind::paragraph, 0, {text("The end.")}));
    return d;
}

void expect_well_formed(const std::string& package) {
    zip_error_t error;
    zip_error_init(&error);
    zip_source_t* source = zip_source_buffer_create(package.data(), package.size(), 0, &error);
    ASSERT_NE(source, nullptr);
    zip_t* z = zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error);
    ASSERT_NE(z, nullptr) << zip_error_strerror(&error);
    for (zip_int64_t i = 0; i < zip_get_num_entries(z, 0); ++i) {
        const std::string name = zip_get_name(z, static_cast<zip_uint64_t>(i), 0);
        if (!name.ends_with(".xml") && !name.ends_with(".rels")) continue;
        zip_stat_t st;
        zip_stat_index(z, static_cast<zip_uint64_t>(i), 0, &st);
        std::string bytes(st.size, '\0');
        zip_file_t* f = zip_fopen_index(z, static_cast<zip_uint64_t>(i), 0);
        zip_fread(f, bytes.data(), st.size);
        zip_fclose(f);
        pugi::xml_document xml;
        const auto parsed = xml.load_buffer(bytes.data(), bytes.size());
        EXPECT_TRUE(parsed) << name << ": " << parsed.description() << " at " << parsed.offset;
    }
    zip_discard(z);
}

// One part of a ZIP package, or "" when it is missing.
std::string package_part(const std::string& package, const char* part) {
    zip_error_t error;
    zip_error_init(&error);
    zip_source_t* source = zip_source_buffer_create(package.data(), package.size(), 0, &error);
    zip_t* z = source ? zip_open_from_source(source, ZIP_RDONLY, &error) : nullptr;
    if (!z) return {};
    std::string bytes;
    zip_stat_t st;
    if (zip_stat(z, part, 0, &st) == 0) {
        bytes.assign(st.size, '\0');
        zip_file_t* f = zip_fopen(z, part, 0);
        zip_fread(f, bytes.data(), st.size);
        zip_fclose(f);
    }
    zip_discard(z);
    return bytes;
}

std::size_t occurrences(std::string_view text, std::string_view what) {
    std::size_t n = 0;
    for (auto i = text.find(what); i != std::string_view::npos; i = text.find(what, i + what.size())) ++n;
    return n;
}

}  // namespace

TEST(OfficeExport, EveryConstructComesBackFromDocxAndOdt) {
    const auto doc = every_construct();
    for (const auto format : {exporter::OfficeFormat::docx, exporter::OfficeFormat::odt}) {
        SCOPED_TRACE(format == exporter::OfficeFormat::docx ? "docx" : "odt");
        auto file = exporter::to_office(doc, format);
        ASSERT_TRUE(file) << file.error().to_string();
        EXPECT_TRUE(file->warnings.empty()) << file->warnings.front();
        expect_well_formed(file->bytes);
        const auto back = reopen(doc, format);
        EXPECT_SAME_BLOCKS(blocks_of(back), doc.blocks);
        EXPECT_TRUE(back.warnings.empty());
    }
}

Span in_language(std::string t, std::string language, std::uint8_t emphasis = document::emphasis_none) {
    auto s = text(std::move(t), emphasis);
    s.language = std::move(language);
    return s;
}

// Passages in another language: an English document with a Chinese (Taiwan)
// passage, a Chinese one with English passages. Each passage holds
// characters of every script class (Han, CJK punctuation, Latin, spaces,
// digits) and comes back whole, in its language, from DOCX (w:lang) and ODT
// (fo:language, style:language-asian, style:language-complex); the text
// around it keeps none, and nothing is named lost.
TEST(OfficeExport, LanguagesComeBackFromDocxAndOdt) {
    document::Document english;
    english.blocks.push_back(block(BlockKind::heading, 1, {text("Words in "), in_language("中文", "zh-TW")}));
    english.blocks.push_back(block(BlockKind::paragraph, 0,
                                   {text("The word "), in_language("中文，好 2024", "zh-TW"), text(" means "),
                                    in_language("Chinese", "zh-TW", document::emphasis_italic), text(".")}));
    english.blocks.push_back(block(BlockKind::paragraph, 0,
                                   {text("Pinyin: "), in_language("Zhōngwén", "zh-Latn-pinyin"), text(" and "),
                                    in_language("漢字", "zh-Hant-TW"), text(".")}));
    document::Document chinese;
    chinese.blocks.push_back(block(BlockKind::paragraph, 0,
                                   {text("我住在"), in_language("New York, 2024", "en"), text("，"),
                                    in_language("colour", "en-GB", document::emphasis_bold), text("。")}));
    chinese.blocks.push_back(block(BlockKind::list_item, 1, {text("\u2022 "), in_language("Apple 蘋果", "en-US")}));
    Block row;
    row.kind = BlockKind::table_row;
    chinese.blocks.push_back(row);
    chinese.blocks.push_back(block(BlockKind::table_cell, 0, {text("中文")}));
    chinese.blocks.push_back(block(BlockKind::table_cell, 1, {in_language("English words", "en")}));
    for (const auto* doc : {&english, &chinese})
        for (const auto format : {exporter::OfficeFormat::docx, exporter::OfficeFormat::odt}) {
            SCOPED_TRACE(std::string(doc == &english ? "english" : "chinese") +
                         (format == exporter::OfficeFormat::docx ? " -> docx" : " -> odt"));
            auto file = exporter::to_office(*doc, format);
            ASSERT_TRUE(file) << file.error().to_string();
            EXPECT_TRUE(file->warnings.empty()) << file->warnings.front();
            expect_well_formed(file->bytes);
            EXPECT_SAME_BLOCKS(blocks_of(reopen(*doc, format)), doc->blocks);
        }
}

// The document's main language (document/main_language.hpp) is written where
// each format keeps it (DOCX's w:docDefaults, ODT's default style,
// Markdown's front matter) and read back from there; its passages in
// another language stay passages, its own text stays unmarked, and nothing
// is named lost. Other metadata (a title) is still named.
TEST(OfficeExport, TheMainLanguageComesBackFromDocxOdtAndMarkdown) {
    for (const std::string main : {"zh-TW", "en-GB", "sr-Latn"}) {
        document::Document doc;
        document::set_main_language(doc, main);
        doc.blocks.push_back(block(BlockKind::heading, 1, {text("中文 and English")}));
        doc.blocks.push_back(block(BlockKind::paragraph, 0,
                                   {text("我住在"), in_language("New York", "en"), text("，"), in_language("漢字", "ja")}));
        for (const auto format : {exporter::OfficeFormat::docx, exporter::OfficeFormat::odt}) {
            SCOPED_TRACE(main + (format == exporter::OfficeFormat::docx ? " -> docx" : " -> odt"));
            auto file = exporter::to_office(doc, format);
            ASSERT_TRUE(file) << file.error().to_string();
            EXPECT_TRUE(file->warnings.empty()) << file->warnings.front();
            expect_well_formed(file->bytes);
            const auto back = reopen(doc, format);
            EXPECT_EQ(document::main_language(back), main);
            EXPECT_SAME_BLOCKS(blocks_of(back), doc.blocks);
        }
        SCOPED_TRACE(main + " -> md");
        const auto markdown = exporter::to_markdown(doc);
        EXPECT_TRUE(markdown.starts_with("---\nlang: " + main + "\n---\n\n# ")) << markdown;
        auto back = import::import_bytes(markdown, "saved.md");
        ASSERT_TRUE(back) << back.error().to_string();
        EXPECT_EQ(document::main_language(*back), main);
        EXPECT_EQ(dump(blocks_of(*back)), dump(blocks_of(doc)));
    }
    // A document without one writes none: no front matter, no default language.
    document::Document plain;
    plain.blocks.push_back(block(BlockKind::paragraph, 0, {text("Words")}));
    EXPECT_EQ(exporter::to_markdown(plain), "Words\n");
    EXPECT_EQ(document::main_language(reopen(plain, exporter::OfficeFormat::docx)), "");
    EXPECT_EQ(document::main_language(reopen(plain, exporter::OfficeFormat::odt)), "");
    // A title is not written by the office writers, and says so.
    auto titled = plain;
    document::set_main_language(titled, "en");
    titled.metadata.push_back({"title", "A title"});
    auto file = exporter::to_office(titled, exporter::OfficeFormat::docx);
    ASSERT_TRUE(file);
    ASSERT_EQ(file->warnings.size(), 1u);
    EXPECT_NE(file->warnings.front().find("metadata"), std::string::npos);
}

// Real documents keep their main language through a DOCX and an ODT save.
TEST(OfficeExport, RealDocumentsKeepTheirMainLanguage) {
    int kept = 0;
    for (const auto& path : test::real_office_files(data)) {
        auto doc = import::import_file(path);
        if (!doc || document::main_language(*doc).empty()) continue;
        SCOPED_TRACE(path.filename().string());
        for (const auto format : {exporter::OfficeFormat::docx, exporter::OfficeFormat::odt})
            EXPECT_EQ(document::main_language(reopen(*doc, format)), document::main_language(*doc));
        ++kept;
    }
    EXPECT_GE(kept, 20);
}

TEST(OfficeExport, EveryConstructComesBackFromMarkdown) {
    auto doc = every_construct();
    doc.blocks.push_back(block(BlockKind::paragraph, 0, {text("Say ")}));
    doc.blocks.back().spans.push_back(text("Guten Tag", document::emphasis_italic));
    doc.blocks.back().spans.back().language = "de";
    doc.blocks.back().spans.push_back(text("."));
    auto once = import::import_bytes(exporter::to_markdown(doc), "saved.md");
    ASSERT_TRUE(once) << once.error().to_string();
    // Boxes, underline, raised and lowered text and languages are kept
    // (as HTML, document/markdown_html.hpp), each where it was.
    const auto where = [](const document::Document& d, auto&& has) {
        std::vector<std::string> out;
        for (const auto& b : d.blocks)
            for (const auto& s : b.spans)
                if (has(b, s)) out.push_back(s.text);
        return out;
    };
    for (const auto& has : std::vector<std::function<bool(const Block&, const Span&)>>{
             [](const Block& b, const Span&) { return b.box != 0; },
             [](const Block&, const Span& s) { return (s.emphasis & document::emphasis_underline) != 0; },
             [](const Block&, const Span& s) { return s.position == document::Position::superscript; },
             [](const Block&, const Span& s) { return s.position == document::Position::subscript; },
             [](const Block&, const Span& s) { return s.language == "de"; }}) {
        EXPECT_FALSE(where(doc, has).empty());
        EXPECT_EQ(where(*once, has), where(doc, has));
    }
    auto twice = import::import_bytes(exporter::to_markdown(*once), "saved.md");
    ASSERT_TRUE(twice);
    EXPECT_SAME_BLOCKS(blocks_of(*twice), blocks_of(*once));
    // And Markdown's document through DOCX and ODT, its language included.
    for (const auto format : {exporter::OfficeFormat::docx, exporter::OfficeFormat::odt})
        EXPECT_SAME_BLOCKS(blocks_of(reopen(*once, format)), blocks_of(*once));
}

TEST(OfficeExport, PlainTextComesBackFromText) {
    const auto doc = import::import_file(data / "import/utf8.txt");
    ASSERT_TRUE(doc);
    auto back = import::import_bytes(exporter::to_text(*doc), "saved.txt");
    ASSERT_TRUE(back);
    EXPECT_SAME_BLOCKS(blocks_of(*back), blocks_of(*doc));
    for (const auto format : {exporter::OfficeFormat::docx, exporter::OfficeFormat::odt})
        EXPECT_SAME_BLOCKS(blocks_of(reopen(*doc, format)), blocks_of(*doc));
}

// Real documents nobody here wrote: opened, saved as DOCX and as ODT, and
// opened again, each gives the blocks it gave the first time.
TEST(OfficeExport, RealDocumentsComeBackTheSame) {
    int files = 0;
    for (const auto& path : test::real_office_files(data)) {
        auto doc = import::import_file(path);
        if (!doc) continue;  // the importer's own error files (truncated, invalid XML)
        ++files;
        for (const auto format : {exporter::OfficeFormat::docx, exporter::OfficeFormat::odt}) {
            SCOPED_TRACE(path.filename().string() + (format == exporter::OfficeFormat::docx ? " -> docx" : " -> odt"));
            auto file = exporter::to_office(*doc, format);
            ASSERT_TRUE(file) << file.error().to_string();
            expect_well_formed(file->bytes);
            if (format == exporter::OfficeFormat::odt && path.filename() == "unreferenced_notes.docx") {
                // ODT's notes stand in the text: the warning says so.
                ASSERT_EQ(file->warnings.size(), 1u);
                EXPECT_NE(file->warnings[0].find("a note nothing refers to"), std::string::npos);
                continue;
            }
            const auto back = reopen(*doc, format);
            EXPECT_SAME_BLOCKS(blocks_of(back), blocks_of(*doc));
        }
    }
    EXPECT_GE(files, 40);
}

TEST(OfficeExport, WhatAFormatCannotHoldIsNamed) {
    document::Document doc;
    Block braille;
    braille.kind = BlockKind::braille;
    braille.braille_lines.resize(1);
    doc.blocks.push_back(block(BlockKind::paragraph, 0, {text("Text.")}));
    doc.blocks.push_back(braille);
    doc.blocks.push_back(block(BlockKind::quote, 2, {text("Deep quote.")}));
    for (const auto format : {exporter::OfficeFormat::docx, exporter::OfficeFormat::odt}) {
        auto file = exporter::to_office(doc, format);
        ASSERT_TRUE(file);
        ASSERT_EQ(file->warnings.size(), 2u);
        EXPECT_NE(file->warnings[0].find("ready-made braille is left out"), std::string::npos) << file->warnings[0];
        EXPECT_NE(file->warnings[0].find("first at block 2"), std::string::npos) << file->warnings[0];
        EXPECT_NE(file->warnings[1].find("quote in a quote"), std::string::npos) << file->warnings[1];
    }
}

TEST(OfficeExport, OdtStartsWithItsMimetypeStored) {
    auto file = exporter::to_odt(every_construct());
    ASSERT_TRUE(file);
    // The first local header: name "mimetype", method 0 (stored), then the type.
    ASSERT_GT(file->bytes.size(), 38u + 39u);
    EXPECT_EQ(file->bytes.substr(30, 8), "mimetype");
    EXPECT_EQ(file->bytes[8], '\0');
    EXPECT_EQ(file->bytes.substr(38, 39), "application/vnd.oasis.opendocument.text");
}

TEST(OfficeExport, WritingIsAtomicAndRepeatable) {
    const auto dir = std::filesystem::temp_directory_path() / "tactus_office_export_test";
    std::filesystem::create_directories(dir);
    const auto path = dir / "out.docx";
    const auto doc = every_construct();
    auto warnings = exporter::write_office_file(doc, exporter::OfficeFormat::docx, path);
    ASSERT_TRUE(warnings) << warnings.error().to_string();
    EXPECT_EQ(slurp(path), exporter::to_docx(doc)->bytes);  // the same bytes every time
    // A folder that does not exist: an error, nothing written.
    auto bad = exporter::write_office_file(doc, exporter::OfficeFormat::odt, dir / "missing" / "out.odt");
    EXPECT_FALSE(bad);
    EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
    std::filesystem::remove_all(dir);
}

// Random documents of the constructs, as the importers would give them:
// saved and opened again, they are the same blocks.
TEST(OfficeExport, RandomDocumentsComeBackTheSame) {
    std::mt19937 random(20261207);
    const std::vector<std::string> words = {"alpha", "beta", "&amp;", "<tag>", "中文", "x  y", "end."};
    const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(random); };
    for (int round = 0; round < 100; ++round) {
        document::Document doc;
        for (int i = 0, n = static_cast<int>(pick(12)) + 1; i < n; ++i) {
            std::vector<Span> spans;
            for (std::size_t k = 0, m = pick(3) + 1; k < m; ++k) {
                auto e = static_cast<std::uint8_t>(k == 0 ? 0 : pick(8));
                // Adjacent spans of the same emphasis are one span.
                if (!spans.empty() && spans.back().emphasis == e) e = static_cast<std::uint8_t>(e ^ 1u);
                spans.push_back(text((k == 0 ? "" : " ") + words[pick(words.size())], e));
                // A passage in another language (never the first span: a
                // list item's label stands there).
                if (k > 0 && pick(4) == 0) spans.back().language = pick(2) ? "zh-TW" : "en";
            }
            if (pick(4) == 0) {
                // Raised text, an image's description, a note reference.
                Span extra = text(words[pick(2)]);
                switch (pick(3)) {
                    case 0: extra.position = document::Position::superscript; break;
                    case 1: extra.transcriber_note = true; break;
                    default: extra.note_reference = true; extra.text = "9"; break;
                }
                spans.push_back(extra);
                spans.push_back(text(" end"));
            }
            const bool referring = spans.size() > 1 && spans[spans.size() - 2].note_reference;
            switch (pick(referring ? 4 : 7)) {
                case 0: doc.blocks.push_back(block(BlockKind::heading, static_cast<int>(pick(6)) + 1, spans)); break;
                case 1: doc.blocks.push_back(block(BlockKind::quote, 1, spans)); break;
                case 2: {
                    const int level = static_cast<int>(pick(3)) + 1;
                    spans.front().text = (pick(2) ? std::to_string(pick(9) + 1) + ". " : "\u2022 ") + spans.front().text;
                    doc.blocks.push_back(block(BlockKind::list_item, level, spans));
                    break;
                }
                case 4: {  // a table
                    for (std::size_t r = 0, rows = pick(3) + 1; r < rows; ++r) {
                        Block row;
                        row.kind = BlockKind::table_row;
                        row.level = r == 0 && pick(2) ? 1 : 0;
                        doc.blocks.push_back(row);
                        for (std::size_t c = 0, cells = pick(3) + 1; c < cells; ++c)
                            doc.blocks.push_back(block(BlockKind::table_cell, static_cast<int>(c), {text(words[pick(words.size())])}));
                    }
                    break;
                }
                case 5: {  // a page break
                    Block page;
                    page.kind = BlockKind::print_page_break;
                    page.label = "2";
                    page.label_counted = true;
                    doc.blocks.push_back(page);
                    break;
                }
                case 6: {  // a box
                    const int box = static_cast<int>(doc.blocks.size()) + 1;
                    for (std::size_t k = 0, m = pick(2) + 1; k < m; ++k) {
                        doc.blocks.push_back(block(BlockKind::paragraph, 0, {text(words[pick(words.size())])}));
                        doc.blocks.back().box = box;
                    }
                    break;
                }
                default: doc.blocks.push_back(block(BlockKind::paragraph, 0, spans));
            }
            if (referring && document::is_text_kind(doc.blocks.back().kind))
                doc.blocks.push_back(block(BlockKind::note, 0, {reference("9"), text(" A note.")}));
        }
        // The importers count list numbers: take the document they give,
        // and check it is a fixed point of a save and an open.
        const auto once = reopen(doc, exporter::OfficeFormat::odt);
        // The passages in another language come back, each in its language.
        const auto marked = [](const document::Document& d) {
            std::vector<std::string> out;
            for (const auto& b : d.blocks)
                for (const auto& s : b.spans)
                    if (!s.language.empty()) out.push_back(s.language + ":" + s.text);
            return out;
        };
        EXPECT_EQ(marked(once), marked(doc)) << round;
        for (const auto format : {exporter::OfficeFormat::docx, exporter::OfficeFormat::odt}) {
            SCOPED_TRACE(round);
            EXPECT_SAME_BLOCKS(blocks_of(reopen(once, format)), blocks_of(once));
        }
    }
}

// Markdown and text name what they leave out, as the office writers do.
TEST(OfficeExport, MarkdownAndTextNameWhatTheyLeaveOut) {
    const auto dir = std::filesystem::temp_directory_path() / "tactus_print_losses_test";
    std::filesystem::create_directories(dir);
    const auto doc = every_construct();
    auto md = exporter::save_document(doc, exporter::DocumentFormat::markdown, dir / "out.md");
    ASSERT_TRUE(md);
    std::string said;
    for (const auto& w : *md) said += w + "\n";
    for (const auto* what : {"a merged cell is written as its columns", "an image's description",
                             "a list item without a bullet or number is written with a bullet (1 time; the first at block 18)"})
        EXPECT_NE(said.find(what), std::string::npos) << what << " in\n" << said;
    // Markdown keeps headings, boxes, underline and raised text.
    for (const auto* kept : {"heading", "box", "underline", "raised"})
        EXPECT_EQ(said.find(kept), std::string::npos) << kept << " in\n" << said;
    auto txt = exporter::save_document(doc, exporter::DocumentFormat::text, dir / "out.txt");
    ASSERT_TRUE(txt);
    said.clear();
    for (const auto& w : *txt) said += w + "\n";
    EXPECT_NE(said.find("text: a heading is written as a plain line (7 times; the first at block 1)"), std::string::npos)
        << said;
    for (const auto* what : {"a box is written", "underline is left out", "raised and lowered text"})
        EXPECT_NE(said.find(what), std::string::npos) << what << " in\n" << said;
    // Metadata: Markdown keeps the main language (its front matter) and names
    // the rest; text keeps none.
    const auto metadata_said = [&](const document::Document& d, exporter::DocumentFormat format) {
        auto w = exporter::save_document(d, format, dir / (format == exporter::DocumentFormat::text ? "m.txt" : "m.md"));
        EXPECT_TRUE(w);
        for (const auto& line : w.value_or(std::vector<std::string>{}))
            if (line.find("metadata") != std::string::npos) return true;
        return false;
    };
    auto in_chinese = doc;
    document::set_main_language(in_chinese, "zh-TW");
    EXPECT_FALSE(metadata_said(in_chinese, exporter::DocumentFormat::markdown));
    EXPECT_TRUE(metadata_said(in_chinese, exporter::DocumentFormat::text));
    in_chinese.metadata.push_back({"title", "A title"});
    EXPECT_TRUE(metadata_said(in_chinese, exporter::DocumentFormat::markdown));
    std::filesystem::remove_all(dir);
}

// tactus-cli convert: the format from the output's name (or --to), what is
// left out on stderr, and the documented exit codes for bad input (3) and an
// output format it cannot tell (2).
TEST(OfficeExport, ConvertCommand) {
    const auto dir = std::filesystem::temp_directory_path() / "tactus_convert_test";
    std::filesystem::create_directories(dir);
    const std::string cli = TACTUS_CLI;
    const auto lesson = (data / "import/lesson.docx").string();
    auto r = test::run_captured({cli, "convert", lesson, (dir / "lesson.odt").string()});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    auto odt = import::import_file(dir / "lesson.odt");
    auto docx = import::import_file(lesson);
    ASSERT_TRUE(odt && docx);
    EXPECT_SAME_BLOCKS(blocks_of(*odt), blocks_of(*docx));
    r = test::run_captured({cli, "convert", "--to", "docx", lesson, (dir / "lesson.out").string()});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(slurp(dir / "lesson.out").substr(0, 2), "PK");
    // Ready-made braille in a print format: named on stderr, written all the same.
    r = test::run_captured({cli, "convert", (data / "import/lesson.pef").string(), (dir / "braille.docx").string()});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("ready-made braille is left out"), std::string::npos) << r.err;
    r = test::run_captured({cli, "convert", (data / "import/truncated.docx").string(), (dir / "bad.odt").string()});
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.odt"));
    r = test::run_captured({cli, "convert", lesson, (dir / "lesson.xyz").string()});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("--to"), std::string::npos) << r.err;
    std::filesystem::remove_all(dir);
}

// A table cell of several paragraphs (document/cell_paragraphs.hpp), as the
// importers give one: saved as DOCX or ODT, each is a paragraph of the cell;
// saved as Markdown, they are <br> apart in the pipe table's cell. Opened
// again, every format gives the same blocks.
TEST(OfficeExport, CellParagraphsComeBackFromDocxOdtAndMarkdown) {
    document::Document doc;
    auto& b = doc.blocks;
    Block header;
    header.kind = BlockKind::table_row;
    header.level = 1;
    b.push_back(header);
    b.push_back(block(BlockKind::table_cell, 0, {text("Name")}));
    b.push_back(block(BlockKind::table_cell, 1, {text("Notes")}));
    Block row;
    row.kind = BlockKind::table_row;
    b.push_back(row);
    b.push_back(block(BlockKind::table_cell, 0, {text("Simple\nMultiparagraph")}));
    b.push_back(block(BlockKind::table_cell, 1,
                      {text("1. First", document::emphasis_bold), text("\n2. Second "), text("item", document::emphasis_italic)}));
    b.push_back(row);
    b.push_back(block(BlockKind::table_cell, 0, {text("one")}));
    b.push_back(block(BlockKind::table_cell, 1, {text("A list of\n3 paras\nhere")}));

    for (const auto format : {exporter::OfficeFormat::docx, exporter::OfficeFormat::odt}) {
        const bool docx = format == exporter::OfficeFormat::docx;
        SCOPED_TRACE(docx ? "docx" : "odt");
        auto file = exporter::to_office(doc, format);
        ASSERT_TRUE(file) << file.error().to_string();
        EXPECT_TRUE(file->warnings.empty()) << file->warnings.front();
        const auto body = package_part(file->bytes, docx ? "word/document.xml" : "content.xml");
        // 2 + 2 + 1 + 3 paragraphs in the body cells, one in each header cell, and no line breaks.
        EXPECT_EQ(occurrences(body, docx ? "<w:p>" : "<text:p text:style-name=\"Table_20_Contents\">"), 10u) << body;
        EXPECT_EQ(occurrences(body, docx ? "<w:br/>" : "<text:line-break/>"), 0u);
        EXPECT_SAME_BLOCKS(blocks_of(reopen(doc, format)), doc.blocks);
    }
    const auto markdown = exporter::to_markdown(doc);
    EXPECT_NE(markdown.find("| Simple<br>Multiparagraph | **1. First**<br>2. Second *item* |"), std::string::npos) << markdown;
    auto back = import::import_bytes(markdown, "saved.md");
    ASSERT_TRUE(back) << back.error().to_string();
    EXPECT_SAME_BLOCKS(blocks_of(*back), doc.blocks);
}

namespace {

Span description(std::string t) {
    Span s;
    s.text = std::move(t);
    s.transcriber_note = true;
    return s;
}

// A picture file the test data keeps (PngSuite, libjpeg-turbo, the SVG
// drawings and W3C tests: tests/data/graphics/README.md).
document::Image picture(const std::string& relative, std::string media_type) {
    auto bytes = slurp(data / relative);
    if (bytes.empty()) throw std::runtime_error("missing test picture " + relative);
    return {std::move(bytes), std::move(media_type), relative};
}

const auto kPng = [] { return picture("graphics/pictures/basn6a08.png", "image/png"); };        // 32 x 32
const auto kGreyPng = [] { return picture("graphics/pictures/basn0g01.png", "image/png"); };    // 32 x 32
const auto kJpeg = [] { return picture("graphics/pictures/testorig.jpg", "image/jpeg"); };      // 227 x 149
const auto kSvg = [] { return picture("graphics/line-drawing.svg", "image/svg+xml"); };         // 160 x 230 mm
const auto kW3cSvg = [] { return picture("graphics/w3c/paths-data-02-t.svg", "image/svg+xml"); };  // 100%, viewBox 480 x 360

// Pictures where the office importers put them: described ones with their
// description where they stand, an undescribed one after them, in headings,
// list items, table cells and notes.
document::Document with_pictures() {
    document::Document d;
    auto& b = d.blocks;
    b.push_back(block(BlockKind::heading, 1, {text("Pictures")}));
    b.push_back(block(BlockKind::paragraph, 0, {text("The chart "), description("A bar chart of rainfall"), text(" shows it.")}));
    b.back().images = {kPng()};
    b.push_back(block(BlockKind::heading, 2, {text("A photograph "), description("Testorig & <friends>")}));
    b.back().images = {kJpeg()};
    b.push_back(block(BlockKind::paragraph, 0, {description("The water cycle"), text(" and "), description("Path data")}));
    b.back().images = {kSvg(), kW3cSvg(), kGreyPng()};
    auto alone = block(BlockKind::paragraph, 0, {});
    alone.images = {kJpeg()};
    b.push_back(alone);
    b.push_back(block(BlockKind::list_item, 1, {text("\u2022 An item "), description("A small square")}));
    b.back().images = {kPng()};
    Block row;
    row.kind = BlockKind::table_row;
    row.level = 1;
    b.push_back(row);
    b.push_back(block(BlockKind::table_cell, 0, {text("Map")}));
    b.push_back(block(BlockKind::table_cell, 1, {description("A map")}));
    b.back().images = {kPng()};
    b.push_back(block(BlockKind::paragraph, 0, {text("Noted"), reference("1"), text(".")}));
    b.push_back(block(BlockKind::note, 0, {reference("1"), text(" A note with "), description("A tiny chart")}));
    b.back().images = {kGreyPng()};
    auto boxed = block(BlockKind::paragraph, 0, {text("Boxed "), description("A boxed drawing")});
    boxed.box = 1;
    boxed.images = {kSvg()};
    b.push_back(boxed);
    b.push_back(block(BlockKind::paragraph, 0, {text("The end.")}));
    return d;
}

document::Document reopen_with_pictures(const document::Document& doc, exporter::OfficeFormat format) {
    auto file = exporter::to_office(doc, format);
    if (!file) throw std::runtime_error(file.error().to_string());
    import::ImportOptions options;
    options.images = true;
    auto back = import::import_bytes(file->bytes, format == exporter::OfficeFormat::docx ? "saved.docx" : "saved.odt",
                                     options);
    if (!back) throw std::runtime_error(back.error().to_string());
    return std::move(*back);
}

// The blocks with their pictures' names left out: a saved picture is named
// by the part the saved file keeps it in ("word/media/image1.png").
std::vector<Block> unnamed(const document::Document& d) {
    auto blocks = blocks_of(d);
    for (auto& b : blocks)
        for (auto& i : b.images) i.name.clear();
    return blocks;
}

std::size_t picture_count(const document::Document& d) {
    std::size_t n = 0;
    for (const auto& b : d.blocks) n += b.images.size();
    return n;
}

const char* name_of(exporter::OfficeFormat format) { return format == exporter::OfficeFormat::docx ? "docx" : "odt"; }

}  // namespace

// Saved and opened again with pictures, a document gives the same text and
// the same pictures (bytes and type) on the same blocks; saved once more, the
// same document to the picture's name.
TEST(OfficeExport, PicturesComeBackFromDocxAndOdt) {
    const auto doc = with_pictures();
    for (const auto format : {exporter::OfficeFormat::docx, exporter::OfficeFormat::odt}) {
        SCOPED_TRACE(name_of(format));
        auto file = exporter::to_office(doc, format);
        ASSERT_TRUE(file) << file.error().to_string();
        EXPECT_TRUE(file->warnings.empty()) << file->warnings.front();
        expect_well_formed(file->bytes);
        EXPECT_EQ(exporter::to_office(doc, format)->bytes, file->bytes);  // the same bytes every time
        const auto back = reopen_with_pictures(doc, format);
        EXPECT_EQ(picture_count(back), picture_count(doc));
        EXPECT_SAME_BLOCKS(unnamed(back), unnamed(doc));
        const auto again = reopen_with_pictures(back, format);
        EXPECT_SAME_BLOCKS(blocks_of(again), blocks_of(back));
        // Opened without pictures, the descriptions are what they were.
        auto descriptions = doc;
        for (auto& b : descriptions.blocks) b.images.clear();
        descriptions.blocks.erase(descriptions.blocks.begin() + 4);  // the undescribed picture's paragraph
        EXPECT_SAME_BLOCKS(blocks_of(reopen(doc, format)), blocks_of(descriptions));
    }
}

// The package holds each picture's bytes as they were, under its type, and
// sizes it by its own pixels (96 to the inch), narrowed to the text's width.
TEST(OfficeExport, PicturesAreStoredAsTheyAreAndSizedByTheirOwnPixels) {
    const auto doc = with_pictures();
    const auto docx = exporter::to_docx(doc)->bytes;
    EXPECT_EQ(package_part(docx, "word/media/image1.png"), kPng().bytes);
    EXPECT_EQ(package_part(docx, "word/media/image2.jpeg"), kJpeg().bytes);
    EXPECT_EQ(package_part(docx, "word/media/image3.svg"), kSvg().bytes);
    EXPECT_EQ(package_part(docx, "word/media/image5.png"), kGreyPng().bytes);
    EXPECT_EQ(package_part(docx, "word/media/placeholder.png"), "");  // every description has its picture
    const auto types = package_part(docx, "[Content_Types].xml");
    EXPECT_NE(types.find("<Default Extension=\"jpeg\" ContentType=\"image/jpeg\"/>"), std::string::npos);
    EXPECT_NE(types.find("<Default Extension=\"svg\" ContentType=\"image/svg+xml\"/>"), std::string::npos);
    const auto rels = package_part(docx, "word/_rels/document.xml.rels");
    EXPECT_NE(rels.find("Id=\"rIdImage2\" Type=\"http://schemas.openxmlformats.org/officeDocument/2006/relationships/"
                        "image\" Target=\"media/image2.jpeg\""),
              std::string::npos);
    EXPECT_NE(package_part(docx, "word/_rels/footnotes.xml.rels").find("rIdImage"), std::string::npos);
    const auto body = package_part(docx, "word/document.xml");
    EXPECT_NE(body.find("<wp:extent cx=\"304800\" cy=\"304800\"/><wp:docPr id=\"1\" name=\"Picture 1\" "
                        "descr=\"A bar chart of rainfall\"/>"),
              std::string::npos);  // 32 px
    EXPECT_NE(body.find("<wp:extent cx=\"2162175\" cy=\"1419225\"/>"), std::string::npos);  // 227 x 149 px
    // 160 x 230 mm is wider than the text (15.92 cm): narrowed, its shape kept.
    EXPECT_NE(body.find("<wp:extent cx=\"5731510\" cy=\"8239046\"/>"), std::string::npos);
    EXPECT_NE(body.find("<wp:extent cx=\"4572000\" cy=\"3429000\"/>"), std::string::npos);  // viewBox 480 x 360
    EXPECT_NE(body.find("asvg:svgBlip"), std::string::npos);
    EXPECT_EQ(occurrences(body, "<w:drawing>"), 10u);  // the box is one too; the note's picture is in footnotes.xml

    const auto odt = exporter::to_odt(doc)->bytes;
    EXPECT_EQ(package_part(odt, "Pictures/image1.png"), kPng().bytes);
    EXPECT_EQ(package_part(odt, "Pictures/image2.jpeg"), kJpeg().bytes);
    EXPECT_EQ(package_part(odt, "Pictures/image4.svg"), kW3cSvg().bytes);
    const auto manifest = package_part(odt, "META-INF/manifest.xml");
    EXPECT_NE(manifest.find("<manifest:file-entry manifest:full-path=\"Pictures/image3.svg\" "
                            "manifest:media-type=\"image/svg+xml\"/>"),
              std::string::npos);
    const auto content = package_part(odt, "content.xml");
    EXPECT_NE(content.find("svg:width=\"0.847cm\" svg:height=\"0.847cm\" draw:z-index=\"0\"><draw:image "
                           "xlink:href=\"Pictures/image1.png\""),
              std::string::npos);
    EXPECT_NE(content.find("<svg:desc>Testorig &amp; &lt;friends&gt;</svg:desc>"), std::string::npos);
    EXPECT_NE(content.find("svg:width=\"15.921cm\" svg:height=\"22.886cm\""), std::string::npos);
}

// A description whose picture the document does not keep stands on the
// placeholder, which opening again does not take for a picture.
TEST(OfficeExport, ADescriptionWithoutItsPictureComesBackWithoutAPicture) {
    auto doc = with_pictures();
    doc.blocks[1].images.clear();
    doc.blocks.push_back(block(BlockKind::paragraph, 0, {text("A picture of another type: "), description("A GIF")}));
    doc.blocks.back().images = {{"GIF89a", "image/gif", "media/anim.gif"}};
    for (const auto format : {exporter::OfficeFormat::docx, exporter::OfficeFormat::odt}) {
        SCOPED_TRACE(name_of(format));
        auto file = exporter::to_office(doc, format);
        ASSERT_TRUE(file);
        ASSERT_EQ(file->warnings.size(), 1u);
        EXPECT_NE(file->warnings[0].find("a picture not PNG, JPEG or SVG is left out (its description stays)"),
                  std::string::npos)
            << file->warnings[0];
        auto expected = doc;
        expected.blocks.back().images.clear();
        EXPECT_SAME_BLOCKS(unnamed(reopen_with_pictures(doc, format)), unnamed(expected));
    }
}

// Real documents with pictures nobody here wrote: opened with pictures,
// saved as DOCX and as ODT and opened again, the same text and pictures.
TEST(OfficeExport, RealDocumentsKeepTheirPictures) {
    int files = 0;
    std::size_t pictures = 0;
    for (const auto& path : test::real_office_files(data)) {
        import::ImportOptions options;
        options.images = true;
        auto doc = import::import_file(path, options);
        if (!doc || picture_count(*doc) == 0) continue;
        ++files;
        pictures += picture_count(*doc);
        for (const auto format : {exporter::OfficeFormat::docx, exporter::OfficeFormat::odt}) {
            SCOPED_TRACE(path.filename().string() + " -> " + name_of(format));
            auto file = exporter::to_office(*doc, format);
            ASSERT_TRUE(file) << file.error().to_string();
            expect_well_formed(file->bytes);
            const auto back = reopen_with_pictures(*doc, format);
            EXPECT_EQ(picture_count(back), picture_count(*doc));
            EXPECT_SAME_BLOCKS(unnamed(back), unnamed(*doc));
        }
    }
    EXPECT_GE(files, 9);  // pandoc's, python-docx's, LibreOffice's and the constructs
    EXPECT_GE(pictures, 14u);
}

// Markdown and text do not write pictures: they say so.
TEST(OfficeExport, MarkdownAndTextNameThePicturesTheyLeaveOut) {
    const auto dir = std::filesystem::temp_directory_path() / "tactus_picture_losses_test";
    std::filesystem::create_directories(dir);
    for (const auto format : {exporter::DocumentFormat::markdown, exporter::DocumentFormat::text}) {
        auto warnings = exporter::save_document(with_pictures(), format, dir / "out");
        ASSERT_TRUE(warnings);
        std::string said;
        for (const auto& w : *warnings) said += w + "\n";
        EXPECT_NE(said.find("a picture is left out (its description stays) (8 times; the first at block 2)"),
                  std::string::npos)
            << said;
    }
    std::filesystem::remove_all(dir);
}

// A picture's own size, from its header: the sizes `file` and the SVGs' own
// width, height and viewBox give for the test data's pictures.
TEST(OfficeExport, APicturesOwnSizeIsReadFromItsHeader) {
    const auto size = [](const document::Image& i) {
        const auto s = exporter::picture_pixel_size(i.bytes, i.media_type);
        return s ? std::to_string(std::lround(s->width)) + "x" + std::to_string(std::lround(s->height)) : "none";
    };
    EXPECT_EQ(size(kPng()), "32x32");
    EXPECT_EQ(size(picture("graphics/pictures/shapes.png", "image/png")), "400x300");
    EXPECT_EQ(size(kJpeg()), "227x149");
    EXPECT_EQ(size(picture("import/pictures/movie.jpg", "image/jpeg")), "20x22");  // a comment before its frame
    EXPECT_EQ(size(kSvg()), "605x869");                                          // 160 x 230 mm
    EXPECT_EQ(size(kW3cSvg()), "480x360");                                       // 100%: the viewBox
    EXPECT_EQ(size({"<svg width='2in' viewBox='0,0 40 10'/>", "image/svg+xml", ""}), "192x48");
    EXPECT_EQ(size({"<svg xmlns='http://www.w3.org/2000/svg'/>", "image/svg+xml", ""}), "none");
    EXPECT_EQ(size({"\x89PNG\r\n\x1a\n", "image/png", ""}), "none");  // cut short
    EXPECT_EQ(size({"\xff\xd8\xff\xd9", "image/jpeg", ""}), "none");
}

// tactus-cli convert to DOCX or ODT keeps a document's pictures.
TEST(OfficeExport, ConvertKeepsPictures) {
    const auto dir = std::filesystem::temp_directory_path() / "tactus_convert_pictures_test";
    std::filesystem::create_directories(dir);
    const auto source = data / "import/public/pandoc-inline_images.docx";
    import::ImportOptions options;
    options.images = true;
    const auto original = import::import_file(source, options);
    ASSERT_TRUE(original);
    ASSERT_EQ(picture_count(*original), 2u);
    for (const auto* name : {"pictures.odt", "pictures.docx"}) {
        SCOPED_TRACE(name);
        const auto r = test::run_captured({TACTUS_CLI, "convert", source.string(), (dir / name).string()});
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const auto back = import::import_file(dir / name, options);
        ASSERT_TRUE(back);
        EXPECT_SAME_BLOCKS(unnamed(*back), unnamed(*original));
    }
    std::filesystem::remove_all(dir);
}
