// SPDX-License-Identifier: GPL-3.0-or-later
// Six-key chords: committed on the last release, auto-repeat ignored, mapping
// configurable; and typed into the braille pane they become the paragraph's braille.
#include <QTextBlock>
#include <QtTest>

#include "braille_pane.hpp"
#include "editor_widget.hpp"
#include "six_key.hpp"

using namespace tactus;
using namespace tactus::gui;


class SixKeyTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void chord_commits_on_last_release() {
        SixKeyChord chord;
        QVERIFY(chord.press(Qt::Key_F, false));  // dot 1
        QVERIFY(chord.press(Qt::Key_K, false));  // dot 5
        QVERIFY(chord.press(Qt::Key_D, false));  // dot 2
        QVERIFY(!chord.release(Qt::Key_F, false).has_value());
        QVERIFY(!chord.release(Qt::Key_D, false).has_value());
        const auto cell = chord.release(Qt::Key_K, false);
        QVERIFY(cell.has_value());
        QCOMPARE(document::dot_numbers(*cell), std::string("1-2-5"));  // h
        QVERIFY(!chord.active());
    }

    void default_keys_are_perkins_layout() {
        SixKeyChord chord;
        const int keys[] = {Qt::Key_S, Qt::Key_D, Qt::Key_F, Qt::Key_J, Qt::Key_K, Qt::Key_L};
        const char* dots[] = {"3", "2", "1", "4", "5", "6"};
        for (int i = 0; i < 6; ++i) {
            chord.press(keys[i], false);
            QCOMPARE(document::dot_numbers(*chord.release(keys[i], false)), std::string(dots[i]));
        }
    }

    void auto_repeat_is_ignored() {
        SixKeyChord chord;
        chord.press(Qt::Key_F, false);
        for (int i = 0; i < 5; ++i) {
            QVERIFY(chord.press(Qt::Key_F, true));
            QVERIFY(!chord.release(Qt::Key_F, true).has_value());  // repeat releases too
        }
        const auto cell = chord.release(Qt::Key_F, false);
        QVERIFY(cell && cell->dots == 1);
        QVERIFY(!chord.release(Qt::Key_F, false).has_value());  // nothing held any more
    }

    void mapping_is_configurable_and_other_keys_pass() {
        SixKeyChord chord({Qt::Key_1, Qt::Key_2, Qt::Key_3, Qt::Key_4, Qt::Key_5, Qt::Key_6});
        QVERIFY(!chord.press(Qt::Key_F, false));
        chord.press(Qt::Key_6, false);
        chord.press(Qt::Key_1, false);
        chord.release(Qt::Key_1, false);
        QCOMPARE(document::dot_numbers(*chord.release(Qt::Key_6, false)), std::string("1-6"));
        chord.press(Qt::Key_2, false);
        chord.cancel();
        QVERIFY(!chord.active());
    }

    void chords_space_and_backspace_in_the_braille_pane() {
        EditorWidget editor;
        auto layout = edit::LiveLayout::create("en-ueb-g1.ctb", {});
        QVERIFY(layout.has_value());
        layout->reset({""});
        editor.adopt(std::move(*layout));
        editor.show();
        auto* pane = editor.braille_pane();
        pane->setFocus();
        const auto chord = [&](std::initializer_list<Qt::Key> keys) {
            for (auto k : keys) QTest::keyPress(pane, k);
            for (auto k : keys) QTest::keyRelease(pane, k);
        };
        chord({Qt::Key_F, Qt::Key_D, Qt::Key_K});  // h: 1-2-5
        chord({Qt::Key_F, Qt::Key_K});             // e: 1-5
        QTest::keyClick(pane, Qt::Key_Space);
        chord({Qt::Key_F});                        // a
        chord({Qt::Key_F, Qt::Key_D});             // b (typed by mistake)
        QTest::keyClick(pane, Qt::Key_Backspace);
        QCOMPARE(editor.text(), QStringLiteral("\u2813\u2811\u2800\u2801"));
        QCOMPARE(editor.braille_pane()->toPlainText(), editor.text());
        QCOMPARE(editor.layout().paged().pages.front().lines.front().size(), std::size_t{4});
        // One undo step per edit, through the window's stack.
        editor.undo_stack()->undo();
        QCOMPARE(editor.text(), QStringLiteral("\u2813\u2811\u2800\u2801\u2803"));
        editor.undo_stack()->redo();
        QCOMPARE(editor.text(), QStringLiteral("\u2813\u2811\u2800\u2801"));
    }

    // A chord inserts its one cell into the braille pane, so a
    // screen reader echoes that cell; it used to replace the whole paragraph
    // (Orca echoed nothing), and the caret, the status and the preview cursor
    // jumped to cell 1.
    void a_chord_inserts_only_its_cell_and_the_caret_follows() {
        EditorWidget editor;
        auto layout = edit::LiveLayout::create("en-ueb-g1.ctb", {});
        QVERIFY(layout.has_value());
        layout->reset({"hello world", "second line"});
        editor.adopt(std::move(*layout));
        editor.show();
        QVERIFY(QTest::qWaitForWindowExposed(&editor));
        auto* pane = editor.braille_pane();
        pane->setFocus();
        const auto before = pane->document()->findBlockByNumber(0).text();
        const int at = 3;
        QTextCursor c(pane->document()->findBlockByNumber(0));
        c.setPosition(c.position() + at);
        pane->setTextCursor(c);
        std::vector<edit::PagePosition> reported;
        connect(&editor, &EditorWidget::position_changed, &editor,
                [&](const edit::PagePosition& p) { reported.push_back(p); });

        // Every change of the pane's document is what Qt's text control reports
        // to AT-SPI as object:text-changed (insert, delete or both): record them.
        struct Change {
            int position, removed, added;
        };
        std::vector<Change> changes;
        connect(pane->document(), &QTextDocument::contentsChange, &editor,
                [&](int position, int removed, int added) { changes.push_back({position, removed, added}); });
        for (auto k : {Qt::Key_F, Qt::Key_D}) QTest::keyPress(pane, k);  // b: dots 1 2
        for (auto k : {Qt::Key_F, Qt::Key_D}) QTest::keyRelease(pane, k);

        const auto after = pane->document()->findBlockByNumber(0).text();
        QCOMPARE(after, before.left(at) + QChar(0x2803) + before.mid(at));
        // The pane's text changes by exactly that cell: one insertion, nothing removed.
        QCOMPARE(changes.size(), std::size_t{1});
        QCOMPARE(changes.front().position, at);
        QCOMPARE(changes.front().removed, 0);
        QCOMPARE(changes.front().added, 1);
        // The caret stands after the new cell, in the pane, the status and the preview.
        QCOMPARE(pane->textCursor().blockNumber(), 0);
        QCOMPARE(pane->textCursor().positionInBlock(), at + 1);
        QCOMPARE(editor.current_cell(), std::size_t(at + 1));
        const auto want = editor.layout().position_of(0, std::size_t(at + 1));
        QVERIFY(!reported.empty());
        for (const auto& p : reported) {
            QCOMPARE(p.page, want.page);
            QCOMPARE(p.line, want.line);
            QCOMPARE(p.cell, want.cell);
        }
    }
};

QTEST_MAIN(SixKeyTest)
#include "six_key_test.moc"
