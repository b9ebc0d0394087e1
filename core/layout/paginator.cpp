// SPDX-License-Identifier: GPL-3.0-or-later
#include "layout/paginator.hpp"

#include <algorithm>

#include "layout/line_breaker.hpp"

namespace tactus::layout {
namespace {

constexpr document::Cell kGuideDots{0x24};  // dots 3-6: the print-page separator line

bool is_blank(const document::BrailleLine& l) { return std::ranges::all_of(l, &document::Cell::blank); }

void trim_right(document::BrailleLine& l) {
    while (!l.empty() && l.back().blank()) l.pop_back();
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
        if (stripped)
            doc_.warnings.push_back(
                (source_line > 0 ? "line " + std::to_string(source_line) + ": " : std::string{}) +
                "cells with dots 7-8 (often a character the table does not know) shown as 6-dot;"
                " use 8-dot layout to keep them");
    }
    trim_right(line);
    if (body_.empty()) page_top_print_page_ = print_page_;
    body_.push_back(std::move(line));
}

void Paginator::add_blank_line() {
    // Never at the top of a page, never two in a row, never as the last body line.
    if (body_.empty() || is_blank(body_.back())) return;
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

void Paginator::add(const translate::TranslatedBlock& b) {
    switch (b.kind) {
        case document::BlockKind::heading: {
            if (o_.blank_line_before_heading) add_blank_line();
            // Keep a heading off the last body line of a page: it would head nothing.
            if (!body_.empty() && static_cast<int>(body_.size()) + 2 > body_capacity()) close_page();
            add_wrapped(b, block_indents(o_, b.kind, b.level));
            if (o_.blank_line_after_heading && b.level <= 1) add_blank_line();
            break;
        }
        case document::BlockKind::paragraph:
            if (o_.blank_line_between_paragraphs) add_blank_line();
            add_wrapped(b, block_indents(o_, b.kind, b.level));
            break;
        case document::BlockKind::list_item:
            add_wrapped(b, block_indents(o_, b.kind, b.level));
            break;
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

PagedDocument Paginator::finish() && {
    if (!body_.empty() || doc_.pages.empty()) close_page();
    return std::move(doc_);
}

}  // namespace tactus::layout
