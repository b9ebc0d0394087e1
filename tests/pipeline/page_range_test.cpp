// SPDX-License-Identifier: GPL-3.0-or-later
// Page ranges named by the numbers on the pages (the CLI's --pages and the
// app's printer panel), the labels of a real book's pages, and when a
// document is laid out as a book.
#include <gtest/gtest.h>

#include <filesystem>

#include "import/import.hpp"
#include "pipeline/book_choice.hpp"
#include "pipeline/page_range.hpp"
#include "pipeline/pipeline.hpp"
#include "translate/translator.hpp"

using namespace tactus;
using pipeline::PageRange;

namespace {

TEST(PageRange, ParsesTheForms) {
    EXPECT_EQ(pipeline::parse_page_range("3-10"), (PageRange{"3", "10"}));
    EXPECT_EQ(pipeline::parse_page_range(" 5- "), (PageRange{"5", ""}));
    EXPECT_EQ(pipeline::parse_page_range("7"), (PageRange{"7", "7"}));
    EXPECT_EQ(pipeline::parse_page_range("P1-p02"), (PageRange{"p1", "p2"}));
    EXPECT_EQ(pipeline::parse_page_range("t1 - 4"), (PageRange{"t1", "4"}));
}

TEST(PageRange, RefusesWhatNamesNoPage) {
    for (const char* bad : {"", "-5", "0", "3-0", "a-b", "3-4-5", "x3", "p", "3..5"}) {
        const auto r = pipeline::parse_page_range(bad);
        ASSERT_FALSE(r) << bad;
        EXPECT_EQ(r.error().kind, ErrorKind::usage) << bad;
    }
    EXPECT_NE(pipeline::parse_page_range("0").error().message.find("count from 1"), std::string::npos);
}

TEST(PageRange, FindsPagesByTheirLabels) {
    // A two-volume book: title, blank back, contents, then the body going on.
    const std::vector<std::string> labels{"t1", "", "p1", "p2", "1", "2", "3", "t1", "", "p1", "", "4", "5"};
    using P = std::pair<std::size_t, std::size_t>;
    EXPECT_EQ(pipeline::find_page_range(labels, {"2", "4"}), (P{6, 12}));
    EXPECT_EQ(pipeline::find_page_range(labels, {"p1", "p2"}), (P{3, 4}));
    EXPECT_EQ(pipeline::find_page_range(labels, {"4", ""}), (P{12, 13}));
    EXPECT_EQ(pipeline::find_page_range(labels, {"5", "5"}), (P{13, 13}));
    const auto missing = pipeline::find_page_range(labels, {"9", "12"});
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().kind, ErrorKind::input);
    EXPECT_NE(missing.error().message.find("page 9 is not in the document (its pages run from t1 to 5)"),
              std::string::npos)
        << missing.error().message;
    const auto backwards = pipeline::find_page_range(labels, {"5", "2"});
    ASSERT_FALSE(backwards);
    EXPECT_NE(backwards.error().message.find("comes before"), std::string::npos);
}

// Jekyll and Hyde (Standard Ebooks, public domain) in volumes of 20 sheets.
class JekyllInVolumes : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(doc) << doc.error().to_string();
        ASSERT_TRUE(table);
        book.sheets_per_volume = 20;
    }
    const decltype(import::import_file(std::filesystem::path{})) doc =
        import::import_file(std::filesystem::path(TACTUS_TEST_DATA) / "import" / "books" / "jekyll-and-hyde.epub");
    const decltype(translate::Translator::open(translate::kDefaultTable)) table =
        translate::Translator::open(translate::kDefaultTable);
    pipeline::BookOptions book;
    const layout::LayoutOptions layout;
};
using PageLabels = JekyllInVolumes;
using BookProgress = JekyllInVolumes;

