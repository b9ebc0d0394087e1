// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "spool/snapshot.hpp"
#include "spool_fixtures.hpp"

namespace tactus::spool {
namespace {

TEST(Snapshot, RoundTripsEveryCellIncludingDots7And8) {
    layout::PagedDocument doc = test::make_document(5, true);
    doc.geometry.eight_dot = true;
    doc.pages[2].lines[1][3] = document::Cell{0xC5};  // dots 1, 3, 7, 8
    doc.pages[4].print_page = "xii";
    auto back = from_snapshot(to_snapshot(doc));
    ASSERT_TRUE(back) << back.error().to_string();
    EXPECT_EQ(back->geometry, doc.geometry);
    EXPECT_EQ(back->pages, doc.pages);
    EXPECT_EQ(back->sheet_count(), 3u);
}

TEST(Snapshot, RefusesALineWiderThanItsGeometry) {
    layout::PagedDocument doc = test::make_document(2, false);
    doc.pages[1].lines[0].resize(static_cast<std::size_t>(doc.geometry.cells_per_line) + 2, document::Cell{1});
    auto back = from_snapshot(to_snapshot(doc));
    ASSERT_FALSE(back);
    EXPECT_EQ(back.error().where, "page 2 line 1");
    EXPECT_NE(back.error().message.find("29 cells"), std::string::npos);
}

TEST(Snapshot, RefusesGarbageAndForeignFormats) {
    EXPECT_FALSE(from_snapshot("not json"));
    EXPECT_FALSE(from_snapshot(R"({"format":"other","geometry":{},"pages":[]})"));
    auto missing = from_snapshot(R"({"format":"tactus-paged-1","geometry":{"cells_per_line":27,"lines_per_page":24,"interpoint":true},"pages":[]})");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().where, "geometry.eight_dot");
    auto text = from_snapshot(R"({"format":"tactus-paged-1","geometry":{"cells_per_line":27,"lines_per_page":24,"interpoint":true,"eight_dot":false},"pages":[{"number":1,"print_page":"","lines":["abc"]}]})");
    ASSERT_FALSE(text);
    EXPECT_EQ(text.error().where, "page 1 line 1");
}

TEST(Snapshot, SelectPagesPutsTheFirstChosenPageOnAFront) {
    const layout::PagedDocument doc = test::make_document(7, true);
    auto part = select_pages(doc, 4, 6);
    ASSERT_TRUE(part);
    ASSERT_EQ(part->pages.size(), 3u);
    EXPECT_EQ(part->pages[0], doc.pages[3]);
    EXPECT_EQ(part->sheet(1).front, &part->pages[0]);
    EXPECT_EQ(part->sheet_count(), 2u);
    EXPECT_TRUE(select_pages(doc, 0, 0));
    EXPECT_FALSE(select_pages(doc, 3, 9));
    EXPECT_FALSE(select_pages(doc, 5, 2));
}

}  // namespace
}  // namespace tactus::spool
