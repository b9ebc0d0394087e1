// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include "layout/page.hpp"
#include "profile/profile.hpp"

namespace tactus::cli {

// Tells stderr about every sheet whose front and back dots crush each other on
// this printer (plan::find_conflicts, the rule the preview marks), one line per
// sheet. Returns the number of such dot pairs. A warning, not an error: the
// teacher may know the paper takes it.
std::size_t warn_about_conflicts(const layout::PagedDocument& doc, const profile::PrinterProfile& profile);

}  // namespace tactus::cli
