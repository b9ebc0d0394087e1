// SPDX-License-Identifier: GPL-3.0-or-later
// Alt+letter must do one thing. Walks every window of the app (the main window
// with all its docks, the find dialog, the keyboard shortcuts dialog) and every
// menu, and fails when two controls in one scope share a mnemonic: in a window,
// the menu bar's titles, buttons, check boxes and labels with a buddy; in a menu,
// its items. A clash makes Alt+P press "Pause" or tick "Compare profile shapes"
// depending on which Qt finds first, and a screen reader announces both as Alt+P.
#include <QAbstractButton>
#include <QApplication>
#include <QDialog>
#include <QGroupBox>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QTabBar>
#include <QTimer>
#include <QToolButton>
#include <QtTest>

#include "main_window.hpp"

using namespace tactus::gui;

namespace {

// The mnemonic letter of a text ("Ca&ncel" -> 'n'), or 0. "&&" is a literal '&'.
QChar mnemonic(const QString& text) {
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text[i] != QLatin1Char('&')) continue;
        if (text[i + 1] == QLatin1Char('&')) {
            ++i;
            continue;
        }
        return text[i + 1].toLower();
    }
    return {};
}

struct Owner {
    QString what;
    QString text;
};

// Mnemonics that Alt+letter reaches in the window `window` (not in its child windows).
QMap<QChar, QList<Owner>> window_scope(QWidget* window) {
    QMap<QChar, QList<Owner>> out;
    const auto add = [&](const QString& what, const QString& text) {
        if (const auto m = mnemonic(text); !m.isNull()) out[m].append({what, text});
    };
    for (auto* w : window->findChildren<QWidget*>()) {
        if (w->window() != window) continue;  // a dialog or floating dock: its own scope
        if (qobject_cast<QMenu*>(w)) continue;
        // A tool button showing an action shows its icon text, which has no mnemonic.
        if (auto* b = qobject_cast<QAbstractButton*>(w); b && !qobject_cast<QToolButton*>(w))
            add(QStringLiteral("button"), b->text());
        if (auto* l = qobject_cast<QLabel*>(w); l && l->buddy()) add(QStringLiteral("label"), l->text());
        if (auto* g = qobject_cast<QGroupBox*>(w)) add(QStringLiteral("group"), g->title());
        if (auto* t = qobject_cast<QTabBar*>(w))
            for (int i = 0; i < t->count(); ++i) add(QStringLiteral("tab"), t->tabText(i));
    }
    if (auto* mw = qobject_cast<QMainWindow*>(window); mw && mw->menuBar())
        for (auto* a : mw->menuBar()->actions()) add(QStringLiteral("menu"), a->text());
    return out;
}

QMap<QChar, QList<Owner>> menu_scope(QMenu* menu) {
    QMap<QChar, QList<Owner>> out;
    for (auto* a : menu->actions())
        if (!a->isSeparator())
            if (const auto m = mnemonic(a->text()); !m.isNull()) out[m].append({QStringLiteral("item"), a->text()});
    return out;
}

QStringList clashes(const QString& scope, const QMap<QChar, QList<Owner>>& map) {
    QStringList out;
    for (auto it = map.begin(); it != map.end(); ++it) {
        if (it.value().size() < 2) continue;
        QStringList who;
        for (const auto& o : it.value()) who << QStringLiteral("%1 \"%2\"").arg(o.what, o.text);
        out << QStringLiteral("%1: Alt+%2 is %3").arg(scope, it.key().toUpper(), who.join(QStringLiteral(", ")));
    }
    return out;
}

}  // namespace

class MnemonicsTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    // Off Windows a lone Alt leaves the focus where it is: the menu bar took
    // the Alt of Alt+P, Orca said "File." and the next key opened a menu.
    void a_lone_alt_leaves_the_focus_where_it_is() {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QApplication::setActiveWindow(&w);
        auto* focus = QApplication::focusWidget();
        QVERIFY(focus);
        // Through the window system, as a real key arrives: the menu bar
        // watches the window's key events, not the focus widget's.
        QTest::keyPress(w.windowHandle(), Qt::Key_Alt, Qt::AltModifier);
        QTest::keyRelease(w.windowHandle(), Qt::Key_Alt, Qt::NoModifier);
        QTest::qWait(20);
        const auto* active = w.menuBar()->activeAction();
        QVERIFY2(!active, qPrintable(active ? active->text() : QString()));
        QCOMPARE(QApplication::focusWidget(), focus);
        // The menus are still one key away.
        QTest::keyClick(w.windowHandle(), Qt::Key_F10);
        QVERIFY(w.menuBar()->activeAction());
    }

    void the_parser_reads_mnemonics() {
        QCOMPARE(mnemonic(QStringLiteral("Ca&ncel")), QChar(u'n'));
        QCOMPARE(mnemonic(QStringLiteral("Fish && &Chips")), QChar(u'c'));
        QVERIFY(mnemonic(QStringLiteral("No mnemonic")).isNull());
        QVERIFY(mnemonic(QStringLiteral("R&&D")).isNull());
    }

    void every_scope_has_unique_mnemonics() {
        MainWindow w;
        w.show();
        QStringList problems;
        int scopes = 0;
        // The main window with every dock; then each child window (find dialog...).
        QList<QWidget*> windows{&w};
        for (auto* c : w.findChildren<QWidget*>())
            if (c->isWindow() && !qobject_cast<QMenu*>(c) && !windows.contains(c)) windows << c;
        for (auto* win : windows) {
            problems << clashes(win->objectName().isEmpty() ? QString::fromLatin1(win->metaObject()->className())
                                                              : win->objectName(),
                                window_scope(win));
            ++scopes;
        }
        for (auto* menu : w.findChildren<QMenu*>()) {
            problems << clashes(QStringLiteral("menu \"%1\"").arg(menu->title()), menu_scope(menu));
            ++scopes;
        }
        // The keyboard shortcuts dialog is modal: inspect it while it is open.
        QTimer::singleShot(0, &w, [&] {
            for (auto* d : QApplication::topLevelWidgets())
                if (auto* dialog = qobject_cast<QDialog*>(d); dialog && dialog->isVisible()) {
                    problems << clashes(dialog->windowTitle(), window_scope(dialog));
                    ++scopes;
                    dialog->reject();
                }
        });
        for (auto* a : w.all_actions())
            if (a->objectName() == QLatin1String("helpShortcuts")) a->trigger();
        QVERIFY(scopes >= 6);
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }
};

QTEST_MAIN(MnemonicsTest)
#include "mnemonics_test.moc"
