// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A drawing as braille pages: one graphic page of dots, its back left blank on
// interpoint paper (a dot struck from behind would crush the graphic's), and
// a key page after it listing the labels that found no room on the drawing.
#include "common/result.hpp"
#include "graphic/dots.hpp"
#include "layout/page.hpp"
#include "machine/firmware_tables.hpp"
#include "profile/profile.hpp"
#include "translate/translator.hpp"

namespace tactus::graphic {

// The dot options for a machine: the grid it can address, its cell geometry,
// and the separation the profile keeps between dots of the two sides as the
// least distance between any two dots. The grid is one motor step on each
// axis, unless the plan is for the reference firmware (protocol 3), whose
// pass records count distances in its tables' grid units (20 carriage steps
// and 50 feed steps for the bundled profile: 0.25 mm across, 1.25 mm down).
DotOptions dot_options(const profile::PrinterProfile& machine, const machine::FirmwareTables* firmware = nullptr);

// How far a picture's traced outline may stray from its pixel contour: the
// finer of the grid's two steps: the dots are rounded that far anyway.
double simplify_tolerance_mm(const DotOptions& options);

// The area a graphic may use: the paper inside the profile's margins.
Area page_area(const profile::PrinterProfile& machine);

struct GraphicLayout {
    layout::PagedDocument document;
    GraphicDots dots;    // in page millimetres, as placed
    Drawing placed;      // the drawing moved and scaled onto the page
    double scale = 1;    // < 1 when the drawing was shrunk to fit the area
};

// `geometry`: the page format of the document (its sides and cell grid, for the key page).
Result<GraphicLayout> lay_out_drawing(const Drawing& drawing, const profile::PrinterProfile& machine,
                                      const layout::PageGeometry& geometry, const translate::Translator& table,
                                      const DotOptions& options);

}  // namespace tactus::graphic
