// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where each braille dot sits on the paper. A side's reading coordinates put the
// origin at the top-left corner of that side as the reader holds it; paper
// coordinates are the front side's frame, in which the sheet runs through the
// machine. The back page is mirrored (the sheet is turned over), then offset so
// its dots fall between the front's.
#include "plan/plan.hpp"
#include "profile/profile.hpp"

namespace tactus::plan {

struct DotPlace {
    double read_x_mm = 0, read_y_mm = 0;    // in the side's reading coordinates
    double paper_x_mm = 0, paper_y_mm = 0;  // in paper coordinates
};

// Dot `dot` (1..8) of the cell at `line`, `column` (0-based) on `side`.
DotPlace dot_place(const profile::PrinterProfile& p, Side side, int line, int column, int dot);

// Which hammer makes dots on which side: the convex one raises dots toward the
// front, the concave one toward the back.
constexpr Hammer hammer_for(Side s) { return s == Side::front ? Hammer::convex : Hammer::concave; }

// Where the carriage must stand for `hammer` to strike paper x.
double carriage_target_mm(const profile::PrinterProfile& p, Hammer h, double paper_x_mm);

}  // namespace tactus::plan
