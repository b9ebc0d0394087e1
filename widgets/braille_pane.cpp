// SPDX-License-Identifier: GPL-3.0-or-later
#include "braille_pane.hpp"

#include <QKeyEvent>
#include <QMimeData>
#include <QUrl>

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
    setReadOnly(true);
    setTextInteractionFlags(Qt::TextSelectableByKeyboard | Qt::TextSelectableByMouse);
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

PrintPane::PrintPane(QWidget* parent) : QPlainTextEdit(parent) {
    setObjectName(QStringLiteral("printPane"));
    setAccessibleName(tr("Print text"));
    setAccessibleDescription(
        tr("One paragraph per line: # for headings, - for list items, *italic*, **bold**"));
    setTabChangesFocus(true);
    setContextMenuPolicy(Qt::ActionsContextMenu);
}

bool PrintPane::event(QEvent* e) {
    if (leave_to_window(e)) return true;
    return QPlainTextEdit::event(e);
}

bool PrintPane::canInsertFromMimeData(const QMimeData* source) const {
    return source->hasUrls() || QPlainTextEdit::canInsertFromMimeData(source);
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
    QPlainTextEdit::insertFromMimeData(source);
}

}  // namespace tactus::gui
