// SPDX-License-Identifier: GPL-3.0-or-later
#include "layout/paginator.hpp"

#include <algorithm>
#include <span>

#include "layout/line_breaker.hpp"

namespace tactus::layout {
namespace {

constexpr document::Cell kGuideDots{0x24};  // dots 3-6: the print-page separator line
constexpr document::Cell kTableGuideDot{0x10};   // dot 5: guide dots between table columns
constexpr document::Cell kSeparationLine{0x12};  // dots 2-5: the line under column headings
constexpr document::Cell kTopBoxLine{0x36};     // dots 2356: the line above boxed material
constexpr document::Cell kBottomBoxLine{0x1B};  // dots 1245: the line below it
constexpr int kColumnGap = 2;                    // blank cells between two columns, at least

bool is_blank(const document::BrailleLine& l) { return std::ranges::all_of(l, &document::Cell::blank); }

void trim_right(document::BrailleLine& l) {
    while (!l.empty() && l.back().blank()) l.pop_back();
}

// A table cell's cells without blanks around them.
std::span<const document::Cell> entry(const translate::TranslatedBlock& b) {
    std::size_t first = 0, last = b.cells.size();
    while (first < last && b.cells[first].blank()) ++first;
    while (last > first && b.cells[last - 1].blank()) --last;
    return std::span(b.cells).subspan(first, last - first);
}

}  // namespace

Paginator::Paginator(LayoutOptions options, std::function<document::BrailleLine(int)> number_cells)
    : o_(std::move(options)), number_cells_(std::move(number_cells)) {
    doc_.geometry = o_.geometry;
}

bool page_is_numbered(const LayoutOptions& o, std::size_t page_index) {
    if (o.page_numbers == PageNumberPosition::none) return false;
    // Interpoint: only the front of each sheet carries a number.
    return !o.geometry.interpoint || page_index % 2 == 0;
}

int body_top(const LayoutOptions& o, std::size_t page_index) {
    const bool number_on_top = page_is_numbered(o, page_index) && o.page_numbers == PageNumberPosition::top_right;
    return o.top_margin + (number_on_top ? 1 : 0);
}

int body_capacity(const LayoutOptions& o, std::size_t page_index) {
    const int lines = o.geometry.lines_per_page - o.top_margin - o.bottom_margin;
    return page_is_numbered(o, page_index) ? lines - 1 : lines;
}

bool Paginator::numbered(std::size_t page_index) const { return page_is_numbered(o_, page_index); }

int Paginator::width() const {
    return o_.geometry.cells_per_line - o_.left_margin - o_.right_margin;
}

int Paginator::body_capacity() const { return layout::body_capacity(o_, doc_.pages.size()); }

void Paginator::add_line(document::BrailleLine line, int source_line) {
    if (static_cast<int>(body_.size()) >= body_capacity()) close_page();
    if (!o_.geometry.eight_dot) {
        bool stripped = false;
        for (auto& c : line) {
            if (c.dots & 0xC0) {
                c.dots &= 0x3F;
                stripped = true;
            }
        }
        if (stripped) note_dots_78(source_line);
    }
    trim_right(line);
    under_box_line_ = false;
    if (body_.empty()) page_top_print_page_ = print_page_;
    body_.push_back(std::move(line));
}

void Paginator::note_dots_78(int source_line) {
    // One warning for the whole document, however many lines have such cells:
    // where they are first, and on how many source lines in all.
    if (dots_78_.warning && source_line == dots_78_.last_line) return;
    ++dots_78_.lines;
    dots_78_.last_line = source_line;
    if (!dots_78_.warning) {
        dots_78_.warning = doc_.warnings.size();
        dots_78_.first = source_line > 0 ? "line " + std::to_string(source_line) + ": " : std::string{};
        doc_.warnings.emplace_back();
    }
    doc_.warnings[*dots_78_.warning] =
        dots_78_.first + "cells with dots 7-8 (often a character the table does not know) shown as 6-dot;"
                         " use 8-dot layout to keep them" +
        (dots_78_.lines > 1 ? " (on " + std::to_string(dots_78_.lines) + " lines; the first named)" : std::string{});
}

void Paginator::add_blank_line() {
    // Never at the top of a page, never two in a row, never as the last body
    // line, never under a top box line.
    if (body_.empty() || is_blank(body_.back()) || under_box_line_) return;
    if (static_cast<int>(body_.size()) + 1 >= body_capacity()) {
        close_page();
        return;
    }
    body_.emplace_back();
}

void Paginator::break_page() {
    if (!body_.empty()) close_page();
}

void Paginator::close_page() {
    Page page;
    const std::size_t index = doc_.pages.size();
    page.braille_number = o_.first_page_number + static_cast<int>(index);
    page.print_page = body_.empty() ? print_page_ : page_top_print_page_;
    const auto& g = o_.geometry;
    page.lines.assign(static_cast<std::size_t>(g.lines_per_page), document::BrailleLine{});

    // Remove a trailing blank line left by a block rule.
    while (!body_.empty() && is_blank(body_.back())) body_.pop_back();

    const bool has_number = numbered(index);
    std::size_t row = static_cast<std::size_t>(body_top(o_, index));
    const document::BrailleLine indent(static_cast<std::size_t>(o_.left_margin), document::Cell{});
    for (auto& l : body_) {
        if (!l.empty()) {
            document::BrailleLine full = indent;
            full.insert(full.end(), l.begin(), l.end());
            page.lines[row] = std::move(full);
        }
        ++row;
    }
    if (has_number) {
        const auto number = number_cells_(page.braille_number);
        const auto line_index = o_.page_numbers == PageNumberPosition::top_right
                                    ? static_cast<std::size_t>(o_.top_margin)
                                    : static_cast<std::size_t>(g.lines_per_page - o_.bottom_margin - 1);
        const int right_edge = g.cells_per_line - o_.right_margin;
        const int len = static_cast<int>(number.size());
        int start = o_.page_numbers == PageNumberPosition::bottom_centre
                        ? o_.left_margin + (width() - len) / 2
                        : right_edge - len;
        start = std::max(start, 0);
        document::BrailleLine l(static_cast<std::size_t>(start), document::Cell{});
        l.insert(l.end(), number.begin(), number.end());
        if (static_cast<int>(l.size()) > g.cells_per_line)
            l.resize(static_cast<std::size_t>(g.cells_per_line));
        page.lines[line_index] = std::move(l);
    }
    doc_.pages.push_back(std::move(page));
    body_.clear();
}

void Paginator::add_wrapped(const translate::TranslatedBlock& b, const BlockIndents& in) {
    auto lines = break_lines(b.cells, b.breaks, width(), in.first, in.runover);
    const bool centre = in.centred;
    const int source_line = b.source_line;
    for (auto& l : lines) {
        if (centre) {
            trim_right(l);
            const auto pad = static_cast<std::size_t>(std::max(0, (width() - static_cast<int>(l.size())) / 2));
            l.insert(l.begin(), pad, document::Cell{});
        }
        add_line(std::move(l), source_line);
    }
}

bool Paginator::settled() const {
    // After a quote or a list item the next block's blank line depends on it.
    return table_.empty() && last_kind_ != document::BlockKind::quote && last_kind_ != document::BlockKind::list_item;
}

void Paginator::add_table_block(const translate::TranslatedBlock& b) {
    if (b.kind == document::BlockKind::table_row) {
        table_.push_back(TableRow{b.level == 1, {}});
        return;
    }
    if (table_.empty()) table_.emplace_back();  // cells before any row marker: a first row
    auto& cells = table_.back().cells;
    // `level` is the column: a missing cell before it is an empty one.
    while (static_cast<int>(cells.size()) < b.level) {
        cells.emplace_back();
        cells.back().kind = document::BlockKind::table_cell;
        cells.back().level = static_cast<int>(cells.size()) - 1;
    }
    cells.push_back(b);
}

std::vector<Paginator::Merged> Paginator::merged_entries(const TableRow& row) {
    // A cell's span reaches over the empty cells that stand for the columns it
    // covers (add_table_block fills them in); a cell with text ends it.
    std::vector<Merged> out;
    for (std::size_t c = 0; c < row.cells.size();) {
        std::size_t span = 1;
        const auto wanted = static_cast<std::size_t>(std::max(1, row.cells[c].span));
        while (span < wanted && c + span < row.cells.size() && entry(row.cells[c + span]).empty()) ++span;
        if (c + span == row.cells.size()) span = wanted;  // the row's last cell covers what it says
        out.push_back(Merged{&row.cells[c], c, span});
        c += span;
    }
    return out;
}

// BANA Braille Formats §11: a table is preceded and followed by a blank line;
// as columns when every row fits the line, else in listed format.
void Paginator::flush_table() {
    if (table_.empty()) return;
    add_blank_line();
    if (!lay_out_simple_table()) lay_out_listed_table();
    add_blank_line();
    table_.clear();
}

// Columns side by side, each as wide as its widest entry, two cells apart at
// least; in body rows guide dots (dot 5, a blank cell on each side) lead from a
// short entry to the next column. Under a header row, a separation line of
// dots 2-5 as wide as each column. Returns false, having laid out nothing, when
// the table does not fit the line, an entry had to be divided or an entry has
// more than one paragraph.
bool Paginator::lay_out_simple_table() {
    // Each row as its entries and the columns each covers (a merged cell more
    // than one: it is as wide as those columns and the gaps between them).
    std::vector<std::vector<Merged>> rows;
    std::size_t columns = 0;
    for (const auto& row : table_) {
        rows.push_back(merged_entries(row));
        if (!rows.back().empty()) columns = std::max(columns, rows.back().back().column + rows.back().back().span);
    }
    std::vector<std::size_t> widths(columns, 0);
    const auto group_width = [&widths](const Merged& m) {
        std::size_t w = kColumnGap * (m.span - 1);
        for (std::size_t c = m.column; c < m.column + m.span; ++c) w += widths[c];
        return w;
    };
    // Single columns first, then a merged entry wider than its columns widens the last of them.
    for (int pass = 0; pass < 2; ++pass)
        for (const auto& row : rows)
            for (const auto& m : row) {
                // A divided word, or an entry of several paragraphs: not one line.
                if (std::ranges::any_of(m.cell->breaks, [](translate::BreakBefore b) {
                        return b == translate::BreakBefore::forced || b == translate::BreakBefore::paragraph;
                    }))
                    return false;
                const auto need = entry(*m.cell).size();
                if (pass == 0 && m.span == 1) widths[m.column] = std::max(widths[m.column], need);
                if (pass == 1 && m.span > 1 && need > group_width(m)) widths[m.column + m.span - 1] += need - group_width(m);
            }
    if (widths.empty()) return true;
    std::size_t total = kColumnGap * (widths.size() - 1);
    for (const auto w : widths) total += w;
    if (total > static_cast<std::size_t>(width())) return false;

    const int source_line = table_.front().cells.empty() ? 0 : table_.front().cells.front().source_line;
    // The column headings, their separation line and the first row stay
    // together, as a heading stays with what it heads.
    std::size_t head = 0;
    while (head < table_.size() && table_[head].header) ++head;
    const auto together = static_cast<int>(head == 0 ? 1 : std::min(head + 2, table_.size() + 1));
    if (!body_.empty() && static_cast<int>(body_.size()) + together > body_capacity()) close_page();
    // The column headings and their separation line, repeated at the top of a
    // page the table runs on to (BANA Braille Formats §11: a table continued on
    // a new page repeats its column headings).
    std::vector<document::BrailleLine> headings;
    for (std::size_t r = 0; r < table_.size(); ++r) {
        const auto& row = table_[r];
        if (!row.header && r >= head && !headings.empty() && static_cast<int>(body_.size()) >= body_capacity() &&
            static_cast<int>(headings.size()) + 1 < body_capacity()) {
            close_page();
            for (const auto& h : headings) add_line(h, source_line);
        }
        document::BrailleLine line;
        // The row's entries and the columns after its last one, empty.
        auto groups = rows[r];
        for (auto c = groups.empty() ? 0 : groups.back().column + groups.back().span; c < widths.size(); ++c)
            groups.push_back(Merged{nullptr, c, 1});
        for (std::size_t g = 0; g < groups.size(); ++g) {
            const auto e = groups[g].cell ? entry(*groups[g].cell) : std::span<const document::Cell>{};
            line.insert(line.end(), e.begin(), e.end());
            if (g + 1 == groups.size()) break;
            const std::size_t gap = group_width(groups[g]) - e.size() + kColumnGap;
            if (!row.header && gap >= 4) {
                line.emplace_back();
                line.insert(line.end(), gap - 2, kTableGuideDot);
                line.emplace_back();
            } else {
                line.insert(line.end(), gap, document::Cell{});
            }
        }
        if (r < head) headings.push_back(line);
        add_line(std::move(line), source_line);
        const bool last_header = row.header && (r + 1 == table_.size() || !table_[r + 1].header);
        if (last_header) {
            // Under each heading, as wide as the columns it heads.
            document::BrailleLine sep;
            for (std::size_t g = 0; g < groups.size(); ++g) {
                sep.insert(sep.end(), group_width(groups[g]), kSeparationLine);
                if (g + 1 < groups.size()) sep.insert(sep.end(), kColumnGap, document::Cell{});
            }
            if (r < head) headings.push_back(sep);
            add_line(std::move(sep), source_line);
        }
    }
    return true;
}

// Listed format: each row's entries in column order, one after the other, the
// first in cell 1 and the others in cell 3, runover lines in cell 5
// (block_indents of table_cell); each further paragraph of an entry starts a
// line where the entry started (line_breaker.hpp). A header row is listed first like any row, so
// the reader learns the order of the columns. Empty entries are left out; a
// row whose first column is empty (or merged away) starts in cell 1 with its
// first entry, so each row still starts at the margin.
//
// On a page the table runs on to, the column headings (the header rows' lines)
// are repeated at its top, as for a simple table (BANA Braille Formats §11;
// docs/layout.md "Tables"). So that they head whole rows, a row that would
// run over the page's end starts on the next page when it fits there under
// the headings; the headings and the first row stay together.
void Paginator::lay_out_listed_table() {
    struct Line {
        document::BrailleLine cells;
        int source_line = 0;
    };
    std::vector<std::vector<Line>> rows;
    rows.reserve(table_.size());
    for (const auto& row : table_) {
        auto& lines = rows.emplace_back();
        bool first = true;
        for (const auto& cell : row.cells) {
            if (entry(cell).empty()) continue;
            const auto in = block_indents(o_, document::BlockKind::table_cell, first ? 0 : std::max(cell.level, 1));
            for (auto& l : break_lines(cell.cells, cell.breaks, width(), in.first, in.runover))
                lines.push_back(Line{std::move(l), cell.source_line});
            first = false;
        }
    }
    std::size_t head = 0;
    while (head < table_.size() && table_[head].header) ++head;
    std::vector<Line> headings;
    for (std::size_t r = 0; r < head; ++r) headings.insert(headings.end(), rows[r].begin(), rows[r].end());
    const auto next_capacity = [this] { return layout::body_capacity(o_, doc_.pages.size() + 1); };
    // The headings and the first row together, when they fit on a page at all.
    if (!headings.empty() && head < rows.size()) {
        const auto together = static_cast<int>(headings.size() + rows[head].size());
        if (!body_.empty() && static_cast<int>(body_.size()) + together > body_capacity() && together <= next_capacity())
            close_page();
    }
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const auto need = static_cast<int>(rows[r].size());
        if (r >= head && !headings.empty() && need > 0) {
            const bool runs_over = static_cast<int>(body_.size()) + need > body_capacity();
            const bool fits_below_headings = static_cast<int>(headings.size()) + need <= next_capacity();
            if (runs_over && fits_below_headings && !body_.empty()) {
                close_page();
                for (const auto& h : headings) add_line(h.cells, h.source_line);
            }
        }
        for (auto& l : rows[r]) add_line(std::move(l.cells), l.source_line);
    }
}

