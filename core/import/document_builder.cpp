// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/document_builder.hpp"

#include <algorithm>
#include <utility>

#include "document/print_page.hpp"

namespace tactus::import::detail {
namespace {

bool is_page_break(const document::Block& b) {
    return b.kind == document::BlockKind::print_page_break || b.kind == document::BlockKind::braille_page_break;
}

bool visible(std::string_view text) {
    return std::any_of(text.begin(), text.end(), [](char c) {
        return c != ' ' && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v';
    });
}

}  // namespace

void DocumentBuilder::begin(document::BlockKind kind, int level, int source_line) {
    if (in_note_) {
        // A note is one block: its paragraphs run on, a space apart.
        add_text(" ");
        return;
    }
    end();
    current_ = document::Block{};
    current_.kind = kind;
    current_.level = level;
    current_.source_line = source_line;
    open_ = true;
}

void DocumentBuilder::note_line(int source_line) {
    if (open_ && current_.source_line == 0) current_.source_line = source_line;
}

void DocumentBuilder::trim_end() {
    if (!open_ || current_.spans.empty() || current_.spans.back().note_reference ||
        current_.spans.back().transcriber_note)
        return;
    auto& t = current_.spans.back().text;
    t.erase(std::min(t.size(), t.find_last_not_of(" \t\v") + 1));
    if (t.empty()) current_.spans.pop_back();
}

void DocumentBuilder::add_transcriber_note(std::string_view utf8) {
    if (utf8.empty()) return;
    if (!open_) begin(document::BlockKind::paragraph, 0, 0);
    document::Span span;
    span.text = std::string(utf8);
    span.transcriber_note = true;
    current_.spans.push_back(std::move(span));
}

void DocumentBuilder::add_image(document::Image image) {
    if (!open_) begin(document::BlockKind::paragraph, 0, 0);
    current_.images.push_back(std::move(image));
}

void DocumentBuilder::begin_box() {
    if (box_depth_++ > 0) return;
    end();
    box_ = ++boxes_;
}

void DocumentBuilder::end_box() {
    if (box_depth_ == 0 || --box_depth_ > 0) return;
    end();
    box_ = 0;
}

void DocumentBuilder::add_text(std::string_view utf8, std::uint8_t emphasis, document::Position position,
                               std::string_view language) {
    if (utf8.empty()) return;
    if (!open_) begin(document::BlockKind::paragraph, 0, 0);
    auto& spans = current_.spans;
    if (in_note_ && !spans.empty() && spans.back().text.ends_with(' ')) {
        // A note's paragraphs run on a space apart: one space at each join.
        const auto text = utf8.find_first_not_of(' ');
        if (text == std::string_view::npos) return;
        utf8.remove_prefix(text);
    }
    if (!spans.empty() && spans.back().emphasis == emphasis && spans.back().position == position &&
        !spans.back().note_reference && !spans.back().transcriber_note && spans.back().language == language)
        spans.back().text.append(utf8);
    else
        spans.push_back(document::Span{std::string(utf8), emphasis, false, position, false, std::string(language)});
}

void DocumentBuilder::end() {
    if (!open_ || in_note_) return;  // end_note() ends a note
    open_ = false;
    const bool keep = current_.kind == document::BlockKind::table_cell || !current_.images.empty() ||
                      std::any_of(current_.spans.begin(), current_.spans.end(),
                                  [](const document::Span& s) { return visible(s.text); });
    if (keep) push(std::move(current_));
    current_ = document::Block{};
    if (!in_table_) flush_notes();
}

void DocumentBuilder::note_reference(std::string label) {
    if (!open_) begin(document::BlockKind::paragraph, 0, 0);
    document::Span span;
    span.text = std::move(label);
    span.note_reference = true;
    current_.spans.push_back(std::move(span));
}

void DocumentBuilder::begin_note(std::string label, int source_line) {
    if (in_note_) end_note();  // notes do not nest: a note in a note follows it
    set_aside_ = std::move(current_);
    set_aside_open_ = open_;
    current_ = document::Block{};
    current_.kind = document::BlockKind::note;
    current_.source_line = source_line;
    document::Span reference;
    reference.text = std::move(label);
    reference.note_reference = true;
    current_.spans.push_back(std::move(reference));
    current_.spans.push_back(document::Span{" "});
    open_ = true;
    in_note_ = true;
}

void DocumentBuilder::end_note() {
    if (!in_note_) return;
    // Spaces at the end (a paragraph break inside the note) say nothing.
    while (!current_.spans.empty() && !current_.spans.back().note_reference) {
        auto& t = current_.spans.back().text;
        while (!t.empty() && (t.back() == ' ' || t.back() == '\n')) t.pop_back();
        if (!t.empty()) break;
        current_.spans.pop_back();
    }
    notes_.push_back(std::move(current_));
    in_note_ = false;
    current_ = std::move(set_aside_);
    open_ = set_aside_open_;
    set_aside_ = document::Block{};
    set_aside_open_ = false;
    if (!open_ && !in_table_) flush_notes();
}

void DocumentBuilder::table_row(bool header, int source_line) {
    end();
    in_table_ = true;
    document::Block b;
    b.kind = document::BlockKind::table_row;
    b.level = header ? 1 : 0;
    b.source_line = source_line;
    push(std::move(b));
}

void DocumentBuilder::begin_cell(int column, int source_line, int span, document::Align align) {
    begin(document::BlockKind::table_cell, column, source_line);
    if (open_ && current_.kind == document::BlockKind::table_cell) {
        current_.span = std::max(1, span);
        current_.align = align;
    }
}

void DocumentBuilder::end_table() {
    end();
    in_table_ = false;
    flush_notes();
}

void DocumentBuilder::drop_empty_row() {
    end();
    auto row = blocks_.size();
    while (row > 0 && blocks_[row - 1].kind == document::BlockKind::table_cell) --row;
    if (row == 0 || blocks_[row - 1].kind != document::BlockKind::table_row) return;
    const bool empty = std::all_of(blocks_.begin() + static_cast<std::ptrdiff_t>(row), blocks_.end(),
                                   [](const document::Block& cell) { return !visible(cell.text()); });
    if (!empty) return;
    blocks_.erase(blocks_.begin() + static_cast<std::ptrdiff_t>(row - 1), blocks_.end());
    // The row may have been all there was: then nothing is printed yet.
    has_content_ = std::any_of(blocks_.rbegin(), blocks_.rend(), [](const document::Block& b) { return !is_page_break(b); });
}

void DocumentBuilder::flush_notes() {
    for (auto& n : notes_) push(std::move(n));
    notes_.clear();
}

void DocumentBuilder::print_page_break(int source_line, std::string label) {
    end();
    // One numbering rule for importers, the editor and its layout
    // (document/print_page.hpp): nothing printed yet, an unlabelled break
    // starts no page, while a label says where the print pages start.
    auto own = document::page_break_label(label, print_page_, has_content_ || print_pages_started_);
    if (!own) return;
    print_page_ = std::move(*own);
    print_pages_started_ = true;
    document::Block b;
    b.kind = document::BlockKind::print_page_break;
    b.label = print_page_;
    b.label_counted = label.empty();
    b.source_line = source_line;
    push(std::move(b));
}

void DocumentBuilder::braille_page_break(int source_line, BrailleBreak kind) {
    end();
    if (!has_content_ && kind == BrailleBreak::implied) return;
    document::Block b;
    b.kind = document::BlockKind::braille_page_break;
    b.source_line = source_line;
    push(std::move(b));
    if (kind == BrailleBreak::written && !full()) written_breaks_.push_back(blocks_.size() - 1);
}

void DocumentBuilder::braille_block(std::vector<document::BrailleLine> lines, int source_line) {
    end();
    document::Block b;
    b.kind = document::BlockKind::braille;
    b.braille_lines = std::move(lines);
    b.source_line = source_line;
    push(std::move(b));
}

void DocumentBuilder::push(document::Block block) {
    if (full()) return;
    if (blocks_.size() >= max_import_blocks) {
        overflow_line_ = block.source_line;
        blocks_ = {};  // give the memory back now; the import has failed
        return;
    }
    if (box_ != 0 && block.box == 0) block.box = box_;
    if (!is_page_break(block)) has_content_ = true;
    blocks_.push_back(std::move(block));
}

Result<document::Document> DocumentBuilder::finish() {
    end_note();
    end_table();
    if (full())
        return fail(ErrorKind::input, "more than " + std::to_string(max_import_blocks) +
                        " blocks (paragraphs, pages); split the document",
                    overflow_line_ > 0 ? std::to_string(overflow_line_) : std::string{});
    // A print page break after all text is kept: saving and opening again must
    // not lose it, and it adds nothing to the braille (the paginator
    // draws no separator line for it). An implied braille page break after all
    // text breaks nothing (every BRF page ends with one) and is dropped; one
    // the source writes out (Markdown's <!-- braillepage -->) is kept, as a
    // print page break is (it adds no page: Paginator::break_page).
    while (!blocks_.empty() && blocks_.back().kind == document::BlockKind::braille_page_break &&
           !std::ranges::binary_search(written_breaks_, blocks_.size() - 1))
        blocks_.pop_back();
    document::Document doc;
    doc.blocks = std::move(blocks_);
    doc.warnings = std::move(warnings_);
    blocks_ = {};
    return doc;
}

}  // namespace tactus::import::detail
