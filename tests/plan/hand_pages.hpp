// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Hand-built pages for the planner tests: each line a string of Unicode braille.
#include <string>
#include <vector>

#include "layout/page.hpp"

namespace tactus::test {

inline layout::Page page_of(const std::vector<std::u32string>& lines) {
    layout::Page p;
    for (const auto& l : lines) {
        document::BrailleLine line;
        for (char32_t c : l) line.push_back(document::Cell::from_unicode(c));
        p.lines.push_back(line);
    }
    return p;
}

inline layout::PagedDocument doc_of(std::vector<layout::Page> pages, bool interpoint = true) {
    layout::PagedDocument d;
    d.geometry.interpoint = interpoint;
    d.pages = std::move(pages);
    return d;
}

}  // namespace tactus::test
