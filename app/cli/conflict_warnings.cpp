// SPDX-License-Identifier: GPL-3.0-or-later
#include "conflict_warnings.hpp"

#include <cstdio>

#include "plan/geometry.hpp"

namespace tactus::cli {

std::size_t warn_about_conflicts(const layout::PagedDocument& doc,
                                 const profile::PrinterProfile& profile) {
    std::size_t total = 0;
    for (std::size_t n = 1; n <= doc.sheet_count(); ++n) {
        const auto conflicts = plan::find_conflicts(profile, doc.sheet(n));
        if (conflicts.empty()) continue;
        total += conflicts.size();
        const auto& c = conflicts.front();
        std::fprintf(
            stderr,
            "warning: sheet %zu: %zu front and back dots closer than %.2f mm (first: front line %d "
            "cell %d dot %d against back line %d cell %d dot %d); check the profile's back "
            "offset\n",
            n, conflicts.size(), plan::min_dot_separation_mm(profile), c.front.line + 1,
            c.front.cell + 1, c.front.dot, c.back.line + 1, c.back.cell + 1, c.back.dot);
    }
    return total;
}

}  // namespace tactus::cli
