// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the DOCX and ODT importers share: a ZIP package of XML parts (libzip,
// pugixml), and the walk that turns their paragraphs, list items, tables and
// notes into blocks (OfficeText). Each importer only reads its own XML.
#include <pugixml.hpp>

#include <cstdint>
#include <string>
#include <string_view>

#include "common/result.hpp"
#include "document/document.hpp"
#include "import/document_builder.hpp"
#include "import/zip_archive.hpp"

namespace tactus::import::detail {

// One parsed part; `bytes` outlives `xml` (error offsets refer to it).
struct XmlPart {
    std::string bytes;
    pugi::xml_document xml;
    [[nodiscard]] pugi::xml_node root() const { return xml.document_element(); }
};

class XmlPackage {
public:
    // `kind` names the format in errors: "a Word document", "an OpenDocument text".
    static Result<XmlPackage> open(std::string_view bytes, std::string kind);

    [[nodiscard]] bool contains(const std::string& part) const { return zip_.contains(part); }
    Result<std::string> read(const std::string& part, std::size_t max_bytes) const {
        return zip_.read(part, max_bytes);
    }
    // Reads and parses a part. A missing part is an error ("not <kind>: missing
    // part ...") when `required`, else `false` with `out` left empty.
    Result<bool> load(const std::string& part, XmlPart& out, bool required) const;

private:
    XmlPackage(ZipArchive zip, std::string kind) : zip_(std::move(zip)), kind_(std::move(kind)) {}
    ZipArchive zip_;
    std::string kind_;
};

// The paragraph walk of a word-processor document. A paragraph's list label
// waits for its first text (an empty item leaves no label behind); paragraphs
// inside a table cell run on into the cell, a line break apart; a table inside a
// cell is read as the cell's text; notes are numbered 1, 2, 3 in the order of
// their references; a page break inside a table or a note comes after it.
class OfficeText {
public:
    void begin_paragraph(document::BlockKind kind, int level, std::string label);
    // `language`: the passage's, when it is not the document's own (Span::language).
    void text(std::string_view utf8, std::uint8_t emphasis,
              document::Position position = document::Position::baseline, std::string_view language = {});
    // Text the transcriber adds (an image's description, a ruby guide): a
    // transcriber's note at this place in the text.
    void transcriber_note(std::string_view utf8);
    // A text box or frame: its paragraphs are boxed material, blocks of their
    // own after the paragraph it is anchored in (the importer calls this once
    // that paragraph has ended). In a table cell or a note its text runs on
    // in the cell or note.
    void begin_box();
    void end_box();
    // A picture with no description: nothing to put in braille, so it is
    // counted and named in one warning (`where`: the first one's place).
    void picture_without_description(std::string where);
    // A picture's bytes (ImportOptions::images), kept on the paragraph it
    // stands in, after its description. A picture without a description is
    // kept too (one warning counts them); it then leaves no warning that it
    // was left out.
    void image(document::Image image, bool described, std::string where);
    void warn(std::string line) { builder_.warn(std::move(line)); }
    void end_paragraph();
    // A print page break between paragraphs, or inside one (the paragraph goes
    // on after it as a block of the same kind).
    void page_break();
    void page_break_inside();

    void begin_table();
    void begin_row(bool header);
    // A cell covering `span` columns (a merged cell), or `skip` columns no
    // cell starts in (DOCX w:gridBefore, ODT's covered cells): the next cell
    // keeps its column, as the paginator lays columns out by their index.
    void begin_cell(int span = 1, document::Align align = document::Align::none);
    void skip_columns(int count);
    void end_cell();
    void end_table();

    // A note reference in the text; begin_note/end_note around the note's text.
    void begin_note(int source_line = 0);
    void end_note();
    // A note nothing in the text refers to: a note block of its own where the
    // text now ends (numbered on after the others), no reference; end_note after
    // its text (docs/layout.md "Notes").
    void begin_unreferenced_note();

    [[nodiscard]] bool full() const { return builder_.full(); }
    Result<document::Document> finish();

private:
    void flush_page_break();

    DocumentBuilder builder_;
    document::BlockKind kind_ = document::BlockKind::paragraph;
    int level_ = 0;
    std::string label_;  // list label not yet written
    int table_depth_ = 0;
    int column_ = 0;
    bool cell_has_text_ = false;
    int notes_ = 0;
    int note_depth_ = 0;
    int pending_breaks_ = 0;  // page breaks met inside a table or a note
    int undescribed_pictures_ = 0;
    std::string first_undescribed_;
    int uncaptioned_pictures_ = 0;
    std::string first_uncaptioned_;
};

}  // namespace tactus::import::detail
