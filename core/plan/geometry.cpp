// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/geometry.hpp"

namespace tactus::plan {

DotPlace dot_place(const profile::PrinterProfile& p, Side side, int line, int column, int dot) {
    const auto& g = p.geometry;
    // Dots 1-3 down the left column, 4-6 down the right, 7 and 8 below them.
    static constexpr int kCol[8] = {0, 0, 0, 1, 1, 1, 0, 1};
    static constexpr int kRow[8] = {0, 1, 2, 0, 1, 2, 3, 3};
    DotPlace d;
    d.read_x_mm = p.paper.margin_left_mm + column * g.cell_pitch_mm + kCol[dot - 1] * g.dot_pitch_mm;
    d.read_y_mm = p.paper.margin_top_mm + line * g.line_pitch_mm + kRow[dot - 1] * g.dot_pitch_mm;
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

double carriage_target_mm(const profile::PrinterProfile& p, Hammer h, double paper_x_mm) {
    return h == Hammer::convex ? paper_x_mm : paper_x_mm - p.head.concave_offset_mm;
}

}  // namespace tactus::plan
