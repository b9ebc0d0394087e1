// SPDX-License-Identifier: GPL-3.0-or-later
// What assistive technology is told when Tab reaches a text entry, in order.
// Run on X with accessibility on (tests/accessibility/x11_session.sh): Qt
// sends accessibility events only when a platform bridge is active, which the
// offscreen platform of the other widget tests never is.
#include <QAccessible>
#include <QLineEdit>
#include <QVBoxLayout>
#include <QtTest>

#include <utility>
#include <vector>

#include "entry_focus.hpp"

using namespace tactus::gui;

namespace {

std::vector<std::pair<QAccessible::Event, QString>> g_told;

void record_told(QAccessibleEvent* event) {
    auto* object = event->object();
    g_told.emplace_back(event->type(), object ? object->objectName() : QString());
}

struct Told {
    std::size_t focus;
    std::size_t first_caret;  // the first selection or caret event
    std::size_t count;
};

// Tab from one entry to the next (holding "3-10"), recording what is told.
Told tab_into_entry(bool spoken, QString* typed_after) {
    QWidget window;
    auto* before = new QLineEdit(&window);
    before->setObjectName(QStringLiteral("before"));
    auto* entry = new QLineEdit(QStringLiteral("3-10"), &window);
    entry->setObjectName(QStringLiteral("entry"));
    if (spoken) speak_entry_on_focus(entry);
    auto* layout = new QVBoxLayout(&window);
    layout->addWidget(before);
    layout->addWidget(entry);
    window.show();
    window.activateWindow();
    if (!QTest::qWaitForWindowActive(&window)) return {0, 0, 0};
    before->setFocus();
    const auto previous = QAccessible::installUpdateHandler(record_told);
    g_told.clear();
    QTest::keyClick(before, Qt::Key_Tab);
    QTest::qWait(50);
    QCoreApplication::processEvents();
    QAccessible::installUpdateHandler(previous);
    const std::size_t none = g_told.size();
    Told told{none, none, none};
    for (std::size_t i = 0; i < g_told.size(); ++i) {
        if (g_told[i].second != QStringLiteral("entry")) continue;
        if (g_told[i].first == QAccessible::Focus && told.focus == none) told.focus = i;
        if ((g_told[i].first == QAccessible::TextCaretMoved || g_told[i].first == QAccessible::TextSelectionChanged) &&
            told.first_caret == none)
            told.first_caret = i;
    }
    // What is typed after Tab replaces the entry's text, as in any entry.
    QTest::keyClicks(entry, QStringLiteral("5-"));
    *typed_after = entry->text();
    return told;
}

}  // namespace

class EntryFocusTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        // The bridge turns itself on once it has reached the AT-SPI bus.
        QTRY_VERIFY2_WITH_TIMEOUT(QAccessible::isActive(), "no accessibility bridge: run under tests/accessibility/x11_session.sh", 20000);
    }

    // Orca takes the object of a selection or caret event as focused,
    // silently; a focus event after it then changes nothing and the entry is
    // never named. Qt's own order is that one, which is why the entry needs
    // speak_entry_on_focus.
    void qt_alone_moves_the_caret_before_the_focus() {
        QString typed;
        const auto told = tab_into_entry(false, &typed);
        QVERIFY(told.focus < told.count);
        QVERIFY2(told.first_caret < told.focus, "Qt's own order changed: speak_entry_on_focus may be needless");
        QCOMPARE(typed, QStringLiteral("5-"));
    }

    void a_spoken_entry_is_focused_before_its_caret_moves() {
        QString typed;
        const auto told = tab_into_entry(true, &typed);
        QVERIFY(told.focus < told.count);
        QVERIFY2(told.focus < told.first_caret, "the caret moved before the entry was told focused");
        QCOMPARE(typed, QStringLiteral("5-"));
    }
};

QTEST_MAIN(EntryFocusTest)
#include "entry_focus_test.moc"
