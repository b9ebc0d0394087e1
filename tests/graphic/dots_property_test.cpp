// SPDX-License-Identifier: GPL-3.0-or-later
// Properties of the dots, on random drawings (fixed seeds): on the step grid,
// on their strokes, evenly spaced, inside the page area, never closer than the
// hammer allows, labels clear of the lines.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>

#include "common/utf8.hpp"
#include "graphic/dots.hpp"
#include "graphic/graphic_page.hpp"
#include "graphic/svg_import.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile.hpp"
#include "translate/catalogue.hpp"
#include "translate/translator.hpp"

namespace tactus::graphic {
namespace {

const translate::Translator& table() {
    static const auto t = *translate::Translator::open(translate::kDefaultTable);
    return t;
}

Braille braille() {
    return [](const std::string& s) -> Result<document::BrailleLine> { return table().translate(*utf8_to_utf32(s)); };
}

double dist(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

double distance_to(const Polyline& pl, Point q) {
    double best = pl.points.size() == 1 ? dist(q, pl.points[0]) : 1e18;
    const auto n = pl.points.size();
    for (std::size_t i = 1; i < n; ++i) best = std::min(best, distance_to_segment(q, pl.points[i - 1], pl.points[i]));
    if (pl.closed && n > 1) best = std::min(best, distance_to_segment(q, pl.points[n - 1], pl.points[0]));
    return best;
}

// A random drawing of `shapes` shapes (lines, polylines, circles, ellipses,
// curves, rectangles; solid, dashed or dotted; some filled) and `labels` labels.
std::string random_svg(std::mt19937& rng, int shapes, int labels) {
    std::uniform_real_distribution<double> x(0, 150), y(0, 230), r(3, 40), u(0, 1);
    std::ostringstream s;
    s.precision(6);
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"150mm\" height=\"230mm\" viewBox=\"0 0 150 230\">\n";
    const char* dashes[] = {"", " stroke-dasharray=\"4 3\"", " stroke-dasharray=\"0.3 2\""};
    for (int i = 0; i < shapes; ++i) {
        const std::string style = std::string(" stroke=\"black\" stroke-width=\"") + (rng() % 4 == 0 ? "2" : "0.5") +
                                  "\"" + dashes[rng() % 3] +
                                  (u(rng) < 0.2 ? " fill=\"#" + std::to_string(100000 + rng() % 4) + "\"" : " fill=\"none\"");
        switch (rng() % 6) {
            case 0: s << "<line x1=\"" << x(rng) << "\" y1=\"" << y(rng) << "\" x2=\"" << x(rng) << "\" y2=\"" << y(rng) << "\"" << style << "/>\n"; break;
            case 1: s << "<polyline points=\"" << x(rng) << "," << y(rng) << " " << x(rng) << "," << y(rng) << " " << x(rng) << "," << y(rng) << "\"" << style << "/>\n"; break;
            case 2: s << "<circle cx=\"" << x(rng) << "\" cy=\"" << y(rng) << "\" r=\"" << r(rng) << "\"" << style << "/>\n"; break;
            case 3: s << "<ellipse cx=\"" << x(rng) << "\" cy=\"" << y(rng) << "\" rx=\"" << r(rng) << "\" ry=\"" << r(rng) << "\" transform=\"rotate(" << 360 * u(rng) << ")\"" << style << "/>\n"; break;
            case 4: s << "<path d=\"M" << x(rng) << " " << y(rng) << " C" << x(rng) << " " << y(rng) << " " << x(rng) << " " << y(rng) << " " << x(rng) << " " << y(rng) << " a 10 5 30 1 0 " << r(rng) << " " << r(rng) << "\"" << style << "/>\n"; break;
            default: s << "<rect x=\"" << x(rng) << "\" y=\"" << y(rng) << "\" width=\"" << r(rng) << "\" height=\"" << r(rng) << "\"" << style << "/>\n";
        }
    }
    const char* words[] = {"A", "river", "42", "north", "x"};
    for (int i = 0; i < labels; ++i)
        s << "<text x=\"" << x(rng) << "\" y=\"" << y(rng) << "\">" << words[rng() % 5] << "</text>\n";
    s << "</svg>\n";
    return s.str();
}

struct Placed {
    Drawing drawing;  // on the page
    GraphicDots dots;
};

Placed place(const std::string& text, const DotOptions& o, const Area& area) {
    auto d = read_svg(text);
    EXPECT_TRUE(d) << d.error().to_string();
    Placed p;
    p.drawing = fit_to_area(*d, area);
    auto g = place_dots(p.drawing, area, o, braille());
    EXPECT_TRUE(g) << g.error().to_string();
    p.dots = std::move(*g);
    return p;
}

const profile::PrinterProfile kMachine = profile::default_profile();

// Every rule on random drawings, on the grid of one motor step and on the
// reference firmware's coarser grid (protocol 3).
void check_random_drawings(const DotOptions& o) {
    const Area area = page_area(kMachine);
    // How far snapping may move a dot: half a step on each axis.
    const double snap_error = std::hypot(o.x_step_mm, o.y_step_mm) / 2;
    std::size_t total = 0, labels = 0;
    for (unsigned seed = 1; seed <= 12; ++seed) {
        std::mt19937 rng(seed);
        const auto placed = place(random_svg(rng, 8, 4), o, area);
        const auto& dots = placed.dots.dots;
        total += dots.size();
        for (const auto& d : dots) {
            // On the machine's grid: a whole number of carriage and feed steps.
            EXPECT_NEAR(d.at.x / o.x_step_mm, std::round(d.at.x / o.x_step_mm), 1e-6);
            EXPECT_NEAR(d.at.y / o.y_step_mm, std::round(d.at.y / o.y_step_mm), 1e-6);
            EXPECT_TRUE(area.contains(d.at)) << "seed " << seed << ": dot at " << d.at.x << "," << d.at.y;
            labels += d.kind == DotKind::label;
        }
        // Every line dot within the grid's reach of its stroke (the flattened
        // stroke is within flatness_mm of the curve itself).
        for (const auto& t : placed.dots.strokes)
            for (auto i : t.dots) ASSERT_LE(distance_to(t.line, dots[i].at), snap_error + 1e-9) << "seed " << seed;
        for (const auto& d : dots) {
            if (d.kind != DotKind::line) continue;
            const auto& shape = placed.drawing.shapes[static_cast<std::size_t>(d.source)];
            const auto lines = flatten(shape.subpaths, o.flatness_mm);
            double best = 1e18;
            for (const auto& l : lines) best = std::min(best, distance_to(l, d.at));
            // A bold stroke's rows stand half their gap off the centre line (twice that at a sharp corner's mitre).
            const double reach = shape.stroke_width_mm >= o.bold_width_mm
                                     ? std::max(shape.stroke_width_mm / 2, o.bold_row_gap_mm)
                                     : 0.0;
            EXPECT_LE(best, reach + snap_error + 1e-9);
        }
        // No two dots closer than the hammer allows; label dots clear of line dots.
        for (std::size_t i = 0; i < dots.size(); ++i)
            for (std::size_t j = i + 1; j < dots.size(); ++j) {
                const double dd = dist(dots[i].at, dots[j].at);
                ASSERT_GE(dd, o.min_distance_mm) << "seed " << seed << ": dots " << i << " and " << j;
                const bool mixed = (dots[i].kind == DotKind::label) != (dots[j].kind == DotKind::label);
                if (mixed && (dots[i].kind == DotKind::line || dots[j].kind == DotKind::line)) {
                    ASSERT_GE(dd, o.label_clearance_mm) << "seed " << seed << ": a label touches a line";
                }
            }
    }
    EXPECT_GT(total, 1000U);  // the drawings did make dots
    EXPECT_GT(labels, 10U);   // and placed labels
}

TEST(GraphicDots, RandomDrawingsKeepEveryRuleOnTheStepGrid) {
    const DotOptions o = dot_options(kMachine);
    EXPECT_DOUBLE_EQ(o.x_step_mm, 1.0 / 80);
    EXPECT_DOUBLE_EQ(o.y_step_mm, 1.0 / 40);
    check_random_drawings(o);
}

TEST(GraphicDots, RandomDrawingsKeepEveryRuleOnTheFirmwareGrid) {
    const auto tables = profile::make_firmware_tables(kMachine);
    ASSERT_TRUE(tables) << tables.error().to_string();
    const DotOptions o = dot_options(kMachine, &*tables);
    EXPECT_DOUBLE_EQ(o.x_step_mm, 0.25);
    EXPECT_DOUBLE_EQ(o.y_step_mm, 1.25);
    check_random_drawings(o);
}

// Along a lone solid stroke the dots are evenly spaced: within a quarter of
// the spacing of it (the stroke's length divided into whole intervals), plus
// what snapping moves them.
TEST(GraphicDots, SpacingAlongAStrokeStaysInTheBand) {
    const DotOptions o = dot_options(kMachine);
    const Area area = page_area(kMachine);
    const double snap_error = std::hypot(o.x_step_mm, o.y_step_mm) / 2;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> x(0, 150), y(0, 230), r(8, 60);
    for (int k = 0; k < 60; ++k) {
        std::ostringstream s;
        s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"150mm\" height=\"230mm\" viewBox=\"0 0 150 230\">";
        if (k % 2) s << "<line x1=\"" << x(rng) << "\" y1=\"" << y(rng) << "\" x2=\"" << x(rng) << "\" y2=\"" << y(rng) << "\"";
        else s << "<circle cx=\"75\" cy=\"115\" r=\"" << r(rng) << "\"";
        s << " stroke=\"black\" fill=\"none\"/></svg>";
        const auto placed = place(s.str(), o, area);
        ASSERT_EQ(placed.dots.strokes.size(), 1U);
        const auto& t = placed.dots.strokes[0];
        const double L = length(t.line);
        if (L < 1.5 * o.spacing_mm) continue;
        const auto n = t.line.closed ? t.dots.size() : t.dots.size() - 1;
        EXPECT_NEAR(L / static_cast<double>(n), o.spacing_mm, o.spacing_mm / 4 + 1e-9) << s.str();
        for (std::size_t i = 1; i < t.dots.size(); ++i) {
            const double d = dist(placed.dots.dots[t.dots[i - 1]].at, placed.dots.dots[t.dots[i]].at);
            // A chord of a circle is a little shorter than its arc.
            EXPECT_GE(d, 0.75 * o.spacing_mm - 2 * snap_error - 0.01) << s.str();
            EXPECT_LE(d, 1.25 * o.spacing_mm + 2 * snap_error) << s.str();
        }
    }
}

// Solid, dashed and dotted lines of one length feel different: their dot
// counts and their gaps differ.
TEST(GraphicDots, LineStylesAreDistinct) {
    const DotOptions o = dot_options(kMachine);
    const Area area = page_area(kMachine);
    std::vector<std::size_t> counts;
    std::vector<double> widest;
    for (const char* dash : {"", "stroke-dasharray=\"4 3\"", "stroke-dasharray=\"0.3 2\""}) {
        const auto placed = place(std::string("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"150mm\" height=\"50mm\" "
                                              "viewBox=\"0 0 150 50\"><line x1=\"0\" y1=\"10\" x2=\"120\" y2=\"10\" "
                                              "stroke=\"black\" ") + dash + "/></svg>",
                                  o, area);
        const auto& t = placed.dots.strokes.at(0);
        counts.push_back(t.dots.size());
        double gap = 0;
        for (std::size_t i = 1; i < t.dots.size(); ++i)
            gap = std::max(gap, dist(placed.dots.dots[t.dots[i - 1]].at, placed.dots.dots[t.dots[i]].at));
        widest.push_back(gap);
    }
    EXPECT_NEAR(widest[0], o.spacing_mm, 0.05);             // solid: no gap
    EXPECT_GE(widest[1], o.dash_gap_mm * 0.8);              // dashed: gaps between dashes
    EXPECT_NEAR(widest[2], o.dotted_spacing_mm, 0.3);       // dotted: single dots farther apart
    EXPECT_GT(counts[0], counts[2]);
    EXPECT_GT(counts[2], 0U);
    EXPECT_NE(counts[1], counts[0]);
}

// A bold stroke is two rows of dots, either side of its centre line.
TEST(GraphicDots, ABoldStrokeIsTwoRows) {
    const DotOptions o = dot_options(kMachine);
    const Area area = page_area(kMachine);
    const double snap_error = std::hypot(o.x_step_mm, o.y_step_mm) / 2;
    std::vector<std::size_t> counts;
    for (const char* width : {"0.5", "2"}) {
        const auto placed = place(std::string("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"150mm\" height=\"150mm\" "
                                              "viewBox=\"0 0 150 150\"><circle cx=\"70\" cy=\"70\" r=\"40\" fill=\"none\" "
                                              "stroke=\"black\" stroke-width=\"") + width + "\"/></svg>",
                                  o, area);
        counts.push_back(placed.dots.dots.size());
        if (std::string(width) == "0.5") continue;
        ASSERT_EQ(placed.dots.strokes.size(), 2U);
        std::size_t inner = 0, outer = 0;
        for (const auto& d : placed.dots.dots) {
            const double r = dist(d.at, {area.left + 70, area.top + 70});
            if (std::abs(r - (40 - o.bold_row_gap_mm / 2)) <= snap_error + 0.01) ++inner;
            else if (std::abs(r - (40 + o.bold_row_gap_mm / 2)) <= snap_error + 0.01) ++outer;
            else ADD_FAILURE() << "a dot " << r << " mm from the centre, on neither row";
        }
        EXPECT_GT(inner, 100U);
        EXPECT_GT(outer, inner);  // the outer row is longer
    }
    EXPECT_GT(counts[1], 2 * counts[0] - 10);
}

// Different fill paints get different textures; textures stay off the outline.
TEST(GraphicDots, FillsBecomeDistinctTextures) {
    const DotOptions o = dot_options(kMachine);
    const Area area = page_area(kMachine);
    const auto placed = place(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"150mm\" height=\"100mm\" viewBox=\"0 0 150 100\">"
        "<rect x=\"0\" y=\"0\" width=\"40\" height=\"40\" fill=\"red\" stroke=\"black\"/>"
        "<rect x=\"50\" y=\"0\" width=\"40\" height=\"40\" fill=\"blue\" stroke=\"black\"/>"
        "<rect x=\"100\" y=\"0\" width=\"40\" height=\"40\" fill=\"red\" stroke=\"black\"/></svg>",
        o, area);
    // Each texture relative to its own rectangle's corner: equal paints equal, different ones not.
    std::vector<std::vector<std::pair<long, long>>> rel(3);
    for (const auto& d : placed.dots.dots) {
        if (d.kind != DotKind::texture) continue;
        const auto s = static_cast<std::size_t>(d.source);
        rel[s].push_back({std::lround((d.at.x - area.left - 50.0 * static_cast<double>(s)) * 80),
                          std::lround((d.at.y - area.top) * 40)});
        for (const auto& e : placed.dots.dots)
            if (e.kind == DotKind::line) {
                ASSERT_GE(dist(d.at, e.at), o.texture_clearance_mm);
            }
    }
    for (const auto& r : rel) EXPECT_GT(r.size(), 10U);
    EXPECT_NE(rel[0], rel[1]);
    EXPECT_NE(rel[0].size(), 0U);
}

// A label with no room near its place goes to the key, named in a warning.
TEST(GraphicDots, ALabelWithNoRoomGoesToTheKey) {
    const DotOptions o = dot_options(kMachine);
    const Area area = page_area(kMachine);
    std::string grid;
    for (int i = 0; i <= 60; i += 3) grid += "<line x1=\"0\" y1=\"" + std::to_string(i) + "\" x2=\"60\" y2=\"" + std::to_string(i) + "\" stroke=\"black\"/>";
    const auto placed = place("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"150mm\" height=\"100mm\" viewBox=\"0 0 150 100\">" +
                                  grid + "<text x=\"30\" y=\"30\">lost</text><text x=\"100\" y=\"80\">found</text></svg>",
                              o, area);
    ASSERT_EQ(placed.dots.key.size(), 1U);
    EXPECT_EQ(placed.dots.key[0], 0);
    bool named = false;
    for (const auto& w : placed.dots.warnings) named = named || w.find("\"lost\"") != std::string::npos;
    EXPECT_TRUE(named);
    std::size_t found = 0;
    for (const auto& d : placed.dots.dots) found += d.kind == DotKind::label && d.source == 1;
    EXPECT_GT(found, 0U);
}

}  // namespace
}  // namespace tactus::graphic

namespace tactus::graphic {
namespace {

// A damaged drawing (found by fuzz_graphic_svg) whose stroke is 2.9e41 mm
// long: counting its dot intervals converted that length to an integer,
// undefined behaviour the sanitizer build stops on. The count is now bounded
// before the conversion; the dots that land stay on the page.
TEST(DotsDamagedDrawing, AStrokeLongerThanAnyIntegerIsPlacedWithoutOverflow) {
    std::ifstream in(std::string(TACTUS_TEST_DATA) + "/graphics/damaged/stroke_longer_than_an_integer.svg",
                     std::ios::binary);
    ASSERT_TRUE(in);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const Area area = page_area(kMachine);
    const auto p = place(text, dot_options(kMachine), area);
    for (const auto& dot : p.dots.dots) EXPECT_TRUE(area.contains(dot.at));
}

}  // namespace
}  // namespace tactus::graphic
