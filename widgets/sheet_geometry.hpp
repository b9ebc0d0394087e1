// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The preview's view of a sheet: the printer profile it draws, and its dots in
// millimetres from the top left of the sheet as the front is read. Where a dot
// lands is plan::dot_place's rule and which dots crush each other is
// plan::find_conflicts'; this file only adapts them to the painter.
#include <vector>

#include "layout/page.hpp"
#include "plan/geometry.hpp"
#include "profile/profile.hpp"

namespace tactus::gui {

struct SheetGeometry {
    profile::PrinterProfile profile = profile::default_profile();

    [[nodiscard]] double paper_width_mm() const { return profile.paper.width_mm; }
    [[nodiscard]] double paper_height_mm() const { return profile.paper.height_mm; }
    [[nodiscard]] double dot_pitch_mm() const { return profile.geometry.dot_pitch_mm; }
    // Drawn dots are 60 % of the pitch, about the proportion of an embossed dot.
    [[nodiscard]] double dot_diameter_mm() const { return 0.6 * profile.geometry.dot_pitch_mm; }
};

inline SheetGeometry sheet_geometry(const profile::PrinterProfile& p) { return SheetGeometry{p}; }

// A dot as the front reader sees the sheet (paper coordinates).
struct DotPoint {
    double x_mm = 0;
    double y_mm = 0;
    int line = 0;
    int cell = 0;
    int dot = 0;  // 1..8; 0 for a graphic's dot
};

// Dot centres of a page on the front side: its cells', then its graphic's.
std::vector<DotPoint> front_dots(const layout::Page& page, const SheetGeometry& g);
// Dot centres of a page embossed on the back, in front-view coordinates.
std::vector<DotPoint> back_dots(const layout::Page& page, const SheetGeometry& g);
// Centre of dot 1's position of a cell, front or back view.
DotPoint cell_origin(int line, int cell, bool back, const SheetGeometry& g);

using plan::DotConflict;
inline std::vector<DotConflict> find_conflicts(const layout::Sheet& sheet, const SheetGeometry& g) {
    return plan::find_conflicts(g.profile, sheet);
}

}  // namespace tactus::gui
