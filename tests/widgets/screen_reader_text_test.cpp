// SPDX-License-Identifier: GPL-3.0-or-later
// What the accessibility layer hands a screen reader, checked through
// QAccessible as AT-SPI reads it: status labels carry their text with their
// caption (a fixed name hid the status), an announcement has no description (a
// cached one made Orca repeat the previous message). The print word the preview
// names is core's (tests/edit/print_word_test.cpp).
#include <QAccessible>
#include <QLabel>
#include <QtTest>

#include "announcer.hpp"
#include "edit/live_layout.hpp"
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
};

QTEST_MAIN(ScreenReaderTextTest)
#include "screen_reader_text_test.moc"
