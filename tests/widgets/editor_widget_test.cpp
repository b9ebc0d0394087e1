// SPDX-License-Identifier: GPL-3.0-or-later
// The editor widget: typing re-translates live, cursor and selection follow
// between print and braille, undo/redo through the QUndoStack, find/replace.
#include <QLineEdit>
#include <QSignalSpy>
#include <QTextBlock>
#include <QtTest>

#include "braille_pane.hpp"
#include "editor_widget.hpp"
#include "find_replace.hpp"
#include "gui_test_support.hpp"
#include "translate/translator.hpp"

using namespace tactus;
using namespace tactus::gui;

namespace {

QString braille(const std::string& table, const std::string& text) {
    auto t = translate::Translator::open(table);
    auto cells = t->translate(QString::fromStdString(text).toStdU32String());
    return QString::fromStdString(document::to_unicode_text(*cells));
}

}  // namespace

class EditorWidgetTest : public QObject {
    Q_OBJECT
    std::unique_ptr<EditorWidget> editor;

private Q_SLOTS:
    void init() {
        editor = std::make_unique<EditorWidget>();
        auto layout = edit::LiveLayout::create("en-ueb-g2.ctb", {});
        QVERIFY(layout.has_value());
        layout->reset(test::sample_lines("welcome.md"));
        editor->adopt(std::move(*layout));
        editor->resize(1000, 600);
        editor->show();
        QVERIFY(QTest::qWaitForWindowExposed(editor.get()));
    }
    void cleanup() { editor.reset(); }

    void braille_pane_shows_each_line_translated() {
        const auto lines = editor->braille_pane()->toPlainText().split(QLatin1Char('\n'));
        QCOMPARE(lines.size(), editor->print_pane()->document()->blockCount());
        QCOMPARE(lines[0], braille("en-ueb-g2.ctb", "Welcome to Braille"));
    }

    void typing_retranslates_the_line_live() {
        auto* print = editor->print_pane();
        print->setFocus();
        print->moveCursor(QTextCursor::End);
        QTest::keyClick(print, Qt::Key_Return);
        QTest::keyClicks(print, "the knowledge");
        const auto lines = editor->braille_pane()->toPlainText().split(QLatin1Char('\n'));
        QCOMPARE(lines.back(), braille("en-ueb-g2.ctb", "the knowledge"));
        QCOMPARE(editor->last_stats().lines_translated, std::size_t{1});
        // And the pages hold it: the last page's text ends with those words.
        const auto& pages = editor->layout().paged().pages;
        bool found = false;
        const auto expected = braille("en-ueb-g2.ctb", "the knowledge").toStdU32String();
        for (const auto& l : pages.back().lines)
            found = found || QString::fromStdString(document::to_unicode_text(l)).toStdU32String().find(expected) != std::u32string::npos;
        QVERIFY(found);
    }

    void undo_and_redo_go_through_the_undo_stack() {
        auto* print = editor->print_pane();
        const auto before = editor->text();
        const auto braille_before = editor->braille_pane()->toPlainText();
        print->setFocus();
        print->moveCursor(QTextCursor::Start);
        print->moveCursor(QTextCursor::EndOfBlock);
        QTest::keyClicks(print, " again");
        QVERIFY(editor->undo_stack()->canUndo());
        editor->undo_stack()->undo();
        QCOMPARE(editor->text(), before);
        QCOMPARE(editor->braille_pane()->toPlainText(), braille_before);
        editor->undo_stack()->redo();
        QVERIFY(editor->text().startsWith(QStringLiteral("# Welcome to Braille again")));
        // Ctrl+Z in the print pane must not bypass the stack (it is the window's shortcut).
        QKeyEvent override(QEvent::ShortcutOverride, Qt::Key_Z, Qt::ControlModifier);
        QApplication::sendEvent(print, &override);
        QVERIFY(!override.isAccepted());
    }

