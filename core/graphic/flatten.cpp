// SPDX-License-Identifier: GPL-3.0-or-later
#include "graphic/flatten.hpp"

#include <algorithm>
#include <cmath>

namespace tactus::graphic {

namespace {

Point mid(Point a, Point b) { return {(a.x + b.x) / 2, (a.y + b.y) / 2}; }

void flatten_cubic(Point p0, Point p1, Point p2, Point p3, double tol, int depth, std::vector<Point>& out) {
    const double flat = std::max(distance_to_segment(p1, p0, p3), distance_to_segment(p2, p0, p3));
    if (flat <= tol || depth >= kMaxFlattenDepth) {
        out.push_back(p3);
        return;
    }
    const Point a = mid(p0, p1), b = mid(p1, p2), c = mid(p2, p3), ab = mid(a, b), bc = mid(b, c), m = mid(ab, bc);
    flatten_cubic(p0, a, ab, m, tol, depth + 1, out);
    flatten_cubic(m, bc, c, p3, tol, depth + 1, out);
}

}  // namespace

double distance_to_segment(Point q, Point a, Point b) {
    const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((q.x - a.x) * dx + (q.y - a.y) * dy) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(q.x - (a.x + t * dx), q.y - (a.y + t * dy));
}

std::vector<Polyline> flatten(const std::vector<Subpath>& subpaths, double tolerance_mm) {
    std::vector<Polyline> out;
    for (const auto& sp : subpaths) {
        Polyline pl;
        pl.closed = sp.closed;
        pl.points.push_back(sp.start);
        Point cur = sp.start;
        for (const auto& s : sp.segments) {
            if (s.line) pl.points.push_back(s.p[2]);
            else flatten_cubic(cur, s.p[0], s.p[1], s.p[2], tolerance_mm, 0, pl.points);
            cur = s.p[2];
        }
        // A closed subpath ends on its start: the closing edge is implied.
        if (pl.closed && pl.points.size() > 1 && pl.points.back() == pl.points.front()) pl.points.pop_back();
        out.push_back(std::move(pl));
    }
    return out;
}

double length(const Polyline& p) {
    double l = 0;
    for (std::size_t i = 1; i < p.points.size(); ++i)
        l += std::hypot(p.points[i].x - p.points[i - 1].x, p.points[i].y - p.points[i - 1].y);
    if (p.closed && p.points.size() > 1)
        l += std::hypot(p.points.front().x - p.points.back().x, p.points.front().y - p.points.back().y);
    return l;
}

}  // namespace tactus::graphic
