// SPDX-License-Identifier: GPL-3.0-or-later
#include "edit/live_layout.hpp"

#include <algorithm>

#include "common/utf8.hpp"
#include "document/print_page.hpp"
#include "edit/cursor_map.hpp"
#include "edit/editor_lines.hpp"
#include "export/text_export.hpp"
#include "import/text_lines.hpp"
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

// A line of Unicode braille cells (with spaces around it) is verbatim braille in both dialects.
bool braille_text_line(std::string_view line) {
    const auto from = line.find_first_not_of(" \t");
    if (from == std::string_view::npos) return false;
    return is_braille_line(line.substr(from, line.find_last_not_of(" \t") + 1 - from));
}

// A text line's pieces between form feeds: the first continues a paragraph, the last may start one.
std::string_view first_piece(std::string_view line) { return line.substr(0, line.find('\f')); }
std::string_view last_piece(std::string_view line) {
    const auto ff = line.rfind('\f');
    return ff == std::string_view::npos ? line : line.substr(ff + 1);
}

}  // namespace

BrailleStructure braille_structure(const document::Document& doc) {
    BrailleStructure s;
    s.grid = doc.braille_grid;
    s.metadata = doc.metadata;
    // The editor line each block starts on, as the Markdown writer writes a
    // ready-made braille document (exporter::markdown_lines): a braille block
    // a line a row (a page without rows one blank row), a page break a line.
    std::vector<std::size_t> line_of(doc.blocks.size() + 1, 0);
    std::size_t line = 0;
    for (std::size_t i = 0; i < doc.blocks.size(); ++i) {
        line_of[i] = line;
        const auto& b = doc.blocks[i];
        line += b.kind == document::BlockKind::braille ? std::max<std::size_t>(b.braille_lines.size(), 1) : 1;
    }
    line_of.back() = line;
    for (auto section : doc.braille_sections) {
        section.first_block = line_of[std::min(section.first_block, doc.blocks.size())];
        s.sections.push_back(section);
    }
    return s;
}

