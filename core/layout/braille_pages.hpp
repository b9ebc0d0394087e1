// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Ready-made braille (BRF, PEF) is embossed and exported page for page: the
// source's rows on the source's pages, with the page numbers it carries and no
// new ones, PEF sections each starting on a new sheet. Laying it out again
// (the paginator) is a choice the user makes, not something done silently.
#include <optional>
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"
#include "layout/layout_options.hpp"
#include "layout/page.hpp"

namespace tactus::layout {

// True when the document is formatted braille: it has braille pages and no text
// to translate (what the BRF and PEF importers produce).
bool is_ready_braille(const document::Document& doc);

// The file's page in one volume: the cols and rows it declares (PEF; the
// largest of its sections'), or a BRF's longest line and page.
struct VolumePage {
    int volume = 0;  // 1-based
    int cols = 0;
    int rows = 0;
    bool fits = false;  // the target's page holds it
    bool operator==(const VolumePage&) const = default;
};

// The first source page that the target's page cannot hold, with both sizes.
struct BraillePageMisfit {
    int page = 0;         // 1-based source page
    int rows = 0;         // its rows
    int cols = 0;         // its longest row, in cells
    int file_cols = 0;    // the file's own page for it (its PEF section's cols/rows; a BRF's grid)
    int file_rows = 0;
    int target_cols = 0;  // the target's page
    int target_rows = 0;
    int source_line = 0;  // where the page starts in the file (0: unknown)
    std::vector<VolumePage> volumes;  // the file's page, volume by volume (one for a BRF)
};

// Nothing when every source page fits the target's page: a PEF page is its
// section's declared page (cols, rows; at least its rows), each laid out on
// its own grid, a BRF page its rows (no row longer than the target's cells, no
// more rows than its lines). The one rule the CLI (exit 5) and the app (its
// question before embossing or exporting) both ask.
std::optional<BraillePageMisfit> find_braille_misfit(const document::Document& doc, const LayoutOptions& target);

// Fails, naming the first page that does not fit and both sizes, when a source
// page has more rows than `target` has lines or a row longer than its cells.
Result<void> check_braille_fits(const document::Document& doc, const LayoutOptions& target);

// The source pages as they are. The result's cells and lines are the source's
// own grid (the largest of its PEF sections' cols/rows; for BRF the longest
// line and page found), each section keeps its own (PageSection: cols, rows,
// rowgap, written back to PEF volume by volume); whether
// sheets are interpoint is the target's (the printer's) choice. On interpoint
// paper a section that would start on a back gets a blank back first, and each
// page of a single-sided section gets a blank back of its own (`Page::filler`).
//
// `places`, when given, receives for each block of `doc` where it lands: the
// page (an index into the result's pages) and the row its first row is on; a
// braille page break, and any block that is no row, where the next row lands
// (the editor maps its lines to paper with it).
struct BlockPlace {
    std::size_t page = 0;
    int row = 0;
    bool operator==(const BlockPlace&) const = default;
};
Result<PagedDocument> keep_braille_pages(const document::Document& doc, const LayoutOptions& target,
                                         std::vector<BlockPlace>* places = nullptr);

}  // namespace tactus::layout
