// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"
#include "layout/page.hpp"

namespace tactus::layout {

enum class PageNumberPosition { none, top_right, bottom_right, bottom_centre };

struct LayoutOptions {
    PageGeometry geometry;  // 27 x 24, interpoint: the source embosser's A4 format
    // Margins inside the cell grid (the paper margins live in the printer profile).
    int left_margin = 0;    // cells
    int right_margin = 0;   // cells
    int top_margin = 0;     // lines
    int bottom_margin = 0;  // lines
    int paragraph_indent = 2;        // blank cells before a paragraph's first line
    int list_runover = 2;            // extra indent of a list item's following lines
    bool centre_headings = true;     // level 1; level 2 starts at cell 5, deeper ones at cell 7
    bool blank_line_before_heading = true;
    bool blank_line_after_heading = true;  // after level-1 headings
    bool blank_line_between_paragraphs = false;
    PageNumberPosition page_numbers = PageNumberPosition::bottom_right;
    bool print_page_indicators = true;
    int first_page_number = 1;
};

// Named formats a teacher picks from; the default is the source embosser's.
struct LayoutPreset {
    std::string name;
    std::string description;
    double paper_width_mm = 0;
    double paper_height_mm = 0;
    PageGeometry geometry;
};

const std::vector<LayoutPreset>& layout_presets();
std::optional<LayoutPreset> find_layout_preset(std::string_view name);

Result<PageNumberPosition> parse_page_number_position(std::string_view);

// Where a block's lines start: the one place these rules live (the paginator,
// word division and the editor's cursor mapping all ask here).
struct BlockIndents {
    int first = 0;    // blank cells before the first line
    int runover = 0;  // blank cells before the following lines
    bool centred = false;
};
BlockIndents block_indents(const LayoutOptions& options, document::BlockKind kind, int level);

// Whether a blank line goes before a text block of `kind` that follows one of
// `previous` (none at the start; see sets_previous_kind): before a heading
// (BANA §4), before and after a block quote and a list (BANA §8, §9), none
// under a cell-5 or cell-7 heading (Braille Formats 2016 Appendix C), none
// before a note, between paragraphs when asked. Tables add their own (the
// paginator). The paginator and the editor's cursor map both ask here.
bool blank_line_before(const LayoutOptions& options, std::optional<document::BlockKind> previous,
                       document::BlockKind kind);

// Whether a block of `kind` is the `previous` of blank_line_before for the
// blocks after it. Page breaks are not, and neither is a note: it belongs to
// the block that refers to it, so a list or a quote goes on (or ends) after
// it as if the note were not there.
bool sets_previous_kind(document::BlockKind kind);

// The cells a word of this block can have on any of its lines: a word longer
// than this is divided (translate/word_division.hpp).
std::size_t word_room(const LayoutOptions& options, document::BlockKind kind, int level);

// Rejects geometries in which no text fits, naming the offending option.
Result<void> validate(const LayoutOptions& options);

}  // namespace tactus::layout
