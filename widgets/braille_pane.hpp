// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The braille side of the editor: one paragraph per print paragraph, in Unicode
// braille. It is never edited as text; keys become cell edits that the editor
// applies to the document (so one undo stack covers print and braille), with
// six-key chord entry, space and backspace, and Unicode braille typed or pasted.
#include <QPlainTextEdit>
#include <QTextEdit>
#include <functional>

#include "document/cell.hpp"
#include "six_key.hpp"


namespace tactus::gui {

class BraillePane : public QPlainTextEdit {
    Q_OBJECT
public:
    explicit BraillePane(QWidget* parent = nullptr);
    SixKeyChord& chord() { return chord_; }

Q_SIGNALS:
    void cells_typed(const tactus::document::BrailleLine& cells);  // replaces the selection
    void erase_backward();
    void erase_forward();
    void new_paragraph();

protected:
    void keyPressEvent(QKeyEvent* e) override;
    void keyReleaseEvent(QKeyEvent* e) override;
    void focusOutEvent(QFocusEvent* e) override;
    void inputMethodEvent(QInputMethodEvent* e) override;
    void dropEvent(QDropEvent* e) override;
    void insertFromMimeData(const QMimeData* source) override;
    bool canInsertFromMimeData(const QMimeData* source) const override;
    bool event(QEvent* e) override;

private:
    SixKeyChord chord_;
};


// The print side: a rich text edit (the structured view, structured_print.hpp,
// or the lines as codes); forwards dropped files to the window instead of
// pasting their names, and leaves undo/redo to the window's undo stack.
class PrintPane : public QTextEdit {
    Q_OBJECT
public:
    explicit PrintPane(QWidget* parent = nullptr);
    // What a line without visible text stands for ("Print page 5" for a text
    // file's form feed), drawn across that line as a rule with the words;
    // empty for other lines.
    void set_line_marker(std::function<QString(int line)> marker) { marker_ = std::move(marker); }
    // What the lines are, for a screen reader: a text file's own lines, or the
    // Markdown dialect's one paragraph a line.
    void set_text_file(bool text_file);
    // The pane says what an open tactile graphic is (read only), not text to edit.
    void set_graphic(bool graphic);
    // The lines shown structured (headings, lists, emphasis) or as their codes.
    void set_codes_shown(bool codes);

Q_SIGNALS:
    void files_dropped(const QStringList& paths);

protected:
    bool canInsertFromMimeData(const QMimeData* source) const override;
    void insertFromMimeData(const QMimeData* source) override;
    bool event(QEvent* e) override;
    void paintEvent(QPaintEvent* e) override;

private:
    std::function<QString(int)> marker_;
    bool text_file_ = false;
    bool graphic_ = false;
    bool codes_ = false;
    void describe();
};

}  // namespace tactus::gui
