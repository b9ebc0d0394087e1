// SPDX-License-Identifier: GPL-3.0-or-later
// LiveLayout on a ready-made braille document whose pages are kept as they
// are: an edit of a row that keeps every page's shape lays out nothing again.
#include "edit/live_layout.hpp"

#include <algorithm>
#include "common/utf8.hpp"
#include "document/print_page.hpp"
#include "edit/cursor_map.hpp"
#include "edit/editor_lines.hpp"
#include "export/text_export.hpp"
#include "import/text_lines.hpp"
#include "layout/line_breaker.hpp"
#include "layout/braille_pages.hpp"
#include "layout/paginator.hpp"
#include "translate/script_check.hpp"

namespace tactus::edit {

bool LiveLayout::one_row(const Entry& e) {
    return e.block && !e.error && e.block->kind == document::BlockKind::braille && e.block->braille_lines.size() == 1;
}

bool LiveLayout::kept_row_edit(std::size_t i, std::pair<std::size_t, std::size_t> place,
                               const document::BrailleLine& old_row) {
    // Only when layout::keep_braille_pages would give the same pages with just
    // this row changed: a row still, no section mark, no change to the page's
    // grid (both rows within the file's cols and the printer's) or to 8-dot.
    // braille_structure_test's random edits compare it with keep_pages.
    auto& e = entries_[i];
    if (!one_row(e) || e.section || !braille_grid_) return false;
    const auto& row = e.block->braille_lines.front();
    // The file's cols for this row: its section's (the nearest mark above it;
    // the first section's above the first mark), else the file's grid.
    int file_cols = braille_grid_->cols;
    std::size_t m = i;
    while (m > 0 && !entries_[m].section) --m;
    if (entries_[m].section) {
        file_cols = entries_[m].section->cols;
    } else {
        for (const auto& later : entries_)
            if (later.section) {
                file_cols = later.section->cols;
                break;
            }
    }
    const auto cols = static_cast<std::size_t>(std::min(file_cols, requested_.geometry.cells_per_line));
    const auto eight = [](const document::BrailleLine& r) {
        return std::ranges::any_of(r, [](document::Cell c) { return (c.dots & 0xC0) != 0; });
    };
    if (row.size() > cols || old_row.size() > cols ||
        (!requested_.geometry.eight_dot && (eight(row) || eight(old_row))))
        return false;
    if (place.first >= paged_.pages.size() || place.second >= paged_.pages[place.first].lines.size()) return false;
    paged_.pages[place.first].lines[place.second] = row;
    e.pages_before = place.first;
    e.lines_before = place.second;
    e.settled_before = true;
    return true;
}

bool LiveLayout::keep_pages() {
    auto doc = document();
    if (!layout::is_ready_braille(doc)) return false;
    std::vector<layout::BlockPlace> places;
    // Refused when a page does not fit (layout::check_braille_fits): laid out again then.
    auto kept = layout::keep_braille_pages(doc, requested_, &places);
    if (!kept) return false;
    paged_ = std::move(*kept);
    if (script_warning_) paged_.warnings.push_back(*script_warning_);
    // Each line where its block landed; a line without one where the next block did.
    const layout::BlockPlace end =
        paged_.pages.empty() ? layout::BlockPlace{} : layout::BlockPlace{paged_.pages.size() - 1, 0};
    std::size_t b = 0;
    for (std::size_t i = 0; i < entries_.size(); ++i) {
        while (b < doc.blocks.size() && doc.blocks[b].source_line < static_cast<int>(i + 1)) ++b;
        const auto place = b < places.size() ? places[b] : end;
        entries_[i].pages_before = place.page;
        entries_[i].lines_before = static_cast<std::size_t>(place.row);
        entries_[i].settled_before = true;
    }
    kept_ = true;
    return true;
}

}  // namespace tactus::edit
