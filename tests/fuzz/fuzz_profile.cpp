// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes printer profiles: any text is a valid profile or an error naming the
// field, never an abort; a profile that is accepted plans a small page in
// bounded time (v_max 1e-6 or a/j 1e-300 once passed validation and the
// planner never returned; libFuzzer's -timeout catches a hang).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "layout/page.hpp"
#include "plan/planner.hpp"
#include "profile/profile_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tactus;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto profile = profile::parse_profile(text);
    if (!profile) return 0;
    // A round trip keeps an accepted profile accepted.
    if (!profile::parse_profile(profile::to_json(*profile).dump())) std::abort();
    // One line of a few cells: enough to move both axes and strike.
    layout::PagedDocument doc;
    doc.geometry.cells_per_line = std::min(profile->geometry.cells_per_line, 4);
    doc.geometry.lines_per_page = 1;
    doc.geometry.interpoint = false;
    layout::Page page;
    page.lines.push_back(document::BrailleLine(static_cast<std::size_t>(doc.geometry.cells_per_line), document::Cell{0x3F}));
    doc.pages.push_back(page);
    (void)plan::plan_job(doc, *profile);
    return 0;
}
