// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/geometry.hpp"

#include <cmath>
#include <unordered_map>

namespace tactus::plan {

DotPlace dot_place(const profile::PrinterProfile& p, Side side, int line, int column, int dot) {
    const auto& g = p.geometry;
    // Dots 1-3 down the left column, 4-6 down the right, 7 and 8 below them.
    static constexpr int kCol[8] = {0, 0, 0, 1, 1, 1, 0, 1};
    static constexpr int kRow[8] = {0, 1, 2, 0, 1, 2, 3, 3};
    return place_on_paper(p, side, p.paper.margin_left_mm + column * g.cell_pitch_mm + kCol[dot - 1] * g.dot_pitch_mm,
                          p.paper.margin_top_mm + line * g.line_pitch_mm + kRow[dot - 1] * g.dot_pitch_mm);
}

DotPlace place_on_paper(const profile::PrinterProfile& p, Side side, double read_x_mm, double read_y_mm) {
    const auto& g = p.geometry;
    DotPlace d;
    d.read_x_mm = read_x_mm;
    d.read_y_mm = read_y_mm;
    d.paper_x_mm = d.read_x_mm;
    d.paper_y_mm = d.read_y_mm;
    if (side == Side::back) {
        switch (g.back_mirror) {
            case profile::BackMirror::x: d.paper_x_mm = p.paper.width_mm - d.read_x_mm; break;
            case profile::BackMirror::y: d.paper_y_mm = p.paper.height_mm - d.read_y_mm; break;
            case profile::BackMirror::none: break;
        }
        d.paper_x_mm += g.back_offset_x_mm;
        d.paper_y_mm += g.back_offset_y_mm;
    }
    return d;
}

CellRef cell_at(const profile::PrinterProfile& p, Side side, double paper_x_mm, double paper_y_mm) {
    const auto& g = p.geometry;
    double x = paper_x_mm, y = paper_y_mm;
    if (side == Side::back) {
        x -= g.back_offset_x_mm;
        y -= g.back_offset_y_mm;
        switch (g.back_mirror) {
            case profile::BackMirror::x: x = p.paper.width_mm - x; break;
            case profile::BackMirror::y: y = p.paper.height_mm - y; break;
            case profile::BackMirror::none: break;
        }
    }
    return {static_cast<int>(std::floor((y - p.paper.margin_top_mm + 1.0) / g.line_pitch_mm)),
            static_cast<int>(std::floor((x - p.paper.margin_left_mm + 1.0) / g.cell_pitch_mm))};
}

std::vector<PlacedDot> page_dots(const profile::PrinterProfile& p, const layout::Page& page, Side side) {
    std::vector<PlacedDot> out;
    for (std::size_t l = 0; l < page.lines.size(); ++l) {
        const auto& line = page.lines[l];
        for (std::size_t c = 0; c < line.size(); ++c)
            for (int d = 1; d <= 8; ++d) {
                if (!line[c].has_dot(d)) continue;
                const auto li = static_cast<int>(l), ci = static_cast<int>(c);
                out.push_back({li, ci, d, dot_place(p, side, li, ci, d)});
            }
    }
    return out;
}

double min_dot_separation_mm(const profile::PrinterProfile& p) { return p.geometry.dot_pitch_mm / 2; }

std::vector<DotConflict> find_conflicts(const profile::PrinterProfile& p, const layout::Sheet& sheet) {
    std::vector<DotConflict> out;
    const double s = min_dot_separation_mm(p);
    if (!sheet.front || !sheet.back || s <= 0) return out;
    // Front dots in a grid of s-by-s buckets: each back dot then looks at its own
    // and the eight neighbouring buckets only, so a sheet costs O(dots).
    const auto bucket = [s](double v) { return static_cast<long long>(std::floor(v / s)); };
    const auto key = [](long long bx, long long by) {
        return (bx << 32) ^ static_cast<long long>(static_cast<unsigned>(by));
    };
    std::unordered_multimap<long long, PlacedDot> grid;
    for (const auto& f : page_dots(p, *sheet.front, Side::front))
        grid.emplace(key(bucket(f.place.paper_x_mm), bucket(f.place.paper_y_mm)), f);
    for (const auto& b : page_dots(p, *sheet.back, Side::back)) {
        const auto bx = bucket(b.place.paper_x_mm), by = bucket(b.place.paper_y_mm);
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy) {
                const auto [lo, hi] = grid.equal_range(key(bx + dx, by + dy));
                for (auto it = lo; it != hi; ++it) {
                    const auto& f = it->second;
                    const double d = std::hypot(f.place.paper_x_mm - b.place.paper_x_mm,
                                                f.place.paper_y_mm - b.place.paper_y_mm);
                    if (d < s) out.push_back({f, b, d});
                }
            }
    }
    return out;
}

double carriage_target_mm(const profile::PrinterProfile& p, Hammer h, double paper_x_mm) {
    return h == Hammer::convex ? paper_x_mm : paper_x_mm - p.head.concave_offset_mm;
}

}  // namespace tactus::plan
