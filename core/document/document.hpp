// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The document model every importer produces and the translator consumes:
// a flat list of blocks, each a run of styled text, or braille taken verbatim.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "document/cell.hpp"

namespace tactus::document {

// Bit flags, combinable; mapped to liblouis typeforms by the translator.
enum Emphasis : std::uint8_t {
    emphasis_none = 0,
    emphasis_italic = 1u << 0,
    emphasis_bold = 1u << 1,
    emphasis_underline = 1u << 2,
};

// Where print sets a run of text: on the line, raised (superscript) or
// lowered (subscript); DOCX w:vertAlign, ODT style:text-position. The
// translator writes the code's level indicator before a raised or lowered
// run (docs/layout.md, "Superscript and subscript").
enum class Position : std::uint8_t { baseline, superscript, subscript };

struct Span {
    std::string text;  // UTF-8
    std::uint8_t emphasis = emphasis_none;
    // The text is a note's reference ("1"): the translator writes it with the
    // note reference indicator in front (docs/formats.md, "Notes").
    bool note_reference = false;
    Position position = Position::baseline;
    // Text the transcriber adds, not print's (an image's description, a
    // ruby guide): written between the code's transcriber's note indicators
    // (docs/layout.md, "Transcriber's notes").
    bool transcriber_note = false;
    // The passage's language as the source marks it (BCP 47, from HTML lang,
    // xml:lang, DOCX w:lang, ODT fo:language); empty = the document's own.
    // The translator gives it its language's table (translate/language_switch.hpp).
    std::string language = {};
    bool operator==(const Span&) const = default;
};

enum class BlockKind : std::uint8_t {
    heading,          // level 1..6
    paragraph,
    list_item,        // level = nesting depth, 1-based
    print_page_break, // source page break; `label` is the print page that starts here
    braille_page_break,  // force a new braille page (BRF form feed, PEF page end)
    braille,          // verbatim braille lines (BRF, PEF); not translated
    quote,            // a paragraph of a block quote; level = quote depth, 1-based
    note,             // a footnote's text, placed after the block that refers to it;
                      // its first span is the note's reference (note_reference)
    table_row,        // starts a row of a table; level 1 = a header row. Its cells
                      // follow as table_cell blocks; the table ends at the next
                      // block of another kind
    table_cell,       // one cell's text (may be empty); level = column, 0-based;
                      // `span` = the columns it covers (a merged cell: DOCX
                      // w:gridSpan, ODT table:number-columns-spanned). A line
                      // break ("\n") in its text ends one of the cell's
                      // paragraphs: braille starts the next on a line of its own,
                      // writers write each as a paragraph of the cell
                      // (document/cell_paragraphs.hpp, docs/layout.md "Tables")
};

// Blocks whose spans are print text to translate.
constexpr bool is_text_kind(BlockKind k) {
    return k == BlockKind::heading || k == BlockKind::paragraph || k == BlockKind::list_item ||
           k == BlockKind::quote || k == BlockKind::note || k == BlockKind::table_cell;
}
// Blocks that make up a table.
constexpr bool is_table_kind(BlockKind k) { return k == BlockKind::table_row || k == BlockKind::table_cell; }

// A table column's print alignment (Markdown's delimiter row "|:--|:-:|--:|",
// DOCX w:jc, ODT fo:text-align). Kept so that saving writes it back; braille
// layout does not follow it (docs/layout.md, "Tables").
enum class Align : std::uint8_t { none, left, centre, right };

// A picture the source holds (a DOCX a:blip part, an ODT draw:image, a
// Markdown image file): its bytes as stored and what they are. Kept only when
// the import is asked for pictures (import::ImportOptions::images); layout
// then makes each a graphic page (docs/graphics.md, "Pictures in documents").
struct Image {
    std::string bytes;       // the file's bytes, undecoded
    std::string media_type;  // "image/png", "image/jpeg", "image/svg+xml"
    std::string name;        // where it came from ("word/media/image1.png"), for messages
    bool operator==(const Image&) const = default;
};

struct Block {
    BlockKind kind = BlockKind::paragraph;
    int level = 0;
    std::vector<Span> spans;                 // text kinds (is_text_kind)
    std::vector<BrailleLine> braille_lines;  // kind == braille
    std::string label;                       // print_page_break: page number as printed
    // print_page_break: the label was counted on from the page before
    // (document/print_page.hpp), not given in the source; a writer writes the
    // break without it, so the pages after a changed label count on from it.
    bool label_counted = false;
    int source_line = 0;                     // 1-based line in the source, 0 if unknown
    int span = 1;                            // table_cell: columns covered, from `level` on
    Align align = Align::none;               // table_cell: its column's alignment
    // Boxed material (a DOCX text box, an ODT frame): blocks with the same
    // non-zero number are one box, drawn between box lines (docs/layout.md,
    // "Boxed material"); 0 = not in a box.
    int box = 0;
    // The pictures this block holds, in order; their descriptions are its
    // transcriber's notes. Empty unless the import kept pictures.
    std::vector<Image> images;
    bool operator==(const Block&) const = default;

    // The plain text of all spans, for display and tests.
    [[nodiscard]] std::string text() const {
        std::string out;
        for (const auto& s : spans) out += s.text;
        return out;
    }
};

// Braille that arrives formatted (BRF, PEF): the page grid it was made for.
struct BrailleGrid {
    int cols = 0;  // PEF cols (the widest section); BRF: the longest line
    int rows = 0;  // PEF rows (the tallest section); BRF: the longest page
    bool operator==(const BrailleGrid&) const = default;
};

// A PEF section: its pages start at block `first_block` and on a new sheet.
// Its grid is the one in force for it (PEF 2008-1: its volume's cols, rows,
// rowgap and duplex, each overridden by the section's own), so volumes of
// different page sizes keep theirs.
struct BrailleSection {
    std::size_t first_block = 0;
    int cols = 0;
    int rows = 0;
    bool duplex = false;
    bool starts_volume = false;
    int rowgap = 0;
    bool operator==(const BrailleSection&) const = default;
};

// One Dublin Core element of a PEF head: "title", "creator", ... and its text.
struct MetadataItem {
    std::string name;
    std::string value;
    bool operator==(const MetadataItem&) const = default;
};

struct Document {
    std::vector<Block> blocks;
    std::string source_name;  // file name the document came from, for messages
    std::string encoding;     // detected or given source encoding (text and Markdown
                              // imports); the file is saved in it again (exporter::encode_text)
    bool byte_order_mark = false;  // the source began with one: it is written again
    std::string line_ending;       // text and Markdown imports: the file's first line end
                                   // ("\n", "\r\n", "\r"), which it is saved with again
    std::optional<BrailleGrid> braille_grid;     // BRF, PEF: the source's page size
    std::vector<BrailleSection> braille_sections;  // PEF sections, in order
    std::vector<MetadataItem> metadata;            // PEF dc: elements, in document order;
                                                   // EPUB, DTBook: the book's title, creator, ...
    // What the importer left out on purpose or could not keep (a picture with
    // no description, a video): what, how many and where (the first); layout
    // reports them on.
    std::vector<std::string> warnings;
    bool operator==(const Document&) const = default;
};

}  // namespace tactus::document
