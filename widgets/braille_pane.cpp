// SPDX-License-Identifier: GPL-3.0-or-later
#include "braille_pane.hpp"

#include <QDropEvent>
#include <QInputMethodEvent>
#include <QKeyEvent>
#include <QMimeData>
#include <QPaintEvent>
#include <QAbstractTextDocumentLayout>
#include <QPainter>
#include <QScrollBar>
#include <QTextBlock>
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

void PrintPane::set_graphic(bool graphic) {
    graphic_ = graphic;
    describe();
}

void PrintPane::set_codes_shown(bool codes) {
    codes_ = codes;
    describe();
}

void PrintPane::describe() {
    setAccessibleDescription(
        graphic_     ? tr("What the tactile graphic is: its title, description, labels and dots")
        : text_file_ ? tr("The text file's lines as written: a blank line between paragraphs, a form feed starts a print page")
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
