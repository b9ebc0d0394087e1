// SPDX-License-Identifier: GPL-3.0-or-later
// Real public books (tests/data/import/books, README there): each opens, keeps
// at least 98 % of the words pandoc reads from the same file, and lays out
// into PEF that the PEF 2008-1 schema accepts.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include <unistd.h>

#include <pugixml.hpp>

#include "../export/pef_checks.hpp"
#include "export/export.hpp"
#include "import/import.hpp"
#include "pipeline/pipeline.hpp"

namespace tactus::test {
namespace {

namespace fs = std::filesystem;

fs::path book(const std::string& name) { return fs::path(TACTUS_TEST_DATA) / "import" / "books" / name; }

std::string run(const std::string& command) {
    std::string out;
    if (FILE* p = ::popen(command.c_str(), "r")) {
        char buf[4096];
        std::size_t n = 0;
        while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
        ::pclose(p);
    }
    return out;
}

// Words as runs of letters and digits (ASCII and any non-ASCII byte), so
// punctuation and the way each tool writes it do not count.
std::map<std::string, int> words(const std::string& text) {
    std::map<std::string, int> out;
    std::string w;
    auto flush = [&] {
        if (!w.empty()) ++out[w];
        w.clear();
    };
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (std::isalnum(u) || u >= 0x80) w += c;
        else flush();
    }
    flush();
    return out;
}

std::string document_text(const document::Document& doc) {
    std::string out;
    for (const auto& b : doc.blocks) {
        for (const auto& s : b.spans) out += s.text;
        out += b.label;
        out += '\n';
    }
    return out;
}

// All the text of a DTBook's <book> (pandoc reads no DTBook): the reference
// for "dtbook", as pandoc's plain text is for the formats it reads.
std::string dtbook_text(const fs::path& file) {
    pugi::xml_document xml;
    if (!xml.load_file(file.c_str())) return {};
    std::string out;
    for (const auto& n : xml.select_nodes("//*[local-name()='book']//text()")) {
        out += n.node().value();
        out += ' ';
    }
    return out;
}

// The share of pandoc's words (counted with repeats) that the import has.
double kept_share(const document::Document& doc, const fs::path& file, const std::string& pandoc_format) {
    const auto reference =
        words(pandoc_format == "dtbook"
                  ? dtbook_text(file)
                  : run("pandoc --wrap=none -f " + pandoc_format + " -t plain '" + file.string() + "' 2>/dev/null"));
    const auto ours = words(document_text(doc));
    long total = 0;
    long kept = 0;
    std::vector<std::string> missing;
    for (const auto& [w, n] : reference) {
        total += n;
        const auto it = ours.find(w);
        const int have = it == ours.end() ? 0 : std::min(n, it->second);
        kept += have;
        if (have < n && missing.size() < 20) missing.push_back(w);
    }
    EXPECT_GT(total, 0) << "pandoc read nothing from " << file;
    if (total == 0) return 0;
    const double share = static_cast<double>(kept) / static_cast<double>(total);
    if (share < 0.98) ADD_FAILURE() << file << ": missing words such as " << ::testing::PrintToString(missing);
    return share;
}

void expect_valid_pef(const document::Document& doc) {
    pipeline::PipelineOptions options;
    options.translation_workers = 1;
    auto paged = pipeline::lay_out(doc, options);
    ASSERT_TRUE(paged) << paged.error().to_string();
    EXPECT_GT(paged->pages.size(), 1u);
    auto pef = exporter::to_pef(*paged, exporter::pef_metadata(doc.metadata, "Untitled", "2024-01-01", "en"));
    ASSERT_TRUE(pef) << pef.error().to_string();
    EXPECT_EQ(validate_pef_schema(*pef), "");
    EXPECT_EQ(check_pef_schematron(*pef), "");
}

struct Book {
    std::string file;
    std::string pandoc_format;
};

class RealBook : public ::testing::TestWithParam<Book> {};

TEST_P(RealBook, OpensKeepsItsWordsAndGivesValidPef) {
    const auto path = book(GetParam().file);
    auto doc = import::import_file(path);
    ASSERT_TRUE(doc) << doc.error().to_string();
    const double share = kept_share(*doc, path, GetParam().pandoc_format);
    EXPECT_GE(share, 0.98) << GetParam().file;
    RecordProperty("kept_words_percent", std::to_string(share * 100));
    expect_valid_pef(*doc);
}

INSTANTIATE_TEST_SUITE_P(Books, RealBook,
                         ::testing::Values(Book{"jekyll-and-hyde.epub", "epub"},
                                           Book{"jekyll-and-hyde-chapter-1.xhtml", "html"}),
                         [](const auto& param_info) {
                             std::string n = param_info.param.file;
                             for (auto& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });

// Books too big to keep here, named in TACTUS_MORE_BOOKS ("file:pandoc-format,...")
// by whoever measures them (docs/import.md lists those read so far).
TEST(RealBook, MoreBooksNamedInTheEnvironment) {
    const char* list = std::getenv("TACTUS_MORE_BOOKS");
    if (!list) GTEST_SKIP() << "TACTUS_MORE_BOOKS is not set";
    std::string rest = list;
    while (!rest.empty()) {
        const auto comma = rest.find(',');
        const auto item = rest.substr(0, comma);
        rest = comma == std::string::npos ? std::string{} : rest.substr(comma + 1);
        const auto colon = item.rfind(':');
        const fs::path path = item.substr(0, colon);
        auto doc = import::import_file(path);
        ASSERT_TRUE(doc) << doc.error().to_string();
        const double share = kept_share(*doc, path, item.substr(colon + 1));
        std::cout << path << ": " << share * 100 << " % of pandoc's words, " << doc->blocks.size() << " blocks, "
                  << doc->warnings.size() << " warnings\n";
        for (const auto& w : doc->warnings) std::cout << "  warning: " << w << "\n";
        expect_valid_pef(*doc);
    }
}

TEST(RealBook, StandardEbooksMetadataBecomesTheDocumentsMetadata) {
    auto doc = import::import_file(book("jekyll-and-hyde.epub"));
    ASSERT_TRUE(doc) << doc.error().to_string();
    std::map<std::string, std::string> m;
    for (const auto& item : doc->metadata) m.emplace(item.name, item.value);
    EXPECT_EQ(m["title"], "The Strange Case of Dr. Jekyll and Mr. Hyde");
    EXPECT_EQ(m["creator"], "Robert Louis Stevenson");
    EXPECT_EQ(m["language"], "en-GB");
}

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Compares with tests/books/expected/NAME; TACTUS_UPDATE_GOLDEN=1 writes it.
void expect_golden(const std::string& name, const std::string& actual) {
    const auto path = fs::path(TACTUS_BOOKS_GOLDEN_DIR) / name;
    if (std::getenv("TACTUS_UPDATE_GOLDEN")) {
        std::ofstream(path, std::ios::binary) << actual;
        return;
    }
    EXPECT_EQ(read_text(path), actual) << name << " differs (TACTUS_UPDATE_GOLDEN=1 regenerates; review the diff)";
}

// BANA Braille Formats 2016 book layout (docs/layout.md "Books"), UEB contracted:
// three chapters of Jekyll and Hyde in volumes of about six sheets.
TEST(BookLayout, AShortBookInTwoVolumes) {
    auto doc = import::import_file(book("jekyll-and-hyde-short.html"));
    ASSERT_TRUE(doc) << doc.error().to_string();
    pipeline::PipelineOptions options;
    options.translation_workers = 1;
    pipeline::BookOptions b;
    b.sheets_per_volume = 6;
    b.publisher = "Standard Ebooks";
    b.year = "2017";
    b.transcriber = "Tactus";
    options.book = b;
    auto paged = pipeline::lay_out(*doc, options);
    ASSERT_TRUE(paged) << paged.error().to_string();

    std::vector<std::size_t> volume_starts;
    for (const auto& s : paged->sections)
        if (s.starts_volume) volume_starts.push_back(s.first_page);
    ASSERT_EQ(volume_starts.size(), 2u) << paged->pages.size() << " pages";
    EXPECT_EQ(volume_starts.front(), 0u);
    // Each volume within its sheets, on whole sheets.
    for (std::size_t v = 0; v < volume_starts.size(); ++v) {
        const auto end = v + 1 < volume_starts.size() ? volume_starts[v + 1] : paged->pages.size();
        EXPECT_EQ(volume_starts[v] % 2, 0u);
        EXPECT_LE((end - volume_starts[v] + 1) / 2, 6u + 1) << "volume " << v + 1;
    }

    auto brf = exporter::to_brf(*paged);
    ASSERT_TRUE(brf) << brf.error().to_string();
    // Title page: the title, "Volume 1 of 2", "Transcribed by"; the preliminary
    // title page numbered t1, the contents p1 (UEB ⠞⠼⠁, ⠏⠼⠁); the contents list the chapters.
    EXPECT_THAT(*brf, ::testing::HasSubstr(",VOLUME #A ( #B"));
    EXPECT_THAT(*brf, ::testing::HasSubstr(",TRANSCRIB$ BY ,TACTUS"));
    EXPECT_THAT(*brf, ::testing::HasSubstr("T#A"));
    EXPECT_THAT(*brf, ::testing::HasSubstr("P#A"));
    EXPECT_THAT(*brf, ::testing::HasSubstr(",3T5TS"));
    expect_golden("jekyll-short-volumes.brf", *brf);

    auto pef = exporter::to_pef(*paged, exporter::pef_metadata(doc->metadata, "Untitled", "2024-01-01", "en"));
    ASSERT_TRUE(pef) << pef.error().to_string();
    EXPECT_EQ(validate_pef_schema(*pef), "");
    EXPECT_EQ(check_pef_schematron(*pef), "");
    EXPECT_EQ(std::count(pef->begin(), pef->end(), '\n') > 0, true);
    std::size_t volumes = 0;
    for (std::size_t at = pef->find("<volume "); at != std::string::npos; at = pef->find("<volume ", at + 1)) ++volumes;
    EXPECT_EQ(volumes, 2u);
    expect_golden("jekyll-short-volumes.pef", *pef);
}

// The same book through `tactus-cli layout --volumes`: the command line's
// options reach the book layout (the BRF is the golden above, byte for byte),
// `--brf-volumes files` writes one file per volume, and the PEF carries the
// volumes and passes the schema.
TEST(BookLayout, TheCommandLineLaysOutTheSameVolumes) {
    const fs::path dir = fs::temp_directory_path() / ("tactus-book-cli-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string cli = TACTUS_CLI;
    const std::string common = " layout --volumes --sheets-per-volume 6 --book-publisher 'Standard Ebooks' "
                               "--book-year 2017 --transcriber Tactus '" +
                               book("jekyll-and-hyde-short.html").string() + "'";
    auto quiet = [](const std::string& c) { return std::system((c + " >/dev/null 2>&1").c_str()); };

    ASSERT_EQ(quiet("'" + cli + "'" + common + " --to brf -o '" + (dir / "book.brf").string() + "'"), 0);
    EXPECT_EQ(read_text(dir / "book.brf"), read_text(fs::path(TACTUS_BOOKS_GOLDEN_DIR) / "jekyll-short-volumes.brf"));

    ASSERT_EQ(quiet("'" + cli + "'" + common + " --to brf --brf-volumes files -o '" + (dir / "vol.brf").string() +
                    "'"),
              0);
    ASSERT_TRUE(fs::exists(dir / "vol-1.brf"));
    ASSERT_TRUE(fs::exists(dir / "vol-2.brf"));
    EXPECT_FALSE(fs::exists(dir / "vol-3.brf"));
    EXPECT_FALSE(fs::exists(dir / "vol.brf"));
    const auto first = read_text(dir / "vol-1.brf");
    const auto second = read_text(dir / "vol-2.brf");
    EXPECT_THAT(first, ::testing::HasSubstr(",VOLUME #A ( #B"));
    EXPECT_THAT(second, ::testing::HasSubstr(",VOLUME #B ( #B"));
    EXPECT_THAT(first, ::testing::Not(::testing::HasSubstr(",VOLUME #B ( #B")));
    // Together they hold the one-file book's pages: the volume files are its parts.
    const auto whole = read_text(dir / "book.brf");
    EXPECT_NE(whole.find(first.substr(0, first.size() / 2)), std::string::npos);
    EXPECT_NE(whole.find(second.substr(second.size() / 2)), std::string::npos);

    ASSERT_EQ(quiet("'" + cli + "'" + common + " --to pef -o '" + (dir / "book.pef").string() + "'"), 0);
    const auto pef = read_text(dir / "book.pef");
    EXPECT_EQ(validate_pef_schema(pef), "");
    std::size_t volumes = 0;
    for (std::size_t at = pef.find("<volume "); at != std::string::npos; at = pef.find("<volume ", at + 1)) ++volumes;
    EXPECT_EQ(volumes, 2u);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace tactus::test
