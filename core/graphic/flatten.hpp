// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Curves -> polylines, adaptively: a cubic is halved (de Casteljau) until its
// control points lie within the tolerance of its chord. The curve lies in the
// hull of its control points, so every point of the curve is then within the
// tolerance of the polyline; straight segments stay one piece.
#include <vector>

#include "graphic/drawing.hpp"

namespace tactus::graphic {

struct Polyline {
    std::vector<Point> points;
    bool closed = false;
};

// Halvings of one cubic at most: 2^16 pieces is far below any tolerance asked.
inline constexpr int kMaxFlattenDepth = 16;

std::vector<Polyline> flatten(const std::vector<Subpath>& subpaths, double tolerance_mm);

// Length of a polyline, its closing edge included when closed.
double length(const Polyline& p);

// Distance from q to the segment a-b.
double distance_to_segment(Point q, Point a, Point b);

}  // namespace tactus::graphic
