// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/office_package.hpp"

#include <algorithm>

#include "import/import.hpp"
#include "import/xml_util.hpp"
#include "common/try.hpp"

namespace tactus::import::detail {
namespace {

// Columns a table may have (LibreOffice's limit; Word's is 63): a span or
// skip in a hostile file cannot make the layout fill millions of empty cells.
constexpr int kMaxColumns = 1024;

}  // namespace

Result<XmlPackage> XmlPackage::open(std::string_view bytes, std::string kind) {
    TACTUS_TRY(zip, ZipArchive::open(bytes));
    return XmlPackage(std::move(zip), std::move(kind));
}

Result<bool> XmlPackage::load(const std::string& part, XmlPart& out, bool required) const {
    if (!zip_.contains(part)) {
        if (required) return fail(ErrorKind::input, "not " + kind_ + ": missing part " + part, part);
        return false;
    }
    TACTUS_TRY(bytes, zip_.read(part, max_import_bytes));
    out.bytes = std::move(bytes);
    TACTUS_TRY_VOID(parse_xml(out.xml, out.bytes, part));
    return true;
}

void OfficeText::begin_paragraph(document::BlockKind kind, int level, std::string label) {
    label_ = std::move(label);
    if (!label_.empty()) label_ += ' ';
    if (note_depth_ > 0) {
        builder_.add_text(" ");  // a note's paragraphs run on
        return;
    }
    if (table_depth_ > 0) {
        // A cell's paragraphs stay apart: a line break between them.
        if (cell_has_text_) builder_.add_text("\n");
        return;
    }
    kind_ = kind;
    level_ = level;
    builder_.begin(kind_, level_, 0);
}

void OfficeText::text(std::string_view s, std::uint8_t emphasis, document::Position position,
                      std::string_view language) {
    if (s.empty()) return;
    if (!builder_.is_open() && note_depth_ == 0 && table_depth_ == 0) builder_.begin(kind_, level_, 0);
    if (!label_.empty()) {
        builder_.add_text(label_);
        label_.clear();
    }
    builder_.add_text(s, emphasis, position, language);
    cell_has_text_ = true;
}

void OfficeText::transcriber_note(std::string_view s) {
    if (s.find_first_not_of(" \t\n") == std::string_view::npos) return;
    if (!builder_.is_open() && note_depth_ == 0 && table_depth_ == 0) builder_.begin(kind_, level_, 0);
    if (!label_.empty()) {
        builder_.add_text(label_);
        label_.clear();
    }
    builder_.add_transcriber_note(s);
    cell_has_text_ = true;
}

void OfficeText::begin_box() {
    if (note_depth_ > 0 || table_depth_ > 0) {
        if (cell_has_text_) builder_.add_text(note_depth_ > 0 ? " " : "\n");
        return;
    }
    builder_.begin_box();
}

void OfficeText::end_box() {
    if (note_depth_ > 0 || table_depth_ > 0) return;
    builder_.end_box();
}

void OfficeText::picture_without_description(std::string where) {
    if (undescribed_pictures_++ == 0) first_undescribed_ = std::move(where);
}

void OfficeText::image(document::Image image, bool described, std::string where) {
    if (!builder_.is_open() && note_depth_ == 0 && table_depth_ == 0) builder_.begin(kind_, level_, 0);
    if (!described && uncaptioned_pictures_++ == 0) first_uncaptioned_ = std::move(where);
    builder_.add_image(std::move(image));
}

Result<document::Document> OfficeText::finish() {
    if (uncaptioned_pictures_ > 0)
        builder_.warn(std::to_string(uncaptioned_pictures_) +
                      (uncaptioned_pictures_ == 1 ? " picture has" : " pictures have") +
                      " no description (alt text): a graphic without a caption; the first is at " +
                      first_uncaptioned_);
    if (undescribed_pictures_ > 0)
        builder_.warn(std::to_string(undescribed_pictures_) +
                      (undescribed_pictures_ == 1 ? " picture has" : " pictures have") +
                      " no description (alt text) and " + (undescribed_pictures_ == 1 ? "is" : "are") +
                      " left out; the first is at " + first_undescribed_);
    return builder_.finish();
}

void OfficeText::end_paragraph() {
    label_.clear();
    if (note_depth_ > 0 || table_depth_ > 0) return;
    builder_.end();
    flush_page_break();
}

// A break inside a table cell or a note waits for the end of the table or of
// the paragraph holding the note: the print page is counted, the structure
// stays whole.
void OfficeText::page_break() {
    if (note_depth_ > 0 || table_depth_ > 0) {
        ++pending_breaks_;
        return;
    }
    builder_.print_page_break(0);
}

void OfficeText::page_break_inside() {
    if (note_depth_ > 0 || table_depth_ > 0) {
        ++pending_breaks_;
        return;
    }
    builder_.print_page_break(0);
    builder_.begin(kind_, level_, 0);
}

void OfficeText::flush_page_break() {
    for (; pending_breaks_ > 0; --pending_breaks_) builder_.print_page_break(0);
}

void OfficeText::begin_table() {
    if (note_depth_ > 0) return;
    if (table_depth_++ > 0) return;  // a table in a cell is the cell's text
    builder_.end();
}

void OfficeText::begin_row(bool header) {
    if (note_depth_ > 0 || table_depth_ != 1) return;
    builder_.table_row(header, 0);
    column_ = 0;
}

void OfficeText::begin_cell(int span, document::Align align) {
    if (note_depth_ > 0 || table_depth_ != 1) {
        if (cell_has_text_) builder_.add_text(" ");
        return;
    }
    column_ = std::min(column_, kMaxColumns - 1);
    span = std::clamp(span, 1, kMaxColumns - column_);
    builder_.begin_cell(column_, 0, span, align);
    column_ += span;
    cell_has_text_ = false;
}

void OfficeText::skip_columns(int count) {
    if (note_depth_ > 0 || table_depth_ != 1) return;
    column_ = std::min(column_ + std::clamp(count, 0, kMaxColumns), kMaxColumns);
}

void OfficeText::end_cell() {
    if (note_depth_ > 0 || table_depth_ != 1) return;
    builder_.end();
}

void OfficeText::end_table() {
    if (note_depth_ > 0 || table_depth_ == 0) return;
    if (--table_depth_ > 0) return;
    builder_.end_table();
    flush_page_break();
}

void OfficeText::begin_note(int source_line) {
    if (note_depth_++ > 0) return;  // a note in a note: its text runs on
    if (!builder_.is_open() && table_depth_ == 0) builder_.begin(kind_, level_, 0);
    if (!label_.empty()) {
        builder_.add_text(label_);
        label_.clear();
    }
    const auto label = std::to_string(++notes_);
    builder_.note_reference(label);
    builder_.begin_note(label, source_line);
}

void OfficeText::begin_unreferenced_note() {
    if (note_depth_++ > 0) return;
    builder_.end();
    builder_.begin_note(std::to_string(++notes_), 0);
}

void OfficeText::end_note() {
    if (note_depth_ == 0 || --note_depth_ > 0) return;
    builder_.end_note();
}

}  // namespace tactus::import::detail
