// SPDX-License-Identifier: GPL-3.0-or-later
#include "profile/page_geometry.hpp"

namespace tactus::profile {

layout::PageGeometry page_geometry(const PrinterProfile& machine) {
    layout::PageGeometry g;
    g.cells_per_line = machine.geometry.cells_per_line;
    g.lines_per_page = machine.geometry.lines_per_page;
    g.interpoint = machine.geometry.interpoint;
    g.eight_dot = machine.geometry.eight_dot;
    return g;
}

}  // namespace tactus::profile
