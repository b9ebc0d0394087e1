// SPDX-License-Identifier: GPL-3.0-or-later
#include "layout/layout_options.hpp"

#include <algorithm>

namespace tactus::layout {

const std::vector<LayoutPreset>& layout_presets() {
    static const std::vector<LayoutPreset> presets = {
        {"a4", "A4, 27 cells x 24 lines, interpoint (the source embosser)", 210.0, 297.0,
         {27, 24, true, false}},
        {"a4-single", "A4, 27 cells x 24 lines, single-sided", 210.0, 297.0,
         {27, 24, false, false}},
        {"us-braille", "11 x 11.5 in, 40 cells x 25 lines, interpoint", 279.4, 292.1,
         {40, 25, true, false}},
        {"letter", "8.5 x 11 in, 34 cells x 25 lines, interpoint", 215.9, 279.4,
         {34, 25, true, false}},
    };
    return presets;
}

std::optional<LayoutPreset> find_layout_preset(std::string_view name) {
    const auto& p = layout_presets();
    const auto it = std::ranges::find(p, name, &LayoutPreset::name);
    if (it == p.end()) return std::nullopt;
    return *it;
}

Result<PageNumberPosition> parse_page_number_position(std::string_view s) {
    if (s == "none") return PageNumberPosition::none;
    if (s == "top-right") return PageNumberPosition::top_right;
    if (s == "bottom-right") return PageNumberPosition::bottom_right;
    if (s == "bottom-centre" || s == "bottom-center") return PageNumberPosition::bottom_centre;
    return fail(ErrorKind::usage, "unknown page number position '" + std::string(s) +
                    "' (none, top-right, bottom-right, bottom-centre)",
                "--page-numbers");
}

BlockIndents block_indents(const LayoutOptions& o, document::BlockKind kind, int level) {
    const int width = o.geometry.cells_per_line - o.left_margin - o.right_margin;
    switch (kind) {
        case document::BlockKind::heading:
            // BANA Braille Formats §4.4-4.6: the main heading centred, the next
            // level a cell-5 heading, deeper levels cell-7 headings; cell-5 and
            // cell-7 headings are blocked (their runover lines start in the same cell).
            if (o.centre_headings && level <= 1) return {0, 0, true};
            return level <= 2 ? BlockIndents{4, 4, false} : BlockIndents{6, 6, false};
        case document::BlockKind::list_item: {
            // BANA Braille Formats §8 (lists): an item at cell 1, its runover
            // lines at cell 3; each nested level two cells deeper.
            const int indent = std::min(2 * std::max(level - 1, 0), width / 2);
            return {indent, indent + o.list_runover, false};
        }
        case document::BlockKind::note:
            // BANA Braille Formats §16 (notes; number not verified, docs/layout.md
            // "Sources"): 7-5, the note starts in cell 7
            // with its reference, runover lines in cell 5.
            return {std::min(6, width / 2), std::min(4, width / 2), false};
        case document::BlockKind::table_cell:
            // A listed table (BANA §11): the first entry of a row in cell 1, the
            // others in cell 3, every runover line in cell 5. `level` is the column.
            return {level == 0 ? 0 : std::min(2, width / 2), std::min(4, width / 2), false};
        default:
            return {o.paragraph_indent, 0, false};
    }
}

bool blank_line_before(const LayoutOptions& o, std::optional<document::BlockKind> previous,
                       document::BlockKind kind) {
    if (kind == document::BlockKind::heading) return o.blank_line_before_heading;
    // A note follows the block that refers to it, inside that block's structure
    // (a list, a quote): no blank line before it (its 7-5 format sets it off).
    if (kind == document::BlockKind::note) return false;
    const bool paragraph_spacing = kind == document::BlockKind::paragraph && o.blank_line_between_paragraphs;
    // Braille Formats 2016, Appendix C "Blank Lines": a blank line before but
    // not after a cell-5 or cell-7 heading, whatever follows it (a list or a
    // block quote starts right under it); a centred heading has its blank line
    // after it already, and a table (columned material, the one exception)
    // gets its own in the paginator.
    if (previous == document::BlockKind::heading) return paragraph_spacing;
    // Block quotes (displayed material, Braille Formats §9) and lists (§8): a
    // blank line before and after.
    const bool quote = kind == document::BlockKind::quote;
    const bool after_quote = previous == document::BlockKind::quote;
    if (quote != after_quote) return true;
    const bool list = kind == document::BlockKind::list_item;
    const bool after_list = previous == document::BlockKind::list_item;
    if (previous && list != after_list) return true;
    return paragraph_spacing;
}

bool sets_previous_kind(document::BlockKind kind) {
    return kind != document::BlockKind::note && kind != document::BlockKind::print_page_break &&
           kind != document::BlockKind::braille_page_break;
}

std::size_t word_room(const LayoutOptions& o, document::BlockKind kind, int level) {
    const int width = o.geometry.cells_per_line - o.left_margin - o.right_margin;
    const auto in = block_indents(o, kind, level);
    return static_cast<std::size_t>(std::max(1, width - std::max(in.first, in.runover)));
}

Result<void> validate(const LayoutOptions& o) {
    const auto& g = o.geometry;
    if (g.cells_per_line < 4 || g.cells_per_line > 200)
        return fail(ErrorKind::usage, "cells per line must be between 4 and 200", "cells_per_line");
    if (g.lines_per_page < 3 || g.lines_per_page > 200)
        return fail(ErrorKind::usage, "lines per page must be between 3 and 200", "lines_per_page");
    if (o.left_margin < 0 || o.right_margin < 0 || o.top_margin < 0 || o.bottom_margin < 0)
        return fail(ErrorKind::usage, "margins cannot be negative", "margins");
    const int width = g.cells_per_line - o.left_margin - o.right_margin;
    if (width < 4) return fail(ErrorKind::usage, "margins leave fewer than 4 cells per line", "margins");
    if (g.lines_per_page - o.top_margin - o.bottom_margin < 3)
        return fail(ErrorKind::usage, "margins leave fewer than 3 lines per page", "margins");
    if (o.paragraph_indent < 0 || o.paragraph_indent >= width)
        return fail(ErrorKind::usage, "paragraph indent must be smaller than the line", "paragraph_indent");
    if (o.list_runover < 0 || o.list_runover >= width / 2)
        return fail(ErrorKind::usage, "list runover indent too large for the line", "list_runover");
    if (o.first_page_number < 0) return fail(ErrorKind::usage, "page numbers start at 0 or above", "first_page_number");
    return {};
}

}  // namespace tactus::layout