// Boxed material (BANA Braille Formats 2016 §7, "Boxed Material"): a full
// line of dots 2356 above the box and of dots 1245 below it, no blank line
// after the top line or before the bottom one, and a blank line between two
// boxes that follow each other.
void Paginator::enter_box(int box) {
    if (box == box_) return;
    const auto w = static_cast<std::size_t>(width());
    if (box_ != 0) {
        while (!body_.empty() && is_blank(body_.back())) body_.pop_back();
        add_line(document::BrailleLine(w, kBottomBoxLine), 0);
    }
    if (box != 0) {
        if (box_ != 0) add_blank_line();
        // A top box line as a page's last line would head nothing.
        if (!body_.empty() && static_cast<int>(body_.size()) + 2 > body_capacity()) close_page();
        add_line(document::BrailleLine(w, kTopBoxLine), 0);
        under_box_line_ = true;
    }
    box_ = box;
}

void Paginator::add(const translate::TranslatedBlock& b) {
    if (b.kind != document::BlockKind::print_page_break) trailing_separators_ = 0;
    if (b.box != box_ && (document::is_text_kind(b.kind) || b.kind == document::BlockKind::braille ||
                          b.kind == document::BlockKind::table_row)) {
        if (!table_.empty()) {
            flush_table();
            last_kind_ = document::BlockKind::table_row;
        }
        enter_box(b.box);
    }
    if (document::is_table_kind(b.kind)) {
        add_table_block(b);
        return;
    }
    if (!table_.empty()) {
        flush_table();
        last_kind_ = document::BlockKind::table_row;
    }
    if (document::is_text_kind(b.kind) || b.kind == document::BlockKind::braille) {
        if (blank_line_before(o_, last_kind_, b.kind)) add_blank_line();
        if (sets_previous_kind(b.kind)) last_kind_ = b.kind;
    }
    switch (b.kind) {
        case document::BlockKind::heading: {
            // Keep a heading off the last body line of a page: it would head nothing.
            if (!body_.empty() && static_cast<int>(body_.size()) + 2 > body_capacity()) close_page();
            add_wrapped(b, block_indents(o_, b.kind, b.level));
            if (o_.blank_line_after_heading && b.level <= 1) add_blank_line();
            break;
        }
        case document::BlockKind::paragraph:
        case document::BlockKind::list_item:
        case document::BlockKind::quote:
        case document::BlockKind::note:
            add_wrapped(b, block_indents(o_, b.kind, b.level));
            break;
        case document::BlockKind::table_row:
        case document::BlockKind::table_cell:
            break;  // handled above
        case document::BlockKind::print_page_break: {
            print_page_ = document::to_unicode_text(b.label);
            if (!o_.print_page_indicators || body_.empty()) break;
            // A separator line of dots 3-6 ending in the new print page number.
            const auto w = static_cast<std::size_t>(width());
            document::BrailleLine l(w, kGuideDots);
            const auto n = std::min(b.label.size(), w / 2);
            std::copy(b.label.begin(), b.label.begin() + static_cast<std::ptrdiff_t>(n),
                      l.end() - static_cast<std::ptrdiff_t>(n));
            if (static_cast<int>(body_.size()) + 1 >= body_capacity()) {
                close_page();  // a separator as a page's last line separates nothing
                page_top_print_page_ = print_page_;
                break;
            }
            add_line(std::move(l), b.source_line);
            ++trailing_separators_;
            break;
        }
        case document::BlockKind::braille_page_break:
            break_page();
            break;
        case document::BlockKind::braille:
            for (const auto& line : b.lines) {
                // Verbatim lines keep their spacing; overlong ones are cut, not lost.
                const auto w = static_cast<std::size_t>(width());
                if (line.empty()) {
                    if (static_cast<int>(body_.size()) >= body_capacity()) close_page();
                    body_.emplace_back();
                    continue;
                }
                for (std::size_t s = 0; s < line.size(); s += w)
                    add_line(document::BrailleLine(line.begin() + static_cast<std::ptrdiff_t>(s),
                                         line.begin() + static_cast<std::ptrdiff_t>(std::min(line.size(), s + w))),
                             b.source_line);
            }
            break;
    }
}