// Each volume's pages are t1, then p1, ..., then body numbers that go on.
TEST_F(PageLabels, ARealBookInVolumes) {
    const auto laid = pipeline::lay_out_book(*doc, layout, book, *table);
    ASSERT_TRUE(laid) << laid.error().to_string();
    ASSERT_GE(laid->volumes.size(), 2u);
    const auto labels = pipeline::page_labels(*laid);
    ASSERT_EQ(labels.size(), laid->pages.pages.size());
    int last_body = 0;
    for (const auto& v : laid->volumes) {
        EXPECT_EQ(labels[v.first_page], "t1");
        EXPECT_LT(v.first_page, v.contents_first_page);
        EXPECT_EQ(labels[v.contents_first_page], "p1");
        const int body = std::stoi(labels[v.body_first_page]);
        // A volume's body ends on a sheet of its own: a blank back may take a number.
        EXPECT_TRUE(body == last_body + 1 || body == last_body + 2) << "body numbers go on: " << body;
        for (std::size_t i = v.body_first_page; i < v.end_page; ++i)
            if (!labels[i].empty()) last_body = std::stoi(labels[i]);
    }
    // Volume 2's contents are found by choosing from its first page on.
    const auto& second = laid->volumes[1];
    std::vector<std::string> from_volume_2(labels.begin() + static_cast<std::ptrdiff_t>(second.first_page), labels.end());
    const auto p1 = pipeline::find_page_range(from_volume_2, {"p1", "p1"});
    ASSERT_TRUE(p1);
    EXPECT_EQ(second.first_page + p1->first - 1, second.contents_first_page);
    // The pipeline gives the CLI the same labels.
    pipeline::PipelineOptions options;
    options.book = book;
    options.translation_workers = 1;
    std::vector<std::string> from_pipeline;
    const auto paged = pipeline::lay_out(*doc, options, &from_pipeline);
    ASSERT_TRUE(paged);
    EXPECT_EQ(from_pipeline, labels);
}

TEST(BookChoice, EpubAndLongTextsAreBooks) {
    const pipeline::BookOptions book;  // 70 sheets a volume
    layout::PageGeometry interpoint;
    const auto room = pipeline::volume_body_room(book, interpoint);
    EXPECT_EQ(room, 136u);  // 140 pages less a title page and contents, each on its own sheet
    using F = import::SourceFormat;
    EXPECT_TRUE(pipeline::lays_out_as_book(F::epub, false, 3, book, interpoint));
    EXPECT_FALSE(pipeline::lays_out_as_book(F::markdown, false, room, book, interpoint));
    EXPECT_TRUE(pipeline::lays_out_as_book(F::markdown, false, room + 1, book, interpoint));
    EXPECT_FALSE(pipeline::lays_out_as_book(F::pef, true, 10000, book, interpoint));
    EXPECT_FALSE(pipeline::lays_out_as_book(F::brf, false, 10000, book, interpoint));
}

}  // namespace

namespace {

// The book layout tells its progress block by block, to the last, gives the
// same pages as without progress, and stops when progress says so (the app
// lays books out on a worker and stops one the editor has overtaken).
TEST_F(BookProgress, CountsEveryBlockAndStopsWhenAsked) {
    const auto plain = pipeline::lay_out_book(*doc, layout, book, *table);
    ASSERT_TRUE(plain);

    std::size_t calls = 0, last_done = 0, total = 0;
    const auto told = pipeline::lay_out_book(*doc, layout, book, *table, [&](std::size_t done, std::size_t all) {
        ++calls;
        EXPECT_EQ(done, last_done + 1);
        last_done = done;
        total = all;
        return false;
    });
    ASSERT_TRUE(told) << told.error().to_string();
    ASSERT_TRUE(told->has_value());
    EXPECT_EQ(total, doc->blocks.size());
    EXPECT_EQ(calls, doc->blocks.size());
    EXPECT_EQ(last_done, total);
    const auto& with = (*told)->pages;
    ASSERT_EQ(with.pages.size(), plain->pages.pages.size());
    for (std::size_t i = 0; i < with.pages.size(); ++i) EXPECT_EQ(with.pages[i].lines, plain->pages.pages[i].lines) << i;
    EXPECT_EQ((*told)->volumes.size(), plain->volumes.size());

    std::size_t seen = 0;
    const auto stopped = pipeline::lay_out_book(*doc, layout, book, *table, [&](std::size_t done, std::size_t all) {
        seen = done;
        return done * 2 >= all;
    });
    ASSERT_TRUE(stopped);
    EXPECT_FALSE(stopped->has_value());
    EXPECT_EQ(seen, (doc->blocks.size() + 1) / 2);
}

}  // namespace
