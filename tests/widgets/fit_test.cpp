// SPDX-License-Identifier: GPL-3.0-or-later
// Nothing a user reads is cut off: every main view, in
// English and in zh_TW, at 1280 x 800 and 1920 x 1080. Each visible label,
// button, tab and header is checked against the room it was given, and a
// screenshot of each view is saved for CI's artefacts
// (TACTUS_SCREENSHOT_DIR, default: screenshots/ in the working directory).
// The question asked at start, before any window, is in zh_TW too.
#include <QAbstractAxis>
#include <QAbstractButton>
#include <QChart>
#include <QChartView>
#include <QGraphicsSimpleTextItem>
#include <QGraphicsTextItem>
#include <QDir>
#include <QDockWidget>
#include <QGroupBox>
#include <QHeaderView>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMessageBox>
#include <QTabBar>
#include <QToolBar>
#include <QToolButton>
#include <QTranslator>
#include <QtTest>

#include "announcer.hpp"
#include "autosave.hpp"
#include "gui_test_support.hpp"
#include "main_window.hpp"

using namespace tactus;
using namespace tactus::gui;

namespace {

QString plain(QString text) {
    text.remove(QRegularExpression(QStringLiteral("<[^>]*>")));
    // A mnemonic's & is not drawn; "&&" is one drawn ampersand.
    text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
    text.remove(QLatin1Char('&'));
    text.replace(QLatin1Char('\x01'), QLatin1Char('&'));
    return text;
}

QString describe(const QWidget* w, const QString& text, int need, int have) {
    return QStringLiteral("%1 '%2' \"%3\" needs %4 px, has %5")
        .arg(QString::fromLatin1(w->metaObject()->className()), w->objectName(), text)
        .arg(need)
        .arg(have);
}

// Tabified docks keep isVisible() when another tab is raised, and offscreen
// windows have no visible region: a widget in a dock is drawn when its dock is
// the raised tab of the main window's dock tab bar (or in no tab bar at all).
bool drawn(QWidget* root, QWidget* w) {
    QDockWidget* dock = nullptr;
    for (auto* p = w; p && !dock; p = p->parentWidget()) dock = qobject_cast<QDockWidget*>(p);
    if (!dock) return true;
    for (auto* bar : root->findChildren<QTabBar*>(Qt::FindDirectChildrenOnly)) {
        for (int i = 0; i < bar->count(); ++i)
            if (bar->tabText(i) == dock->windowTitle()) return i == bar->currentIndex();
    }
    return true;
}

// A chart draws its titles, legend and axis labels as scene text items, and
// elides them with "..." when there is no room; an axis says so itself.
void clipped_in_chart(QChartView* view, QStringList& out) {
    const auto name = QStringLiteral("QChartView '%1'").arg(view->objectName());
    for (auto* item : view->scene()->items()) {
        if (!item->isVisible()) continue;
        QString text;
        if (auto* simple = dynamic_cast<QGraphicsSimpleTextItem*>(item)) text = simple->text();
        else if (auto* rich = dynamic_cast<QGraphicsTextItem*>(item)) text = rich->toPlainText();
        if (text.contains(QStringLiteral("...")) || text.contains(QChar(0x2026)))
            out << QStringLiteral("%1 draws \"%2\"").arg(name, text);
    }
    for (auto* axis : view->chart()->axes())
        if (axis->isVisible() && axis->labelsTruncated())
            out << QStringLiteral("%1: axis '%2' truncates its labels").arg(name, axis->titleText());
}

// What is drawn narrower than its text, in the visible part of the window.
QStringList clipped(QWidget* root) {
    QStringList out;
    for (auto* w : root->findChildren<QWidget*>()) {
        if (!w->isVisible() || w->width() <= 1 || !drawn(root, w)) continue;
        if (auto* chart = qobject_cast<QChartView*>(w)) {
            clipped_in_chart(chart, out);
        } else if (auto* bar = qobject_cast<QToolBar*>(w)) {
            // Actions that do not fit go behind the extension button ("»").
            const auto name = QStringLiteral("qt_toolbar_ext_button");
            for (auto* more : bar->findChildren<QToolButton*>(name, Qt::FindDirectChildrenOnly))
                if (more->isVisible()) out << QStringLiteral("QToolBar '%1' hides actions behind \u00bb").arg(bar->objectName());
        } else if (auto* l = qobject_cast<QLabel*>(w)) {
            if (l->wordWrap() || l->text().isEmpty()) continue;
            const int need = l->minimumSizeHint().width();
            if (need > l->width()) out << describe(l, plain(l->text()), need, l->width());
        } else if (auto* b = qobject_cast<QAbstractButton*>(w)) {
            if (b->text().isEmpty()) continue;
            const int need = b->minimumSizeHint().width();
            if (need > b->width()) out << describe(b, plain(b->text()), need, b->width());
        } else if (auto* g = qobject_cast<QGroupBox*>(w)) {
            const int need = g->fontMetrics().horizontalAdvance(plain(g->title())) + 16;
            if (need > g->width()) out << describe(g, plain(g->title()), need, g->width());
        } else if (auto* t = qobject_cast<QTabBar*>(w)) {
            for (int i = 0; i < t->count(); ++i) {
                const auto text = plain(t->tabText(i));
                const int need = t->fontMetrics().horizontalAdvance(text);
                if (need > t->tabRect(i).width()) out << describe(t, text, need, t->tabRect(i).width());
            }
        } else if (auto* h = qobject_cast<QHeaderView*>(w)) {
            if (!h->model()) continue;
            for (int i = 0; i < h->count(); ++i) {
                if (h->isSectionHidden(i)) continue;
                const auto text = h->model()->headerData(i, h->orientation()).toString();
                // The header's own measure of its text with the style's margins.
                const int need = h->orientation() == Qt::Horizontal ? h->sectionSizeHint(i)
                                                                    : h->fontMetrics().horizontalAdvance(text);
                const int have = h->orientation() == Qt::Horizontal ? h->sectionSize(i) : h->width();
                if (need > have) out << describe(h, text, need, have);
            }
        }
    }
    return out;
}

}  // namespace

class FitTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("TactusTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tactus-fit-test"));
        QSettings().clear();
        install_accessibility();
    }

    void every_view_fits_its_text_data() {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QSize>("size");
        for (const auto* lang : {"en", "zh_TW"})
            for (const auto size : {QSize(1280, 800), QSize(1920, 1080)})
                QTest::addRow("%s %dx%d", lang, size.width(), size.height()) << QString::fromLatin1(lang) << size;
    }

    void every_view_fits_its_text() {
        QFETCH(QString, language);
        QFETCH(QSize, size);
        QTranslator translator;
        if (language != QLatin1String("en")) {
            QVERIFY2(translator.load(QStringLiteral("tactus_") + language, QStringLiteral(TACTUS_QM_DIR)),
                     "the app's .qm file is not built");
            QCoreApplication::installTranslator(&translator);
        }
        const auto restore = qScopeGuard([&] {
            QCoreApplication::removeTranslator(&translator);
            QLocale::setDefault(QLocale(QLocale::English));
        });
        QLocale::setDefault(QLocale(language));
        const auto shots = QDir(qEnvironmentVariable("TACTUS_SCREENSHOT_DIR", QStringLiteral("screenshots")));
        QVERIFY(QDir().mkpath(shots.path()));

        MainWindow w;
        w.set_interactive(false);
        w.resize(size);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        // The motion and vibration views show their tables and charts only
        // for a plan: check them full, as a technician sees them.
        const auto plan = w.plan_now();
        QVERIFY(plan && !plan->error);
        QStringList problems;
        for (const auto* panel : {"preview", "motion", "vibration", "profile", "printer"}) {
            w.show_panel(QString::fromLatin1(panel));
            QTest::qWait(20);  // the layout settles the new view
            for (const auto& p : clipped(&w)) problems << QStringLiteral("%1: %2").arg(QString::fromLatin1(panel), p);
            const auto file = shots.filePath(
                QStringLiteral("%1-%2-%3x%4.png").arg(language, QString::fromLatin1(panel)).arg(size.width()).arg(size.height()));
            QVERIFY2(w.grab().save(file), qPrintable(file));
        }
        problems.removeDuplicates();
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    // The offer to recover work a crashed Tactus left is asked by the
    // autosave, not the window: its words are translated in its own context.
    void the_recovery_question_is_in_zh_TW() {
        QTranslator translator;
        QVERIFY2(translator.load(QStringLiteral("tactus_zh_TW"), QStringLiteral(TACTUS_QM_DIR)),
                 "the app's .qm file is not built");
        QCoreApplication::installTranslator(&translator);
        const auto restore = qScopeGuard([&] { QCoreApplication::removeTranslator(&translator); });
        QDir dir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + QStringLiteral("/autosave"));
        QVERIFY(dir.removeRecursively() && dir.mkpath(QStringLiteral(".")));
        const auto copy = dir.filePath(QStringLiteral("1-1.md"));
        const auto write = [](const QString& path, const QByteArray& bytes) {
            QFile f(path);
            return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
        };
        QVERIFY(write(copy, "Unsaved words."));
        // Owned by a process that does not exist: a Tactus that crashed.
        const QJsonObject meta{{QStringLiteral("pid"), 999999999},
                               {QStringLiteral("path"), QString()},
                               {QStringLiteral("time"), QDateTime::currentDateTimeUtc().toString(Qt::ISODate)}};
        QVERIFY(write(copy + QStringLiteral(".json"), QJsonDocument(meta).toJson()));
        QString title, text;
        QTimer answer;
        connect(&answer, &QTimer::timeout, this, [&] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box) return;
            answer.stop();
            title = box->windowTitle();
            text = box->text();
            box->button(QMessageBox::Discard)->click();
        });
        answer.start(10);
        QVERIFY(!Autosave::ask(nullptr));
        QCOMPARE(title, QStringLiteral("復原未儲存的內容"));
        QVERIFY2(text.startsWith(QStringLiteral("Tactus 關閉時 未命名文件 尚未儲存")), qPrintable(text));
        QVERIFY2(text.endsWith(QStringLiteral("要復原嗎？")), qPrintable(text));
        QVERIFY(!QFile::exists(copy));  // declined for good
        QVERIFY(Autosave::pending().isEmpty());
    }
};

QTEST_MAIN(FitTest)
#include "fit_test.moc"
