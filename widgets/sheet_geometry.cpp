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
