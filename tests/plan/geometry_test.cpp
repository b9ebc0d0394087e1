// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "plan/geometry.hpp"

using namespace tactus::plan;

// Worked by hand for the default profile: A4 210 x 297 mm, margins 25 mm left,
// 30 mm top; dot 2.5, cell 6, line 10 mm; back mirrored in x, offset (1.25, 1.25).
TEST(Geometry, FrontDotsOnTheGrid) {
    const auto p = tactus::profile::default_profile();
    auto d = dot_place(p, Side::front, 0, 0, 1);
    EXPECT_DOUBLE_EQ(d.paper_x_mm, 25.0);
    EXPECT_DOUBLE_EQ(d.paper_y_mm, 30.0);
    d = dot_place(p, Side::front, 1, 1, 6);  // line 2, cell 2, dot 6: right column, third row
    EXPECT_DOUBLE_EQ(d.paper_x_mm, 25.0 + 6.0 + 2.5);
    EXPECT_DOUBLE_EQ(d.paper_y_mm, 30.0 + 10.0 + 5.0);
    d = dot_place(p, Side::front, 23, 26, 4);  // last cell of the page
    EXPECT_DOUBLE_EQ(d.paper_x_mm, 25.0 + 156.0 + 2.5);
    EXPECT_DOUBLE_EQ(d.paper_y_mm, 30.0 + 230.0);
    EXPECT_EQ(d.paper_x_mm, d.read_x_mm);
}

TEST(Geometry, BackIsMirroredThenOffset) {
    const auto p = tactus::profile::default_profile();
    auto d = dot_place(p, Side::back, 0, 0, 1);
    EXPECT_DOUBLE_EQ(d.read_x_mm, 25.0);  // the reader sees it top-left
    EXPECT_DOUBLE_EQ(d.paper_x_mm, 210.0 - 25.0 + 1.25);
    EXPECT_DOUBLE_EQ(d.paper_y_mm, 30.0 + 1.25);
    d = dot_place(p, Side::back, 0, 0, 4);  // right column: further left on the paper
    EXPECT_DOUBLE_EQ(d.paper_x_mm, 210.0 - 27.5 + 1.25);
    // The concave hammer sits 12 mm right of the convex one: the carriage stops 12 mm short.
    EXPECT_DOUBLE_EQ(carriage_target_mm(p, Hammer::concave, 186.25), 174.25);
    EXPECT_DOUBLE_EQ(carriage_target_mm(p, Hammer::convex, 25.0), 25.0);
    auto q = p;
    q.geometry.back_mirror = tactus::profile::BackMirror::y;
    d = dot_place(q, Side::back, 0, 0, 1);
    EXPECT_DOUBLE_EQ(d.paper_x_mm, 25.0 + 1.25);
    EXPECT_DOUBLE_EQ(d.paper_y_mm, 297.0 - 30.0 + 1.25);
}

TEST(Geometry, FrontAndBackNeverShareADotRow) {
    const auto p = tactus::profile::default_profile();
    for (int line = 0; line < 24; ++line)
        for (int dot : {1, 2, 3})
            for (int l2 = 0; l2 < 24; ++l2)
                for (int d2 : {1, 2, 3})
                    ASSERT_NE(dot_place(p, Side::front, line, 0, dot).paper_y_mm,
                              dot_place(p, Side::back, l2, 0, d2).paper_y_mm);
}
