// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared by every importer: assembles blocks so that all formats follow the same
// rules (docs/import.md): blocks without visible text are dropped, adjacent runs
// with the same emphasis are merged, print pages are numbered, an unlabelled page
// break before any content and a braille page break after all of it are ignored
// (a print page break after all of it is kept), and the block count is capped so a
// pathological input fails clearly instead of exhausting memory.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"
#include "document/print_page.hpp"

namespace tactus::import::detail {

// About 200 bytes of bookkeeping per block: 2 M blocks stay below ~400 MB even
// when every paragraph is one character long. Real text has far fewer.
inline constexpr std::size_t max_import_blocks = 2'000'000;

class DocumentBuilder {
public:
    // Starts a text block (document::is_text_kind); an open one is ended first.
    void begin(document::BlockKind kind, int level, int source_line);
    [[nodiscard]] bool is_open() const { return open_; }
    [[nodiscard]] document::BlockKind open_kind() const { return current_.kind; }
    [[nodiscard]] int open_level() const { return current_.level; }
    // Sets the source line of the open block if it is still unknown.
    void note_line(int source_line);
    // Appends text to the open block; opens a paragraph if none is open.
    // `language`: the passage's language when the source marks one (Span::language).
    void add_text(std::string_view utf8, std::uint8_t emphasis = document::emphasis_none,
                  document::Position position = document::Position::baseline, std::string_view language = {});
    // Appends a transcriber's note (document::Span::transcriber_note) to the
    // open block; opens a paragraph if none is open.
    void add_transcriber_note(std::string_view utf8);
    // A picture's bytes, kept on the block being built (document::Block::images);
    // a block holding one is kept even without text.
    void add_image(document::Image image);
    // Boxed material (document::Block::box): the blocks kept between
    // begin_box and end_box are one box. A box in a box is part of it.
    void begin_box();
    void end_box();
    // What the importer left out on purpose: one line per kind in
    // Document::warnings.
    void warn(std::string line) { warnings_.push_back(std::move(line)); }
    // Drops spaces and tabs at the end of the open block's text.
    void trim_end();
    // Ends the open block; it is kept only if it contains visible text.
    void end();

    // Notes (docs/formats.md): a reference in the open block's text, and the
    // note's own text between begin_note and end_note (the open block is set
    // aside meanwhile and goes on after). The note is placed after the block
    // that refers to it, or after the table when the reference is in a table.
    void note_reference(std::string label);
    void begin_note(std::string label, int source_line);
    void end_note();

    // Tables: a row marker, then begin_cell(column) and text for each cell; an
    // empty cell is kept (it holds its column). end_table() after the last row.
    void table_row(bool header, int source_line);
    // `span`: the columns a merged cell covers, from `column` on.
    void begin_cell(int column, int source_line, int span = 1, document::Align align = document::Align::none);
    void end_table();
    // Drops the last row when all its cells are empty: a Markdown table without
    // a header row is written with an empty one (as Pandoc does).
    void drop_empty_row();

    // `label` empty = the next print page (document::next_print_page; the first page is "1").
    void print_page_break(int source_line, std::string label = {});
    // A braille page break the source implies (a BRF form feed, a PEF page)
    // is dropped before any text and after all text, where it breaks nothing;
    // one it writes out (Markdown's <!-- braillepage -->) is kept there too,
    // so saving and opening again does not lose it.
    enum class BrailleBreak { implied, written };
    void braille_page_break(int source_line, BrailleBreak kind = BrailleBreak::implied);
    void braille_block(std::vector<document::BrailleLine> lines, int source_line);

    // Blocks kept so far (the open one not counted).
    [[nodiscard]] std::size_t size() const { return blocks_.size(); }
    // True once the block cap is reached; importers may stop early.
    [[nodiscard]] bool full() const { return overflow_line_ >= 0; }
    Result<document::Document> finish();

private:
    void push(document::Block block);
    void flush_notes();

    std::vector<document::Block> blocks_;
    document::Block current_;
    bool open_ = false;
    bool has_content_ = false;  // a non-break block has been kept
    bool print_pages_started_ = false;  // a print page break has been kept
    std::vector<std::size_t> written_breaks_;  // indices of BrailleBreak::written breaks, ascending
    std::string print_page_{document::first_print_page};  // the print page in effect
    int overflow_line_ = -1;
    std::vector<document::Block> notes_;  // notes waiting for their block's end
    document::Block set_aside_;           // the block a note interrupted
    bool set_aside_open_ = false;
    bool in_note_ = false;
    bool in_table_ = false;
    int box_ = 0;        // the box being read, 0 = none
    int box_depth_ = 0;
    int boxes_ = 0;      // boxes numbered so far
    std::vector<std::string> warnings_;
};

}  // namespace tactus::import::detail
