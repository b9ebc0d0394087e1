// SPDX-License-Identifier: GPL-3.0-or-later
// LiveLayout's state and file format: the lines it holds and their dialect,
// the document and braille structure they make, and what it reports. The
// translation, the relayout, the text dialect's paragraphs and the kept
// pages each have their own file (live_translation.cpp, live_relayout.cpp,
// live_text_paragraphs.cpp, live_kept_pages.cpp).
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
using live_lines::merge_mark;

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

bool LiveLayout::reset(const document::Document& document, const Progress& progress) {
    auto named = document;
    pictures_.clear();
    if (dialect_ == Dialect::markdown) store_pictures(named, pictures_);
    return reset(render_editor_lines(named, dialect_), progress, edit::braille_structure(named));
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
    // Boxes numbered 1, 2, 3 in order, as the importer numbers them; a box
    // line inside a box is part of it (DocumentBuilder::begin_box).
    int boxes = 0, box = 0, box_depth = 0;
    for (std::size_t i = 0; i < entries_.size();) {
        if (const int step = box_line(entries_[i].line, dialect_); step != 0) {
            if (step > 0 && box_depth++ == 0) box = ++boxes;
            if (step < 0 && box_depth > 0 && --box_depth == 0) box = 0;
            ++i;
            continue;
        }
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
            doc.blocks.back().box = box;
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
                doc.blocks.back().box = box;
                align(doc.blocks.back());
            }
            for (auto c = e.cells.size(); c < width; ++c) {
                document::Block empty;
                empty.kind = document::BlockKind::table_cell;
                empty.level = static_cast<int>(c);
                empty.source_line = line;
                empty.box = box;
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
    std::vector<std::string> missing;
    for (auto& b : doc.blocks)
        if (!b.images.empty()) fill_pictures(b, pictures_, missing);
    if (!missing.empty())
        doc.warnings.push_back(std::to_string(missing.size()) + " picture mark(s) name no picture this document holds (" +
                               missing.front() + "...): their descriptions stay");
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

std::size_t LiveLayout::error_count() const {
    return static_cast<std::size_t>(std::ranges::count_if(entries_, [](const Entry& e) { return e.error.has_value(); }));
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
