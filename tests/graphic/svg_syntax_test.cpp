// SPDX-License-Identifier: GPL-3.0-or-later
// SVG's attribute languages: lengths, transform lists, path data and arcs.
#include <gtest/gtest.h>

#include <cmath>

#include "graphic/flatten.hpp"
#include "graphic/svg_syntax.hpp"

namespace tactus::graphic {
namespace {

using svg::parse_length_mm;
using svg::parse_path;
using svg::parse_transform;

void expect_point(Point p, double x, double y, double tol = 1e-9) {
    EXPECT_NEAR(p.x, x, tol);
    EXPECT_NEAR(p.y, y, tol);
}

TEST(SvgSyntax, LengthsInEveryUnit) {
    EXPECT_DOUBLE_EQ(*parse_length_mm("10mm"), 10);
    EXPECT_DOUBLE_EQ(*parse_length_mm("1.5cm"), 15);
    EXPECT_DOUBLE_EQ(*parse_length_mm("2in"), 50.8);
    EXPECT_DOUBLE_EQ(*parse_length_mm("96"), 25.4);
    EXPECT_DOUBLE_EQ(*parse_length_mm("96px"), 25.4);
    EXPECT_DOUBLE_EQ(*parse_length_mm("72pt"), 25.4);
    EXPECT_DOUBLE_EQ(*parse_length_mm("6pc"), 25.4);
    EXPECT_DOUBLE_EQ(*parse_length_mm("50%", 200), 100);
    EXPECT_DOUBLE_EQ(*parse_length_mm(" 1e1mm "), 10);
    const auto bad = parse_length_mm("10furlongs");
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("furlongs"), std::string::npos);
    EXPECT_EQ(bad.error().where, "character 3");
    EXPECT_FALSE(parse_length_mm("mm"));
    EXPECT_FALSE(parse_length_mm("50%"));
}

TEST(SvgSyntax, TransformListsComposeRightToLeft) {
    // translate(10,20) scale(2): the point is scaled first, then moved.
    expect_point(parse_transform("translate(10,20) scale(2)")->apply({1, 1}), 12, 22);
    expect_point(parse_transform("scale(2) translate(10,20)")->apply({1, 1}), 22, 42);
    expect_point(parse_transform("rotate(90)")->apply({1, 0}), 0, 1);
    expect_point(parse_transform("rotate(90 10 10)")->apply({20, 10}), 10, 20);
    expect_point(parse_transform("skewX(45)")->apply({0, 1}), 1, 1);
    expect_point(parse_transform("skewY(45)")->apply({1, 0}), 1, 1);
    expect_point(parse_transform("matrix(1 2 3 4 5 6)")->apply({1, 1}), 9, 12);
    expect_point(parse_transform("translate(5)")->apply({0, 0}), 5, 0);
    expect_point(parse_transform("scale(2,3),translate(1 1)")->apply({0, 0}), 2, 3);
    EXPECT_DOUBLE_EQ(parse_transform("scale(2 8)")->scale(), 4);
    const auto three = parse_transform("scale(1,2,3)");
    ASSERT_FALSE(three);
    EXPECT_NE(three.error().message.find("scale takes 1 or 2 numbers, not 3"), std::string::npos);
    const auto unknown = parse_transform("translate(1) shear(2)");
    ASSERT_FALSE(unknown);
    EXPECT_EQ(unknown.error().where, "character 14");
    EXPECT_FALSE(parse_transform("rotate(10"));
}

TEST(SvgSyntax, RelativeAndAbsoluteCommandsDrawTheSame) {
    const auto abs = parse_path("M10 10 L20 10 L20 20 H10 V10 Z");
    const auto rel = parse_path("m10 10 l10 0 l0 10 h-10 v-10 z");
    ASSERT_TRUE(abs && rel);
    ASSERT_EQ(abs->size(), 1U);
    ASSERT_EQ(rel->size(), 1U);
    ASSERT_EQ((*abs)[0].segments.size(), (*rel)[0].segments.size());
    for (std::size_t i = 0; i < (*abs)[0].segments.size(); ++i)
        expect_point((*rel)[0].segments[i].p[2], (*abs)[0].segments[i].p[2].x, (*abs)[0].segments[i].p[2].y);
    EXPECT_TRUE((*abs)[0].closed);
    // A moveto's extra pairs are linetos; numbers may touch ("1.5.5", "-1-2").
    const auto packed = parse_path("M1.5.5-1-2");
    ASSERT_TRUE(packed);
    expect_point((*packed)[0].start, 1.5, 0.5);
    expect_point((*packed)[0].segments[0].p[2], -1, -2);
}

TEST(SvgSyntax, SmoothCurvesReflectTheLastControlPoint) {
    const auto c = parse_path("M0 0 C 0 10 10 10 10 0 S 20 -10 20 0");
    ASSERT_TRUE(c);
    const auto& s = (*c)[0].segments;
    ASSERT_EQ(s.size(), 2U);
    expect_point(s[1].p[0], 10, -10);
    // Q then T: T's control is Q's reflected, (15,-10); as a cubic, c1 = end + 2/3 (q - end).
    const auto q = parse_path("M0 0 Q 5 10 10 0 T 20 0");
    ASSERT_TRUE(q);
    const auto& t = (*q)[0].segments;
    expect_point(t[0].p[0], 10.0 / 3, 20.0 / 3, 1e-12);
    expect_point(t[1].p[0], 10 + 2.0 / 3 * 5, 2.0 / 3 * -10, 1e-12);
    expect_point(t[1].p[2], 20, 0);
}

// Every flattened point of an arc lies on its circle, and the sweep flag picks the side.
TEST(SvgSyntax, ArcsFollowTheEndpointParameterisation) {
    for (const char* d : {"M 0 0 A 10 10 0 0 1 20 0", "M0 0a10 10 0 0120 0", "M 0 0 A 1 1 0 0 1 20 0"}) {
        const auto p = parse_path(d);
        ASSERT_TRUE(p) << d << ": " << p.error().to_string();
        const auto lines = flatten(*p, 1e-4);
        double lowest = 0;
        for (const auto& pt : lines[0].points) {
            EXPECT_NEAR(std::hypot(pt.x - 10, pt.y), 10, 2e-4) << d;
            lowest = std::min(lowest, pt.y);
        }
        EXPECT_NEAR(lowest, -10, 1e-3) << d << ": sweep 1 goes through negative y";
        expect_point((*p)[0].segments.back().p[2], 20, 0);
    }
    const auto other_side = flatten(*parse_path("M 0 0 A 10 10 0 0 0 20 0"), 1e-4);
    double highest = 0;
    for (const auto& pt : other_side[0].points) highest = std::max(highest, pt.y);
    EXPECT_NEAR(highest, 10, 1e-3);
    // A rotated ellipse's large arc: the end point exact, the pieces at most 45° each.
    const auto big = parse_path("M 0 0 A 30 10 30 1 0 10 10");
    ASSERT_TRUE(big);
    expect_point((*big)[0].segments.back().p[2], 10, 10);
    EXPECT_LE((*big)[0].segments.size(), 8U);
    // Zero radius: a straight line.
    const auto flat = parse_path("M 0 0 A 0 5 0 0 1 10 0");
    ASSERT_EQ((*flat)[0].segments.size(), 1U);
    EXPECT_TRUE((*flat)[0].segments[0].line);
}

TEST(SvgSyntax, BadPathDataSaysWhere) {
    const auto no_move = parse_path("L 10 10");
    ASSERT_FALSE(no_move);
    EXPECT_NE(no_move.error().message.find("moveto"), std::string::npos);
    const auto half = parse_path("M 10 10 L 5");
    ASSERT_FALSE(half);
    EXPECT_EQ(half.error().where, "character 12");
    const auto flag = parse_path("M 0 0 A 1 1 0 2 1 5 5");
    ASSERT_FALSE(flag);
    EXPECT_NE(flag.error().message.find("arc flag"), std::string::npos);
    EXPECT_FALSE(parse_path("M 0 0 X 1 1"));
    EXPECT_TRUE(parse_path("")->empty());
}

TEST(SvgSyntax, FlatteningStaysWithinItsTolerance) {
    const auto c = parse_path("M 0 0 C 0 50 100 50 100 0");
    ASSERT_TRUE(c);
    for (double tol : {0.5, 0.05, 0.005}) {
        const auto pl = flatten(*c, tol);
        // Sample the true curve; each sample lies within tol of the polyline.
        for (int i = 0; i <= 1000; ++i) {
            const double t = i / 1000.0, u = 1 - t;
            const Point q{3 * u * t * t * 100 + t * t * t * 100, 3 * u * u * t * 50 + 3 * u * t * t * 50};
            double best = 1e9;
            for (std::size_t k = 1; k < pl[0].points.size(); ++k)
                best = std::min(best, distance_to_segment(q, pl[0].points[k - 1], pl[0].points[k]));
            ASSERT_LE(best, tol + 1e-9) << "t=" << t << " tol=" << tol;
        }
    }
    // Straight segments stay one piece.
    EXPECT_EQ(flatten(*parse_path("M0 0 L 10 0 L 10 10"), 0.01)[0].points.size(), 3U);
}

}  // namespace
}  // namespace tactus::graphic
