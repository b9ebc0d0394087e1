// SPDX-License-Identifier: GPL-3.0-or-later
// LiveLayout's translation: the translator it is made with, each editor
// line's block translated on its own (Markdown lines), the tables changed, and
// braille read back to print.
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
#include "translate/language_switch.hpp"
#include "translate/script_check.hpp"
#include "common/try.hpp"

namespace tactus::edit {

using live_lines::starts_table_line;
using live_lines::braille_text_line;

Result<LiveLayout> LiveLayout::create(const std::string& tables, layout::LayoutOptions options) {
    TACTUS_TRY_VOID(validate(options));
    // As the pipeline does: passages in another language with their table,
    // so the editor shows the braille that is embossed.
    TACTUS_TRY(translator, translate::open_translator(tables, {}));
    LiveLayout l(std::move(translator), std::move(options));
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
    if (dialect_ == Dialect::text && !braille_text_line(e.line)) {
        translate_text_entry(i);
        return;
    }
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

Result<void> LiveLayout::set_tables(const std::string& tables) {
    // As the pipeline does: passages in another language with their table,
    // so the editor shows the braille that is embossed.
    TACTUS_TRY(translator, translate::open_translator(tables, {}));
    translator_ = std::move(translator);
    numbers_.clear();
    for (std::size_t i = 0; i < entries_.size(); ++i) translate_entry(i);
    paged_ = {};
    check_script();
    relayout_from(0);
    return {};
}

std::string LiveLayout::back_translate(const document::BrailleLine& cells) const {
    auto text = translator_.back_translate(cells);
    return text ? utf32_to_utf8(*text) : std::string{};
}

}  // namespace tactus::edit
