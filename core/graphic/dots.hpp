// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Geometry -> dots a hammer can strike (docs/graphics.md, "Dots"). Strokes
// become dots evenly spaced along them, in a pattern that tells solid, dashed
// and dotted lines apart; filled areas a texture by their paint; labels
// braille cells placed clear of the lines, or into the key when they do not
// fit. Every dot lies on the machine's step grid, inside the page area, and no
// two dots are closer than the hammer allows.
#include <functional>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "document/cell.hpp"
#include "graphic/drawing.hpp"
#include "graphic/flatten.hpp"

namespace tactus::graphic {

struct DotOptions {
    // Along a solid line, dot centre to centre: close enough that a finger
    // reads a line, not a row of dots (docs/graphics.md says where it comes from).
    double spacing_mm = 1.5;
    // A dotted line's dots: twice as far apart as a solid line's.
    double dotted_spacing_mm = 3.0;
    // A dashed line: dashes of three dots (two spacings long), gaps about this long.
    double dash_gap_mm = 4.5;
    // A stroke at least this wide is bold: two rows of dots this far apart.
    double bold_width_mm = 1.5;
    double bold_row_gap_mm = 1.5;
    // No two dots closer: the hammer would strike into the last dot's crater.
    double min_distance_mm = 1.25;
    // The machine's addressable grid: one carriage step across, one feed step down.
    double x_step_mm = 1.0 / 80;
    double y_step_mm = 1.0 / 40;
    // Curves are flattened to within this of the true curve.
    double flatness_mm = 0.02;
    // Textures: rows (or single dots) at this pitch, kept this far from every
    // line dot; along a texture's rows, dots at texture_spacing_mm. Both are
    // whole multiples of the reference firmware's grid (0.25 mm x 1.25 mm).
    double texture_pitch_mm = 5.0;
    double texture_spacing_mm = 2.5;
    double texture_clearance_mm = 3.0;
    // A label's dots stay this far from every line and texture dot.
    double label_clearance_mm = 5.0;
    // Braille cells of labels (the profile's cell geometry).
    double dot_pitch_mm = 2.5;
    double cell_pitch_mm = 6.0;
};

// Where the drawing goes: the page area, in page millimetres.
struct Area {
    double left = 0, top = 0, right = 0, bottom = 0;
    [[nodiscard]] bool contains(Point p) const { return p.x >= left && p.x <= right && p.y >= top && p.y <= bottom; }
};

enum class DotKind : unsigned char { line, texture, label };

struct Dot {
    Point at;
    DotKind kind = DotKind::line;
    int source = 0;  // index of its shape (line, texture) or label in the drawing
};

// One row of dots along a stroke (the stroke's centre line; one of a bold
// stroke's two rows) and its dots in order (indices into GraphicDots::dots).
struct StrokeTrace {
    int shape = 0;
    Polyline line;
    std::vector<std::size_t> dots;
};

struct GraphicDots {
    std::vector<Dot> dots;
    std::vector<StrokeTrace> strokes;
    std::vector<int> key;  // labels (indices) that did not fit: the key lists them
    std::vector<std::string> warnings;
};

// Braille for a label's text (the document's table).
using Braille = std::function<Result<document::BrailleLine>(const std::string& utf8)>;

// `drawing` in page millimetres (fit_to_area), its dots inside `area`.
Result<GraphicDots> place_dots(const Drawing& drawing, const Area& area, const DotOptions& o, const Braille& braille);

// The drawing moved to the area's top-left corner, scaled down to fit it when
// it is larger (never up: a tactile graphic keeps its size when it can).
// `scale` receives the factor.
Drawing fit_to_area(const Drawing& drawing, const Area& area, double* scale = nullptr);

// The nearest point of the grid.
Point snap(Point p, const DotOptions& o);

}  // namespace tactus::graphic
