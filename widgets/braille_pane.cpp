// SPDX-License-Identifier: GPL-3.0-or-later
#include "braille_pane.hpp"

#include <QAccessibleWidget>
#include <QDropEvent>
#include <QInputMethodEvent>
#include <QKeyEvent>
#include <QMimeData>
#include <QPaintEvent>
#include <QAbstractTextDocumentLayout>
#include <QPainter>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextLayout>
#include <QUrl>
#include <algorithm>

#include "text_units.hpp"

namespace tactus::gui {
namespace {

document::BrailleLine braille_in(const QString& text) {
    document::BrailleLine cells;
    for (char32_t c : text.toStdU32String()) {
        if (document::Cell::is_unicode_braille(c)) cells.push_back(document::Cell::from_unicode(c));
        else if (c == U' ') cells.push_back(document::Cell{});
    }
    return cells;
}

// Undo and redo belong to the window's QUndoStack, not to the text widget.
bool leave_to_window(QEvent* e) {
    if (e->type() != QEvent::ShortcutOverride) return false;
    auto* k = static_cast<QKeyEvent*>(e);
    if (k->matches(QKeySequence::Undo) || k->matches(QKeySequence::Redo)) {
        e->ignore();
        return true;
    }
    return false;
}

}  // namespace

BraillePane::BraillePane(QWidget* parent) : QPlainTextEdit(parent) {
    setObjectName(QStringLiteral("braillePane"));
    // Not read-only: a read-only pane is announced "Braille read only text" and
    // screen readers stop echoing it. Every edit still goes through
    // cells_typed / erase_*: keys, input methods, cut, paste and drops are
    // intercepted below, so the text is never changed behind the document's back.
    setContextMenuPolicy(Qt::NoContextMenu);  // its Cut and Delete would edit the text directly
    setAccessibleName(tr("Braille"));
    setAccessibleDescription(
        tr("The braille of each paragraph. Type with S D F J K L as dots 3 2 1 4 5 6; "
           "space, backspace and delete edit cells"));
    setUndoRedoEnabled(false);
    setTabChangesFocus(true);
}

bool BraillePane::event(QEvent* e) {
    if (leave_to_window(e)) return true;
    if (e->type() == QEvent::ShortcutOverride) {
        // Chord keys are plain letters: make sure no single-letter shortcut eats them.
        auto* k = static_cast<QKeyEvent*>(e);
        if (chord_.is_chord_key(k->key()) && (k->modifiers() & ~Qt::KeypadModifier) == 0) {
            e->accept();
            return true;
        }
    }
    return QPlainTextEdit::event(e);
}

void BraillePane::keyPressEvent(QKeyEvent* e) {
    // Qt's own word moves take a whole braille paragraph for one word: words here
    // are the cells between blank cells, as a screen reader reads them.
    const bool next = e->matches(QKeySequence::MoveToNextWord) || e->matches(QKeySequence::SelectNextWord);
    const bool previous = e->matches(QKeySequence::MoveToPreviousWord) || e->matches(QKeySequence::SelectPreviousWord);
    if (next || previous) {
        const bool select = e->matches(QKeySequence::SelectNextWord) || e->matches(QKeySequence::SelectPreviousWord);
        const auto text = toPlainText();
        auto c = textCursor();
        c.setPosition(next ? next_word_start(text, c.position()) : previous_word_start(text, c.position()),
                      select ? QTextCursor::KeepAnchor : QTextCursor::MoveAnchor);
        setTextCursor(c);
        e->accept();
        return;
    }
    const bool plain = (e->modifiers() & ~(Qt::KeypadModifier | Qt::ShiftModifier)) == 0;
    if (plain && (e->modifiers() & Qt::ShiftModifier) == 0 && chord_.press(e->key(), e->isAutoRepeat())) {
        e->accept();
        return;
    }
    if (plain && !chord_.active()) {
        switch (e->key()) {
            case Qt::Key_Space:
                Q_EMIT cells_typed(document::BrailleLine{document::Cell{}});
                e->accept();
                return;
            case Qt::Key_Backspace:
                Q_EMIT erase_backward();
                e->accept();
                return;
            case Qt::Key_Delete:
                Q_EMIT erase_forward();
                e->accept();
                return;
            case Qt::Key_Return:
            case Qt::Key_Enter:
                Q_EMIT new_paragraph();
                e->accept();
                return;
            default:
                break;
        }
        const auto typed = braille_in(e->text());
        if (!typed.empty() && !e->text().contains(QLatin1Char(' '))) {
            Q_EMIT cells_typed(typed);
            e->accept();
            return;
        }
    }
    if (e->matches(QKeySequence::Cut)) {
        copy();
        if (textCursor().hasSelection()) Q_EMIT cells_typed({});
        e->accept();
        return;
    }
    if (e->matches(QKeySequence::Paste)) {
        paste();  // through insertFromMimeData: braille only
        e->accept();
        return;
    }
    // Anything else that would change the text (other letters, word deletes)
    // is not braille: swallow it.
    const bool deletes = e->matches(QKeySequence::DeleteEndOfWord) || e->matches(QKeySequence::DeleteStartOfWord) ||
                         e->matches(QKeySequence::DeleteEndOfLine) || e->matches(QKeySequence::DeleteCompleteLine) ||
                         e->key() == Qt::Key_Backspace || e->key() == Qt::Key_Delete ||
                         e->key() == Qt::Key_Return || e->key() == Qt::Key_Enter;
    const bool prints = !e->text().isEmpty() && e->text().front().isPrint();
    if (deletes || prints) {
        e->accept();
        return;
    }
    QPlainTextEdit::keyPressEvent(e);
}

void BraillePane::keyReleaseEvent(QKeyEvent* e) {
    if (chord_.is_chord_key(e->key())) {
        if (auto cell = chord_.release(e->key(), e->isAutoRepeat())) {
            if (!cell->blank()) Q_EMIT cells_typed(document::BrailleLine{*cell});
        }
        e->accept();
        return;
    }
    QPlainTextEdit::keyReleaseEvent(e);
}

void BraillePane::inputMethodEvent(QInputMethodEvent* e) {
    // Composed text is print, not braille: only Unicode braille gets in, as cells.
    if (const auto cells = braille_in(e->commitString()); !cells.empty()) Q_EMIT cells_typed(cells);
    e->accept();
}

void BraillePane::dropEvent(QDropEvent* e) {
    // Moving a selection by dragging would cut it out of the text directly.
    if (e->source() == this || e->source() == viewport()) {
        e->ignore();
        return;
    }
    QPlainTextEdit::dropEvent(e);
}

void BraillePane::focusOutEvent(QFocusEvent* e) {
    chord_.cancel();
    QPlainTextEdit::focusOutEvent(e);
}

bool BraillePane::canInsertFromMimeData(const QMimeData* source) const {
    return source->hasText() && !braille_in(source->text()).empty();
}

void BraillePane::insertFromMimeData(const QMimeData* source) {
    const auto cells = braille_in(source->text());
    if (!cells.empty()) Q_EMIT cells_typed(cells);
}

namespace {

// The braille pane (or a read-only log) for a screen reader: Qt's text interface
// for a plain text edit, but with the units of text_units.hpp: words that end at
// blank cells, and a unit that always holds the offset asked about.
//
// A blank cell (U+2800) is shown to the screen reader as the space it is.
// Orca takes the word passed by Ctrl+Right to start after the last space or
// letter before the caret; a braille cell is neither to it, so the first word
// move said the blank cell alone instead of the word. Same length, so every
// offset stays the pane's own.
class AccessiblePlainText : public QAccessibleWidget, public QAccessibleTextInterface {
public:
    explicit AccessiblePlainText(QPlainTextEdit* w) : QAccessibleWidget(w, QAccessible::EditableText) {}
    QPlainTextEdit* pane() const { return static_cast<QPlainTextEdit*>(widget()); }