void Paginator::add_graphic(const PagedDocument& graphic) {
    if (graphic.pages.empty()) return;
    flush_table();
    enter_box(0);
    for (; trailing_separators_ > 0 && !body_.empty(); --trailing_separators_) body_.pop_back();
    if (!body_.empty()) close_page();
    const bool interpoint = o_.geometry.interpoint;
    // An empty back, unnumbered as every back is, so the graphic starts a sheet.
    if (interpoint && doc_.pages.size() % 2 == 1) close_page();
    for (const auto& source : graphic.pages) {
        Page page = source;
        page.filler = false;  // a blank back among text pages is a page like any other
        page.braille_number = o_.first_page_number + static_cast<int>(doc_.pages.size());
        page.print_page = print_page_;
        if (page.lines.empty() && page.graphic.empty())
            page.lines.assign(static_cast<std::size_t>(o_.geometry.lines_per_page), document::BrailleLine{});
        doc_.pages.push_back(std::move(page));
    }
    if (interpoint && doc_.pages.size() % 2 == 1) close_page();
    doc_.warnings.insert(doc_.warnings.end(), graphic.warnings.begin(), graphic.warnings.end());
    last_kind_.reset();
    under_box_line_ = false;
}

PagedDocument Paginator::finish() && {
    flush_table();
    enter_box(0);
    // Print page breaks after all text start no print page: their separator
    // lines would separate nothing.
    for (; trailing_separators_ > 0 && !body_.empty(); --trailing_separators_) body_.pop_back();
    if (!body_.empty() || doc_.pages.empty()) close_page();
    return std::move(doc_);
}

}  // namespace tactus::layout
