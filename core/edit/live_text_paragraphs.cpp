// SPDX-License-Identifier: GPL-3.0-or-later
// LiveLayout in the text dialect: paragraphs that run over several editor
// lines (import/text_lines.hpp, the rules text_import.cpp reads a file by),
// translated as one block, and an edit's reach over them.
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

using live_lines::braille_text_line;
using live_lines::first_piece;
using live_lines::last_piece;

// ---- the text dialect (import/text_lines.hpp, the rules text_import.cpp reads a file by) ----

bool LiveLayout::find_paragraph_breaks() const {
    import::ParagraphBreaks breaks;
    for (const auto& e : entries_)
        if (breaks.line(e.line)) return true;
    return false;
}

bool LiveLayout::continues(std::size_t i) const {
    if (dialect_ != Dialect::text || !runs_on_ || i == 0 || i >= entries_.size()) return false;
    const auto& line = entries_[i].line;
    const auto& above = entries_[i - 1].line;
    return !import::is_blank_text_line(first_piece(line)) && !import::is_blank_text_line(last_piece(above)) &&
           !braille_text_line(line) && !braille_text_line(above);
}

std::size_t LiveLayout::paragraph_head(std::size_t i) const {
    while (continues(i)) --i;
    return i;
}

std::vector<std::string_view> LiveLayout::paragraph_lines(std::size_t head) const {
    std::vector<std::string_view> lines{last_piece(entries_[head].line)};
    // A line ending in a form feed ends its paragraph there.
    for (std::size_t j = head + 1; j < entries_.size() && continues(j); ++j) {
        lines.push_back(first_piece(entries_[j].line));
        if (entries_[j].line.find('\f') != std::string::npos) break;
    }
    return lines;
}

std::string LiveLayout::page_before(std::size_t i, std::span<const document::Block> earlier, bool& started) const {
    started = false;
    const auto scan = [&started](const document::Block& b) -> std::optional<std::string> {
        if (b.kind == document::BlockKind::print_page_break) {
            started = true;
            return b.label;
        }
        if (b.kind != document::BlockKind::braille_page_break) started = true;
        return std::nullopt;
    };
    for (auto b = earlier.rbegin(); b != earlier.rend(); ++b)
        if (auto label = scan(*b)) return *label;
    for (std::size_t j = i; j-- > 0;) {
        const auto& e = entries_[j];
        if (!e.block) continue;
        if (dialect_ == Dialect::text)
            for (auto c = e.cells.rbegin(); c != e.cells.rend(); ++c)
                if (auto label = scan(*c)) return *label;
        if (auto label = scan(*e.block)) return *label;
    }
    return std::string(document::first_print_page);
}

void LiveLayout::translate_text_entry(std::size_t i) {
    auto& e = entries_[i];
    e.block.reset();
    e.error.reset();
    e.translated = translate::TranslatedBlock{};
    e.cells.clear();
    e.translated_cells.clear();
    // The blocks the line starts, as the importer reads them (TextReader):
    // a form feed ends the paragraph and starts a print page; a piece of text
    // starts a paragraph unless it continues the one above.
    std::vector<document::Block> blocks;
    std::string_view rest = e.line;
    for (bool first = true;; first = false) {
        const auto ff = rest.find('\f');
        const auto piece = rest.substr(0, ff);
        if (!import::is_blank_text_line(piece) && !(first && continues(i))) {
            document::Block p;
            if (ff == std::string_view::npos) {
                // The lines that continue it, a soft line break apart (document/soft_break.hpp).
                std::string text;
                for (const auto line : paragraph_lines(i)) {
                    if (line.data() != piece.data()) text += '\n';
                    text += line;
                }
                p.spans.push_back(document::Span{std::move(text)});
            } else {
                p.spans.push_back(document::Span{std::string(piece)});
            }
            blocks.push_back(std::move(p));
        }
        if (ff == std::string_view::npos) break;
        document::Block b;
        b.kind = document::BlockKind::print_page_break;
        blocks.push_back(std::move(b));
        rest.remove_prefix(ff + 1);
    }
    // Page breaks numbered by the importers' rule (document/print_page.hpp);
    // one before any text starts no page and is no block, as the importer drops it.
    std::vector<document::Block> kept;
    for (auto& b : blocks) {
        if (b.kind == document::BlockKind::print_page_break) {
            bool started = false;
            const auto current = page_before(i, kept, started);
            auto label = document::page_break_label({}, current, started);
            if (!label) continue;
            b.label = std::move(*label);
            b.label_counted = true;
        }
        kept.push_back(std::move(b));
    }
    if (kept.empty()) return;
    std::vector<translate::TranslatedBlock> translated;
    for (const auto& b : kept) {
        auto tb = translate::translate_block(b, translator_, layout::word_room(options_, b.kind, b.level));
        if (!tb) {
            e.error = located(tb.error(), "line " + std::to_string(i + 1));
            e.block = kept.front();
            return;
        }
        translated.push_back(std::move(*tb));
    }
    e.block = std::move(kept.front());
    e.translated = std::move(translated.front());
    for (std::size_t k = 1; k < kept.size(); ++k) {
        e.cells.push_back(std::move(kept[k]));
        e.translated_cells.push_back(std::move(translated[k]));
    }
}