    void* interface_cast(QAccessible::InterfaceType t) override {
        if (t == QAccessible::TextInterface) return static_cast<QAccessibleTextInterface*>(this);
        return QAccessibleWidget::interface_cast(t);
    }
    QAccessible::State state() const override {
        auto s = QAccessibleWidget::state();
        s.editable = !pane()->isReadOnly();
        s.readOnly = pane()->isReadOnly();
        s.multiLine = true;
        s.selectableText = true;
        return s;
    }
    QString text(QAccessible::Text t) const override {
        if (t == QAccessible::Value) return shown();
        return QAccessibleWidget::text(t);
    }

    // QAccessibleTextInterface
    void selection(int index, int* start, int* end) const override {
        const auto c = pane()->textCursor();
        if (index != 0 || !c.hasSelection()) {
            *start = *end = 0;
            return;
        }
        *start = c.selectionStart();
        *end = c.selectionEnd();
    }
    int selectionCount() const override { return pane()->textCursor().hasSelection() ? 1 : 0; }
    void addSelection(int start, int end) override { setSelection(0, start, end); }
    void removeSelection(int) override {
        auto c = pane()->textCursor();
        c.clearSelection();
        pane()->setTextCursor(c);
    }
    void setSelection(int, int start, int end) override {
        auto c = pane()->textCursor();
        c.setPosition(clamped(start));
        c.setPosition(clamped(end), QTextCursor::KeepAnchor);
        pane()->setTextCursor(c);
    }
    int cursorPosition() const override { return pane()->textCursor().position(); }
    void setCursorPosition(int position) override {
        auto c = pane()->textCursor();
        c.setPosition(clamped(position));
        pane()->setTextCursor(c);
    }
    QString text(int start, int end) const override { return shown().mid(start, end - start); }
    int characterCount() const override { return static_cast<int>(pane()->toPlainText().size()); }
    QRect characterRect(int offset) const override {
        QTextCursor c(pane()->document());
        c.setPosition(clamped(offset));
        auto r = pane()->cursorRect(c);
        r.setWidth(std::max(1, pane()->fontMetrics().horizontalAdvance(QChar(0x2800))));
        return {pane()->viewport()->mapToGlobal(r.topLeft()), r.size()};
    }
    int offsetAtPoint(const QPoint& point) const override {
        return pane()->cursorForPosition(pane()->viewport()->mapFromGlobal(point)).position();
    }
    void scrollToSubstring(int, int) override { pane()->ensureCursorVisible(); }
    QString attributes(int, int* start, int* end) const override {
        *start = 0;
        *end = characterCount();
        return {};
    }
    QString textAtOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_at_offset(shown(), offset, b, start, end, lines());
    }
    QString textBeforeOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_before_offset(shown(), offset, b, start, end, lines());
    }
    QString textAfterOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_after_offset(shown(), offset, b, start, end, lines());
    }

