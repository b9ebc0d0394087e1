// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>

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

namespace {

tactus::layout::Page full_page(int lines, int cells, tactus::document::Cell c = tactus::document::Cell{0xFF}) {
    tactus::layout::Page p;
    p.lines.assign(static_cast<std::size_t>(lines),
                   tactus::document::BrailleLine(static_cast<std::size_t>(cells), c));
    return p;
}

}  // namespace

TEST(Geometry, PageDotsAreDotPlaces) {
    const auto p = tactus::profile::default_profile();
    const auto page = full_page(2, 3, tactus::document::Cell{0x09});  // dots 1 and 4
    for (const auto side : {Side::front, Side::back}) {
        const auto dots = page_dots(p, page, side);
        ASSERT_EQ(dots.size(), 2U * 3U * 2U);
        for (const auto& d : dots) {
            const auto want = dot_place(p, side, d.line, d.cell, d.dot);
            EXPECT_EQ(d.place.paper_x_mm, want.paper_x_mm);
            EXPECT_EQ(d.place.paper_y_mm, want.paper_y_mm);
            EXPECT_TRUE(d.dot == 1 || d.dot == 4);
        }
    }
}

// Every dot of every cell raised on both sides, eight-dot cells: the worst case
// for crushing, and the default offset still keeps them apart.
TEST(Geometry, FullSheetsClearWithTheDefaultOffset) {
    const auto p = tactus::profile::default_profile();
    const auto page = full_page(24, 27);
    EXPECT_TRUE(find_conflicts(p, tactus::layout::Sheet{1, &page, &page}).empty());
    // The closest pair is one offset apart: a larger pitch (so a larger
    // minimum separation) with the same offset makes them collide.
    auto wide = p;
    wide.geometry.dot_pitch_mm = 2 * std::hypot(p.geometry.back_offset_x_mm, p.geometry.back_offset_y_mm) + 0.1;
    EXPECT_FALSE(find_conflicts(wide, tactus::layout::Sheet{1, &page, &page}).empty());
}

TEST(Geometry, ZeroOffsetPutsBackDotsOnFrontDots) {
    auto p = tactus::profile::default_profile();
    p.geometry.back_offset_x_mm = 0;
    p.geometry.back_offset_y_mm = 0;
    // The mirrored grid coincides with the front grid when 2 * margin + k * cell
    // pitch + dot pitch equals the paper width: choose the paper to make it so.
    p.paper.width_mm = 2 * p.paper.margin_left_mm + 10 * p.geometry.cell_pitch_mm + p.geometry.dot_pitch_mm;
    const auto ones = full_page(1, 11, tactus::document::Cell{0x01});
    EXPECT_TRUE(find_conflicts(p, tactus::layout::Sheet{1, &ones, &ones}).empty());  // 2.5 mm apart at best
    const auto fours = full_page(1, 11, tactus::document::Cell{0x08});
    const auto c = find_conflicts(p, tactus::layout::Sheet{1, &ones, &fours});
    ASSERT_EQ(c.size(), 11U);  // each back dot 4 on a front dot 1
    for (const auto& x : c) {
        EXPECT_LT(x.distance_mm, 1e-9);
        EXPECT_EQ(x.front.dot, 1);
        EXPECT_EQ(x.back.dot, 4);
        EXPECT_EQ(x.front.cell, 10 - x.back.cell);  // mirrored
    }
}

// cell_at inverts dot_place on both sides and every mirror.
TEST(Geometry, CellAtFindsTheCellOfEveryDot) {
    for (const auto mirror : {tactus::profile::BackMirror::x, tactus::profile::BackMirror::y,
                              tactus::profile::BackMirror::none}) {
        auto p = tactus::profile::default_profile();
        p.geometry.back_mirror = mirror;
        for (const auto side : {Side::front, Side::back})
            for (int line : {0, 7, 23})
                for (int cell : {0, 13, 26})
                    for (int dot = 1; dot <= 8; ++dot) {
                        const auto d = dot_place(p, side, line, cell, dot);
                        const auto at = cell_at(p, side, d.paper_x_mm, d.paper_y_mm);
                        EXPECT_EQ(at.line, line) << "dot " << dot;
                        EXPECT_EQ(at.cell, cell) << "dot " << dot;
                    }
    }
}
