// SPDX-License-Identifier: GPL-3.0-or-later
#include "graphic/raster_trace.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "common/file_io.hpp"
#include "graphic/flatten.hpp"
#include "common/try.hpp"

namespace tactus::graphic {

namespace {

// More outline vertices than this, after simplification, is a photograph's
// noise, not a drawing a finger can read (the SVG reader's limit on segments).
constexpr std::size_t kMaxVertices = 200000;

// A point between two pixel centres, in half-pixel units, shifted by 2 so the
// white frame around the picture has non-negative coordinates.
struct HalfPoint {
    std::int64_t x = 0, y = 0;
};

class ContourGraph {
public:
    explicit ContourGraph(std::int64_t rows) : rows_(rows) {}
    void link(HalfPoint a, HalfPoint b) {
        const auto ka = key(a), kb = key(b);
        attach(ka, kb);
        attach(kb, ka);
    }
    // Every closed contour, as half-pixel points, in the order first met.
    [[nodiscard]] std::vector<std::vector<HalfPoint>> loops() {
        std::vector<std::vector<HalfPoint>> out;
        for (const auto start : order_) {
            auto& s = nodes_.at(start);
            if (s.seen) continue;
            std::vector<HalfPoint> loop{point(start)};
            s.seen = true;
            std::uint64_t prev = start, cur = s.next[0];
            while (cur != start && loop.size() <= nodes_.size()) {
                auto& n = nodes_.at(cur);
                n.seen = true;
                loop.push_back(point(cur));
                const auto next = n.next[0] == prev ? n.next[1] : n.next[0];
                prev = cur;
                cur = next;
            }
            out.push_back(std::move(loop));
        }
        return out;
    }

private:
    struct Node {
        std::array<std::uint64_t, 2> next{};
        int degree = 0;
        bool seen = false;
    };
    [[nodiscard]] std::uint64_t key(HalfPoint p) const {
        return static_cast<std::uint64_t>(p.x) * static_cast<std::uint64_t>(rows_) + static_cast<std::uint64_t>(p.y);
    }
    [[nodiscard]] HalfPoint point(std::uint64_t k) const {
        return {static_cast<std::int64_t>(k / static_cast<std::uint64_t>(rows_)),
                static_cast<std::int64_t>(k % static_cast<std::uint64_t>(rows_))};
    }
    void attach(std::uint64_t from, std::uint64_t to) {
        auto [it, inserted] = nodes_.try_emplace(from);
        if (inserted) order_.push_back(from);
        // Every point between a dark and a light pixel is on exactly two cells'
        // segments (the white frame keeps every such pair inside the grid).
        if (it->second.degree < 2) it->second.next[static_cast<std::size_t>(it->second.degree++)] = to;
    }
    std::int64_t rows_;
    std::unordered_map<std::uint64_t, Node> nodes_;
    std::vector<std::uint64_t> order_;
};

// Douglas-Peucker on pts[first..last] (both kept), without recursion.
void simplify_open(const std::vector<Point>& pts, std::size_t first, std::size_t last, double tolerance,
                   std::vector<bool>& keep) {
    std::vector<std::pair<std::size_t, std::size_t>> todo{{first, last}};
    while (!todo.empty()) {
        const auto [a, b] = todo.back();
        todo.pop_back();
        keep[a] = keep[b] = true;
        double worst = -1;
        std::size_t at = a;
        for (std::size_t i = a + 1; i < b; ++i)
            if (const double d = distance_to_segment(pts[i], pts[a], pts[b]); d > worst) worst = d, at = i;
        if (worst > tolerance) {
            todo.emplace_back(a, at);
            todo.emplace_back(at, b);
        }
    }
}

// A closed contour: split at its first point and the point farthest from it,
// each half simplified on its own, so the result is closed and within tolerance.
std::vector<Point> simplify_closed(const std::vector<Point>& loop, double tolerance) {
    if (loop.size() < 4) return loop;
    std::size_t far = 0;
    double far_d = -1;
    for (std::size_t i = 1; i < loop.size(); ++i)
        if (const double d = std::hypot(loop[i].x - loop[0].x, loop[i].y - loop[0].y); d > far_d) far_d = d, far = i;
    auto ring = loop;
    ring.push_back(loop[0]);
    std::vector<bool> keep(ring.size(), false);
    simplify_open(ring, 0, far, tolerance, keep);
    simplify_open(ring, far, ring.size() - 1, tolerance, keep);
    std::vector<Point> out;
    for (std::size_t i = 0; i + 1 < ring.size(); ++i)
        if (keep[i]) out.push_back(ring[i]);
    return out;
}

Segment straight(Point from, Point to) {
    const auto at = [&](double t) { return Point{from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t}; };
    return {{at(1.0 / 3), at(2.0 / 3), to}, true};
}

}  // namespace

int otsu_threshold(const GreyImage& image) {
    std::array<double, 256> histogram{};
    for (const auto v : image.pixels) ++histogram[v];
    const double total = static_cast<double>(image.pixels.size());
    double sum_all = 0;
    for (int v = 0; v < 256; ++v) sum_all += v * histogram[static_cast<std::size_t>(v)];
    double weight_dark = 0, sum_dark = 0, best = 0;
    int threshold = -1;
    for (int t = 0; t < 255; ++t) {
        weight_dark += histogram[static_cast<std::size_t>(t)];
        sum_dark += t * histogram[static_cast<std::size_t>(t)];
        const double weight_light = total - weight_dark;
        if (weight_dark == 0 || weight_light == 0) continue;
        const double mean_dark = sum_dark / weight_dark, mean_light = (sum_all - sum_dark) / weight_light;
        const double between = weight_dark * weight_light * (mean_dark - mean_light) * (mean_dark - mean_light);
        if (between > best) best = between, threshold = t;
    }
    return threshold < 0 ? 127 : threshold;
}

Result<Drawing> trace_image(const GreyImage& image, const TraceOptions& options) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
        return fail(ErrorKind::input, "the picture has no pixels");
    if (options.threshold < -1 || options.threshold > 254)
        return fail(ErrorKind::usage, "the threshold " + std::to_string(options.threshold) +
                                          " is not a grey level from 0 to 254 (or -1 for Otsu's)");
    const int threshold = options.threshold >= 0 ? options.threshold : otsu_threshold(image);
    const int w = image.width, h = image.height;
    // Ink, with a frame of paper one pixel wide all round.
    const auto dark = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < w && y < h && image.at(x, y) <= threshold;
    };
    ContourGraph graph(2 * static_cast<std::int64_t>(h) + 8);
    // Cell (i, j) has the pixel centres (i, j) top left, (i+1, j), (i+1, j+1)
    // and (i, j+1) as corners; the contour crosses an edge between a dark and
    // a light corner at its middle.
    for (int j = -1; j < h; ++j)
        for (int i = -1; i < w; ++i) {
            const bool a = dark(i, j), b = dark(i + 1, j), c = dark(i + 1, j + 1), d = dark(i, j + 1);
            if (a == b && b == c && c == d) continue;
            const std::int64_t x = 2 * std::int64_t{i} + 2, y = 2 * std::int64_t{j} + 2;
            const HalfPoint top{x + 2, y + 1}, right{x + 3, y + 2}, bottom{x + 2, y + 3}, left{x + 1, y + 2};
            if (a == c && b == d) {
                // A saddle: two dark corners diagonally. The dark pixels are
                // joined (8-connected ink: a diagonal line stays one line); the
                // contour cuts off the two light corners.
                if (!a) graph.link(top, left), graph.link(right, bottom);  // a and c light
                else graph.link(top, right), graph.link(bottom, left);      // b and d light
                continue;
            }
            std::vector<HalfPoint> cut;
            if (a != b) cut.push_back(top);
            if (b != c) cut.push_back(right);
            if (c != d) cut.push_back(bottom);
            if (d != a) cut.push_back(left);
            graph.link(cut[0], cut[1]);
        }

    const double dpi_x = image.dpi_x > 0 ? image.dpi_x : options.default_dpi;
    const double dpi_y = image.dpi_y > 0 ? image.dpi_y : options.default_dpi;
    const double mm_x = 25.4 / dpi_x, mm_y = 25.4 / dpi_y;
    // The contour between pixel centres is known to half a pixel (its steps on
    // a slanted edge): simplifying to less would keep the staircase.
    const double tolerance = std::max(options.simplify_mm, 0.5 * std::min(mm_x, mm_y));
    Drawing drawing;
    drawing.width_mm = w * mm_x;
    drawing.height_mm = h * mm_y;
    Shape shape;
    shape.stroked = true;
    shape.style = LineStyle::solid;
    shape.stroke_width_mm = 0.5;
    shape.filled = true;
    shape.even_odd = true;
    shape.fill_paint = "ink";
    shape.element = "picture";
    std::size_t specks = 0, vertices = 0;
    for (const auto& loop : graph.loops()) {
        std::vector<Point> pts;
        pts.reserve(loop.size());
        double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
        for (const auto& p : loop) {
            // Half-pixel units, shifted by 2 -> pixel units -> millimetres.
            const Point q{(static_cast<double>(p.x) - 2) / 2 * mm_x, (static_cast<double>(p.y) - 2) / 2 * mm_y};
            x0 = std::min(x0, q.x), y0 = std::min(y0, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
            pts.push_back(q);
        }
        if (x1 - x0 < options.speck_mm && y1 - y0 < options.speck_mm) {
            ++specks;
            continue;
        }
        const auto simple = simplify_closed(pts, tolerance);
        if (simple.size() < 3) {
            ++specks;
            continue;
        }
        Subpath sp;
        sp.start = simple[0];
        sp.closed = true;
        for (std::size_t k = 1; k <= simple.size(); ++k) sp.segments.push_back(straight(simple[k - 1], simple[k % simple.size()]));
        vertices += simple.size();
        if (vertices > kMaxVertices)
            return fail(ErrorKind::input, "the picture's outlines have more than " + std::to_string(kMaxVertices) +
                                              " corners, far more than a tactile graphic can show: "
                                              "simplify it, or give a threshold that leaves out its shading");
        shape.subpaths.push_back(std::move(sp));
    }
    if (specks > 0)
        drawing.warnings.push_back(std::to_string(specks) + " dark specks smaller than " +
                                   std::to_string(std::lround(options.speck_mm * 10) / 10) + "." +
                                   std::to_string(std::lround(options.speck_mm * 10) % 10) +
                                   " mm across left out (noise, not a shape)");
    if (shape.subpaths.empty())
        drawing.warnings.push_back("nothing in the picture is darker than grey level " + std::to_string(threshold) +
                                   " (of 255): the graphic is empty");
    else
        drawing.shapes.push_back(std::move(shape));
    return drawing;
}

Result<Drawing> load_image(const std::filesystem::path& path, const TraceOptions& options) {
    TACTUS_TRY(bytes, read_file(path, std::size_t{256} << 20));
    auto image = read_raster(bytes);
    if (!image) return std::unexpected(located(image.error(), path.string()));
    auto d = trace_image(*image, options);
    if (!d) return std::unexpected(located(d.error(), path.string()));
    return d;
}

}  // namespace tactus::graphic