    void cursor_follows_word_by_word() {
        auto* print = editor->print_pane();
        // Line 1: "Braille is a tactile writing system. ..." Put the cursor on "tactile".
        const auto block = print->document()->findBlockByNumber(1);
        const int col = static_cast<int>(block.text().indexOf(QStringLiteral("tactile")));
        QTextCursor c(block);
        c.setPosition(block.position() + col);
        print->setTextCursor(c);
        const auto bc = editor->braille_pane()->textCursor();
        QCOMPARE(bc.blockNumber(), 1);
        // The braille cursor sits at the start of the fourth braille word.
        const auto cells = editor->layout().braille_of(1);
        int words = 0;
        std::size_t start = 0;
        for (std::size_t i = 0; i < cells.size(); ++i)
            if (!cells[i].blank() && (i == 0 || cells[i - 1].blank()) && ++words == 4) start = i;
        QCOMPARE(static_cast<std::size_t>(bc.positionInBlock()), start);
        // And back: a braille cursor on that word puts the print cursor on "tactile".
        editor->print_pane()->moveCursor(QTextCursor::Start);
        QTextCursor b2(editor->braille_pane()->document()->findBlockByNumber(1));
        b2.setPosition(b2.position() + static_cast<int>(start));
        editor->braille_pane()->setTextCursor(b2);
        QCOMPARE(editor->print_pane()->textCursor().positionInBlock(), col);
    }

    void selection_follows() {
        auto* print = editor->print_pane();
        const auto block = print->document()->findBlockByNumber(0);  // the heading "Welcome to Braille"
        QTextCursor c(block);
        c.setPosition(block.position());
        c.setPosition(block.position() + 7, QTextCursor::KeepAnchor);  // "Welcome"
        print->setTextCursor(c);
        const auto sel = editor->braille_pane()->textCursor().selectedText();
        QCOMPARE(sel, braille("en-ueb-g2.ctb", "Welcome"));
    }

    void find_and_replace_one_undo_step() {
        FindReplaceDialog dialog(editor->print_pane());
        dialog.set_find_text(QStringLiteral("braille"));
        auto* replace = dialog.findChildren<QLineEdit*>().at(1);
        replace->setText(QStringLiteral("Braille code"));
        const auto before = editor->text();
        QVERIFY(dialog.find_next());
        QCOMPARE(editor->print_pane()->textCursor().selectedText().toLower(), QStringLiteral("braille"));
        const int n = dialog.replace_all();
        QCOMPARE(n, static_cast<int>(before.count(QStringLiteral("braille"), Qt::CaseInsensitive)));
        QVERIFY(editor->text().contains(QStringLiteral("Braille code")));
        QVERIFY(editor->braille_pane()->toPlainText().contains(braille("en-ueb-g2.ctb", "code")));
        editor->undo_stack()->undo();
        QCOMPARE(editor->text(), before);
    }

    void editing_braille_directly_pins_the_cells() {
        auto* pane = editor->braille_pane();
        pane->setFocus();
        QTextCursor c(pane->document()->findBlockByNumber(0));
        pane->setTextCursor(c);
        QTest::keyClick(pane, Qt::Key_Delete);  // erase the first cell of the heading
        const auto expected = braille("en-ueb-g2.ctb", "Welcome to Braille").mid(1);
        QCOMPARE(editor->print_pane()->document()->findBlockByNumber(0).text(), expected);
        QCOMPARE(pane->document()->findBlockByNumber(0).text(), expected);
        // The line is braille now: its cells appear on the page as written.
        const auto& first = editor->layout().paged().pages.front().lines.front();
        QCOMPARE(QString::fromStdString(document::to_unicode_text(first)), expected);
    }

