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

struct Page {
    std::vector<document::BrailleLine> lines;  // at most lines_per_page; each at most cells_per_line
    int braille_number = 0;          // 1-based braille page number
    std::string print_page;          // print page in effect at the top of this page ("" if none)
    // A blank back added to ready-made braille so a section, or a page of a
    // single-sided section, ends its sheet on interpoint paper. Written to BRF
    // (the embosser must feed it), left out of PEF (its sections say the same).
    bool filler = false;
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
};

// Ready-made braille (PEF) keeps its sections: each starts on a new sheet.
struct PageSection {
    std::size_t first_page = 0;
    bool duplex = false;  // the source section's duplex, written back to PEF
    bool operator==(const PageSection&) const = default;
};

struct PagedDocument {
    PageGeometry geometry;
    std::vector<Page> pages;
    std::vector<PageSection> sections;   // empty: one section
    std::vector<document::MetadataItem> metadata;  // the source's PEF metadata, for export
    // Things the reader should know that did not stop the layout, as "line N: why".
    std::vector<std::string> warnings;

    [[nodiscard]] std::size_t sheet_count() const {
        return geometry.interpoint ? (pages.size() + 1) / 2 : pages.size();
    }
    // Sheet n (1-based) points into `pages`; valid while this object lives unchanged.
    [[nodiscard]] Sheet sheet(std::size_t number) const {
        Sheet s;
        s.number = number;
        if (geometry.interpoint) {
            const auto i = 2 * (number - 1);
            s.front = i < pages.size() ? &pages[i] : nullptr;
            s.back = i + 1 < pages.size() ? &pages[i + 1] : nullptr;
        } else {
            s.front = number - 1 < pages.size() ? &pages[number - 1] : nullptr;
        }
        return s;
    }
};

}  // namespace tactus::layout