namespace {

// Two section marks meet on one line: the later one's section, a volume start if either had one.
void merge_mark(std::optional<document::BrailleSection>& onto, const document::BrailleSection& later) {
    const bool volume = (onto && onto->starts_volume) || later.starts_volume;
    onto = later;
    onto->starts_volume = volume;
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

bool LiveLayout::reset(const document::Document& document, const Progress& progress) {
    return reset(render_editor_lines(document, dialect_), progress, edit::braille_structure(document));
}

bool LiveLayout::reset(std::vector<std::string> lines, const Progress& progress, BrailleStructure structure) {
    entries_.clear();
    entries_.resize(lines.size());
    for (std::size_t i = 0; i < lines.size(); ++i) entries_[i].line = std::move(lines[i]);
    for (const auto& section : structure.sections)
        if (section.first_block < entries_.size()) merge_mark(entries_[section.first_block].section, section);
    braille_grid_ = std::move(structure.grid);
    metadata_ = std::move(structure.metadata);
    kept_ = false;
    runs_on_ = dialect_ == Dialect::text && find_paragraph_breaks();
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

void LiveLayout::set_dialect(Dialect dialect) {
    if (dialect == dialect_) return;
    dialect_ = dialect;
    runs_on_ = dialect_ == Dialect::text && find_paragraph_breaks();
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
    doc.encoding = encoding_;
    doc.byte_order_mark = byte_order_mark_;
    doc.blocks.reserve(entries_.size());
    doc.braille_grid = braille_grid_;
    doc.metadata = metadata_;
    std::optional<document::BrailleSection> mark;  // a section starts at the next block
    for (std::size_t i = 0; i < entries_.size();) {
        std::size_t end = i + 1;
        std::size_t width = 0;
        std::vector<document::Align> aligns;  // the columns', from the delimiter row
        if (dialect_ == Dialect::markdown && starts_table_line(entries_[i].line)) {
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
            if (e.section) merge_mark(mark, *e.section);
            if (!e.block) continue;
            const int line = static_cast<int>(i + 1);
            if (mark) {
                mark->first_block = doc.blocks.size();
                doc.braille_sections.push_back(*mark);
                mark.reset();
            }
            doc.blocks.push_back(*e.block);
            doc.blocks.back().source_line = line;
            if (dialect_ == Dialect::text) {
                // The further blocks a text line starts (after a form feed inside it).
                for (const auto& b : e.cells) {
                    doc.blocks.push_back(b);
                    doc.blocks.back().source_line = line;
                }
                continue;
            }
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
    // The lines above the first section's mark (typed in above it) are in it.
    if (!doc.braille_sections.empty()) {
        doc.braille_sections.front().first_block = 0;
        doc.braille_sections.front().starts_volume = true;
    }
    return doc;
}

BrailleStructure LiveLayout::braille_structure() const {
    BrailleStructure s;
    s.grid = braille_grid_;
    s.metadata = metadata_;
    for (std::size_t i = 0; i < entries_.size(); ++i)
        if (entries_[i].section) {
            s.sections.push_back(*entries_[i].section);
            s.sections.back().first_block = i;
        }
    return s;
}

bool LiveLayout::one_row(const Entry& e) {
    return e.block && !e.error && e.block->kind == document::BlockKind::braille && e.block->braille_lines.size() == 1;
}

bool LiveLayout::kept_row_edit(std::size_t i, std::pair<std::size_t, std::size_t> place,
                               const document::BrailleLine& old_row) {
    // Only when layout::keep_braille_pages would give the same pages with just
    // this row changed: a row still, no section mark, no change to the page's
    // grid (both rows within the file's cols and the printer's) or to 8-dot.
    // braille_structure_test's random edits compare it with keep_pages.
    auto& e = entries_[i];
    if (!one_row(e) || e.section || !braille_grid_) return false;
    const auto& row = e.block->braille_lines.front();
    // The file's cols for this row: its section's (the nearest mark above it;
    // the first section's above the first mark), else the file's grid.
    int file_cols = braille_grid_->cols;
    std::size_t m = i;
    while (m > 0 && !entries_[m].section) --m;
    if (entries_[m].section) {
        file_cols = entries_[m].section->cols;
    } else {
        for (const auto& later : entries_)
            if (later.section) {
                file_cols = later.section->cols;
                break;
            }
    }
    const auto cols = static_cast<std::size_t>(std::min(file_cols, requested_.geometry.cells_per_line));
    const auto eight = [](const document::BrailleLine& r) {
        return std::ranges::any_of(r, [](document::Cell c) { return (c.dots & 0xC0) != 0; });
    };
    if (row.size() > cols || old_row.size() > cols ||
        (!requested_.geometry.eight_dot && (eight(row) || eight(old_row))))
        return false;
    if (place.first >= paged_.pages.size() || place.second >= paged_.pages[place.first].lines.size()) return false;
    paged_.pages[place.first].lines[place.second] = row;
    e.pages_before = place.first;
    e.lines_before = place.second;
    e.settled_before = true;
    return true;
}

bool LiveLayout::keep_pages() {
    auto doc = document();
    if (!layout::is_ready_braille(doc)) return false;
    std::vector<layout::BlockPlace> places;
    // Refused when a page does not fit (layout::check_braille_fits): laid out again then.
    auto kept = layout::keep_braille_pages(doc, requested_, &places);
    if (!kept) return false;
    paged_ = std::move(*kept);
    if (script_warning_) paged_.warnings.push_back(*script_warning_);
    // Each line where its block landed; a line without one where the next block did.
    const layout::BlockPlace end =
        paged_.pages.empty() ? layout::BlockPlace{} : layout::BlockPlace{paged_.pages.size() - 1, 0};
    std::size_t b = 0;
    for (std::size_t i = 0; i < entries_.size(); ++i) {
        while (b < doc.blocks.size() && doc.blocks[b].source_line < static_cast<int>(i + 1)) ++b;
        const auto place = b < places.size() ? places[b] : end;
        entries_[i].pages_before = place.page;
        entries_[i].lines_before = static_cast<std::size_t>(place.row);
        entries_[i].settled_before = true;
    }
    kept_ = true;
    return true;
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
        if (dialect_ == Dialect::markdown && starts_table_line(e.line) && j >= table_end) {
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

std::size_t LiveLayout::error_count() const {
    return static_cast<std::size_t>(std::ranges::count_if(entries_, [](const Entry& e) { return e.error.has_value(); }));
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

std::string LiveLayout::back_translate(const document::BrailleLine& cells) const {
    auto text = translator_.back_translate(cells);
    return text ? utf32_to_utf8(*text) : std::string{};
}

std::optional<document::BlockKind> LiveLayout::previous_kind(std::size_t index) const {
    for (std::size_t j = index; j-- > 0;) {
        const auto& p = entries_[j];
        if (!p.block || p.error) continue;
        if (dialect_ == Dialect::text)  // the further blocks a text line starts, last first
            for (auto c = p.cells.rbegin(); c != p.cells.rend(); ++c)
                if (layout::sets_previous_kind(c->kind)) return c->kind;
        if (!layout::sets_previous_kind(p.block->kind)) continue;
        return p.block->kind;
    }
    return std::nullopt;
}

}  // namespace tactus::edit