    void large_paste_is_one_edit() {
        auto* print = editor->print_pane();
        print->moveCursor(QTextCursor::End);
        const auto lines = test::synthetic_book(300);
        QStringList text;
        for (const auto& l : lines) text << QString::fromStdString(l);
        print->insertPlainText(QLatin1Char('\n') + text.join(QLatin1Char('\n')));
        QCOMPARE(editor->braille_pane()->document()->blockCount(), print->document()->blockCount());
        std::vector<std::string> all;
        for (const auto& l : editor->text().split(QLatin1Char('\n'))) all.push_back(l.toStdString());
        QCOMPARE(all.size(), lines.size() + test::sample_lines("welcome.md").size());
        auto fresh = edit::LiveLayout::create("en-ueb-g2.ctb", {});
        fresh->reset(all);
        QVERIFY(fresh->paged().pages == editor->layout().paged().pages);
    }

    // A text file's form feed must not show and say nothing. Its
    // line is drawn as a page break with its print page, and the cursor coming
    // to it says "Print page break, page 2"; the text saved is unchanged.
    void a_form_feed_line_is_shown_and_spoken_as_a_page_break() {
        auto layout = edit::LiveLayout::create("en-ueb-g2.ctb", {});
        QVERIFY(layout.has_value());
        layout->set_dialect(edit::Dialect::text);
        layout->reset({"one", "\f", "two", "---"});
        editor->adopt(std::move(*layout));
        QCOMPARE(editor->page_break_text(1), QStringLiteral("Print page break, page 2"));
        QVERIFY(editor->page_break_text(0).isEmpty());
        QVERIFY(editor->page_break_text(3).isEmpty());  // "---" is text in a text file
        QSignalSpy spoken(editor.get(), &EditorWidget::page_break_reached);
        auto* print = editor->print_pane();
        print->setFocus();
        auto c = print->textCursor();
        c.setPosition(print->document()->findBlockByNumber(1).position());
        print->setTextCursor(c);
        QCOMPARE(spoken.count(), 1);
        QCOMPARE(spoken.front().front().toString(), QStringLiteral("Print page break, page 2"));
        c.setPosition(print->document()->findBlockByNumber(2).position());
        print->setTextCursor(c);
        QCOMPARE(spoken.count(), 1);  // an ordinary line says nothing more
        // The rule is drawn on the form feed's line and nowhere else: the
        // line's pixels hold the marker's ink, the blank line's none.
        const auto image = print->viewport()->grab().toImage();
        const auto ink_in = [&](int line) {
            QTextCursor at(print->document()->findBlockByNumber(line));
            const QRectF box = print->cursorRect(at);
            const auto background = image.pixel(image.width() - 2, static_cast<int>(box.top()) + 1);
            int ink = 0;
            for (int y = static_cast<int>(box.top()); y < static_cast<int>(box.bottom()); ++y)
                for (int x = static_cast<int>(print->width() * 0.6); x < image.width() - 6; ++x)
                    if (image.pixel(x, y) != background) ++ink;
            return ink;
        };
        QVERIFY(ink_in(1) > 0);
        QCOMPARE(ink_in(0), 0);
        // A form feed inside a line starts a page as well, and says so.
        auto inside = edit::LiveLayout::create("en-ueb-g2.ctb", {});
        QVERIFY(inside.has_value());
        inside->set_dialect(edit::Dialect::text);
        inside->reset({"one", "\fChapter two", "text", "end\fthree"});
        editor->adopt(std::move(*inside));
        QCOMPARE(editor->page_break_text(1), QStringLiteral("Print page break, page 2"));
        QVERIFY(editor->page_break_text(2).isEmpty());
        QCOMPARE(editor->page_break_text(3), QStringLiteral("Print page break, page 3"));
        // Saved as text, the form feed line is the form feed it was (the
        // lines as they are: a last line end is an empty last line).
        QCOMPARE(QString::fromStdString(edit::file_text(std::vector<std::string>{"one", "\f", "two", "---", ""},
                                                        edit::Dialect::text, editor->layout().document(), "t.txt")),
                 QStringLiteral("one\n\f\ntwo\n---\n"));
    }
};

QTEST_MAIN(EditorWidgetTest)
#include "editor_widget_test.moc"
