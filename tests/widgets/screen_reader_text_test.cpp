// SPDX-License-Identifier: GPL-3.0-or-later
// What the accessibility layer hands a screen reader, checked through
// QAccessible as AT-SPI reads it: status labels carry their text with their
// caption (a fixed name hid the status), an announcement has no description (a
// cached one made Orca repeat the previous message), and the preview names the
// print word that produced a cell, not a back-translation of its braille.
#include <QAccessible>
#include <QLabel>
#include <QtTest>

#include "announcer.hpp"
#include "edit/live_layout.hpp"
#include "print_word.hpp"
#include "status_label.hpp"

using namespace tactus;
using namespace tactus::gui;

class ScreenReaderTextTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { install_accessibility(); }

    void a_status_label_is_named_by_its_caption_and_text() {
        QLabel label;
        expose_status(&label, QStringLiteral("Controller status"));
        label.setText(QStringLiteral("Connected to sim: idle"));
        auto* a = QAccessible::queryAccessibleInterface(&label);
        QVERIFY(a);
        QCOMPARE(a->text(QAccessible::Name), QStringLiteral("Controller status: Connected to sim: idle"));
        QCOMPARE(a->role(), QAccessible::StaticText);
        label.setText(QStringLiteral("<b>Paper out</b>: put paper in the feeder"));
        QCOMPARE(a->text(QAccessible::Name), QStringLiteral("Controller status: Paper out: put paper in the feeder"));
        label.clear();
        QCOMPARE(a->text(QAccessible::Name), QStringLiteral("Controller status"));
    }

    void other_labels_keep_their_own_names() {
        QLabel label(QStringLiteral("Plain"));
        QVERIFY(status_caption(&label).isEmpty());
        QCOMPARE(QAccessible::queryAccessibleInterface(&label)->text(QAccessible::Name), QStringLiteral("Plain"));
    }

    void an_announcement_has_no_stale_description() {
        Announcer a;
        a.announce(QStringLiteral("Opened welcome.md: 1 sheet(s)"));
        a.announce(QStringLiteral("Braille table: English uncontracted"));
        auto* i = QAccessible::queryAccessibleInterface(&a);
        QCOMPARE(i->text(QAccessible::Name), QStringLiteral("Braille table: English uncontracted"));
        QVERIFY(i->text(QAccessible::Description).isEmpty());
    }

    void the_preview_names_the_print_word() {
        auto l = edit::LiveLayout::create("en-ueb-g2.ctb", {});
        QVERIFY(l);
        l->reset({"See you on FRIDAY, at noon."});
        const auto cells = l->braille_of(0);
        QVERIFY(!cells.empty());
        // Every non-blank cell of the paragraph names a word of the print line as written.
        const QStringList words{QStringLiteral("See"), QStringLiteral("you"), QStringLiteral("on"),
                                QStringLiteral("FRIDAY,"), QStringLiteral("at"), QStringLiteral("noon.")};
        QStringList seen;
        for (std::size_t k = 0; k < cells.size(); ++k) {
            if (cells[k].blank()) continue;
            const auto word = print_word_at(*l, l->position_of(0, k));
            QVERIFY2(words.contains(word), qPrintable(QStringLiteral("cell %1: \"%2\"").arg(k).arg(word)));
            if (seen.isEmpty() || seen.back() != word) seen << word;
        }
        QCOMPARE(seen, words);
    }

    void chinese_names_the_character_written() {
        auto l = edit::LiveLayout::create("zh-tw.ctb", {});
        QVERIFY(l);
        l->reset({"今天星期五"});
        const auto cells = l->braille_of(0);
        QString heard;
        for (std::size_t k = 0; k < cells.size(); ++k) {
            if (cells[k].blank()) continue;
            const auto word = print_word_at(*l, l->position_of(0, k));
            QCOMPARE(word.size(), 1);  // one ideograph of the line, never another one
            QVERIFY2(QStringLiteral("今天星期五").contains(word), qPrintable(word));
            if (!heard.endsWith(word)) heard += word;
        }
        QCOMPARE(heard, QStringLiteral("今天星期五"));
    }
};

QTEST_MAIN(ScreenReaderTextTest)
#include "screen_reader_text_test.moc"
