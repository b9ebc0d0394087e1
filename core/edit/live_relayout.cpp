// SPDX-License-Identifier: GPL-3.0-or-later
// LiveLayout's relayout: an edit replaces lines and lays pages out again from
// the sheet holding the first changed line; where each cell and line sits on
// paper, and the print page it belongs to.
#include "edit/live_layout.hpp"

#include <algorithm>
#include "common/utf8.hpp"
#include "document/print_page.hpp"
#include "edit/cursor_map.hpp"
#include "edit/editor_lines.hpp"
#include "edit/live_lines.hpp"
#include "export/text_export.hpp"
#include "import/text_lines.hpp"
#include "layout/line_breaker.hpp"
#include "layout/braille_pages.hpp"
#include "layout/paginator.hpp"
#include "translate/script_check.hpp"

namespace tactus::edit {

using live_lines::starts_table_line;
using live_lines::braille_text_line;
using live_lines::merge_mark;

RelayoutStats LiveLayout::replace(std::size_t first, std::size_t removed,
                                  std::vector<std::string> lines) {
    first = std::min(first, entries_.size());
    removed = std::min(removed, entries_.size() - first);
    const auto at = entries_.begin() + static_cast<std::ptrdiff_t>(first);
    // One row of kept pages edited in place (a cell typed): where it is, for kept_row_edit.
    std::optional<std::pair<std::size_t, std::size_t>> row_place;
    if (kept_ && removed == 1 && lines.size() == 1 && !at->section && one_row(*at))
        row_place = std::pair{at->pages_before, at->lines_before};
    const auto old_row = row_place ? at->block->braille_lines.front() : document::BrailleLine{};
    const bool removed_breaks = std::any_of(at, at + static_cast<std::ptrdiff_t>(removed), [](const Entry& e) {
        return (e.block && e.block->kind == document::BlockKind::print_page_break) ||
               e.line.find('\f') != std::string::npos;  // a text line's form feed
    });
    // The section marks (BrailleStructure; see the header). The editor reports
    // an edit as the lines it touched: the removed lines the same at the start
    // and the end of the new ones were kept as they were (a line inserted above
    // a line is that line replaced by the new line and itself), and keep
    // their marks. The marks of the lines really deleted go to the first line
    // that replaces them, or else to the line after them.
    // The end first: a line inserted above another (the common report, and
    // undo's) is matched so even when the lines look alike (page breaks).
    std::size_t prefix = 0, suffix = 0;
    while (suffix < removed && suffix < lines.size() &&
           at[static_cast<std::ptrdiff_t>(removed - 1 - suffix)].line == lines[lines.size() - 1 - suffix])
        ++suffix;
    while (prefix < removed - suffix && prefix < lines.size() - suffix &&
           at[static_cast<std::ptrdiff_t>(prefix)].line == lines[prefix])
        ++prefix;
    struct Kept {
        std::size_t line;  // in the new lines
        document::BrailleSection section;
        std::optional<std::string> origin;
    };
    std::vector<Kept> kept;
    std::optional<document::BrailleSection> moved;
    std::string moved_from;  // the text of the line the winning mark was on
    for (std::size_t r = 0; r < removed; ++r) {
        const auto& e = at[static_cast<std::ptrdiff_t>(r)];
        if (!e.section) continue;
        if (r < prefix) kept.push_back({first + r, *e.section, e.mark_origin});
        else if (r >= removed - suffix) kept.push_back({first + lines.size() - (removed - r), *e.section, e.mark_origin});
        else {
            merge_mark(moved, *e.section);
            moved_from = e.mark_origin.value_or(e.line);
        }
    }
    const std::size_t middle_end = first + lines.size() - suffix;  // the new lines in the middle: [first + prefix, middle_end)
    entries_.erase(at, at + static_cast<std::ptrdiff_t>(removed));
    std::vector<Entry> fresh(lines.size());
    for (std::size_t i = 0; i < lines.size(); ++i) fresh[i].line = std::move(lines[i]);
    entries_.insert(entries_.begin() + static_cast<std::ptrdiff_t>(first),
                    std::make_move_iterator(fresh.begin()), std::make_move_iterator(fresh.end()));
    for (auto& k : kept) {
        // A mark moved here by a deletion goes back to its own line when that
        // line comes back above it (the deletion undone).
        std::size_t onto = k.line;
        if (k.origin)
            for (std::size_t m = first + prefix; m < middle_end; ++m)
                if (entries_[m].line == *k.origin) {
                    onto = m;
                    k.origin.reset();
                    break;
                }
        merge_mark(entries_[onto].section, k.section);
        entries_[onto].mark_origin = k.origin;
    }
    if (moved && first + prefix < entries_.size()) {
        auto& onto = entries_[first + prefix];
        if (onto.section) {
            onto.section->starts_volume = onto.section->starts_volume || moved->starts_volume;
        } else {
            onto.section = moved;
            // Moved onto a line that was there: the line it came from, for an undo.
            if (first + prefix >= middle_end) onto.mark_origin = moved_from;
        }
    }
    if (dialect_ == Dialect::text) return replace_text(first, fresh.size(), removed_breaks);
    RelayoutStats stats;
    // Page breaks change the print page of every page after them: no early stop then.
    bool breaks_touched = removed_breaks;
    // A table row is the header when the delimiter row follows it: the line
    // above the edit may have become one, or stopped being one.
    std::size_t count = fresh.size();
    if (first > 0 && starts_table_line(entries_[first - 1].line)) {
        --first;
        ++count;
    }
    if (first + count < entries_.size() && starts_table_line(entries_[first + count].line)) ++count;
    for (std::size_t i = first; i < first + count; ++i) {
        translate_entry(i);
        ++stats.lines_translated;
        const auto& b = entries_[i].block;
        breaks_touched = breaks_touched || (b && b->kind == document::BlockKind::print_page_break);
    }
    // A changed page break renumbers the unlabelled breaks after it, up to the next labelled one.
    for (std::size_t i = first + count; i < entries_.size(); ++i) {
        const auto& b = entries_[i].block;
        if (b && b->kind != document::BlockKind::print_page_break) continue;
        // A line without a block is blank, or a break before any text (it may start a page now).
        if (!b && entries_[i].line.find_first_not_of(" \t\r") == std::string::npos) continue;
        const auto own = parse_editor_line(entries_[i].line, dialect_);
        if (!own || own->kind != document::BlockKind::print_page_break) continue;
        if (own->label.empty()) {
            const auto before = b ? std::optional<std::string>(b->label) : std::nullopt;
            translate_entry(i);
            ++stats.lines_translated;
            const auto& now = entries_[i].block;
            breaks_touched = breaks_touched || (now ? std::optional<std::string>(now->label) : std::nullopt) != before;
            continue;
        }
        break;
    }
    if (row_place && count == 1 && kept_row_edit(first, *row_place, old_row)) {
        RelayoutStats in_place;
        in_place.lines_translated = stats.lines_translated;
        in_place.first_page_relaid = row_place->first;
        in_place.pages_relaid = 1;
        in_place.braille_first = first;
        in_place.braille_end = first + 1;
        return in_place;
    }
    auto layout = relayout_from(first, breaks_touched ? npos : first + count);
    layout.lines_translated = stats.lines_translated;
    layout.braille_first = first;
    layout.braille_end = first + count;
    return layout;
}

Result<void> LiveLayout::set_options(layout::LayoutOptions options) {
    if (auto ok = validate(options); !ok) return ok;
    requested_ = std::move(options);
    decide_ready_braille();
    // Braille lines wrap to the new width, and a word too long for the new line
    // is divided again (the division is made at translation).
    for (std::size_t i = 0; i < entries_.size(); ++i) translate_entry(i);
    paged_ = {};
    relayout_from(0);
    return {};
}

// Pages kept as they are have no margins and no page number lines of ours.
int LiveLayout::body_top(std::size_t page) const { return kept_ ? 0 : layout::body_top(options_, page); }

int LiveLayout::body_capacity(std::size_t page) const {
    return kept_ ? paged_.geometry.lines_per_page : layout::body_capacity(options_, page);
}

RelayoutStats LiveLayout::relayout_from(std::size_t first, std::size_t unchanged_from) {
    // Ready-made braille is kept page for page, as the CLI keeps it, while it fits.
    if (ready_braille_ && keep_pages()) {
        RelayoutStats stats;
        stats.pages_relaid = paged_.pages.size();
        return stats;
    }
    if (kept_) {
        // The entries hold kept pages' places, not the paginator's: lay everything out again.
        kept_ = false;
        first = 0;
        unchanged_from = npos;
        paged_ = {};
    }
    // Restart point: an entry before the edit that starts on a sheet front, moved
    // back to the first entry starting on that page so no page break lies between
    // the top of the page and the restart (the page's own print page then holds).
    std::size_t k = first == 0 || entries_.empty() ? 0 : std::min(first, entries_.size()) - 1;
    const auto sheet_front = [&](std::size_t p) {
        return !options_.geometry.interpoint || p % 2 == 0;
    };
    while (k > 0 && !sheet_front(entries_[k].pages_before)) --k;
    while (k > 0 && entries_[k - 1].pages_before == entries_[k].pages_before) --k;
    std::size_t base = k == 0 ? 0 : entries_[k].pages_before;
    if (k > 0 && (base > paged_.pages.size() ||
                  (base == paged_.pages.size() && entries_[k].lines_before > 0))) {
        k = 0;
        base = 0;
    }

    layout::LayoutOptions opts = options_;
    opts.first_page_number = options_.first_page_number + static_cast<int>(base);
    layout::Paginator pag(opts, [this](int n) { return number_cells(n); });
    if (k > 0) {
        // The print page in effect at the restart: the last page break's before
        // it (not the page's own: breaks after the restart at the page's top
        // may have set that, and an inserted line now comes before them).
        for (std::size_t j = k; j-- > 0;) {
            const auto& e = entries_[j];
            if (!e.block || e.error) continue;
            // A text line's further blocks come after its first (a form feed inside it).
            const translate::TranslatedBlock* last = nullptr;
            if (dialect_ == Dialect::text)
                for (auto c = e.translated_cells.rbegin(); c != e.translated_cells.rend() && !last; ++c)
                    if (c->kind == document::BlockKind::print_page_break) last = &*c;
            if (!last && e.block->kind == document::BlockKind::print_page_break) last = &e.translated;
            if (!last) continue;
            translate::TranslatedBlock mark;
            mark.kind = document::BlockKind::print_page_break;
            mark.label = last->label;
            pag.add(mark);  // empty body: sets the print page without drawing a separator
            break;
        }
    }
    if (k > 0 && base < paged_.pages.size()) {
        const layout::Page& top = paged_.pages[base];
        const auto lines = entries_[k].lines_before;
        if (lines > 0) {
            // The body lines already on the restart page, as the page holds them.
            translate::TranslatedBlock body;
            body.kind = document::BlockKind::braille;
            const auto row0 = static_cast<std::size_t>(body_top(base));
            const auto margin = static_cast<std::ptrdiff_t>(options_.left_margin);
            for (std::size_t r = row0; r < row0 + lines && r < top.lines.size(); ++r) {
                const auto& l = top.lines[r];
                body.lines.emplace_back(l.size() > static_cast<std::size_t>(margin) ? l.begin() + margin : l.end(),
                                        l.end());
            }
            pag.add(body);
        }
        // What came before the restart decides the blank line before it.
        pag.set_previous_kind(previous_kind(k));
    }
    // The box open at the restart goes on (its top line is on the pages kept).
    // Boxes are numbered 1 and 2 in turn: the paginator only tells a box from
    // the one before it.
    int box = k > 0 ? entries_[k].box_open_before : 0;
    int depth = k > 0 ? entries_[k].box_depth_before : 0;
    int laid = k > 0 ? entries_[k].box_laid_before : 0;
    if (laid != 0) pag.continue_box(laid);
    std::vector<layout::Page> old = std::move(paged_.pages);
    paged_.pages.clear();
    paged_.pages.reserve(old.size() + 8);
    for (std::size_t p = 0; p < base && p < old.size(); ++p) paged_.pages.push_back(std::move(old[p]));

    // Same page, same lines on it, same content: everything after is what it was.
    const auto same_state = [&](const Entry& e) {
        const auto page = base + pag.pages_closed();
        // The old layout was settled here too: a table it had open then is not in its lines.
        if (!e.settled_before || page != e.pages_before || pag.body_lines() != e.lines_before || page >= old.size())
            return false;
        // In the same box, or in none, as the last layout was here.
        if (e.box_open_before != box || e.box_depth_before != depth || e.box_laid_before != laid) return false;
        const auto& rows = old[page].lines;
        const auto row0 = static_cast<std::size_t>(body_top(page));
        const auto margin = static_cast<std::size_t>(options_.left_margin);
        for (std::size_t r = 0; r < pag.body().size(); ++r) {
            const auto& mine = pag.body()[r];
            const auto& theirs = rows[row0 + r];
            if (mine.empty() ? !theirs.empty()
                             : theirs.size() != mine.size() + margin ||
                                   !std::equal(mine.begin(), mine.end(), theirs.begin() + static_cast<std::ptrdiff_t>(margin)))
                return false;
        }
        return true;
    };

    RelayoutStats stats;
    stats.first_page_relaid = base;
    std::vector<std::string> warnings;
    std::size_t j = k;
    std::size_t table_end = 0, columns = 0;  // the table entry j is in (table_columns)
    for (; j < entries_.size(); ++j) {
        auto& e = entries_[j];
        if (j >= unchanged_from && pag.settled() && same_state(e)) {
            stats.converged = true;
            break;
        }
        e.pages_before = base + pag.pages_closed();
        e.lines_before = pag.body_lines();
        e.settled_before = pag.settled();
        e.box_open_before = box;
        e.box_depth_before = depth;
        e.box_laid_before = laid;
        // A box line opens or closes a box for the blocks after it (a box in a
        // box is part of it, as LiveLayout::document() reads them); a box
        // right after another gets the other number.
        if (const int step = box_line(e.line, dialect_); step != 0) {
            if (step > 0 && depth++ == 0) box = laid == 1 ? 2 : 1;
            if (step < 0 && depth > 0 && --depth == 0) box = 0;
            continue;
        }
        if (dialect_ == Dialect::markdown && starts_table_line(e.line) && j >= table_end) {
            table_end = j;
            while (table_end < entries_.size() && starts_table_line(entries_[table_end].line)) ++table_end;
            columns = table_columns(j);
        }
        if (e.block && !e.error) {
            const auto kind = e.block->kind;
            if (document::is_text_kind(kind) || kind == document::BlockKind::braille ||
                kind == document::BlockKind::table_row)
                laid = box;  // as Paginator::add enters a box
            e.translated.box = box;
            pag.add(e.translated);
            for (auto& cell : e.translated_cells) {
                cell.box = box;
                pag.add(cell);
            }
            if (e.block->kind == document::BlockKind::table_row)
                for (auto c = e.translated_cells.size(); c < columns; ++c) {
                    translate::TranslatedBlock empty;  // as document() pads the row
                    empty.kind = document::BlockKind::table_cell;
                    empty.level = static_cast<int>(c);
                    empty.box = box;
                    pag.add(empty);
                }
        }
    }
    if (stats.converged) {
        const auto resume = base + pag.pages_closed();
        const auto& tail = pag.closed();
        stats.pages_relaid = tail.pages.size();
        paged_.pages.insert(paged_.pages.end(), tail.pages.begin(), tail.pages.end());
        for (std::size_t p = resume; p < old.size(); ++p) paged_.pages.push_back(std::move(old[p]));
        warnings = tail.warnings;
    } else if (!(base > 0 && pag.pages_closed() == 0 && pag.body_lines() == 0 && pag.settled())) {
        // (A table still open in the paginator has lines to come: finish lays it out.)
        auto tail = std::move(pag).finish();
        stats.pages_relaid = tail.pages.size();
        for (auto& p : tail.pages) paged_.pages.push_back(std::move(p));
        warnings = std::move(tail.warnings);
    }
    paged_.geometry = options_.geometry;
    paged_.sections.clear();
    paged_.metadata = metadata_;  // a PEF's own, when it was opened from one
    if (base == 0) {
        paged_.warnings.clear();
        if (script_warning_) paged_.warnings.push_back(*script_warning_);
    }
    for (auto& w : warnings)
        if (std::ranges::find(paged_.warnings, w) == paged_.warnings.end())
            paged_.warnings.push_back(std::move(w));
    return stats;
}

document::BrailleLine LiveLayout::braille_of(std::size_t i) const {
    const auto& e = entries_[i];
    if (dialect_ == Dialect::text && !braille_text_line(e.line)) {
        // A text line shows its own part of its paragraph's braille (a
        // hard-wrapped paragraph is brailled as one), then the page numbers
        // and paragraphs it starts.
        document::BrailleLine out;
        const auto add = [&out](auto begin, auto end) {
            if (begin == end) return;
            if (!out.empty()) out.push_back(document::Cell{});
            out.insert(out.end(), begin, end);
        };
        const auto add_part = [&](std::size_t head) {
            const auto* tb = last_translated(head);
            const auto [b, en] = part_of(head, i);
            if (tb) add(tb->cells.begin() + static_cast<std::ptrdiff_t>(b), tb->cells.begin() + static_cast<std::ptrdiff_t>(en));
        };
        if (continues(i)) add_part(paragraph_head(i));
        if (!e.block || e.error) return out;
        const auto count = 1 + e.translated_cells.size();
        for (std::size_t k = 0; k < count; ++k) {
            const auto& tb = k == 0 ? e.translated : e.translated_cells[k - 1];
            if (tb.kind == document::BlockKind::print_page_break) add(tb.label.begin(), tb.label.end());
            else if (k + 1 == count) add_part(i);
            else add(tb.cells.begin(), tb.cells.end());
        }
        return out;
    }
    if (!e.block || e.error) return {};
    switch (e.translated.kind) {
        case document::BlockKind::braille: {
            // The line as written, before any wrapping (so columns match the print line).
            document::BrailleLine all;
            for (const auto& l : e.block->braille_lines) all.insert(all.end(), l.begin(), l.end());
            return all;
        }
        case document::BlockKind::print_page_break:
            return e.translated.label;
        case document::BlockKind::braille_page_break:
            return {};
        case document::BlockKind::table_row: {
            // The row's entries, two blank cells apart (editor_line_content spaces them so).
            document::BrailleLine all;
            for (const auto& cell : e.translated_cells) {
                if (!all.empty()) all.insert(all.end(), 2, document::Cell{});
                all.insert(all.end(), cell.cells.begin(), cell.cells.end());
            }
            return all;
        }
        default:
            return e.translated.cells;
    }
}

PagePosition LiveLayout::position_of(std::size_t i, std::size_t cell) const {
    PagePosition pos;
    if (entries_.empty()) return pos;
    i = std::min(i, entries_.size() - 1);
    if (continues(i)) {
        // A line of a hard-wrapped paragraph: its cells are on in the paragraph's braille.
        const auto head = paragraph_head(i);
        return position_of(head, entries_[head].cells.empty() ? part_of(head, i).first + cell : 0);
    }
    const auto& e = entries_[i];
    pos.page = e.pages_before;
    if (kept_) {
        // A row of a kept page: its own cells, where the page has it.
        pos.line = static_cast<int>(e.lines_before);
        pos.cell = static_cast<int>(cell);
        if (pos.page >= paged_.pages.size() && !paged_.pages.empty()) pos.page = paged_.pages.size() - 1;
        return pos;
    }
    int line = static_cast<int>(e.lines_before);
    int column = 0;
    const int width = options_.geometry.cells_per_line - options_.left_margin - options_.right_margin;
    const auto& tb = e.translated;
    if (e.block && !e.error && document::is_text_kind(tb.kind) && tb.kind != document::BlockKind::table_cell) {
        // The paginator's own indents (one rule, in core/layout).
        const auto indents = layout::block_indents(options_, tb.kind, tb.level);
        const int first = indents.first, runover = indents.runover;
        const bool centre = indents.centred;
        // The paginator's blank line before this block (one rule, in core/layout).
        const auto previous = previous_kind(i);
        // As the paginator adds it: never at a page top, and on a page's last
        // body line (or a full page) the page closes instead.
        if (layout::blank_line_before(options_, previous, tb.kind) && line > 0) {
            const int capacity = body_capacity(pos.page);
            line = line + 1 >= capacity ? std::max(line, capacity) : line + 1;
        }
        // Count the written cells before the target; blanks at line ends vanish when wrapping.
        cell = std::min(cell, tb.cells.size());
        std::size_t target = 0;
        for (std::size_t c = 0; c < cell; ++c) if (!tb.cells[c].blank()) ++target;
        const auto lines = layout::break_lines(tb.cells, tb.breaks, width, first, runover);
        std::size_t seen = 0;
        for (std::size_t l = 0; l < lines.size(); ++l) {
            int pad = 0;
            if (centre) {
                auto len = lines[l].size();
                while (len > 0 && lines[l][len - 1].blank()) --len;
                pad = std::max(0, (width - static_cast<int>(len)) / 2);
            }
            const auto& cells = lines[l];
            std::size_t c = 0;
            while (c < cells.size() && cells[c].blank()) ++c;
            bool found = false;
            for (; c < cells.size(); ++c) {
                if (cells[c].blank()) continue;
                if (seen == target) {
                    found = true;
                    break;
                }
                ++seen;
            }
            if (found || l + 1 == lines.size()) {
                line += static_cast<int>(l);
                column = pad + static_cast<int>(std::min(c, cells.size()));
                break;
            }
        }
    }
    while (line >= body_capacity(pos.page) && pos.page + 1 < paged_.pages.size()) {
        line -= body_capacity(pos.page);
        ++pos.page;
    }
    pos.line = body_top(pos.page) + line;
    pos.cell = options_.left_margin + column;
    if (pos.page >= paged_.pages.size() && !paged_.pages.empty()) pos.page = paged_.pages.size() - 1;
    return pos;
}

std::size_t LiveLayout::line_at(std::size_t page, int line) const {
    if (entries_.empty()) return 0;
    const auto row = static_cast<std::size_t>(std::max(0, line - body_top(page)));
    auto it = std::upper_bound(entries_.begin(), entries_.end(), std::pair{page, row},
                               [](const std::pair<std::size_t, std::size_t>& key, const Entry& e) {
                                   return key < std::pair{e.pages_before, e.lines_before};
                               });
    std::size_t i = it == entries_.begin() ? 0 : static_cast<std::size_t>(it - entries_.begin()) - 1;
    while (i > 0 && !entries_[i].block) --i;
    return i;
}

std::string LiveLayout::print_page_of(std::size_t page) const {
    if (entries_.empty()) return {};
    for (std::size_t i = line_at(page, 0) + 1; i-- > 0;) {
        const auto& b = entries_[i].block;
        if (b && b->kind == document::BlockKind::print_page_break &&
            (entries_[i].pages_before < page || (entries_[i].pages_before == page && entries_[i].lines_before == 0)))
            return b->label;
    }
    return std::string(document::first_print_page);
}

std::string LiveLayout::print_page_at(std::size_t line) const {
    if (entries_.empty()) return std::string(document::first_print_page);
    // The page breaks before the end of the line (a text line's further blocks too).
    bool started = false;
    const auto i = std::min(line, entries_.size() - 1);
    if (dialect_ == Dialect::text && entries_[i].block) {
        std::vector<document::Block> own{*entries_[i].block};
        own.insert(own.end(), entries_[i].cells.begin(), entries_[i].cells.end());
        return page_before(i, own, started);
    }
    return page_before(i + 1, {}, started);
}

}  // namespace tactus::edit
