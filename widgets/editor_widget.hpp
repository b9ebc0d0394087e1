// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Print and braille side by side over one live layout. Typing in the print pane
// re-translates the lines it touched and re-lays pages from their sheet; cell
// edits in the braille pane turn that paragraph into verbatim braille. Both go
// through the print document, so one QUndoStack undoes either.
#include <QSplitter>
#include <QTextBlock>
#include <QUndoStack>
#include <memory>
#include <optional>

#include "edit/live_layout.hpp"

namespace tactus::gui {

class BraillePane;
class PrintPane;

class EditorWidget : public QSplitter {
    Q_OBJECT
public:
    explicit EditorWidget(QWidget* parent = nullptr);
    ~EditorWidget() override;

    // Takes a layout built elsewhere (a worker thread) and shows its lines.
    void adopt(edit::LiveLayout layout);
    [[nodiscard]] bool has_layout() const { return layout_.has_value(); }
    [[nodiscard]] const edit::LiveLayout& layout() const { return *layout_; }
    // A layout of the same lines built elsewhere (new table or options off-thread):
    // the print text and its undo history stay.
    void swap_layout(edit::LiveLayout layout);
    // The encoding the file is saved in from now on (the user chose UTF-8 for
    // a character the file's own encoding cannot hold).
    void set_encoding(const std::string& encoding, bool byte_order_mark) {
        if (layout_) layout_->set_encoding(encoding, byte_order_mark);
    }
    Result<void> set_tables(const std::string& tables);
    Result<void> set_layout_options(const layout::LayoutOptions& options);

    // The editor's lines, one per print block (layout().dialect()): the model's
    // lines, whatever the print pane shows.
    [[nodiscard]] QString text() const;
    // "Show codes": the print pane shows the lines' Markdown instead of their
    // structure (a .txt is always its own lines).
    void set_codes_shown(bool codes);
    [[nodiscard]] bool codes_shown() const { return codes_; }
    // The print pane shows structure (a Markdown-dialect document, codes hidden).
    [[nodiscard]] bool structured() const;

    // Styles, as a word processor's (the Styles menu): on the paragraphs the
    // print cursor's selection touches. Each is one step of undo. In the codes
    // view and in a text file they do nothing (the marks are typed there).
    enum class ParagraphStyle { body, heading, bulleted, numbered, quotation };
    void set_paragraph_style(ParagraphStyle style, int level = 1);
    // Bold, italic or underline (document::Emphasis) on the selection, or off
    // when all of it has it already.
    void toggle_emphasis(std::uint8_t emphasis);
    // Raised (superscript) or lowered (subscript) on the selection, or back
    // on the line when all of it is so already; what is typed next without one.
    void toggle_position(document::Position position);
    // A passage's language (BCP 47, document::Span::language; "" = the
    // document's own, a mark taken away) on the selection; without one, on
    // the word the cursor is in, else on what is typed next; with
    // `paragraph`, on all of the paragraphs the selection touches
    // (LibreOffice's Tools > Language > For Selection and For Paragraph).
    // The braille of the passage comes from that language's table. One step
    // of undo.
    void set_language(const QString& tag, bool paragraph = false);
    // The language of the character after the print cursor (the one a
    // screen reader reads from there), else of the one before it; "" = the
    // document's own, and in the codes view (the marks are read there).
    [[nodiscard]] QString language_at_cursor() const;
    // The paragraphs the selection touches put in a box (a box line above
    // them and one below), or, when the first of them is in a box already,
    // that box's lines taken away. One step of undo.
    void toggle_box();
    // A print page break as a paragraph of its own before the cursor's paragraph.
    void insert_page_break();
    // A footnote, as word processors insert one: its reference (the next
    // number) raised at the cursor, its text a note paragraph after the
    // cursor's paragraph, where the cursor goes to type it. One undo step.
    // Returns the reference, empty when nothing was inserted.
    QString insert_note();
    // A picture as a paragraph of its own after the cursor's (in the cursor's
    // paragraph when it is empty): kept in the layout's pictures, shown as
    // itself, its description its transcriber's note (edit/editor_pictures.hpp).
    // One undo step. False when the view cannot hold one (a text file).
    bool insert_picture(document::Image image, const QString& description);
    [[nodiscard]] PrintPane* print_pane() const { return print_; }
    [[nodiscard]] BraillePane* braille_pane() const { return braille_; }
    [[nodiscard]] QUndoStack* undo_stack() const { return undo_; }
    [[nodiscard]] const edit::RelayoutStats& last_stats() const { return last_stats_; }

