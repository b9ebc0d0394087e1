// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A drawing as geometry: what the SVG reader makes and the dot placer reads.
// Everything is in millimetres on the drawing (its top-left corner at 0,0, y
// down), transforms and the viewBox already applied; curves are cubic Béziers
// (quadratics and arcs are converted on reading, exactly for quadratics, to
// within kArcTolerance for arcs).
#include <array>
#include <string>
#include <vector>

namespace tactus::graphic {

struct Point {
    double x = 0;
    double y = 0;
    bool operator==(const Point&) const = default;
};

// x' = a x + c y + e, y' = b x + d y + f (SVG's matrix(a b c d e f)).
struct Affine {
    double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
    [[nodiscard]] Point apply(Point p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
    // this ∘ o: o first, then this.
    [[nodiscard]] Affine then_after(const Affine& o) const {
        return {a * o.a + c * o.b, b * o.a + d * o.b, a * o.c + c * o.d,
                b * o.c + d * o.d, a * o.e + c * o.f + e, b * o.e + d * o.f + f};
    }
    // How much the map stretches lengths, on average over directions (for stroke widths).
    [[nodiscard]] double scale() const;
};

// A subpath: from `start`, each segment a cubic from the previous end point
// (a straight segment has its control points on its ends: `line` says so).
struct Segment {
    std::array<Point, 3> p;  // control 1, control 2, end
    bool line = false;
};

struct Subpath {
    Point start;
    std::vector<Segment> segments;
    bool closed = false;
};

enum class LineStyle : unsigned char { solid, dashed, dotted };

struct Shape {
    std::vector<Subpath> subpaths;
    bool stroked = false;
    LineStyle style = LineStyle::solid;
    double stroke_width_mm = 0;
    bool filled = false;  // a fill a reader should feel (not none, not white)
    bool even_odd = false;
    std::string fill_paint;  // as written: equal paints get equal textures
    std::string element;  // "circle", "path", ... for warnings
    int line = 0;         // in the SVG file, for warnings
};

// A <text>: its characters and where its first character's baseline starts.
struct Label {
    std::string text;  // UTF-8, white space collapsed
    Point anchor;
    double font_size_mm = 0;
    int line = 0;
};

struct Drawing {
    double width_mm = 0;
    double height_mm = 0;
    std::string title;        // the root's <title>, for speech and the key
    std::string description;  // the root's <desc>
    std::vector<Shape> shapes;
    std::vector<Label> labels;
    // What was left out or changed, as "line N: why".
    std::vector<std::string> warnings;
};

// Largest distance between an arc and the cubics that replace it.
inline constexpr double kArcTolerance = 1e-5;  // relative to the arc's radius (pieces of at most 45°)

}  // namespace tactus::graphic
