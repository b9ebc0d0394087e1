// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The output of layout: braille pages on sheets. Planning, export, preview and the
// spool all read these types.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "document/cell.hpp"
#include "document/document.hpp"

namespace tactus::layout {

// A dot of a tactile graphic, anywhere on the page: millimetres from the
// top-left corner of the paper as the reader holds this page's side. The
// graphic stage snaps it to what the machine can address.
struct GraphicDot {
    double x_mm = 0;
    double y_mm = 0;
    bool operator==(const GraphicDot&) const = default;
};

struct Page {
    std::vector<document::BrailleLine> lines;  // at most lines_per_page; each at most cells_per_line
    int braille_number = 0;          // 1-based braille page number
    std::string print_page;          // print page in effect at the top of this page ("" if none)
    // A blank back added to ready-made braille so a section, or a page of a
    // single-sided section, ends its sheet on interpoint paper. Written to BRF
    // (the embosser must feed it), left out of PEF (its sections say the same).
    bool filler = false;
    // A graphic page's dots (lines, textures and its braille labels), struck
    // where they are rather than on the cell grid; empty on a page of text.
    std::vector<GraphicDot> graphic;
    bool operator==(const Page&) const = default;
};

// One physical sheet. On interpoint paper the back is the next page, embossed
// on the reverse; single-sided sheets have no back.
struct Sheet {
    std::size_t number = 0;  // 1-based
    const Page* front = nullptr;
    const Page* back = nullptr;
};

struct PageGeometry {
    int cells_per_line = 27;  // the source embosser's A4 format
    int lines_per_page = 24;
    bool interpoint = true;
    bool eight_dot = false;
    bool operator==(const PageGeometry&) const = default;

    // Pages and sheets: an interpoint sheet carries two pages, front then back.
    // Page indices are 0-based (into PagedDocument::pages), sheet numbers 1-based.
    [[nodiscard]] std::size_t sheet_of_page(std::size_t page_index) const {
        return interpoint ? page_index / 2 + 1 : page_index + 1;
    }
    [[nodiscard]] bool page_is_back(std::size_t page_index) const { return interpoint && page_index % 2 == 1; }
    [[nodiscard]] std::size_t first_page_of_sheet(std::size_t sheet) const {
        return interpoint ? 2 * (sheet - 1) : sheet - 1;
    }
    [[nodiscard]] std::size_t sheets_for_pages(std::size_t pages) const {
        return interpoint ? (pages + 1) / 2 : pages;
    }
};

// Ready-made braille (PEF) keeps its sections: each starts on a new sheet.
struct PageSection {
    std::size_t first_page = 0;
    bool duplex = false;  // the source section's duplex, written back to PEF
    // The section starts a PEF <volume> (the first section always does): the
    // PEF writer writes the volumes back as the source had them.
    bool starts_volume = false;
    // The section's own page (PEF cols, rows, rowgap), written back to PEF:
    // volumes of different sizes keep theirs. 0 cols: the geometry's page.
    int cols = 0;
    int rows = 0;
    int rowgap = 0;
    bool operator==(const PageSection&) const = default;
};

struct PagedDocument {
    PageGeometry geometry;
    std::vector<Page> pages;
    std::vector<PageSection> sections;   // empty: one section
    std::vector<document::MetadataItem> metadata;  // the source's PEF metadata, for export
    // Things the reader should know that did not stop the layout, as "line N: why".
    std::vector<std::string> warnings;

    [[nodiscard]] std::size_t sheet_count() const { return geometry.sheets_for_pages(pages.size()); }
    // Sheet n (1-based) points into `pages`; valid while this object lives unchanged.
    [[nodiscard]] Sheet sheet(std::size_t number) const {
        Sheet s;
        s.number = number;
        const auto i = geometry.first_page_of_sheet(number);
        s.front = i < pages.size() ? &pages[i] : nullptr;
        if (geometry.interpoint) s.back = i + 1 < pages.size() ? &pages[i + 1] : nullptr;
        return s;
    }
};

}  // namespace tactus::layout