    // The print line and column of the cursor; the braille cell it maps to.
    [[nodiscard]] int current_line() const;
    [[nodiscard]] std::size_t current_cell() const;
    [[nodiscard]] edit::PagePosition current_position() const;

    // What a print page break line says, drawn on it and spoken when the cursor
    // comes to it ("Print page break, page 5"); empty for any other line.
    [[nodiscard]] QString page_break_text(int line) const;
    // What a structured paragraph is, in words ("Heading level 2"); empty for
    // body text and in the codes view (the marks are read there).
    [[nodiscard]] QString structure_text(int line) const;

    // Cell edits on line `line`: replace cells [from, to) with `cells`.
    void edit_braille(std::size_t line, std::size_t from, std::size_t to, const document::BrailleLine& cells);

Q_SIGNALS:
    void layout_changed();
    void position_changed(const tactus::edit::PagePosition& position);
    void files_dropped(const QStringList& paths);
    // A cell typed with six keys, in words: "dots 1-2, b" (the dots, then the
    // print it back-translates to), for the screen reader to echo.
    void cell_entered(const QString& spoken);
    // The print cursor came to a print page break line: what to say for it
    // (a text file's form feed shows nothing a screen reader could read).
    void page_break_reached(const QString& spoken);
    // The print cursor came to a paragraph with a structure the screen reader
    // cannot hear from the text (Qt's text accessibility has no heading level
    // or list number): "Heading level 2", "List item 3.", "Table row 2 of 4".
    void structure_reached(const QString& spoken);

protected:
    // Return at the end of a heading, a break or a rule starts body text, as in a word processor.
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void refresh_braille();
    void show_lines(const QStringList& lines);
    // What a structured paragraph's kind is, in words (structure_text without its pictures).
    [[nodiscard]] QString paragraph_text(const QTextBlock& block) const;
    // The editor line a print block stands for now.
    [[nodiscard]] std::string line_text(const QTextBlock& block) const;
    // A position in a print block <-> the braille cell it maps to on its line.
    [[nodiscard]] std::size_t cell_at(const QTextBlock& block, int position) const;
    [[nodiscard]] int position_at(const QTextBlock& block, std::size_t cell) const;
    void on_contents_change(int position, int removed, int added);
    void replace_braille_blocks(int first, int removed, int count);
    // Replaces a braille paragraph's text by changing only the cells that differ.
    void replace_changed_cells(const QTextBlock& block, const QString& text);
    void sync_from_print();
    void sync_from_braille();
    void braille_typed(const document::BrailleLine& cells);
    void braille_erase(bool backward);
    void braille_new_paragraph();
    [[nodiscard]] QString braille_text(std::size_t line) const;

    PrintPane* print_ = nullptr;
    BraillePane* braille_ = nullptr;
    QUndoStack* undo_ = nullptr;
    std::optional<edit::LiveLayout> layout_;
    int known_blocks_ = 1;
    int cursor_line_ = -1;  // the print cursor's line when it last moved
    bool syncing_ = false;
    bool codes_ = false;
    edit::RelayoutStats last_stats_;
};

// Column in the editor line <-> column in its content (without Markdown marks).
int content_column(const QString& line, int column, edit::Dialect dialect = edit::Dialect::markdown);
int line_column(const QString& line, int content_column, edit::Dialect dialect = edit::Dialect::markdown);

}  // namespace tactus::gui
