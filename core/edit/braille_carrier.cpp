// SPDX-License-Identifier: GPL-3.0-or-later
#include "edit/braille_carrier.hpp"

#include <limits>

#include "export/export.hpp"
#include "layout/braille_pages.hpp"
#include "common/try.hpp"

namespace tactus::edit {

std::optional<Result<std::string>> structured_braille_pef(const LiveLayout& layout, const std::string& title) {
    if (layout.braille_structure().sections.empty()) return std::nullopt;  // no PEF's structure: no copy made
    const auto doc = layout.document();
    if (doc.braille_sections.empty() || !layout::is_ready_braille(doc)) return std::nullopt;
    // A page that holds every page of the file: its own pages, kept (PEF
    // leaves out the blank backs, so sides do not matter here).
    layout::LayoutOptions own;
    own.geometry.cells_per_line = std::numeric_limits<int>::max();
    own.geometry.lines_per_page = std::numeric_limits<int>::max();
    own.geometry.interpoint = false;
    TACTUS_TRY(paged, layout::keep_braille_pages(doc, own));
    return exporter::to_pef(paged, exporter::pef_metadata(paged.metadata, title, {}, {}));
}

}  // namespace tactus::edit
