// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The editor's incremental pipeline: one entry per editor line with its parsed
// block and cached translation. An edit re-translates only the lines it changed,
// then lays pages out again from the start of the sheet holding the first changed
// line (the pages before it cannot change). No Qt here: the widgets, the tests and
// the benchmark all drive it directly.
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "common/result.hpp"
#include "edit/editor_lines.hpp"
#include "edit/editor_pictures.hpp"
#include "layout/layout_options.hpp"
#include "layout/page.hpp"
#include "translate/translated_document.hpp"
#include "translate/translator.hpp"

namespace tactus::edit {

// Where a cell of the document sits on paper.
struct PagePosition {
    std::size_t page = 0;  // 0-based index into PagedDocument::pages
    int line = 0;          // 0-based line on the page
    int cell = 0;          // 0-based cell on the line
};

struct RelayoutStats {
    std::size_t lines_translated = 0;  // editor lines sent to liblouis
    std::size_t first_page_relaid = 0; // layout restarted at this page (a sheet front)
    std::size_t pages_relaid = 0;      // pages the paginator produced again
    bool converged = false;            // the old layout was reused after the edit
    // Editor lines whose braille (braille_of) may have changed, [first, end):
    // the lines translated again, with the lines of the paragraphs they are in
    // (a hard-wrapped text paragraph is translated as one, from its first line).
    std::size_t braille_first = 0;
    std::size_t braille_end = 0;
};

// Ready-made braille's structure beyond its rows (a PEF's): where its sections
// and volumes start, by editor line, the file's page grid and its dc:
// metadata. The rows are the editor's lines; this is what they do not carry.
// Each section's start is a mark on the line its first page starts on (its
// page break line, or its first row); edits move the marks with their lines
// (LiveLayout::replace says how), so the structure of the pages that still
// exist is kept.
struct BrailleStructure {
    std::vector<document::BrailleSection> sections;  // first_block: the editor line the section starts on
    std::optional<document::BrailleGrid> grid;
    std::vector<document::MetadataItem> metadata;
    bool operator==(const BrailleStructure&) const = default;
};

// The structure of a document as its editor lines (render_editor_lines,
// Markdown) hold it: its sections' first blocks turned into editor lines.
BrailleStructure braille_structure(const document::Document& document);

class LiveLayout {
public:
    // Cancels a long build when it returns true; receives (done, total).
    using Progress = std::function<bool(std::size_t, std::size_t)>;

    static Result<LiveLayout> create(const std::string& tables, layout::LayoutOptions options);

    // The line dialect (editor_lines.hpp); a change translates every line again.
    void set_dialect(Dialect dialect);
    [[nodiscard]] Dialect dialect() const { return dialect_; }
    // The line end a text file is saved with (import/text_lines.hpp line_ending_of;
    // "\n" unless set): the text dialect's lines are the file's lines.
    void set_line_ending(std::string ending) { line_ending_ = std::move(ending); }
    [[nodiscard]] const std::string& line_ending() const { return line_ending_; }
    // The encoding a text or Markdown file is saved in (import::read_text_file,
    // Document::encoding; UTF-8 without a byte-order mark unless set), given to
    // document() as the
    // document's own (Document::encoding, byte_order_mark).
    void set_encoding(std::string encoding, bool byte_order_mark) {
        encoding_ = std::move(encoding);
        byte_order_mark_ = byte_order_mark;
    }
    [[nodiscard]] const std::string& encoding() const { return encoding_; }
    [[nodiscard]] bool byte_order_mark() const { return byte_order_mark_; }

    // The document the lines stand for: their blocks in order, page breaks with
    // the print page they start, a table row followed by its cells, and each
    // block's source_line its 1-based editor line; a ready-made braille
    // document's sections (a section starts at the first block at or after its
    // mark), grid and metadata. What is saved, exported and embossed.
    // A picture's bytes are the editor's (pictures()), found by the name its
    // line's mark gives (edit/editor_pictures.hpp); a mark whose name it
    // does not hold is left out with a warning (Document::warnings).
    [[nodiscard]] document::Document document() const;

    // The pictures the lines' marks name. reset(document) keeps the
    // document's; an inserted picture is added here and its mark typed in.
    [[nodiscard]] const PictureStore& pictures() const { return pictures_; }
    void set_pictures(PictureStore pictures) { pictures_ = std::move(pictures); }
    // Keeps one picture under a free name; returns the name its mark gives.
    std::string add_picture(document::Image image) { return store_picture(std::move(image), pictures_); }

