// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where each braille dot sits on the paper. A side's reading coordinates put the
// origin at the top-left corner of that side as the reader holds it; paper
// coordinates are the front side's frame, in which the sheet runs through the
// machine. The back page is mirrored (the sheet is turned over), then offset so
// its dots fall between the front's.
#include <vector>

#include "layout/page.hpp"
#include "plan/plan.hpp"
#include "profile/profile.hpp"

namespace tactus::plan {

struct DotPlace {
    double read_x_mm = 0, read_y_mm = 0;    // in the side's reading coordinates
    double paper_x_mm = 0, paper_y_mm = 0;  // in paper coordinates
};

// A point of `side` given in its reading coordinates, on the paper.
DotPlace place_on_paper(const profile::PrinterProfile& p, Side side, double read_x_mm, double read_y_mm);

// Dot `dot` (1..8) of the cell at `line`, `column` (0-based) on `side`.
DotPlace dot_place(const profile::PrinterProfile& p, Side side, int line, int column, int dot);

// The cell under a point of the paper on `side`: the inverse of dot_place, with
// a millimetre of slack before each cell so a click on dot 1's edge counts.
struct CellRef {
    int line = 0;  // 0-based; negative above the first line
    int cell = 0;  // 0-based; negative left of the first cell
};
CellRef cell_at(const profile::PrinterProfile& p, Side side, double paper_x_mm, double paper_y_mm);

// A dot of a page and where it lands.
struct PlacedDot {
    int line = 0;  // 0-based on the page
    int cell = 0;  // 0-based on the line
    int dot = 0;   // 1..8
    DotPlace place;
};

// Every dot of `page` embossed on `side`, line by line, cell by cell.
std::vector<PlacedDot> page_dots(const profile::PrinterProfile& p, const layout::Page& page, Side side);

// A front and a back dot closer than this crush each other: half the dot pitch,
// the distance the default interpoint offset is designed to keep.
double min_dot_separation_mm(const profile::PrinterProfile& p);

struct DotConflict {
    PlacedDot front;
    PlacedDot back;
    double distance_mm = 0;  // between their centres on the paper
};

// Front/back dot pairs of one sheet closer than min_dot_separation_mm, in front
// order. The preview marks them, the CLI warns about them.
std::vector<DotConflict> find_conflicts(const profile::PrinterProfile& p, const layout::Sheet& sheet);

// Which hammer makes dots on which side: the convex one raises dots toward the
// front, the concave one toward the back.
constexpr Hammer hammer_for(Side s) { return s == Side::front ? Hammer::convex : Hammer::concave; }

// Where the carriage must stand for `hammer` to strike paper x.
double carriage_target_mm(const profile::PrinterProfile& p, Hammer h, double paper_x_mm);

}  // namespace tactus::plan
