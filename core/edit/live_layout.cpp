// SPDX-License-Identifier: GPL-3.0-or-later
#include "edit/live_layout.hpp"

#include <algorithm>

#include "common/utf8.hpp"
#include "document/print_page.hpp"
#include "edit/editor_lines.hpp"
#include "export/text_export.hpp"
#include "layout/line_breaker.hpp"
#include "layout/braille_pages.hpp"
#include "layout/paginator.hpp"
#include "translate/script_check.hpp"

namespace tactus::edit {
namespace {

// A line of a Markdown table (a row or the delimiter row).
bool starts_table_line(std::string_view line) {
    const auto t = line.find_first_not_of(" \t");
    return t != std::string_view::npos && line[t] == '|';
}

}  // namespace

Result<LiveLayout> LiveLayout::create(const std::string& tables, layout::LayoutOptions options) {
    if (auto ok = validate(options); !ok) return std::unexpected(ok.error());
    auto translator = translate::Translator::open(tables);
    if (!translator) return std::unexpected(translator.error());
    LiveLayout l(std::move(*translator), std::move(options));
    l.relayout_from(0);
    return l;
}

document::BrailleLine LiveLayout::number_cells(int n) {
    if (auto it = numbers_.find(n); it != numbers_.end()) return it->second;
    const auto digits = std::to_string(n);
    auto cells = translator_.translate(std::u32string(digits.begin(), digits.end()));
    return numbers_.emplace(n, cells ? std::move(*cells) : document::BrailleLine{}).first->second;
}

void LiveLayout::translate_entry(std::size_t i) {
    auto& e = entries_[i];
    e.block = parse_editor_line(e.line, dialect_);
    e.error.reset();
    e.translated = translate::TranslatedBlock{};
    e.cells.clear();
    e.translated_cells.clear();
    if (!e.block) return;
    if (e.block->kind == document::BlockKind::table_row) {
        // The header row is a table's first row with the delimiter row under it;
        // an empty one stands for no header (as the Markdown importer reads it).
        const bool first_row = i == 0 || !starts_table_line(entries_[i - 1].line);
        const bool header = first_row && i + 1 < entries_.size() && is_table_delimiter(entries_[i + 1].line);
        e.cells = parse_table_cells(e.line);
        if (header && std::ranges::all_of(e.cells, [](const document::Block& c) {
                return c.text().find_first_not_of(" \t") == std::string::npos;
            })) {
            e.block.reset();
            e.cells.clear();
            return;
        }
        e.block->level = header ? 1 : 0;
        for (const auto& cell : e.cells) {
            auto tc = translate::translate_block(cell, translator_,
                                                 layout::word_room(options_, cell.kind, cell.level));
            if (!tc) {
                e.error = located(tc.error(), "line " + std::to_string(i + 1));
                e.translated_cells.clear();
                return;
            }
            e.translated_cells.push_back(std::move(*tc));
        }
    }
    if (e.block->kind == document::BlockKind::print_page_break && e.block->label.empty()) {
        // "---" continues from the print page in effect above it, by the rule
        // the importers follow (document/print_page.hpp): the first is page 2.
        // Before any text (and any labelled break) it starts no page: the
        // importer drops it, and so it is no block here either.
        std::string current(document::first_print_page);
        bool started = false;
        for (std::size_t j = i; j-- > 0;) {
            const auto& b = entries_[j].block;
            if (!b) continue;
            if (b->kind == document::BlockKind::print_page_break) {
                current = b->label;
                started = true;
                break;
            }
            if (b->kind != document::BlockKind::braille_page_break) started = true;
        }
        auto label = document::page_break_label({}, current, started);
        if (!label) {
            e.block.reset();
            return;
        }
        e.block->label = std::move(*label);
        e.block->label_counted = true;
    }
    auto tb = translate::translate_block(*e.block, translator_,
                              layout::word_room(options_, e.block->kind, e.block->level));
    if (!tb) {
        e.error = located(tb.error(), "line " + std::to_string(i + 1));
        return;
    }
    e.translated = std::move(*tb);
    // A braille line longer than a page line is a paragraph typed or edited as
    // braille: wrap it at word spaces instead of cutting it.
    const int width = options_.geometry.cells_per_line - options_.left_margin - options_.right_margin;
    if (e.translated.kind == document::BlockKind::braille && e.translated.lines.size() == 1 &&
        e.translated.lines.front().size() > static_cast<std::size_t>(width))
        e.translated.lines = layout::break_lines(e.translated.lines.front(), width, 0, 0);
}

bool LiveLayout::reset(std::vector<std::string> lines, const Progress& progress) {
    entries_.clear();
    entries_.resize(lines.size());
    for (std::size_t i = 0; i < lines.size(); ++i) entries_[i].line = std::move(lines[i]);
    for (std::size_t i = 0; i < entries_.size(); ++i) {
        translate_entry(i);
        if (progress && i % 256 == 0 && progress(i, entries_.size())) return false;
    }
    paged_ = {};
    check_script();
    decide_ready_braille();
    relayout_from(0);
    if (progress) progress(entries_.size(), entries_.size());
    return true;
}

void LiveLayout::decide_ready_braille() {
    ready_braille_ = layout::is_ready_braille(document());
    options_ = requested_;
    if (ready_braille_) {
        options_.page_numbers = layout::PageNumberPosition::none;
        options_.print_page_indicators = false;
    }
}

void LiveLayout::check_script() { script_warning_ = translate::check_script(document(), translator_.tables()); }

RelayoutStats LiveLayout::replace(std::size_t first, std::size_t removed,
                                  std::vector<std::string> lines) {
    first = std::min(first, entries_.size());
    removed = std::min(removed, entries_.size() - first);
    const auto at = entries_.begin() + static_cast<std::ptrdiff_t>(first);
    const bool removed_breaks = std::any_of(at, at + static_cast<std::ptrdiff_t>(removed), [](const Entry& e) {
        return e.block && e.block->kind == document::BlockKind::print_page_break;
    });
    entries_.erase(at, at + static_cast<std::ptrdiff_t>(removed));
    std::vector<Entry> fresh(lines.size());
    for (std::size_t i = 0; i < lines.size(); ++i) fresh[i].line = std::move(lines[i]);
    entries_.insert(entries_.begin() + static_cast<std::ptrdiff_t>(first),
                    std::make_move_iterator(fresh.begin()), std::make_move_iterator(fresh.end()));
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
    auto layout = relayout_from(first, breaks_touched ? npos : first + count);
    layout.lines_translated = stats.lines_translated;
    return layout;
}

void LiveLayout::set_dialect(Dialect dialect) {
    if (dialect == dialect_) return;
    dialect_ = dialect;
    for (std::size_t i = 0; i < entries_.size(); ++i) translate_entry(i);
    paged_ = {};
    relayout_from(0);
}

std::size_t LiveLayout::table_columns(std::size_t index) const {
    auto first = index, end = index;
    while (first > 0 && starts_table_line(entries_[first - 1].line)) --first;
    while (end < entries_.size() && starts_table_line(entries_[end].line)) ++end;
    std::vector<std::string> lines;
    lines.reserve(end - first);
    for (auto i = first; i < end; ++i) lines.push_back(entries_[i].line);
    return exporter::markdown_table_width(lines);
}

document::Document LiveLayout::document() const {
    // As the importer reads the saved file: page breaks after all text are
    // kept (DocumentBuilder::finish: <!-- braillepage --> is written out, not
    // implied); an unlabelled print page break before any text is no block
    // here already.
    // A table (a run of table lines) has as many columns as its widest row, as
    // a Markdown table as many as its header: shorter rows get empty entries at
    // the end, which lay out as the missing ones did.
    document::Document doc;
    for (std::size_t i = 0; i < entries_.size();) {
        std::size_t end = i + 1;
        std::size_t width = 0;
        std::vector<document::Align> aligns;  // the columns', from the delimiter row
        if (starts_table_line(entries_[i].line)) {
            width = table_columns(i);
            end = i;
            while (end < entries_.size() && starts_table_line(entries_[end].line)) ++end;
            for (auto d = i; d < end && aligns.empty(); ++d)
                if (is_table_delimiter(entries_[d].line)) aligns = exporter::markdown_table_alignments(entries_[d].line);
        }
        const auto align = [&aligns](document::Block& cell) {
            const auto c = static_cast<std::size_t>(std::max(cell.level, 0));
            if (c < aligns.size()) cell.align = aligns[c];
        };
        for (; i < end; ++i) {
            const auto& e = entries_[i];
            if (!e.block) continue;
            const int line = static_cast<int>(i + 1);
            doc.blocks.push_back(*e.block);
            doc.blocks.back().source_line = line;
            if (e.block->kind != document::BlockKind::table_row) continue;
            for (const auto& cell : e.cells) {
                doc.blocks.push_back(cell);
                doc.blocks.back().source_line = line;
                align(doc.blocks.back());
            }
            for (auto c = e.cells.size(); c < width; ++c) {
                document::Block empty;
                empty.kind = document::BlockKind::table_cell;
                empty.level = static_cast<int>(c);
                empty.source_line = line;
                align(empty);
                doc.blocks.push_back(std::move(empty));
            }
        }
    }
    return doc;
}

Result<void> LiveLayout::set_tables(const std::string& tables) {
    auto translator = translate::Translator::open(tables);
    if (!translator) return std::unexpected(translator.error());
    translator_ = std::move(*translator);
    numbers_.clear();
    for (std::size_t i = 0; i < entries_.size(); ++i) translate_entry(i);
    paged_ = {};
    check_script();
    relayout_from(0);
    return {};
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

int LiveLayout::body_top(std::size_t page) const { return layout::body_top(options_, page); }

int LiveLayout::body_capacity(std::size_t page) const { return layout::body_capacity(options_, page); }

RelayoutStats LiveLayout::relayout_from(std::size_t first, std::size_t unchanged_from) {
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
            if (!e.block || e.error || e.block->kind != document::BlockKind::print_page_break) continue;
            translate::TranslatedBlock mark;
            mark.kind = document::BlockKind::print_page_break;
            mark.label = e.translated.label;
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
        if (starts_table_line(e.line) && j >= table_end) {
            table_end = j;
            while (table_end < entries_.size() && starts_table_line(entries_[table_end].line)) ++table_end;
            columns = table_columns(j);
        }
        if (e.block && !e.error) {
            pag.add(e.translated);
            for (const auto& cell : e.translated_cells) pag.add(cell);
            if (e.block->kind == document::BlockKind::table_row)
                for (auto c = e.translated_cells.size(); c < columns; ++c) {
                    translate::TranslatedBlock empty;  // as document() pads the row
                    empty.kind = document::BlockKind::table_cell;
                    empty.level = static_cast<int>(c);
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

std::size_t LiveLayout::error_count() const {
    return static_cast<std::size_t>(std::ranges::count_if(entries_, [](const Entry& e) { return e.error.has_value(); }));
}

PagePosition LiveLayout::position_of(std::size_t i, std::size_t cell) const {
    PagePosition pos;
    if (entries_.empty()) return pos;
    i = std::min(i, entries_.size() - 1);
    const auto& e = entries_[i];
    pos.page = e.pages_before;
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
    for (std::size_t i = std::min(line + 1, entries_.size()); i-- > 0;) {
        const auto& b = entries_[i].block;
        if (b && b->kind == document::BlockKind::print_page_break) return b->label;
    }
    return std::string(document::first_print_page);
}

std::string LiveLayout::back_translate(const document::BrailleLine& cells) const {
    auto text = translator_.back_translate(cells);
    return text ? utf32_to_utf8(*text) : std::string{};
}

std::optional<document::BlockKind> LiveLayout::previous_kind(std::size_t index) const {
    for (std::size_t j = index; j-- > 0;) {
        const auto& p = entries_[j];
        if (!p.block || p.error || !layout::sets_previous_kind(p.block->kind)) continue;
        return p.block->kind;
    }
    return std::nullopt;
}

}  // namespace tactus::edit