    // Replaces everything; translates every line. Returns false when cancelled.
    // `structure`: a ready-made braille document's sections, volumes, grid
    // and metadata (braille_structure), marked on these lines.
    bool reset(std::vector<std::string> lines, const Progress& progress = {}, BrailleStructure structure = {});
    // The same from a document: its editor lines (render_editor_lines, in
    // this layout's dialect), its pictures (pictures()) and its braille structure.
    bool reset(const document::Document& document, const Progress& progress = {});
    // Replaces `removed` lines starting at `first` with `lines`.
    // The braille structure follows the lines: a line edited keeps its
    // section mark, a line split keeps it on the part that is the same (on
    // the first part when both changed); inserted lines join the section of
    // the line above them (the removed lines equal to the first and last new
    // ones are taken as kept, not replaced: the editor reports a line
    // inserted above a line as that line replaced by both); the mark of a
    // deleted line passes to the first line that replaces it, or else to the
    // line after the deletion, so the pages that are left stay in their
    // section and volume, and goes back to its line when that line comes back
    // above it (undo). When marks meet on one line, the last one's section
    // wins (the sections before it have no line left) and a volume start
    // among them is kept.
    RelayoutStats replace(std::size_t first, std::size_t removed, std::vector<std::string> lines);
    // The braille structure as the lines hold it now (empty when none was given).
    [[nodiscard]] BrailleStructure braille_structure() const;
    // New table or layout options: everything is translated and laid out again.
    Result<void> set_tables(const std::string& tables);
    Result<void> set_options(layout::LayoutOptions options);

    [[nodiscard]] const layout::PagedDocument& paged() const { return paged_; }
    // The options asked for (set_options, create). Ready-made braille (a BRF or
    // PEF opened as it is: only braille lines and braille page breaks) whose
    // pages fit these options' page is laid out by layout::keep_braille_pages,
    // the CLI's call, after every edit: page for page, on the file's own grid,
    // each section on a new sheet, with its volumes and metadata. When its
    // pages do not fit (the app asks before embossing or exporting), or once
    // print text is typed into it, it is laid out by the paginator with these
    // options less the braille page numbers and print page indicators
    // (decided when the text is replaced whole, the table or the options
    // change; not on every edit).
    [[nodiscard]] const layout::LayoutOptions& options() const { return requested_; }
    [[nodiscard]] bool ready_braille() const { return ready_braille_; }
    // The pages are ready-made braille kept as it is (layout::keep_braille_pages),
    // not laid out again by the paginator.
    [[nodiscard]] bool pages_kept() const { return kept_; }
    [[nodiscard]] const std::string& tables() const { return translator_.tables(); }
    [[nodiscard]] std::size_t line_count() const { return entries_.size(); }
    [[nodiscard]] const std::string& line(std::size_t i) const { return entries_[i].line; }
    // The braille of one editor line as the braille pane shows it (unwrapped).
    [[nodiscard]] document::BrailleLine braille_of(std::size_t i) const;
    [[nodiscard]] const std::optional<Error>& error_of(std::size_t i) const { return entries_[i].error; }
    [[nodiscard]] std::size_t error_count() const;

    // Where cell `cell` of line `i`'s braille lands on paper (after wrapping).
    [[nodiscard]] PagePosition position_of(std::size_t i, std::size_t cell = 0) const;
    // The editor line whose braille starts at or before this page line.
    [[nodiscard]] std::size_t line_at(std::size_t page, int line) const;
    // The print page in effect at the top of a page, and at an editor line
    // (print pages count from "1" until the first page break).
    [[nodiscard]] std::string print_page_of(std::size_t page) const;
    [[nodiscard]] std::string print_page_at(std::size_t line) const;

    // What liblouis reads back from cells, for the proofreader and screen readers.
    [[nodiscard]] std::string back_translate(const document::BrailleLine& cells) const;
    [[nodiscard]] const translate::Translator& translator() const { return translator_; }

private:
    struct Entry {
        std::string line;
        std::optional<document::Block> block;
        translate::TranslatedBlock translated;
        // A table row's cells; in the text dialect, the further blocks the
        // line starts (a form feed inside a line starts a page and a paragraph).
        std::vector<document::Block> cells;
        std::vector<translate::TranslatedBlock> translated_cells;
        std::optional<Error> error;
        // A ready-made braille section (and perhaps a volume) starts on this line (BrailleStructure).
        std::optional<document::BrailleSection> section;
        // The section mark came here when the line it was on was deleted: that line's text.
        std::optional<std::string> mark_origin;
        std::size_t pages_before = 0;  // paginator state before this entry
        std::size_t lines_before = 0;
        bool settled_before = false;  // no table or list was open before this entry
        // Before this entry: the box the box lines above have open (box_line),
        // and the paginator's (the last block's; a box is closed when the
        // next block comes), as numbered in the last layout.
        int box_open_before = 0;
        int box_depth_before = 0;  // box lines opened and not closed (a box in a box is part of it)
        int box_laid_before = 0;
    };