private:
    QString shown() const { return pane()->toPlainText().replace(QChar(0x2800), QLatin1Char(' ')); }
    int clamped(int offset) const { return std::clamp(offset, 0, characterCount()); }
    // A line is a wrapped line of the pane, as shown.
    LineUnits lines() const {
        const auto* doc = pane()->document();
        return [doc](int offset) {
            const auto block = doc->findBlock(offset);
            if (!block.isValid()) return TextUnit{offset, offset};
            const int whole_end = block.position() + block.length();
            const auto* layout = block.layout();
            const auto line = layout ? layout->lineForTextPosition(offset - block.position()) : QTextLine();
            if (!line.isValid()) return TextUnit{block.position(), whole_end};
            const int start = block.position() + line.textStart();
            const bool last = line.lineNumber() == layout->lineCount() - 1;
            return TextUnit{start, last ? whole_end : start + line.textLength()};
        };
    }
};

}  // namespace

QAccessibleInterface* make_accessible_plain_text(QPlainTextEdit* pane) { return new AccessiblePlainText(pane); }

PrintPane::PrintPane(QWidget* parent) : QTextEdit(parent) {
    setObjectName(QStringLiteral("printPane"));
    setAccessibleName(tr("Print text"));
    setAcceptRichText(false);  // pasted text takes the style it lands in
    set_text_file(false);
    setTabChangesFocus(true);
    setContextMenuPolicy(Qt::ActionsContextMenu);
}

void PrintPane::set_text_file(bool text_file) {
    text_file_ = text_file;
    describe();
}

void PrintPane::set_codes_shown(bool codes) {
    codes_ = codes;
    describe();
}

void PrintPane::describe() {
    setAccessibleDescription(
        text_file_ ? tr("The text file's lines as written: a blank line between paragraphs, a form feed starts a print page")
        : codes_   ? tr("One paragraph per line: # for headings, - for list items, *italic*, **bold**")
                   : tr("The print text with its styles: headings, lists, tables, emphasis; Styles menu to change them"));
}

bool PrintPane::event(QEvent* e) {
    if (leave_to_window(e)) return true;
    return QTextEdit::event(e);
}

void PrintPane::paintEvent(QPaintEvent* e) {
    QTextEdit::paintEvent(e);
    if (!marker_) return;
    QPainter painter(viewport());
    const QPointF offset(-horizontalScrollBar()->value(), -verticalScrollBar()->value());
    const QColor ink = palette().color(QPalette::PlaceholderText);
    auto* layout = document()->documentLayout();
    for (auto block = cursorForPosition(e->rect().topLeft()).block(); block.isValid(); block = block.next()) {
        const auto box = layout->blockBoundingRect(block).translated(offset);
        if (box.top() > e->rect().bottom()) break;
        if (!block.isVisible() || box.bottom() < e->rect().top()) continue;
        const auto text = marker_(block.blockNumber());
        if (text.isEmpty()) continue;
        // A dashed rule across the line, the words on it: a page break seen as one.
        const int mid = static_cast<int>(box.center().y());
        const int left = static_cast<int>(box.left()) + 4;
        const int words = fontMetrics().horizontalAdvance(text) + 12;
        painter.setPen(QPen(ink, 1, Qt::DashLine));
        painter.drawLine(left, mid, left + 16, mid);
        painter.drawLine(left + 16 + words, mid, viewport()->width() - 4, mid);
        painter.setPen(ink);
        painter.drawText(QRect(left + 22, static_cast<int>(box.top()), words, static_cast<int>(box.height())),
                         Qt::AlignVCenter | Qt::AlignLeft, text);
    }
}

bool PrintPane::canInsertFromMimeData(const QMimeData* source) const {
    return source->hasUrls() || QTextEdit::canInsertFromMimeData(source);
}

void PrintPane::insertFromMimeData(const QMimeData* source) {
    if (source->hasUrls()) {
        QStringList paths;
        for (const auto& url : source->urls())
            if (url.isLocalFile()) paths << url.toLocalFile();
        if (!paths.isEmpty()) {
            Q_EMIT files_dropped(paths);
            return;
        }
    }
    QTextEdit::insertFromMimeData(source);
}

}  // namespace tactus::gui
