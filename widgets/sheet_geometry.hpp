// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where dots land on paper, in millimetres from the top left of the sheet as the
// front is read. The back page is embossed on the reverse: seen from the front its
// dots are mirrored left to right, then shifted by the interpoint offset so that
// they fall between front dots. Values come from the printer profile when one is
// chosen; the defaults are the source embosser's A4 format.
#include <vector>

#include "layout/page.hpp"
#include "profile/profile.hpp"

namespace tactus::gui {

struct SheetGeometry {
    double paper_width_mm = 210.0;
    double paper_height_mm = 297.0;
    double left_margin_mm = 24.0;
    double top_margin_mm = 20.0;
    double dot_pitch_mm = 2.5;    // between dots of one cell
    double cell_pitch_mm = 6.0;   // between cells of one line
    double line_pitch_mm = 10.0;  // between lines
    double dot_diameter_mm = 1.5;
    double back_offset_x_mm = 1.25;  // back dots shifted from the mirrored grid
    double back_offset_y_mm = 1.25;
    double min_separation_mm = 1.25;  // a front and a back dot closer than this crush each other
    profile::BackMirror back_mirror = profile::BackMirror::x;
};

// The sheet as the printer profile places it (the same formulas as plan::dot_place).
// A front and a back dot may not come closer than half the dot pitch: the
// distance the profile's default interpoint offset is designed to keep.
SheetGeometry sheet_geometry(const profile::PrinterProfile& p);

struct DotPoint {
    double x_mm = 0;
    double y_mm = 0;
    int line = 0;
    int cell = 0;
    int dot = 0;  // 1..8
};

// Dot centres of a page on the front side.
std::vector<DotPoint> front_dots(const layout::Page& page, const SheetGeometry& g);
// Dot centres of a page embossed on the back, in front-view coordinates.
std::vector<DotPoint> back_dots(const layout::Page& page, const SheetGeometry& g);
// Centre of dot 1's position of a cell, front or back view.
DotPoint cell_origin(int line, int cell, bool back, const SheetGeometry& g);

struct DotConflict {
    DotPoint front;
    DotPoint back;
    double distance_mm = 0;
};
// Front/back dot pairs closer than the geometry allows.
std::vector<DotConflict> find_conflicts(const layout::Sheet& sheet, const SheetGeometry& g);

}  // namespace tactus::gui
