// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A range of braille pages as the reader names them, by the numbers printed
// on the pages: "3-10", "5-" (to the end), "7", and in a book the
// preliminary pages' "t1" (title) and "p1-p3" (contents). One rule for the
// CLI's `emboss --pages` and the app's printer panel.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "layout/page.hpp"
#include "pipeline/book_layout.hpp"

namespace tactus::pipeline {

struct PageRange {
    std::string first;  // a page label: digits, or t/p and digits
    std::string last;   // empty: to the end
    bool operator==(const PageRange&) const = default;
};

// "FIRST-LAST", "FIRST-" or "N"; labels are lower-cased. A usage error names
// what is wrong ("pages count from 1", "expected FIRST-LAST ...").
Result<PageRange> parse_page_range(std::string_view text);

// The number each page carries as a label: "12"; "" for a blank filler page.
std::vector<std::string> page_labels(const layout::PagedDocument& doc);
// The same for a book: its title pages "t1", "t2", its contents "p1", ...
std::vector<std::string> page_labels(const BookLayout& book);

// The pages the range names, as 1-based page indices (first, last inclusive;
// what spool::select_pages takes). A label names the first page that carries
// it, the last label the first page at or after the first one (so "p1-p2"
// are the first volume's contents pages). An input error when a label is on
// no page or the range runs backwards.
Result<std::pair<std::size_t, std::size_t>> find_page_range(const std::vector<std::string>& labels,
                                                            const PageRange& range);

}  // namespace tactus::pipeline
