// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The laid-out document as stored in a job: a compact JSON text that keeps
// everything the planner reads (geometry, every cell of every page, page
// numbers), so a job embosses exactly what was submitted even if the source
// file changes or disappears afterwards. Cells are Unicode braille, so 8-dot
// cells survive (BRF would drop dots 7-8); a graphic page keeps its dots.
#include <cstddef>
#include <string>
#include <string_view>

#include "common/result.hpp"
#include "layout/page.hpp"

namespace tactus::spool {

inline constexpr std::string_view kSnapshotFormat = "tactus-paged-1";

std::string to_snapshot(const layout::PagedDocument& doc);
// Strict: the format tag, every field and the sizes are checked; errors name
// the page and line ("page 12 line 3: 29 cells, the geometry allows 27").
Result<layout::PagedDocument> from_snapshot(std::string_view text);

// Pages first..last (1-based, inclusive; 0 = to the end) as their own
// document: on interpoint paper page `first` goes on a front.
Result<layout::PagedDocument> select_pages(const layout::PagedDocument& doc, std::size_t first, std::size_t last);

}  // namespace tactus::spool
