// SPDX-License-Identifier: GPL-3.0-or-later
#include "accessible_text_pane.hpp"

#include <QAccessibleWidget>
#include <QPlainTextEdit>
#include <QTextBlock>
#include <QTextEdit>
#include <QTextLayout>
#include <algorithm>

#include "text_units.hpp"

namespace tactus::gui {
namespace {

template <class Edit>
class AccessibleTextPane : public QAccessibleWidget,
                           public QAccessibleTextInterface,
                           public QAccessibleEditableTextInterface {
public:
    AccessibleTextPane(Edit* w, bool blank_cells_as_spaces)
        : QAccessibleWidget(w, QAccessible::EditableText), blank_cells_as_spaces_(blank_cells_as_spaces) {}
    Edit* pane() const { return static_cast<Edit*>(widget()); }

    void* interface_cast(QAccessible::InterfaceType t) override {
        if (t == QAccessible::TextInterface) return static_cast<QAccessibleTextInterface*>(this);
        if (t == QAccessible::EditableTextInterface && !pane()->isReadOnly())
            return static_cast<QAccessibleEditableTextInterface*>(this);
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
        // The width of the one character there, read from the document.
        const QChar ch = offset >= 0 && offset < characterCount() ? pane()->document()->characterAt(offset) : QChar(u' ');
        r.setWidth(std::max(1, pane()->fontMetrics().horizontalAdvance(ch)));
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

    // QAccessibleEditableTextInterface: edits as the pane's own cursor makes them,
    // so they reach its undo stack and its document's signals.
    void deleteText(int start, int end) override { replaceText(start, end, {}); }
    void insertText(int offset, const QString& text) override { replaceText(offset, offset, text); }
    void replaceText(int start, int end, const QString& text) override {
        if (pane()->isReadOnly()) return;
        auto c = pane()->textCursor();
        c.setPosition(clamped(start));
        c.setPosition(clamped(end), QTextCursor::KeepAnchor);
        c.insertText(text);
        pane()->setTextCursor(c);
    }

private:
    bool blank_cells_as_spaces_;

    QString shown() const {
        auto text = pane()->toPlainText();
        if (blank_cells_as_spaces_) text.replace(QChar(0x2800), QLatin1Char(' '));
        // A picture (an image object) is a space: its description is said when
        // the cursor comes to its paragraph (EditorWidget::structure_text), and
        // the bare object character is read as "object". Same length.
        text.replace(QChar::ObjectReplacementCharacter, QLatin1Char(' '));
        return text;
    }
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

QAccessibleInterface* make_accessible_plain_text(QPlainTextEdit* pane) {
    return new AccessibleTextPane<QPlainTextEdit>(pane, true);
}

QAccessibleInterface* make_accessible_rich_text(QTextEdit* pane) {
    return new AccessibleTextPane<QTextEdit>(pane, false);
}

}  // namespace tactus::gui