    LiveLayout(translate::Translator translator, layout::LayoutOptions options)
        : translator_(std::move(translator)), options_(options), requested_(std::move(options)) {}

    void translate_entry(std::size_t i);
    // ---- the text dialect: a .txt shown as its lines (import/text_lines.hpp) ----
    // A line's blocks: the page breaks and paragraphs it starts, each paragraph
    // with the lines that continue it (soft line breaks between them).
    void translate_text_entry(std::size_t i);
    // Line i's first piece continues the paragraph above it.
    [[nodiscard]] bool continues(std::size_t i) const;
    // The line where the paragraph line i continues starts.
    [[nodiscard]] std::size_t paragraph_head(std::size_t i) const;
    // The lines of the paragraph that line `head`'s last piece starts.
    [[nodiscard]] std::vector<std::string_view> paragraph_lines(std::size_t head) const;
    // The last block line `head` starts and its translation: the paragraph its continuation lines belong to.
    [[nodiscard]] const translate::TranslatedBlock* last_translated(std::size_t head) const;
    // The part of line i's head paragraph's braille that is line i's.
    [[nodiscard]] std::pair<std::size_t, std::size_t> part_of(std::size_t head, std::size_t i) const;
    // True when a blank line separates two lines of text: paragraphs run on over lines.
    [[nodiscard]] bool find_paragraph_breaks() const;
    // The print page in effect after the lines before line i and the blocks
    // `earlier` line i starts first; `started`: some text or page came before.
    [[nodiscard]] std::string page_before(std::size_t i, std::span<const document::Block> earlier, bool& started) const;
    // Lays out entries from `first` on, restarting at a sheet boundary at or before it.
    // From entry `unchanged_from` on, the old layout is reused as soon as the
    // paginator reaches exactly the state it had there before (npos: never).
    RelayoutStats relayout_from(std::size_t first, std::size_t unchanged_from = npos);
    // replace() in the text dialect: `count` new lines at `first`.
    RelayoutStats replace_text(std::size_t first, std::size_t count, bool breaks_touched);
    static constexpr std::size_t npos = static_cast<std::size_t>(-1);
    document::BrailleLine number_cells(int n);
    [[nodiscard]] int body_top(std::size_t page) const;
    [[nodiscard]] int body_capacity(std::size_t page) const;

    translate::Translator translator_;
    layout::LayoutOptions options_;    // in effect (see options())
    layout::LayoutOptions requested_;  // as asked for
    bool ready_braille_ = false;
    void decide_ready_braille();
    // The braille structure's grid and metadata (the sections are the entries' marks).
    std::optional<document::BrailleGrid> braille_grid_;
    std::vector<document::MetadataItem> metadata_;
    PictureStore pictures_;
    // paged_ is layout::keep_braille_pages's: entries' pages_before and
    // lines_before are the page and row their block landed on.
    bool kept_ = false;
    // Lays the ready-made braille out page for page (keep_braille_pages) when
    // it still is ready-made braille and fits; false when it is not.
    bool keep_pages();
    // A row of kept pages edited in place: the row changed on its page, when
    // keep_braille_pages would change nothing else (else false: keep_pages).
    bool kept_row_edit(std::size_t i, std::pair<std::size_t, std::size_t> place, const document::BrailleLine& old_row);
    [[nodiscard]] static bool one_row(const Entry& e);
    Dialect dialect_ = Dialect::markdown;
    std::string line_ending_ = "\n";
    std::string encoding_ = "UTF-8";
    bool byte_order_mark_ = false;
    bool runs_on_ = false;  // text dialect: a paragraph's lines run on (find_paragraph_breaks)
    std::vector<Entry> entries_;
    // The kind of the last laid-out text block before entry `index` (page
    // breaks and lines in error skipped): what decides the paginator's blank
    // line before the next block.
    [[nodiscard]] std::optional<document::BlockKind> previous_kind(std::size_t index) const;
    // The columns of the table whose lines include entry `index`, as the saved
    // file has them (exporter::markdown_table_width): a shorter row gets empty
    // entries at its end, in the layout and in document() alike.
    [[nodiscard]] std::size_t table_columns(std::size_t index) const;
    layout::PagedDocument paged_;
    std::unordered_map<int, document::BrailleLine> numbers_;
    // translate::check_script on the whole text, first among the warnings as
    // in the CLI's pipeline; checked when the text is replaced whole (reset)
    // or the table changes, not on every edit.
    std::optional<std::string> script_warning_;
    void check_script();
};

}  // namespace tactus::edit
