// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The braille page a machine embosses, as the layout sees it: the profile's
// cells per line, lines per page, sides and dots. The CLI, the desktop app, the
// CUPS filter, the benches and the tests all lay out for a machine through this
// one rule, so they cannot disagree about which profile fields shape the page.
#include "layout/page.hpp"
#include "profile/profile.hpp"

namespace tactus::profile {

[[nodiscard]] layout::PageGeometry page_geometry(const PrinterProfile& machine);

}  // namespace tactus::profile
