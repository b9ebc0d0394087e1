// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Lays translated blocks out into braille pages, one block at a time, so the
// pipeline can feed it while translation of later blocks is still running.
#include <functional>
#include <optional>
#include <string>

#include "layout/layout_options.hpp"
#include "layout/page.hpp"
#include "translate/translated_document.hpp"

namespace tactus::layout {

// The page rules the paginator follows, for everyone who must know where body
// text sits on a page without laying it out again (the editor's live layout,
// its cursor map): whether page `page_index` (0-based) carries a braille page
// number (interpoint backs do not), the first row of body text, and how many
// rows of body text it holds.
[[nodiscard]] bool page_is_numbered(const LayoutOptions& o, std::size_t page_index);
[[nodiscard]] int body_top(const LayoutOptions& o, std::size_t page_index);
[[nodiscard]] int body_capacity(const LayoutOptions& o, std::size_t page_index);

class Paginator {
public:
    // `number_cells` renders a braille page number in the document's braille code
    // (the translator's digits and number sign).
    Paginator(LayoutOptions options, std::function<document::BrailleLine(int)> number_cells);

    void add(const translate::TranslatedBlock& block);
    // A graphic's pages (graphic::lay_out_drawing: the graphic page, and a key
    // page when labels found no room), each numbered on from the text: the
    // page being filled is closed, the graphic starts on a sheet's front, and
    // on interpoint paper the back of each of its sheets stays empty, so no
    // dot struck from behind crushes the graphic's. Text goes on on the next sheet.
    void add_graphic(const PagedDocument& graphic);
    // Closes the last page and returns the pages. An interpoint document with an
    // odd page count simply has no back on its last sheet.
    PagedDocument finish() &&;

    // The paginator's state between blocks, read by the editor's live layout: it
    // restarts layout after an edit from a sheet front, and stops early once it is
    // back in the state (page, body lines) the previous layout had at that block.
    [[nodiscard]] std::size_t pages_closed() const { return doc_.pages.size(); }
    [[nodiscard]] std::size_t body_lines() const { return body_.size(); }
    [[nodiscard]] const std::vector<document::BrailleLine>& body() const { return body_; }
    // The pages closed so far (finish() would also close the one being filled).
    [[nodiscard]] const PagedDocument& closed() const { return doc_; }
    // False while a structure is open whose lines depend on blocks still to
    // come: a table (laid out whole at its end), a block quote or a list (a
    // blank line follows them). The editor's live layout does not stop early then.
    [[nodiscard]] bool settled() const;
    // The kind of the block before the next one, for a paginator primed with a
    // page's lines (the editor's restart): the blank line before the next block
    // depends on it (blank_line_before).
    void set_previous_kind(std::optional<document::BlockKind> kind) { last_kind_ = kind; }
    // A restart inside a box (the live layout's): the blocks that follow with
    // this box number go on in it, with no top box line drawn again.
    void continue_box(int box) { box_ = box; }

private:
    [[nodiscard]] bool numbered(std::size_t page_index) const;
    [[nodiscard]] int body_capacity() const;
    [[nodiscard]] int width() const;
    void add_line(document::BrailleLine line, int source_line);
    void note_dots_78(int source_line);
    void add_blank_line();
    void break_page();
    void close_page();
    void add_wrapped(const translate::TranslatedBlock& block, const BlockIndents& indents);
    void enter_box(int box);
    void add_table_block(const translate::TranslatedBlock& block);
    void flush_table();
    bool lay_out_simple_table();
    void lay_out_listed_table();

    struct TableRow {
        bool header = false;
        std::vector<translate::TranslatedBlock> cells;
    };
    // An entry of a row and the columns it covers.
    struct Merged {
        const translate::TranslatedBlock* cell = nullptr;  // null: an empty column
        std::size_t column = 0;
        std::size_t span = 1;
    };
    static std::vector<Merged> merged_entries(const TableRow& row);

    LayoutOptions o_;
    std::function<document::BrailleLine(int)> number_cells_;
    PagedDocument doc_;
    // The one warning for cells with dots 7-8 in a six-dot layout.
    struct Dots78 {
        std::optional<std::size_t> warning;  // its index in doc_.warnings
        std::string first;                   // "line N: " of the first source line with such cells
        int last_line = 0;
        std::size_t lines = 0;
    } dots_78_;
    std::vector<document::BrailleLine> body_;  // body lines of the page being filled
    std::string print_page_;         // print page label in effect (UTF-8 of the label cells)
    std::string page_top_print_page_;
    std::vector<TableRow> table_;  // the table being read, laid out at its end
    std::optional<document::BlockKind> last_kind_;  // of the last block, page breaks aside
    int box_ = 0;
    bool under_box_line_ = false;  // the last body line is a top box line  // the box being drawn (document::Block::box), 0 = none
    int trailing_separators_ = 0;  // separator lines at the body's end with only print page breaks after the text
};

}  // namespace tactus::layout
