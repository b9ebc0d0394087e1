// SPDX-License-Identifier: GPL-3.0-or-later
// Pages and sheets: the one place that knows an interpoint sheet holds two pages.
#include "layout/page.hpp"

#include <gtest/gtest.h>

using namespace tactus::layout;

TEST(PageGeometry, PagesAndSheetsRoundTrip) {
    for (const bool interpoint : {false, true}) {
        PagedDocument doc;
        doc.geometry.interpoint = interpoint;
        for (std::size_t pages = 0; pages <= 9; ++pages) {
            doc.pages.assign(pages, Page{});
            const auto sheets = doc.sheet_count();
            EXPECT_EQ(sheets, interpoint ? (pages + 1) / 2 : pages);
            std::size_t seen = 0;
            for (std::size_t n = 1; n <= sheets; ++n) {
                const auto s = doc.sheet(n);
                ASSERT_NE(s.front, nullptr);
                const auto front = static_cast<std::size_t>(s.front - doc.pages.data());
                EXPECT_EQ(front, doc.geometry.first_page_of_sheet(n));
                EXPECT_EQ(doc.geometry.sheet_of_page(front), n);
                EXPECT_FALSE(doc.geometry.page_is_back(front));
                ++seen;
                if (s.back) {
                    const auto back = static_cast<std::size_t>(s.back - doc.pages.data());
                    EXPECT_EQ(back, front + 1);
                    EXPECT_EQ(doc.geometry.sheet_of_page(back), n);
                    EXPECT_TRUE(doc.geometry.page_is_back(back));
                    ++seen;
                }
            }
            EXPECT_EQ(seen, pages) << "every page on exactly one sheet";
        }
    }
}
