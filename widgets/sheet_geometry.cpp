// SPDX-License-Identifier: GPL-3.0-or-later
#include "sheet_geometry.hpp"

#include <cmath>
#include <unordered_map>

namespace tactus::gui {
namespace {

// Dot n's column (0/1) and row (0..3) in the cell: 1 2 3 7 left, 4 5 6 8 right.
constexpr int kColumn[8] = {0, 0, 0, 1, 1, 1, 0, 1};
constexpr int kRow[8] = {0, 1, 2, 0, 1, 2, 3, 3};

std::vector<DotPoint> dots(const layout::Page& page, bool back, const SheetGeometry& g) {
    std::vector<DotPoint> out;
    for (std::size_t l = 0; l < page.lines.size(); ++l) {
        const auto& line = page.lines[l];
        for (std::size_t c = 0; c < line.size(); ++c) {
            for (int d = 1; d <= 8; ++d) {
                if (!line[c].has_dot(d)) continue;
                DotPoint p = cell_origin(static_cast<int>(l), static_cast<int>(c), back, g);
                const double dx = kColumn[d - 1] * g.dot_pitch_mm;
                const double dy = kRow[d - 1] * g.dot_pitch_mm;
                // Mirrored: seen from the front, dot 4 lies left of dot 1 (x mirror)
                // or the rows run upwards (y mirror).
                p.x_mm += back && g.back_mirror == profile::BackMirror::x ? -dx : dx;
                p.y_mm += back && g.back_mirror == profile::BackMirror::y ? -dy : dy;
                p.dot = d;
                out.push_back(p);
            }
        }
    }
    return out;
}

}  // namespace

DotPoint cell_origin(int line, int cell, bool back, const SheetGeometry& g) {
    DotPoint p;
    p.line = line;
    p.cell = cell;
    const double x = g.left_margin_mm + cell * g.cell_pitch_mm;
    const double y = g.top_margin_mm + line * g.line_pitch_mm;
    p.x_mm = x;
    p.y_mm = y;
    if (back) {
        if (g.back_mirror == profile::BackMirror::x) p.x_mm = g.paper_width_mm - x;
        if (g.back_mirror == profile::BackMirror::y) p.y_mm = g.paper_height_mm - y;
        p.x_mm += g.back_offset_x_mm;
        p.y_mm += g.back_offset_y_mm;
    }
    return p;
}

SheetGeometry sheet_geometry(const profile::PrinterProfile& p) {
    SheetGeometry g;
    g.paper_width_mm = p.paper.width_mm;
    g.paper_height_mm = p.paper.height_mm;
    g.left_margin_mm = p.paper.margin_left_mm;
    g.top_margin_mm = p.paper.margin_top_mm;
    g.dot_pitch_mm = p.geometry.dot_pitch_mm;
    g.cell_pitch_mm = p.geometry.cell_pitch_mm;
    g.line_pitch_mm = p.geometry.line_pitch_mm;
    g.dot_diameter_mm = 0.6 * p.geometry.dot_pitch_mm;
    g.back_offset_x_mm = p.geometry.back_offset_x_mm;
    g.back_offset_y_mm = p.geometry.back_offset_y_mm;
    g.back_mirror = p.geometry.back_mirror;
    g.min_separation_mm = p.geometry.dot_pitch_mm / 2;
    return g;
}

std::vector<DotPoint> front_dots(const layout::Page& page, const SheetGeometry& g) {
    return dots(page, false, g);
}

std::vector<DotPoint> back_dots(const layout::Page& page, const SheetGeometry& g) {
    return dots(page, true, g);
}

std::vector<DotConflict> find_conflicts(const layout::Sheet& sheet, const SheetGeometry& g) {
    std::vector<DotConflict> out;
    if (!sheet.front || !sheet.back || g.min_separation_mm <= 0) return out;
    // Bucket front dots in a grid of min_separation squares: each back dot then
    // looks at its own and the eight neighbouring buckets only.
    const double s = g.min_separation_mm;
    const auto key = [s](double x, double y) {
        return (static_cast<long long>(std::floor(x / s)) << 32) ^
               static_cast<long long>(static_cast<unsigned>(static_cast<int>(std::floor(y / s))));
    };
    std::unordered_multimap<long long, DotPoint> grid;
    for (const auto& p : front_dots(*sheet.front, g)) grid.emplace(key(p.x_mm, p.y_mm), p);
    for (const auto& b : back_dots(*sheet.back, g)) {
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy) {
                const auto [lo, hi] = grid.equal_range(key(b.x_mm + dx * s, b.y_mm + dy * s));
                for (auto it = lo; it != hi; ++it) {
                    const double d = std::hypot(it->second.x_mm - b.x_mm, it->second.y_mm - b.y_mm);
                    if (d < s) out.push_back({it->second, b, d});
                }
            }
    }
    return out;
}

}  // namespace tactus::gui