const translate::TranslatedBlock* LiveLayout::last_translated(std::size_t head) const {
    const auto& e = entries_[head];
    if (!e.block || e.error) return nullptr;
    return e.translated_cells.empty() ? &e.translated : &e.translated_cells.back();
}

std::pair<std::size_t, std::size_t> LiveLayout::part_of(std::size_t head, std::size_t i) const {
    const auto* tb = last_translated(head);
    if (!tb || !document::is_text_kind(tb->kind)) return {0, 0};
    std::vector<std::u32string> lines;
    for (const auto line : paragraph_lines(head)) lines.push_back(utf8_to_utf32(line).value_or(std::u32string{}));
    const auto parts = braille_of_lines(lines, tb->cells);
    return i - head < parts.size() ? parts[i - head] : std::pair<std::size_t, std::size_t>{tb->cells.size(), tb->cells.size()};
}

RelayoutStats LiveLayout::replace_text(std::size_t first, std::size_t count, bool breaks_touched) {
    RelayoutStats stats;
    if (const bool runs_on = find_paragraph_breaks(); runs_on != runs_on_) {
        // A first blank line between paragraphs (or the last one gone): every line reads anew.
        runs_on_ = runs_on;
        for (std::size_t i = 0; i < entries_.size(); ++i) translate_entry(i);
        paged_ = {};
        stats = relayout_from(0);
        stats.lines_translated = entries_.size();
        stats.braille_end = entries_.size();
        return stats;
    }
    // The paragraph open above the edit may have run into it (or now does):
    // from its first line; and to the end of the paragraph the edit ends in,
    // with the line after it, which may have started a paragraph or continued one.
    const auto open_above = [this](std::size_t j) {
        const auto& line = entries_[j].line;
        if (!runs_on_ || braille_text_line(line) || import::is_blank_text_line(last_piece(line))) return j + 1;
        return line.find('\f') != std::string::npos ? j : paragraph_head(j);
    };
    const std::size_t from = first > 0 ? std::min(first, open_above(first - 1)) : first;
    std::size_t to = first + count;
    while (to < entries_.size() && continues(to)) ++to;
    if (runs_on_ && to < entries_.size() && !import::is_blank_text_line(first_piece(entries_[to].line))) ++to;
    stats.braille_first = from;
    stats.braille_end = to;
    while (stats.braille_end < entries_.size() && continues(stats.braille_end)) ++stats.braille_end;
    bool text_before = false;
    for (std::size_t i = from; i-- > 0 && !text_before;) text_before = entries_[i].block.has_value();
    for (std::size_t i = from; i < to; ++i) {
        translate_entry(i);
        ++stats.lines_translated;
        breaks_touched = breaks_touched || entries_[i].line.find('\f') != std::string::npos;
    }
    // Changed page breaks (or the first text) number the form feeds after them anew.
    if (breaks_touched || !text_before) {
        const auto labels = [](const Entry& e) {
            std::vector<std::string> out;
            if (e.block) out.push_back(e.block->label);
            for (const auto& c : e.cells) out.push_back(c.label);
            return out;
        };
        for (std::size_t i = to; i < entries_.size(); ++i) {
            if (entries_[i].line.find('\f') == std::string::npos) continue;
            const auto before = labels(entries_[i]);
            translate_entry(i);
            ++stats.lines_translated;
            if (labels(entries_[i]) == before) continue;
            breaks_touched = true;
            stats.braille_end = std::max(stats.braille_end, i + 1);
        }
    }
    auto layout = relayout_from(from, breaks_touched ? npos : to);
    layout.lines_translated = stats.lines_translated;
    layout.braille_first = stats.braille_first;
    layout.braille_end = stats.braille_end;
    return layout;
}

}  // namespace tactus::edit
