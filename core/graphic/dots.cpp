// SPDX-License-Identifier: GPL-3.0-or-later
#include "graphic/dots.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <unordered_map>

namespace tactus::graphic {

namespace {

double dist(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

// "1.25", not "1.250000".
std::string mm(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

// The dots placed so far, in 2 mm buckets: "is any dot of these kinds within r?" in O(1).
class DotIndex {
public:
    explicit DotIndex(const std::vector<Dot>& dots) : dots_(dots) {}
    void add(std::size_t i) { cells_[key(bucket(dots_[i].at.x), bucket(dots_[i].at.y))].push_back(i); }
    // The nearest dot of a kind in `kinds` within r of p: its distance, or r when none.
    [[nodiscard]] double nearest(Point p, double r, std::initializer_list<DotKind> kinds) const {
        double best = r;
        const auto reach = static_cast<long long>(std::ceil(r / kCell));
        const auto bx = bucket(p.x), by = bucket(p.y);
        for (long long dx = -reach; dx <= reach; ++dx)
            for (long long dy = -reach; dy <= reach; ++dy) {
                const auto it = cells_.find(key(bx + dx, by + dy));
                if (it == cells_.end()) continue;
                for (auto i : it->second) {
                    if (std::find(kinds.begin(), kinds.end(), dots_[i].kind) == kinds.end()) continue;
                    best = std::min(best, dist(p, dots_[i].at));
                }
            }
        return best;
    }
    [[nodiscard]] bool any_within(Point p, double r, std::initializer_list<DotKind> kinds) const {
        return nearest(p, r, kinds) < r;
    }

private:
    static constexpr double kCell = 2.0;
    static long long bucket(double v) { return static_cast<long long>(std::floor(v / kCell)); }
    static long long key(long long x, long long y) { return x * 1000003LL + y; }
    const std::vector<Dot>& dots_;
    std::unordered_map<long long, std::vector<std::size_t>> cells_;
};

constexpr auto kAll = {DotKind::line, DotKind::texture, DotKind::label};

// The point at arc length s along a polyline (closed: the closing edge last).
class Walker {
public:
    explicit Walker(const Polyline& p) : pts_(p.points) {
        if (p.closed && pts_.size() > 1) pts_.push_back(pts_.front());
        cum_.push_back(0);
        for (std::size_t i = 1; i < pts_.size(); ++i) cum_.push_back(cum_.back() + dist(pts_[i - 1], pts_[i]));
    }
    [[nodiscard]] double length() const { return cum_.back(); }
    [[nodiscard]] Point at(double s) const {
        if (pts_.size() == 1 || s <= 0) return pts_.front();
        if (s >= cum_.back()) return pts_.back();
        const auto it = std::upper_bound(cum_.begin(), cum_.end(), s);
        const auto i = static_cast<std::size_t>(it - cum_.begin());  // cum_[i-1] <= s < cum_[i]
        const double seg = cum_[i] - cum_[i - 1];
        const double t = seg > 0 ? (s - cum_[i - 1]) / seg : 0;
        return {pts_[i - 1].x + (pts_[i].x - pts_[i - 1].x) * t, pts_[i - 1].y + (pts_[i].y - pts_[i - 1].y) * t};
    }

private:
    std::vector<Point> pts_;
    std::vector<double> cum_;
};

// n intervals of a stroke of length L: about `spacing` each, never under `floor_mm`.
// Counted in double and bounded before the conversion: a damaged drawing's
// stroke can be far longer than any integer (fuzz_graphic_svg found 2.9e41 mm).
// A million intervals is 1.5 km of line at 1.5 mm, far beyond any page; the
// dots past the page are left out and counted anyway.
constexpr double kMaxIntervals = 1 << 20;
int intervals(double L, double spacing, double floor_mm) {
    const double n = std::min(std::round(L / spacing), std::floor(L / floor_mm));
    if (!(n >= 1)) return 1;
    return static_cast<int>(std::min(n, kMaxIntervals));
}

// Arc lengths of a stroke's dots in its style's pattern.
std::vector<double> pattern(double L, bool closed, LineStyle style, const DotOptions& o) {
    std::vector<double> at;
    // Snapping moves a dot by at most half a step each way: on a fine grid the
    // spacing keeps that margin above the minimum; on a coarse one the least
    // distance rule drops the dots that snapping brings too close.
    const double floor_mm = o.min_distance_mm + std::min(std::hypot(o.x_step_mm, o.y_step_mm), 0.05);
    if (L < floor_mm) {
        at.push_back(L / 2);
        return at;
    }
    const auto even = [&](double from, double len, double spacing, bool both_ends) {
        const int n = intervals(len, spacing, floor_mm);
        for (int k = 0; k < n + (both_ends ? 1 : 0); ++k) at.push_back(from + len * k / n);
    };
    if (style == LineStyle::solid || style == LineStyle::dotted) {
        even(0, L, style == LineStyle::solid ? o.spacing_mm : o.dotted_spacing_mm, !closed);
        return at;
    }
    // Dashed: m dashes of three dots two spacings long, the gaps between them even.
    const double dash = 2 * o.spacing_mm;
    const double period = dash + o.dash_gap_mm;
    const double dashes = std::round(closed ? L / period : (L + o.dash_gap_mm) / period);
    long long m = dashes >= 1 ? static_cast<long long>(std::min(dashes, kMaxIntervals)) : 0;
    const auto gap_of = [&](long long k) { return closed ? L / static_cast<double>(k) - dash
                                                         : (L - static_cast<double>(k) * dash) / static_cast<double>(k - 1); };
    while (m > 1 && gap_of(m) < 2 * o.spacing_mm) --m;
    if (m < 1 || (m == 1 && !closed)) {
        even(0, L, o.spacing_mm, !closed);  // too short for a dash and a gap: one dash
        return at;
    }
    const double gap = gap_of(m);
    m = std::min<long long>(m, 1 << 22);
    for (long long k = 0; k < m; ++k) even(static_cast<double>(k) * (dash + gap), dash, o.spacing_mm, true);
    return at;
}

// The polyline moved sideways by d (left of its direction when d > 0): each
// vertex along the mean of its edges' normals, as far as keeps both edges d
// away, at most 2 d (a mitre limit, so a sharp corner does not shoot out).
Polyline offset(const Polyline& pl, double d) {
    Polyline out;
    out.closed = pl.closed;
    const auto n = pl.points.size();
    if (n < 2) {
        out.points = pl.points;
        return out;
    }
    const auto normal = [&](std::size_t i, std::size_t j) {
        const double dx = pl.points[j].x - pl.points[i].x, dy = pl.points[j].y - pl.points[i].y;
        const double len = std::hypot(dx, dy);
        return len > 0 ? Point{-dy / len, dx / len} : Point{0, 0};
    };
    for (std::size_t i = 0; i < n; ++i) {
        const bool has_prev = i > 0 || pl.closed, has_next = i + 1 < n || pl.closed;
        const Point a = has_prev ? normal(i == 0 ? n - 1 : i - 1, i) : Point{0, 0};
        const Point b = has_next ? normal(i, (i + 1) % n) : Point{0, 0};
        Point m{a.x + b.x, a.y + b.y};
        const double len = std::hypot(m.x, m.y);
        double scale = d;
        if (len > 1e-12) {
            m = {m.x / len, m.y / len};
            const double cos_half = has_prev && has_next ? m.x * b.x + m.y * b.y : 1.0;
            scale = d / std::max(cos_half, 0.5);
        }
        out.points.push_back({pl.points[i].x + m.x * scale, pl.points[i].y + m.y * scale});
    }
    return out;
}

bool inside(Point p, const std::vector<Polyline>& rings, bool even_odd) {
    int winding = 0, crossings = 0;
    for (const auto& r : rings) {
        const auto n = r.points.size();
        if (n < 3) continue;
        for (std::size_t i = 0; i < n; ++i) {
            const Point a = r.points[i], b = r.points[(i + 1) % n];
            if ((a.y <= p.y) != (b.y <= p.y)) {
                const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
                if (x > p.x) {
                    ++crossings;
                    winding += b.y > a.y ? 1 : -1;
                }
            }
        }
    }
    return even_odd ? crossings % 2 == 1 : winding != 0;
}

// The texture `id` (0..3) as points over a box, anchored on the page's origin so
// neighbouring areas of one paint line up.
std::vector<Point> texture_points(int id, double x0, double y0, double x1, double y1, const DotOptions& o) {
    std::vector<Point> out;
    const double P = o.texture_pitch_mm;
    const double s = std::max(o.texture_spacing_mm, o.min_distance_mm);  // dots along a texture line
    const auto range = [](double a, double b, double step, auto&& f) {
        for (auto k = static_cast<long long>(std::floor(a / step)); static_cast<double>(k) * step <= b; ++k) f(static_cast<double>(k) * step);
    };
    switch (id % 4) {
        case 0:  // a sparse grid of single dots
            range(y0, y1, P, [&](double y) { range(x0, x1, P, [&](double x) { out.push_back({x, y}); }); });
            break;
        case 1:  // horizontal lines of dots
            range(y0, y1, P, [&](double y) { range(x0, x1, s, [&](double x) { out.push_back({x, y}); }); });
            break;
        case 2:  // vertical lines of dots
            range(x0, x1, P, [&](double x) { range(y0, y1, s, [&](double y) { out.push_back({x, y}); }); });
            break;
        default: {  // diagonal lines of dots, down to the right
            const double u = s / std::sqrt(2.0), q = P * std::sqrt(2.0);
            range(y0, y1, u, [&](double y) {
                const double phase = std::fmod(y, q);
                range(x0 - phase, x1 - phase, q, [&](double x) { out.push_back({x + phase, y}); });
            });
        }
    }
    return out;
}

}  // namespace

Point snap(Point p, const DotOptions& o) {
    return {std::round(p.x / o.x_step_mm) * o.x_step_mm, std::round(p.y / o.y_step_mm) * o.y_step_mm};
}

Drawing fit_to_area(const Drawing& d, const Area& area, double* scale_out) {
    const double aw = area.right - area.left, ah = area.bottom - area.top;
    double s = 1;
    if (d.width_mm > aw || d.height_mm > ah) s = std::min(aw / d.width_mm, ah / d.height_mm);
    if (scale_out) *scale_out = s;
    const auto map = [&](Point p) { return Point{area.left + p.x * s, area.top + p.y * s}; };
    Drawing out = d;
    out.width_mm = d.width_mm * s;
    out.height_mm = d.height_mm * s;
    for (auto& sh : out.shapes) {
        sh.stroke_width_mm *= s;
        for (auto& sp : sh.subpaths) {
            sp.start = map(sp.start);
            for (auto& seg : sp.segments)
                for (auto& p : seg.p) p = map(p);
        }
    }
    for (auto& l : out.labels) {
        l.anchor = map(l.anchor);
        l.font_size_mm *= s;
    }
    return out;
}

Result<GraphicDots> place_dots(const Drawing& drawing, const Area& area, const DotOptions& o, const Braille& braille) {
    GraphicDots g;
    DotIndex index(g.dots);
    std::size_t outside = 0, crowded = 0;
    const auto add = [&](Point p, DotKind kind, int source) {
        g.dots.push_back({p, kind, source});
        index.add(g.dots.size() - 1);
        return g.dots.size() - 1;
    };
    // Lines first: they carry the drawing.
    for (std::size_t si = 0; si < drawing.shapes.size(); ++si) {
        const auto& shape = drawing.shapes[si];
        if (!shape.stroked) continue;
        std::vector<Polyline> rows;
        for (auto& pl : flatten(shape.subpaths, o.flatness_mm)) {
            if (shape.stroke_width_mm >= o.bold_width_mm) {
                // A bold line: two rows of dots, one either side of the centre line.
                const double half = o.bold_row_gap_mm / 2;
                rows.push_back(offset(pl, half));
                rows.push_back(offset(pl, -half));
            } else {
                rows.push_back(std::move(pl));
            }
        }
        for (auto& pl : rows) {
            StrokeTrace trace{static_cast<int>(si), pl, {}};
            const Walker w(pl);
            for (double s : pattern(w.length(), pl.closed, shape.style, o)) {
                const Point p = snap(w.at(s), o);
                if (!area.contains(p)) {
                    ++outside;
                    continue;
                }
                if (index.any_within(p, o.min_distance_mm, kAll)) {
                    ++crowded;
                    continue;
                }
                trace.dots.push_back(add(p, DotKind::line, static_cast<int>(si)));
            }
            g.strokes.push_back(std::move(trace));
        }
    }
    // Labels next, clear of the lines; then textures, clear of both.
    struct Box {
        double x0, y0, x1, y1;
    };
    std::vector<Box> label_boxes;
    for (std::size_t li = 0; li < drawing.labels.size(); ++li) {
        const auto& label = drawing.labels[li];
        auto cells = braille(label.text);
        if (!cells) {
            g.warnings.push_back("line " + std::to_string(label.line) + ": the label \"" + label.text +
                                 "\" has no braille (" + cells.error().message + "): listed in the key");
            g.key.push_back(static_cast<int>(li));
            continue;
        }
        // The label's dots relative to its top-left dot: cells of the profile's geometry.
        std::vector<Point> rel;
        for (std::size_t c = 0; c < cells->size(); ++c)
            for (int d = 1; d <= 6; ++d)
                if ((*cells)[c].has_dot(d))
                    rel.push_back({static_cast<double>(c) * o.cell_pitch_mm + (d > 3 ? o.dot_pitch_mm : 0),
                                   ((d - 1) % 3) * o.dot_pitch_mm});
        const double w = cells->empty() ? 0 : static_cast<double>(cells->size() - 1) * o.cell_pitch_mm + o.dot_pitch_mm;
        const double h = 2 * o.dot_pitch_mm;
        // Where the print text stands (its baseline start), then nearby places, nearest first.
        const Point home{label.anchor.x, label.anchor.y - h};
        std::vector<Point> tries;
        for (int ring = 0; ring <= 6; ++ring)
            for (int dy = -ring; dy <= ring; ++dy)
                for (int dx = -ring; dx <= ring; ++dx)
                    if (std::max(std::abs(dx), std::abs(dy)) == ring)
                        tries.push_back({home.x + dx * o.dot_pitch_mm, home.y + dy * o.dot_pitch_mm});
        bool placed = false;
        for (const Point t : tries) {
            const Point top_left = snap(t, o);
            const Box box{top_left.x - o.dot_pitch_mm, top_left.y - o.dot_pitch_mm, top_left.x + w + o.dot_pitch_mm,
                          top_left.y + h + o.dot_pitch_mm};
            bool ok = area.contains({top_left.x, top_left.y}) && area.contains({top_left.x + w, top_left.y + h});
            for (const auto& b : label_boxes)
                ok = ok && (box.x1 < b.x0 || box.x0 > b.x1 || box.y1 < b.y0 || box.y0 > b.y1);
            for (std::size_t k = 0; ok && k < rel.size(); ++k) {
                const Point p = snap({top_left.x + rel[k].x, top_left.y + rel[k].y}, o);
                ok = !index.any_within(p, o.label_clearance_mm, {DotKind::line}) &&
                     !index.any_within(p, o.min_distance_mm, kAll);
            }
            if (!ok) continue;
            for (const auto& r : rel) add(snap({top_left.x + r.x, top_left.y + r.y}, o), DotKind::label, static_cast<int>(li));
            label_boxes.push_back(box);
            placed = true;
            break;
        }
        if (!placed) {
            g.warnings.push_back("line " + std::to_string(label.line) + ": the label \"" + label.text +
                                 "\" does not fit clear of the lines near its place: listed in the key");
            g.key.push_back(static_cast<int>(li));
        }
    }
    std::map<std::string, int> textures;
    for (std::size_t si = 0; si < drawing.shapes.size(); ++si) {
        const auto& shape = drawing.shapes[si];
        if (!shape.filled) continue;
        const auto [it, fresh] = textures.emplace(shape.fill_paint, static_cast<int>(textures.size()));
        if (fresh && it->second == 4)
            g.warnings.push_back("line " + std::to_string(shape.line) +
                                 ": more than four fill colours; the fifth and later repeat the four textures");
        auto rings = flatten(shape.subpaths, o.flatness_mm);
        double x0 = area.right, y0 = area.bottom, x1 = area.left, y1 = area.top;
        for (const auto& r : rings)
            for (const auto& p : r.points) {
                x0 = std::min(x0, p.x), y0 = std::min(y0, p.y);
                x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
            }
        x0 = std::max(x0, area.left), y0 = std::max(y0, area.top);
        x1 = std::min(x1, area.right), y1 = std::min(y1, area.bottom);
        if (x0 > x1 || y0 > y1) continue;
        for (const Point q : texture_points(it->second, x0, y0, x1, y1, o)) {
            const Point p = snap(q, o);
            if (!area.contains(p) || !inside(p, rings, shape.even_odd)) continue;
            if (index.any_within(p, o.texture_clearance_mm, {DotKind::line}) ||
                index.any_within(p, o.label_clearance_mm, {DotKind::label}) ||
                index.any_within(p, o.min_distance_mm, kAll))
                continue;
            add(p, DotKind::texture, static_cast<int>(si));
        }
    }
    if (outside > 0)
        g.warnings.push_back(std::to_string(outside) + " line dots fall outside the page area and are left out");
    if (crowded > 0)
        g.warnings.push_back(std::to_string(crowded) + " line dots are left out where lines meet, bend sharply or "
                             "round onto the grid together: each would fall closer than " + mm(o.min_distance_mm) +
                             " mm to another dot");
    return g;
}

}  // namespace tactus::graphic
