// SPDX-License-Identifier: GPL-3.0-or-later
#include "sheet_geometry.hpp"

namespace tactus::gui {
namespace {

DotPoint point(const plan::PlacedDot& d) {
    return {d.place.paper_x_mm, d.place.paper_y_mm, d.line, d.cell, d.dot};
}

std::vector<DotPoint> dots(const layout::Page& page, plan::Side side, const SheetGeometry& g) {
    std::vector<DotPoint> out;
    for (const auto& d : plan::page_dots(g.profile, page, side)) out.push_back(point(d));
    // A graphic's dots where the hammer strikes them (plan's rule for a point
    // of a side); they belong to no cell (line, cell and dot 0).
    for (const auto& d : page.graphic) {
        const auto place = plan::place_on_paper(g.profile, side, d.x_mm, d.y_mm);
        out.push_back({place.paper_x_mm, place.paper_y_mm, 0, 0, 0});
    }
    return out;
}

}  // namespace

std::vector<DotPoint> front_dots(const layout::Page& page, const SheetGeometry& g) {
    return dots(page, plan::Side::front, g);
}

std::vector<DotPoint> back_dots(const layout::Page& page, const SheetGeometry& g) {
    return dots(page, plan::Side::back, g);
}

DotPoint cell_origin(int line, int cell, bool back, const SheetGeometry& g) {
    const auto side = back ? plan::Side::back : plan::Side::front;
    return point({line, cell, 1, plan::dot_place(g.profile, side, line, cell, 1)});
}

}  // namespace tactus::gui
