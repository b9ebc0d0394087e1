// SPDX-License-Identifier: GPL-3.0-or-later
// SVG files -> drawings: sizes and viewBox, nested transforms, styles,
// labels, what is left out (named in a warning) and what is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "graphic/flatten.hpp"
#include "graphic/svg_import.hpp"

namespace tactus::graphic {
namespace {

std::string svg(const std::string& attrs, const std::string& body) {
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" " + attrs + ">\n" + body + "\n</svg>\n";
}

TEST(SvgImport, TheTestDrawingHasItsShapesLabelsAndTitle) {
    const auto d = load_svg(std::string(TACTUS_TEST_DATA) + "/graphics/shapes.svg");
    ASSERT_TRUE(d) << d.error().to_string();
    EXPECT_DOUBLE_EQ(d->width_mm, 150);
    EXPECT_DOUBLE_EQ(d->height_mm, 200);
    EXPECT_EQ(d->title, "Test shapes");
    EXPECT_NE(d->description.find("bar chart"), std::string::npos);
    ASSERT_EQ(d->shapes.size(), 8U);  // circle, triangle, 2 lines, the axes, 3 bars
    EXPECT_EQ(d->shapes[0].element, "circle");
    EXPECT_FALSE(d->shapes[0].filled);
    EXPECT_EQ(d->shapes[2].style, LineStyle::dashed);
    EXPECT_EQ(d->shapes[3].style, LineStyle::dotted);
    for (std::size_t i = 5; i < 8; ++i) EXPECT_TRUE(d->shapes[i].filled) << i;
    ASSERT_EQ(d->labels.size(), 3U);
    EXPECT_EQ(d->labels[0].text, "A");
    // translate(75 10) and 1 mm a user unit: (0,62) lands at (75,72).
    EXPECT_NEAR(d->labels[0].anchor.x, 75, 1e-9);
    EXPECT_NEAR(d->labels[0].anchor.y, 72, 1e-9);
    EXPECT_TRUE(d->warnings.empty()) << d->warnings.front();
}

TEST(SvgImport, ViewBoxScalesAndCentres) {
    // 100 mm wide for 50 units: 2 mm a unit; the taller viewport centres the box (meet).
    const auto d = read_svg(svg(R"(width="100mm" height="120mm" viewBox="0 0 50 50")",
                                R"(<circle cx="25" cy="25" r="10" fill="none" stroke="black"/>)"));
    ASSERT_TRUE(d) << d.error().to_string();
    const auto pl = flatten(d->shapes[0].subpaths, 1e-4);
    for (const auto& p : pl[0].points) EXPECT_NEAR(std::hypot(p.x - 50, p.y - 60), 20, 1e-3);
    EXPECT_NEAR(d->shapes[0].stroke_width_mm, 2, 1e-12);
    // No viewBox: a user unit is a CSS pixel; a size from the viewBox alone.
    const auto px = read_svg(svg(R"(width="96" height="96")", R"(<line x1="0" y1="0" x2="96" y2="0" stroke="red"/>)"));
    ASSERT_TRUE(px);
    EXPECT_NEAR(px->shapes[0].subpaths[0].segments.back().p[2].x, 25.4, 1e-9);
    const auto vb = read_svg(svg(R"(viewBox="0 0 96 48")", ""));
    ASSERT_TRUE(vb);
    EXPECT_NEAR(vb->width_mm, 25.4, 1e-9);
    EXPECT_NEAR(vb->height_mm, 12.7, 1e-9);
}

TEST(SvgImport, NestedTransformsApplyInsideOut) {
    const auto d = read_svg(svg(R"(width="100mm" height="100mm" viewBox="0 0 100 100")",
                                R"S(<g transform="translate(10,0)"><g transform="scale(2)">
                                   <line x1="0" y1="0" x2="5" y2="0" stroke="black" transform="rotate(90)"/>
                                   </g></g>)S"));
    ASSERT_TRUE(d) << d.error().to_string();
    const auto& s = d->shapes.at(0).subpaths.at(0);
    EXPECT_NEAR(s.start.x, 10, 1e-9);
    EXPECT_NEAR(s.segments.back().p[2].x, 10, 1e-9);
    EXPECT_NEAR(s.segments.back().p[2].y, 10, 1e-9);
}

TEST(SvgImport, StylesComeFromAttributesStyleAndAncestors) {
    const auto d = read_svg(svg(R"(width="50mm" height="50mm" viewBox="0 0 50 50")",
                                R"(<g style="stroke: black; stroke-width: 0.4">
                                     <path d="M0 0 H10"/>
                                     <path d="M0 5 H10" fill="none"/>
                                     <path d="M0 9 H10 V20 Z" style="fill:#FFFFFF"/>
                                     <path d="M0 25 H10" stroke-dasharray="3,2"/>
                                   </g>
                                   <path d="M0 30 H10" fill="none"/>
                                   <g display="none"><path d="M0 40 H10" stroke="black"/></g>)"));
    ASSERT_TRUE(d) << d.error().to_string();
    ASSERT_EQ(d->shapes.size(), 4U);  // the unstroked, unfilled one and the hidden one draw nothing
    EXPECT_TRUE(d->shapes[0].filled);  // fill defaults to black
    EXPECT_TRUE(d->shapes[0].stroked);
    EXPECT_NEAR(d->shapes[0].stroke_width_mm, 0.4, 1e-12);
    EXPECT_FALSE(d->shapes[1].filled);
    EXPECT_FALSE(d->shapes[2].filled);  // white is the paper
    EXPECT_EQ(d->shapes[3].style, LineStyle::dashed);
}

TEST(SvgImport, WhatIsNotReadIsNamedInAWarning) {
    const auto d = read_svg(svg(R"(width="50mm" height="50mm")",
                                "<rect width=\"10\" height=\"10\"/>\n<image href=\"x.png\" width=\"5\" height=\"5\"/>\n"
                                "<use href=\"#a\"/>"));
    ASSERT_TRUE(d) << d.error().to_string();
    ASSERT_EQ(d->warnings.size(), 2U);
    EXPECT_EQ(d->warnings[0].rfind("line 3: <image> is not embossed", 0), 0U) << d->warnings[0];
    EXPECT_EQ(d->warnings[1].rfind("line 4: <use> is not embossed", 0), 0U) << d->warnings[1];
}

TEST(SvgImport, BadFilesAreRefusedSayingWhatAndWhere) {
    const auto not_xml = read_svg("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1\" height=\"1\">\n<g>\n</svg>");
    ASSERT_FALSE(not_xml);
    EXPECT_EQ(not_xml.error().kind, ErrorKind::input);
    EXPECT_NE(not_xml.error().message.find("not well-formed XML"), std::string::npos);
    const auto html = read_svg("<html/>");
    ASSERT_FALSE(html);
    EXPECT_NE(html.error().message.find("root element is <html>"), std::string::npos);
    const auto no_size = read_svg(svg("", ""));
    ASSERT_FALSE(no_size);
    EXPECT_NE(no_size.error().message.find("no size"), std::string::npos);
    const auto bad_d = read_svg(svg(R"(width="5mm" height="5mm")", "\n<path d=\"M 0 0 L 1\" stroke=\"black\"/>"));
    ASSERT_FALSE(bad_d);
    EXPECT_EQ(bad_d.error().where, "line 3: attribute d, character 10");
    const auto bad_t = read_svg(svg(R"(width="5mm" height="5mm")", "<g transform=\"spin(3)\"/>"));
    ASSERT_FALSE(bad_t);
    EXPECT_EQ(bad_t.error().where.rfind("line 2: attribute transform", 0), 0U) << bad_t.error().where;
    const auto bad_vb = read_svg(svg(R"(viewBox="0 0 0 10")", ""));
    ASSERT_FALSE(bad_vb);
    EXPECT_NE(bad_vb.error().message.find("positive"), std::string::npos);
    std::string deep;
    for (int i = 0; i < 400; ++i) deep += "<g>";
    for (int i = 0; i < 400; ++i) deep += "</g>";
    const auto too_deep = read_svg(svg(R"(width="5mm" height="5mm")", deep));
    ASSERT_FALSE(too_deep);
    EXPECT_NE(too_deep.error().message.find("levels deep"), std::string::npos);
    const auto missing = load_svg("/nonexistent/drawing.svg");
    EXPECT_FALSE(missing);
}

TEST(SvgImport, ShapesBecomeTheirOutlines) {
    const auto d = read_svg(svg(R"(width="100mm" height="100mm" viewBox="0 0 100 100")",
                                R"(<rect x="10" y="10" width="20" height="10" rx="2" fill="none" stroke="black"/>
                                   <ellipse cx="50" cy="50" rx="20" ry="10" fill="none" stroke="black"/>
                                   <polyline points="0,0 10,0 10,10" fill="none" stroke="black"/>
                                   <polygon points="0,0 10,0 10,10" fill="none" stroke="black"/>)"));
    ASSERT_TRUE(d) << d.error().to_string();
    ASSERT_EQ(d->shapes.size(), 4U);
    // The rounded rectangle's perimeter: 2(20+10) less 8 r plus a circle of radius 2.
    EXPECT_NEAR(length(flatten(d->shapes[0].subpaths, 1e-5)[0]), 60 - 16 + 2 * M_PI * 2, 1e-3);
    const auto ellipse = flatten(d->shapes[1].subpaths, 1e-5);
    for (const auto& p : ellipse[0].points)
        EXPECT_NEAR((p.x - 50) * (p.x - 50) / 400 + (p.y - 50) * (p.y - 50) / 100, 1, 1e-3);
    EXPECT_FALSE(d->shapes[2].subpaths[0].closed);
    EXPECT_TRUE(d->shapes[3].subpaths[0].closed);
    EXPECT_NEAR(length(flatten(d->shapes[3].subpaths, 1e-5)[0]), 20 + std::sqrt(200.0), 1e-9);
}


// The W3C test suite's quadratic curves: the smooth (T) curves pass through
// the marked points, their control points the reflections SVG defines.
TEST(SvgImport, W3cQuadraticCurvesPassThroughTheirMarkers) {
    const auto d = load_svg(std::string(TACTUS_TEST_DATA) + "/graphics/w3c/paths-data-02-t.svg");
    ASSERT_TRUE(d) << d.error().to_string();
    const double px = 25.4 / 96;  // width="100%": the viewBox's 480 x 360 CSS pixels
    EXPECT_NEAR(d->width_mm, 480 * px, 1e-9);
    std::vector<const Shape*> paths;
    for (const auto& s : d->shapes)
        if (s.element == "path") paths.push_back(&s);
    ASSERT_EQ(paths.size(), 7U);
    // "M240 296q25-100 47 0t47 0t47 0t47 0t47 0z": ends on the markers 47 apart.
    const auto& sine = paths[5]->subpaths.at(0).segments;
    ASSERT_EQ(sine.size(), 6U);  // five curves and the closing line
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_NEAR(sine[i].p[2].x / px, 287 + 47.0 * static_cast<double>(i), 1e-9);
        EXPECT_NEAR(sine[i].p[2].y / px, 296, 1e-9);
    }
    // The first t's control point is q's (265,196) reflected about (287,296): (309,396).
    EXPECT_NEAR(sine[1].p[0].x / px, 287 + 2.0 / 3 * 22, 1e-9);
    EXPECT_NEAR(sine[1].p[0].y / px, 296 + 2.0 / 3 * 100, 1e-9);
    // Two subpaths where the data has two movetos; the relative m after z starts from the closed subpath's start.
    EXPECT_EQ(paths[1]->subpaths.size(), 2U);
    EXPECT_NEAR(paths[1]->subpaths[1].start.x / px, 442, 1e-9);
    EXPECT_NEAR(paths[1]->subpaths[1].start.y / px, 130, 1e-9);
    // Its test-description elements are named, not silently skipped.
    ASSERT_FALSE(d->warnings.empty());
    EXPECT_NE(d->warnings[0].find("<SVGTestCase> is not embossed"), std::string::npos) << d->warnings[0];
    EXPECT_EQ(d->labels.size(), 9U);
}

// The W3C test suite's nested transforms: each rectangle's far corner lands in its marker square.
TEST(SvgImport, W3cNestedTransformsLandOnTheirMarkers) {
    const auto d = load_svg(std::string(TACTUS_TEST_DATA) + "/graphics/w3c/coords-trans-02-t.svg");
    ASSERT_TRUE(d) << d.error().to_string();
    ASSERT_EQ(d->shapes.size(), 11U);  // four bars, six markers, the frame
    const auto corners = [](const Shape& s) {
        std::vector<Point> v{s.subpaths.at(0).start};
        for (const auto& seg : s.subpaths[0].segments) v.push_back(seg.p[2]);
        return v;
    };
    const auto inside = [&](Point p, const Shape& marker) {
        double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
        for (const auto& c : corners(marker)) {
            x0 = std::min(x0, c.x), y0 = std::min(y0, c.y), x1 = std::max(x1, c.x), y1 = std::max(y1, c.y);
        }
        return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1;
    };
    // Bars 0-3 (blue, red; then blue, red rotated -90°), markers 4-9 (black, blue, red twice).
    const std::pair<std::size_t, std::size_t> bar_marker[] = {{0, 5}, {1, 6}, {2, 8}, {3, 9}};
    for (const auto& [bar, marker] : bar_marker) {
        std::size_t hits = 0;
        for (const auto& c : corners(d->shapes[bar])) hits += inside(c, d->shapes[marker]) ? 1U : 0U;
        EXPECT_GE(hits, 1U) << "bar " << bar << " misses its marker " << marker;
        std::size_t origin = 0;
        for (const auto& c : corners(d->shapes[bar])) origin += inside(c, d->shapes[bar < 2 ? 4 : 7]) ? 1U : 0U;
        EXPECT_GE(origin, 1U) << "bar " << bar << " does not start on its black marker";
    }
}
}  // namespace
}  // namespace tactus::graphic
