// SPDX-License-Identifier: GPL-3.0-or-later
// The main window end to end, offscreen: open (in the background, with progress),
// status bar, tables, save/reopen, BRF/PEF export equal to the CLI's, bad input
// that leaves the document alone, recent files, autosave and crash recovery.
#include <QAccessible>
#include <QCryptographicHash>
#include <QSettings>
#include <QJsonDocument>
#include <QStandardPaths>
#include <QJsonObject>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QStatusBar>
#include <QTextBlock>
#include <QProgressDialog>
#include <QPromise>
#include <QtTest>
#include <unistd.h>

#include "announcer.hpp"
#include "braille_pane.hpp"
#include "editor_widget.hpp"
#include "common/utf8.hpp"
#include "export/export.hpp"
#include "gui_test_support.hpp"
#include "import/import.hpp"
#include "graphic/drawing_file.hpp"
#include "pipeline/pipeline.hpp"
#include "profile/page_geometry.hpp"
#include "profile/profile_json.hpp"
#include "profile_editor.hpp"
#include "document_loader.hpp"
#include "main_window.hpp"
#include "preview_panel.hpp"
#include "table_picker.hpp"

using namespace tactus;
using namespace tactus::gui;

namespace {

// The height a fresh word-wrapped label of the same font needs for this text
// at this width (a fresh one: no size cached at another width).
int needed_height(const QLabel* shown) {
    QLabel probe;
    probe.setWordWrap(true);
    probe.setFont(shown->font());
    probe.setText(shown->text());
    return probe.heightForWidth(shown->width());
}

}  // namespace

class MainWindowTest : public QObject {
    Q_OBJECT
    QTemporaryDir dir;

    // The data row's `bytes` written as `name`, opened in `w` and saved
    // unchanged (the same bytes), then `typed` inserted on editor line `line`
    // and saved again (the row's `expected` bytes). Returns the file's path.
    QString open_edit_and_save(MainWindow& w, const QString& name) {
        QFETCH(QByteArray, bytes);
        QFETCH(int, line);
        QFETCH(QString, typed);
        QFETCH(QByteArray, expected);
        const auto path = dir.filePath(name);
        const auto read = [&path] {
            QFile f(path);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        [&] {
            {
                QFile f(path);
                QVERIFY(f.open(QIODevice::WriteOnly));
                f.write(bytes);
            }
            QVERIFY(w.open_file_now(path));
            // The Markdown is typed as codes: the file's own marks stay as they are.
            w.findChild<QAction*>(QStringLiteral("viewShowCodes"))->setChecked(true);
            const auto save = [&w] { w.findChild<QAction*>(QStringLiteral("fileSave"))->trigger(); };
            save();
            QCOMPARE(read(), bytes);
            QTextCursor c(w.editor()->print_pane()->document()->findBlockByNumber(line));
            c.insertText(typed);  // keyClicks takes Latin-1 only
            save();
            QVERIFY(!w.isWindowModified());
            QCOMPARE(read(), expected);
        }();
        return path;
    }

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);  // settings and autosaves in a test location
        QCoreApplication::setOrganizationName(QStringLiteral("TactusTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tactus-test"));
        QSettings().clear();
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation)).removeRecursively();
        install_accessibility();
    }

    void opens_in_the_background_and_reports() {
        MainWindow w;
        w.show();
        QSignalSpy opened(&w, &MainWindow::opened);
        QSignalSpy spoken(w.announcer(), &Announcer::announced);
        w.open_file(test::sample("welcome.md"));
        QVERIFY(w.is_busy());
        QVERIFY(opened.wait(30000));
        QVERIFY(!w.is_busy());
        QVERIFY(w.editor()->text().startsWith(QStringLiteral("# Welcome to Braille")));
        QVERIFY(w.windowTitle().startsWith(QStringLiteral("welcome.md")));
        // Said a moment later, once the events of the swap are out (Orca drops
        // a message that comes with a flood of them).
        QVERIFY(!w.announcer()->message().contains(QStringLiteral("Opened welcome.md")));
        QTRY_VERIFY(w.announcer()->message().contains(QStringLiteral("Opened welcome.md")));
        QCOMPARE(w.recent_files().value(0), QFileInfo(test::sample("welcome.md")).absoluteFilePath());
    }

    // The progress dialog shown (as on a loaded machine, where a book takes
    // longer than the dialog's delay), the job's last step and its end
    // arrive together: the step's setValue() runs the event loop, where the
    // end was handled ("Opened ..."), and "100 percent" said after it
    // replaced that message before Orca read it: the user never heard that
    // the book was open. The last word is the job's own, and the first
    // ("Opening ...") is not replaced at once by "0 percent" either.
    void the_end_of_a_job_is_its_last_word_with_the_dialog_shown() {
        MainWindow w;
        w.set_progress_delay(0);
        w.show();
        QSignalSpy opened(&w, &MainWindow::opened);
        QSignalSpy spoken(w.announcer(), &Announcer::announced);
        QPromise<LoadResultPtr> job;
        job.start();
        job.setProgressRange(0, 100);
        job.setProgressValue(0);
        w.start_busy(QStringLiteral("Opening welcome.md"), job.future(), true);
        QTRY_VERIFY(w.findChild<QProgressDialog*>(QStringLiteral("progress")) &&
                    w.findChild<QProgressDialog*>(QStringLiteral("progress"))->isVisible());
        job.setProgressValue(100);
        job.addResult(load_file_now(test::sample("welcome.md"), w.editor()->layout().tables(), w.editor()->layout().options()));
        job.finish();
        QVERIFY(opened.wait(30000));
        QTRY_VERIFY(w.announcer()->message().startsWith(QStringLiteral("Opened")));
        QStringList said;
        for (const auto& s : spoken) said << s[0].toString();
        QVERIFY2(w.announcer()->message().startsWith(QStringLiteral("Opened welcome.md")),
                 qPrintable(said.join(QStringLiteral(" | "))));
        QVERIFY2(!said.contains(QStringLiteral("0 percent")) && !said.contains(QStringLiteral("100 percent")),
                 qPrintable(said.join(QStringLiteral(" | "))));
    }

    // A text whose script does not suit the table is
    // warned about in the app as in the CLI, naming the better table (the app
    // showed only the 8-dot escape warning, which names none).
    void a_script_that_does_not_suit_the_table_names_the_better_one() {
        MainWindow w;
        QVERIFY(w.open_file_now(test::sample("chinese-tw.txt")));
        QVERIFY2(w.announcer()->message().contains(QStringLiteral("zh-tw.ctb")), qPrintable(w.announcer()->message()));
        const auto english = dir.filePath(QStringLiteral("english.txt"));
        QFile f(english);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("Braille is a tactile writing system. Teachers emboss it for their pupils every day.\n");
        f.close();
        QVERIFY(w.open_file_now(english));
        QVERIFY2(!w.announcer()->message().contains(QStringLiteral("Warning")), qPrintable(w.announcer()->message()));
        w.set_table(QStringLiteral("zh-tw.ctb"));
        const auto said = w.announcer()->message();
        w.set_table(QStringLiteral("en-ueb-g2.ctb"));  // the table is a setting: leave it as the other tests expect
        QVERIFY2(said.contains(QStringLiteral("en-ueb-g2.ctb")), qPrintable(said));
    }

    void status_bar_says_sheet_line_cell_print_page() {
        MainWindow w;
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        QRegularExpression format(QStringLiteral(R"(^Sheet (\d+) of (\d+), (front|back) \| line (\d+) \| cell (\d+) \| print page (\S+)$)"));
        auto m = format.match(w.status_text());
        QVERIFY2(m.hasMatch(), qPrintable(w.status_text()));
        QCOMPARE(m.captured(1), QStringLiteral("1"));
        QCOMPARE(m.captured(6), QStringLiteral("1"));
        // After the page break the print page is 2.
        auto* print = w.editor()->print_pane();
        const auto text = print->toPlainText();
        const auto at = text.indexOf(QStringLiteral("Keep the hands"));
        QTextCursor c(print->document());
        c.setPosition(static_cast<int>(at));
        print->setTextCursor(c);
        m = format.match(w.status_text());
        QVERIFY2(m.hasMatch(), qPrintable(w.status_text()));
        QCOMPARE(m.captured(6), QStringLiteral("2"));
        // The preview's cell cursor went to the same page position.
        const auto pos = w.editor()->current_position();
        QCOMPARE(w.preview_panel()->preview()->cursor_page(), pos.page);
        QCOMPARE(w.preview_panel()->preview()->cursor_line(), pos.line);
    }

    // A long message must not run into the position indicator and be cut
    // (QStatusBar paints one line under its permanent widgets). The message
    // is a label beside the position that wraps and is as tall as it needs.
    void a_long_message_is_shown_whole_beside_the_position() {
        MainWindow w;
        w.set_interactive(false);
        w.resize(900, 600);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.set_table(QStringLiteral("en-ueb-g2.ctb"));
        QVERIFY(w.open_file_now(test::sample("chinese-tw.txt")));  // Chinese under English: the table warning
        QTest::qWait(50);
        auto* message = w.statusBar()->findChild<QLabel*>(QStringLiteral("statusMessage"));
        QVERIFY2(message, "the status bar has no message label");
        QVERIFY2(message->text().contains(QStringLiteral("does not suit")), qPrintable(message->text()));
        QVERIFY(message->isVisible());
        auto* position = w.statusBar()->findChild<QLabel*>(QStringLiteral("positionLabel"));
        QVERIFY(position && position->isVisible());
        const QRect m(message->mapTo(&w, QPoint(0, 0)), message->size());
        const QRect p(position->mapTo(&w, QPoint(0, 0)), position->size());
        QVERIFY2(!m.intersects(p), "the message runs into the position");
        // Whole: wider than a line of the bar, so it wraps, and every line has room.
        QVERIFY(message->fontMetrics().horizontalAdvance(message->text()) > message->width());
        QVERIFY2(message->height() >= needed_height(message),
                 qPrintable(QStringLiteral("needs %1 px of height, has %2").arg(needed_height(message)).arg(message->height())));
    }

    // A message laid out while the window was narrow left the bar five lines
    // tall for every later one-line message (QLabel's cached height).
    void a_short_message_after_a_narrow_start_takes_one_line() {
        MainWindow w;
        w.set_interactive(false);
        // Before the window is shown, as when the app starts with a table
        // option: the label is still at its first, narrow size. The table is
        // a saved setting: the next tests expect the default back.
        w.set_table(QStringLiteral("en-ueb-g1.ctb"));
        const auto restore = qScopeGuard([&] { w.set_table(QStringLiteral("en-ueb-g2.ctb")); });
        w.resize(1200, 700);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTest::qWait(50);
        QVERIFY(w.open_file_now(test::sample("welcome.md")));  // "Opened welcome.md: 1 sheet(s)"
        QTest::qWait(50);
        auto* message = w.statusBar()->findChild<QLabel*>(QStringLiteral("statusMessage"));
        QVERIFY(message);
        QVERIFY2(message->text().startsWith(QStringLiteral("Opened")), qPrintable(message->text()));
        QCOMPARE(message->height(), needed_height(message));
        QVERIFY2(w.statusBar()->height() < 3 * message->fontMetrics().height(),
                 qPrintable(QStringLiteral("the status bar is %1 px tall").arg(w.statusBar()->height())));
    }

    void exports_match_the_cli_pipeline() {
        MainWindow w;
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        auto expected = pipeline::lay_out_file(test::sample("welcome.md").toStdString(), {});
        QVERIFY(expected.has_value());
        const auto brf = dir.filePath(QStringLiteral("welcome.brf"));
        QVERIFY(w.export_to(brf));
        QFile f(brf);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll().toStdString(), *exporter::to_brf(*expected));
        const auto pef = dir.filePath(QStringLiteral("welcome.pef"));
        QVERIFY(w.export_to(pef));
        QFile p(pef);
        QVERIFY(p.open(QIODevice::ReadOnly));
        const auto xml = p.readAll();
        QVERIFY(xml.contains("<dc:title>welcome</dc:title>"));
        QVERIFY(xml.contains("duplex=\"true\""));
        // Reading the PEF back gives the same pages.
        auto back = pipeline::lay_out_file(pef.toStdString(), {});
        QVERIFY(back.has_value());
    }

    // The app and the CLI give the same bytes for the same
    // document, table and (default) format, compared with the real tactus-cli:
    // Markdown structure (notes, quotes, lists, a table), a Chinese text file, a
    // plain English text file.
    void exports_equal_the_cli_bytes_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("table");
        QTest::newRow("welcome.md") << test::sample("welcome.md") << QStringLiteral("en-ueb-g2.ctb");
        QTest::newRow("structure-formats.md")
            << QStringLiteral(TACTUS_TEST_DATA "/../golden/structure/structure-formats.md") << QStringLiteral("en-ueb-g2.ctb");
        QTest::newRow("chinese-tw.txt") << test::sample("chinese-tw.txt") << QStringLiteral("zh-tw.ctb");
        QTest::newRow("english.txt") << QString() << QStringLiteral("en-ueb-g1.ctb");
    }
    void exports_equal_the_cli_bytes() {
        QFETCH(QString, file);
        QFETCH(QString, table);
        if (file.isEmpty()) {
            file = dir.filePath(QStringLiteral("english.txt"));
            QFile f(file);
            QVERIFY(f.open(QIODevice::WriteOnly));
            for (int i = 0; i < 12; ++i)
                f.write("Braille & print: # and * in 2026; the quick brown fox jumps over the lazy dog.\n\n");
        }
        MainWindow w;
        QVERIFY(w.open_file_now(file));
        w.set_table(table);
        for (const auto* format : {"brf", "pef"}) {
            const auto app = dir.filePath(QStringLiteral("app.%1").arg(QLatin1String(format)));
            const auto cli = dir.filePath(QStringLiteral("cli.%1").arg(QLatin1String(format)));
            QVERIFY(w.export_to(app));
            QProcess p;
            p.start(QStringLiteral(TACTUS_CLI), {QStringLiteral("layout"), QStringLiteral("--to"), QLatin1String(format),
                                                 QStringLiteral("-t"), table, file, QStringLiteral("-o"), cli});
            QVERIFY(p.waitForFinished(60000));
            QCOMPARE(p.exitCode(), 0);
            QFile a(app), c(cli);
            QVERIFY(a.open(QIODevice::ReadOnly) && c.open(QIODevice::ReadOnly));
            auto app_bytes = a.readAll(), cli_bytes = c.readAll();
            if (QLatin1String(format) == QLatin1String("pef")) {
                // The title comes from a file name, which differs here by design.
                const QRegularExpression title(QStringLiteral("<dc:title>[^<]*</dc:title>"));
                app_bytes = QString::fromUtf8(app_bytes).remove(title).toUtf8();
                cli_bytes = QString::fromUtf8(cli_bytes).remove(title).toUtf8();
            }
            QCOMPARE(app_bytes, cli_bytes);
        }
        w.set_table(QStringLiteral("en-ueb-g2.ctb"));
    }

    // In the app, ready-made braille opened and exported again
    // is page for page, as the CLI does it; the app added its own braille page
    // numbers, so a full BRF page ran over and its pages doubled.
    void ready_braille_is_exported_page_for_page_data() {
        QTest::addColumn<QString>("file");
        QTest::newRow("brf") << QStringLiteral(TACTUS_TEST_DATA "/../golden/expected/welcome-interpoint.brf");
        QTest::newRow("pef") << QStringLiteral(TACTUS_TEST_DATA "/../golden/expected/structure-md.pef");
    }
    void ready_braille_is_exported_page_for_page() {
        QFETCH(QString, file);
        MainWindow w;
        QVERIFY(w.open_file_now(file));
        const auto app = dir.filePath(QStringLiteral("again.brf"));
        const auto cli = dir.filePath(QStringLiteral("cli-again.brf"));
        QVERIFY(w.export_to(app));
        QProcess p;
        p.start(QStringLiteral(TACTUS_CLI), {QStringLiteral("layout"), QStringLiteral("--to"), QStringLiteral("brf"), file,
                                             QStringLiteral("-o"), cli});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        QFile a(app), c(cli);
        QVERIFY(a.open(QIODevice::ReadOnly) && c.open(QIODevice::ReadOnly));
        const auto app_bytes = a.readAll();
        QCOMPARE(app_bytes, c.readAll());
        if (file.endsWith(QLatin1String(".brf"))) {
            QFile source(file);
            QVERIFY(source.open(QIODevice::ReadOnly));
            QCOMPARE(app_bytes, source.readAll());
        }
    }

    // Real PEF files (tests/data/pef/real) and
    // multi-volume ones (volume_grids.pef: each volume its own page size): opened in the app and exported without an edit, the
    // PEF and BRF are byte for byte what tactus-cli writes for the same file
    // and page (40 x 30, interpoint): the file's own cols/rows, its sections
    // (each on a new sheet) and their duplex (a single-sided section's blank
    // backs), its volumes, its dc: metadata. Before, the app dropped all of
    // that: it laid the rows out on its own page as one section of one volume,
    // with metadata of its own making.
    void a_pef_is_exported_as_the_cli_exports_it_data() {
        QTest::addColumn<QString>("file");
        for (const auto* name : {"book.pef", "butterfly.pef", "8-dot-chart.pef", "margin-uneven.pef",
                                 "flow-in-header-footer4.pef"})
            QTest::newRow(name) << QStringLiteral(TACTUS_TEST_DATA "/pef/real/") + QLatin1String(name);
        QTest::newRow("volumes.pef") << QStringLiteral(TACTUS_TEST_DATA "/pef/volumes.pef");
        QTest::newRow("volume_grids.pef") << QStringLiteral(TACTUS_TEST_DATA "/pef/volume_grids.pef");
        QTest::newRow("single_sided_section.pef") << QStringLiteral(TACTUS_TEST_DATA "/pef/single_sided_section.pef");
        QTest::newRow("sections.pef") << QStringLiteral(TACTUS_TEST_DATA "/pef/sections.pef");
    }
    void a_pef_is_exported_as_the_cli_exports_it() {
        QFETCH(QString, file);
        MainWindow w;
        auto options = w.editor()->layout().options();
        options.geometry.cells_per_line = 40;
        options.geometry.lines_per_page = 30;
        options.geometry.interpoint = true;
        QVERIFY(w.editor()->set_layout_options(options));
        QVERIFY(w.open_file_now(file));
        for (const auto* format : {"brf", "pef"}) {
            const auto app = dir.filePath(QStringLiteral("app-real.%1").arg(QLatin1String(format)));
            const auto cli = dir.filePath(QStringLiteral("cli-real.%1").arg(QLatin1String(format)));
            QFile::remove(app);
            QFile::remove(cli);
            QProcess p;
            p.start(QStringLiteral(TACTUS_CLI),
                    {QStringLiteral("layout"), QStringLiteral("--to"), QLatin1String(format), QStringLiteral("--cells"),
                     QStringLiteral("40"), QStringLiteral("--lines"), QStringLiteral("30"), QStringLiteral("--interpoint"),
                     file, QStringLiteral("-o"), cli});
            QVERIFY(p.waitForFinished(60000));
            const bool exported = w.export_to(app);
            if (p.exitCode() != 0) {
                // An 8-dot file as BRF: refused by both.
                QCOMPARE(QLatin1String(format), QLatin1String("brf"));
                QVERIFY(!exported);
                continue;
            }
            QVERIFY(exported);
            QFile a(app), c(cli);
            QVERIFY(a.open(QIODevice::ReadOnly) && c.open(QIODevice::ReadOnly));
            const auto app_bytes = a.readAll();
            QCOMPARE(app_bytes, c.readAll());
            if (file.endsWith(QLatin1String("volume_grids.pef")) && QLatin1String(format) == QLatin1String("pef")) {
                // Its volumes' own page sizes (12 x 5, 20 x 8, 16 x 6 with a
                // 10 x 4 section): the file again, byte for byte.
                QFile source(file);
                QVERIFY(source.open(QIODevice::ReadOnly));
                QCOMPARE(app_bytes, source.readAll());
            }
        }
    }

    // The page-too-small question says the file's declared
    // page, volume by volume when its volumes differ, against the printer's
    // (volume_grids.pef: 12 x 5, 20 x 8, 16 x 6, on a 19 x 8 page, where only
    // volume 2 is too large; its longest row is 19 cells, so the question is
    // asked only because its declared page is checked). Before, the question
    // said the first page's own measure ("8 lines of up to 19 cells"), which
    // fits the printer's 19 x 8, and nothing of the file's volumes. What Orca
    // reads (the box's name, its labels, the buttons' names and descriptions)
    // and what a window that cannot ask announces.
    void the_page_too_small_question_says_each_volumes_declared_page() {
        MainWindow w;
        auto options = w.editor()->layout().options();
        options.geometry.cells_per_line = 19;
        options.geometry.lines_per_page = 8;
        QVERIFY(w.editor()->set_layout_options(options));
        QVERIFY(w.open_file_now(QStringLiteral(TACTUS_TEST_DATA "/pef/volume_grids.pef")));
        const auto out = dir.filePath(QStringLiteral("grids-small.pef"));
        const QString sizes = QStringLiteral(
            "The pages of volume_grids.pef differ by volume: volume 1, 12 cells by 5 lines; volume 2, 20 cells by 8 "
            "lines, too large; volume 3, 16 cells by 6 lines. The printer's page holds 19 cells by 8 lines.");

        // A window that cannot ask stops, and says why.
        w.set_interactive(false);
        QVERIFY(!w.export_to(out));
        QVERIFY2(w.announcer()->message().contains(sizes), qPrintable(w.announcer()->message()));
        QVERIFY(!QFile::exists(out));

        w.set_interactive(true);
        w.show();
        QString text, name, labels, buttons;
        QTimer::singleShot(200, [&] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box || box->objectName() != QLatin1String("pageTooSmallQuestion")) return;
            text = box->text() + QLatin1Char(' ') + box->informativeText();
            auto* a = QAccessible::queryAccessibleInterface(box);
            name = a ? a->text(QAccessible::Name) : QString();
            for (int i = 0; a && i < a->childCount(); ++i)
                if (auto* c = a->child(i); c && c->role() == QAccessible::StaticText)
                    labels += c->text(QAccessible::Name) + QLatin1Char(' ');
            for (auto* b : box->buttons())
                if (auto* ba = QAccessible::queryAccessibleInterface(b))
                    buttons += ba->text(QAccessible::Name) + QLatin1Char(':') + ba->text(QAccessible::Description) +
                               QLatin1Char('|');
            box->findChild<QPushButton*>(QStringLiteral("stopButton"))->click();
        });
        QVERIFY(!w.export_to(out));
        QVERIFY(!QFile::exists(out));
        QVERIFY2(text.contains(sizes), qPrintable(text));
        QVERIFY2(!text.contains(QStringLiteral("lines of up to")), qPrintable(text));
        QCOMPARE(name, QStringLiteral("The printer's page is too small"));
        QVERIFY2(labels.contains(sizes), qPrintable(labels));
        QCOMPARE(buttons, QStringLiteral("Reflow:Lay the braille out again on the printer's page and go on|"
                                         "Stop:Emboss or export nothing|"));
        QVERIFY2(w.announcer()->message().contains(QStringLiteral("Stopped: nothing was embossed or exported")),
                 qPrintable(w.announcer()->message()));

        // One page size for the whole file: said once.
        w.set_interactive(false);
        QVERIFY(w.open_file_now(QStringLiteral(TACTUS_TEST_DATA "/pef/volumes.pef")));
        options.geometry.cells_per_line = 11;
        QVERIFY(w.editor()->set_layout_options(options));
        QVERIFY(!w.export_to(out));
        QVERIFY2(w.announcer()->message().contains(QStringLiteral(
                     "The pages of volumes.pef are 12 cells by 5 lines; the printer's page holds 11 cells by 8 lines.")),
                 qPrintable(w.announcer()->message()));
    }

    // A multi-volume PEF through the app: edited (a row changed, a page of
    // volume 2 deleted, a row added to the last page), its volumes, sections,
    // duplex and metadata are still there; only the edited rows differ.
    void an_edited_pef_keeps_its_volumes_sections_and_metadata() {
        MainWindow w;
        QVERIFY(w.open_file_now(QStringLiteral(TACTUS_TEST_DATA "/pef/volumes.pef")));
        auto* print = w.editor()->print_pane();
        const auto lines = w.editor()->text().split(QLatin1Char('\n'));
        // Volume 2's second page: its page break line and its row.
        const auto five = lines.indexOf(QStringLiteral("⠋⠊⠧⠑"));
        QVERIFY(five > 0);
        QCOMPARE(lines[five - 1], QStringLiteral("<!-- braillepage -->"));
        QTextCursor c(print->document()->findBlockByNumber(static_cast<int>(five - 1)));
        c.movePosition(QTextCursor::NextBlock, QTextCursor::KeepAnchor, 2);
        c.removeSelectedText();  // the page break and the row: the page is gone
        // A row changed in volume 1 ("two" -> "twoo"), a row added on the last page.
        const auto two = w.editor()->text().split(QLatin1Char('\n')).indexOf(QStringLiteral("⠞⠺⠕"));
        QVERIFY(two > 0);
        QTextCursor t(print->document()->findBlockByNumber(static_cast<int>(two)));
        t.movePosition(QTextCursor::EndOfBlock);
        t.insertText(QStringLiteral("⠕"));
        QTextCursor end(print->document());
        end.movePosition(QTextCursor::End);
        end.insertText(QStringLiteral("\n⠑⠝⠙"));
        const auto app = dir.filePath(QStringLiteral("volumes-edited.pef"));
        QVERIFY(w.export_to(app));
        QFile a(app);
        QVERIFY(a.open(QIODevice::ReadOnly));
        const auto xml = QString::fromUtf8(a.readAll());
        QCOMPARE(xml.count(QStringLiteral("<volume ")), 3);
        QCOMPARE(xml.count(QStringLiteral("<section")), 4);
        QCOMPARE(xml.count(QStringLiteral("<page")), 6);
        QVERIFY2(xml.contains(QStringLiteral("<section duplex=\"false\">")), qPrintable(xml));
        QVERIFY2(xml.contains(QStringLiteral("<dc:identifier>org.example.tactus.volumes-2026</dc:identifier>")), qPrintable(xml));
        QVERIFY2(xml.contains(QStringLiteral("<dc:creator>Tactus test suite</dc:creator>")), qPrintable(xml));
        QVERIFY2(xml.contains(QStringLiteral("<row>⠞⠺⠕⠕</row>")), qPrintable(xml));
        QVERIFY2(!xml.contains(QStringLiteral("⠋⠊⠧⠑")), qPrintable(xml));
        QVERIFY2(xml.contains(QStringLiteral("<row>⠇⠁⠌</row>\n          <row>⠑⠝⠙</row>")), qPrintable(xml));
        QVERIFY2(xml.contains(QStringLiteral("cols=\"12\" rows=\"5\"")), qPrintable(xml));

        // Every edit undone: the file as the CLI writes it again, structure and all.
        auto* undo = w.editor()->undo_stack();
        while (undo->canUndo()) undo->undo();
        const auto undone = dir.filePath(QStringLiteral("volumes-undone.pef"));
        const auto cli = dir.filePath(QStringLiteral("volumes-cli.pef"));
        QVERIFY(w.export_to(undone));
        QProcess p;
        p.start(QStringLiteral(TACTUS_CLI), {QStringLiteral("layout"), QStringLiteral("--to"), QStringLiteral("pef"),
                                             QStringLiteral(TACTUS_TEST_DATA "/pef/volumes.pef"), QStringLiteral("-o"), cli});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        QFile u(undone), from_cli(cli);
        QVERIFY(u.open(QIODevice::ReadOnly) && from_cli.open(QIODevice::ReadOnly));
        QCOMPARE(u.readAll(), from_cli.readAll());
    }

    // Print text typed into a PEF: the app says, once, that the braille is laid
    // out again and its own pages are no longer kept; taken out, that they are kept again.
    void typing_print_into_a_pef_says_its_pages_are_laid_out_again() {
        MainWindow w;
        QVERIFY(w.open_file_now(QStringLiteral(TACTUS_TEST_DATA "/pef/single_sided_section.pef")));
        QVERIFY(w.editor()->layout().pages_kept());
        QCOMPARE(w.editor()->layout().paged().sheet_count(), std::size_t{4});
        auto* print = w.editor()->print_pane();
        QTextCursor c(print->document());
        c.movePosition(QTextCursor::End);
        c.insertText(QStringLiteral("\nPrint text"));
        QVERIFY(!w.editor()->layout().pages_kept());
        QVERIFY2(w.announcer()->message().contains(QStringLiteral("laid out again")), qPrintable(w.announcer()->message()));
        w.editor()->undo_stack()->undo();
        QVERIFY(w.editor()->layout().pages_kept());
        QVERIFY2(w.announcer()->message().contains(QStringLiteral("kept again")), qPrintable(w.announcer()->message()));
        QCOMPARE(w.editor()->layout().paged().sheet_count(), std::size_t{4});
    }

    // The document is laid out for the printer's page: a profile with narrower,
    // shorter pages lays it out again, as tactus-cli lays it out for that
    // page. The app kept 27 x 24 whatever profile was loaded, so its lines were
    // wider than the machine's page.
    void a_loaded_profile_lays_the_document_out_for_its_page() {
        auto machine = profile::default_profile();
        machine.geometry.cells_per_line = 20;
        machine.geometry.lines_per_page = 22;
        const auto profile_path = dir.filePath(QStringLiteral("narrow.json"));
        const auto saved = profile::save_profile(machine, profile_path.toStdString());
        QVERIFY2(saved, saved ? "" : saved.error().to_string().c_str());
        MainWindow w;
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        QVERIFY(w.profile_editor()->load(profile_path));
        const auto& paged = w.editor()->layout().paged();
        QCOMPARE(paged.geometry, profile::page_geometry(machine));
        for (const auto& page : paged.pages) {
            QVERIFY(page.lines.size() <= 22);
            for (const auto& line : page.lines) QVERIFY(line.size() <= 20);
        }
        const auto app = dir.filePath(QStringLiteral("narrow-app.brf"));
        const auto cli = dir.filePath(QStringLiteral("narrow-cli.brf"));
        QVERIFY(w.export_to(app));
        QProcess p;
        p.start(QStringLiteral(TACTUS_CLI), {QStringLiteral("layout"), QStringLiteral("--to"), QStringLiteral("brf"),
                                             QStringLiteral("--cells"), QStringLiteral("20"), QStringLiteral("--lines"),
                                             QStringLiteral("22"), test::sample("welcome.md"), QStringLiteral("-o"), cli});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        QFile a(app), c(cli);
        QVERIFY(a.open(QIODevice::ReadOnly) && c.open(QIODevice::ReadOnly));
        QCOMPARE(a.readAll(), c.readAll());
    }

    void save_and_reopen_round_trip() {
        MainWindow w;
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        auto* print = w.editor()->print_pane();
        print->moveCursor(QTextCursor::End);
        QTest::keyClick(print, Qt::Key_Return);
        QTest::keyClicks(print, "A *new* paragraph.");
        QVERIFY(w.isWindowModified());
        const auto path = dir.filePath(QStringLiteral("saved.md"));
        QVERIFY(w.save_to(path));
        QVERIFY(!w.isWindowModified());
        const auto pages = w.editor()->layout().paged().pages;
        MainWindow again;
        QVERIFY(again.open_file_now(path));
        QCOMPARE(again.editor()->text(), w.editor()->text());
        QVERIFY(again.editor()->layout().paged().pages == pages);
        QVERIFY(again.editor()->print_pane()->accessibleDescription().startsWith(QStringLiteral("The print text with its styles")));
    }

    // A DOCX or ODT opened is saved in place in its own format, and opens
    // again as the same lines (headings, lists, the table, the note).
    void an_office_file_is_saved_in_its_own_format() {
        for (const auto* name : {"lesson.docx", "lesson.odt"}) {
            const auto path = dir.filePath(QString::fromLatin1(name));
            QFile::remove(path);
            QVERIFY(QFile::copy(QStringLiteral(TACTUS_TEST_DATA "/import/") + QString::fromLatin1(name), path));
            QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
            MainWindow w;
            QVERIFY(w.open_file_now(path));
            QCOMPARE(w.document_path(), QFileInfo(path).absoluteFilePath());
            auto* print = w.editor()->print_pane();
            print->moveCursor(QTextCursor::Start);
            QTest::keyClicks(print, "A *new* paragraph.");
            QTest::keyClick(print, Qt::Key_Return);
            QVERIFY(w.save_to(w.document_path()));
            QVERIFY(!w.isWindowModified());
            QFile saved(path);
            QVERIFY(saved.open(QIODevice::ReadOnly));
            QCOMPARE(saved.read(2), QByteArray("PK"));  // a ZIP package, not Markdown text
            MainWindow again;
            QVERIFY(again.open_file_now(path));
            // The same document: its blocks as the editor's lines give them
            // (a space the importer left at a line's end is not one of them).
            QVERIFY(again.editor()->layout().document().blocks == w.editor()->layout().document().blocks);
            // And the same lines, but for spaces at a line's end.
            const auto trimmed = [](const QString& text) {
                QStringList lines = text.split(QLatin1Char('\n'));
                for (auto& l : lines) {
                    while (l.endsWith(QLatin1Char(' '))) l.chop(1);
                }
                return lines;
            };
            QCOMPARE(trimmed(again.editor()->text()), trimmed(w.editor()->text()));
            QVERIFY(again.editor()->text().contains(QStringLiteral("new")));
            QVERIFY(again.editor()->text().contains(QStringLiteral("1. Look at the sky.")));
        }
    }

private:
    // A document's pictures as the file holds them: each picture's bytes and
    // type with the description before it (its transcriber's note), in order.
    static QStringList pictures_of(const QString& path) {
        import::ImportOptions options;
        options.images = true;
        options.picture_marks = true;  // a Markdown image as the app reads it: its alt text its description
        const auto doc = import::import_file(path.toStdString(), options);
        if (!doc) return {QStringLiteral("unreadable")};
        QStringList out;
        for (const auto& b : doc->blocks) {
            std::size_t next = 0;
            for (const auto& s : b.spans)
                if (s.transcriber_note && next < b.images.size()) {
                    const auto& image = b.images[next++];
                    out << QStringLiteral("%1 %2 bytes %3: %4")
                               .arg(QString::fromStdString(image.media_type))
                               .arg(image.bytes.size())
                               .arg(QString::fromLatin1(QCryptographicHash::hash(QByteArray::fromStdString(image.bytes),
                                                                                 QCryptographicHash::Sha1)
                                                            .toHex()),
                                    QString::fromStdString(s.text));
                }
            for (; next < b.images.size(); ++next) out << QStringLiteral("undescribed %1").arg(b.images[next].bytes.size());
        }
        return out;
    }

    static int picture_objects(const QTextDocument* doc) {
        return static_cast<int>(doc->toPlainText().count(QChar::ObjectReplacementCharacter));
    }

private Q_SLOTS:
    // The editor keeps a document's pictures (pandoc's inline_images: three
    // in a DOCX; image.odt: one): shown as pictures, never as their marks;
    // an edit, undo and redo keep them; Save over the file asks nothing and
    // writes the same picture bytes with the same descriptions.
    void pictures_are_kept_through_edit_and_save() {
        for (const auto* name : {"pandoc-inline_images.docx", "pandoc-image.odt"}) {
            const auto path = dir.filePath(QString::fromLatin1(name));
            QFile::remove(path);
            QVERIFY(QFile::copy(QStringLiteral(TACTUS_TEST_DATA "/import/public/") + QString::fromLatin1(name), path));
            QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
            const auto original = pictures_of(path);
            QVERIFY(!original.isEmpty());
            MainWindow w;
            QVERIFY(w.open_file_now(path));
            auto* print = w.editor()->print_pane();
            QCOMPARE(picture_objects(print->document()), static_cast<int>(original.size()));
            QVERIFY2(!print->document()->toPlainText().contains(QStringLiteral("![")), name);
            const auto images = [&w] {
                std::size_t n = 0;
                for (const auto& b : w.editor()->layout().document().blocks) n += b.images.size();
                return n;
            };
            QCOMPARE(images(), static_cast<std::size_t>(original.size()));
            // Edit the paragraph before the first picture, undo, redo.
            QTextCursor c(print->document());
            print->setTextCursor(c);
            QTest::keyClicks(print, "Edited ");
            QCOMPARE(images(), static_cast<std::size_t>(original.size()));
            w.editor()->undo_stack()->undo();
            QCOMPARE(images(), static_cast<std::size_t>(original.size()));
            w.editor()->undo_stack()->redo();
            QVERIFY(w.editor()->text().startsWith(QStringLiteral("Edited ")));
            QVERIFY(w.save_to(path));  // not interactive: it would refuse if it had to ask
            QVERIFY(!w.isWindowModified());
            QCOMPARE(pictures_of(path), original);
            MainWindow again;
            QVERIFY(again.open_file_now(path));
            QCOMPARE(picture_objects(again.editor()->print_pane()->document()), static_cast<int>(original.size()));
            QVERIFY(again.editor()->text().startsWith(QStringLiteral("Edited ")));
            // Saved as Markdown in a folder of its own: the pictures are files beside it.
            const QString folder = dir.filePath(QStringLiteral("md-") + QString::fromLatin1(name));
            QVERIFY(QDir().mkpath(folder));
            const auto md = folder + QStringLiteral("/saved.md");
            QVERIFY(again.save_to(md));
            QVERIFY2(again.announcer()->message().contains(QStringLiteral("picture file")), qPrintable(again.announcer()->message()));
            QVERIFY(!QDir(folder).entryList({QStringLiteral("picture1.*")}).isEmpty());
            QCOMPARE(pictures_of(md), original);
        }
    }

    // Where pictures really are lost (a text file keeps descriptions only; a
    // Markdown file has no picture files beside it) it asks first: refused
    // without someone to ask; asked, Cancel saves nothing, the other button
    // writes the descriptions.
    void saving_pictures_where_they_are_lost_is_asked_first() {
        const auto path = dir.filePath(QStringLiteral("lost-pictures.docx"));
        QFile::remove(path);
        QVERIFY(QFile::copy(QStringLiteral(TACTUS_TEST_DATA "/import/public/pandoc-inline_images.docx"), path));
        QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
        MainWindow w;
        QVERIFY(w.open_file_now(path));
        // A Markdown file where another file has a picture's name would name the wrong picture.
        const QString taken = dir.filePath(QStringLiteral("taken"));
        QVERIFY(QDir().mkpath(taken));
        {
            std::string first;  // the first picture's name, as its mark gives it
            for (const auto& b : w.editor()->layout().document().blocks)
                if (first.empty() && !b.images.empty()) first = b.images.front().name;
            QVERIFY(!first.empty());
            QFile other(taken + QLatin1Char('/') + QString::fromStdString(first));
            QVERIFY(other.open(QIODevice::WriteOnly));
            other.write("another picture");
        }
        for (const auto& to : {dir.filePath(QStringLiteral("lost-pictures.txt")), taken + QStringLiteral("/lost-pictures.md")}) {
            const auto target = QFileInfo(to).fileName();
            QFile::remove(to);
            QVERIFY(!w.save_to(to));
            QVERIFY(!QFile::exists(to));
            const auto said = w.announcer()->message();
            QVERIFY2(said.contains(QStringLiteral("picture")) && said.contains(target), qPrintable(said));
        }
        const auto text = dir.filePath(QStringLiteral("lost-pictures.txt"));
        w.set_interactive(true);
        w.show();
        struct Seen {
            bool asked = false;
            QString name;
        };
        const auto answer = [](Seen& seen, bool go) {
            QTimer::singleShot(200, [&seen, go] {
                auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
                if (!box) return;
                seen.asked = box->objectName() == QLatin1String("picturesQuestion");
                if (auto* a = QAccessible::queryAccessibleInterface(box)) seen.name = a->text(QAccessible::Name);
                (go ? box->findChild<QPushButton*>(QStringLiteral("replacePicturesButton")) : box->button(QMessageBox::Cancel))
                    ->click();
            });
        };
        Seen cancel;
        answer(cancel, false);
        QVERIFY(!w.save_to(text));
        QVERIFY(cancel.asked);
        QCOMPARE(cancel.name, QStringLiteral("Saving would lose pictures"));
        QVERIFY(!QFile::exists(text));
        Seen go;
        answer(go, true);
        QVERIFY(w.save_to(text));
        QVERIFY(go.asked);
        QVERIFY(QFile::exists(text));
    }

    // Insert > Graphic: the picture after the cursor's paragraph with its
    // description, announced; one undo step takes it away, redo brings it
    // back; saved as DOCX it is the file's bytes. No description, no picture.
    void inserted_graphic_is_one_undo_step_and_saved() {
        const auto path = dir.filePath(QStringLiteral("inserted.md"));
        QFile::remove(path);
        QVERIFY(QFile::copy(test::sample("welcome.md"), path));
        QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
        MainWindow w;
        QVERIFY(w.open_file_now(path));
        const auto picture = QStringLiteral(TACTUS_TEST_DATA "/graphics/shapes.svg");
        QVERIFY(!w.insert_graphic(picture, QStringLiteral("  ")));
        QVERIFY(w.announcer()->message().contains(QStringLiteral("description")));
        const auto steps = w.editor()->undo_stack()->index();
        QVERIFY(w.insert_graphic(picture, QStringLiteral("A circle, a square and a triangle")));
        QVERIFY(w.announcer()->message().contains(QStringLiteral("A circle, a square and a triangle")));
        QCOMPARE(w.editor()->undo_stack()->index(), steps + 1);
        auto* print = w.editor()->print_pane();
        QCOMPARE(picture_objects(print->document()), 1);
        QVERIFY(!print->document()->toPlainText().contains(QStringLiteral("![")));
        // The cursor's line says what the picture is, for the screen reader.
        QVERIFY(w.editor()->structure_text(w.editor()->current_line()).contains(QStringLiteral("A circle")));
        const auto images = [&w] {
            std::vector<document::Image> out;
            for (const auto& b : w.editor()->layout().document().blocks) out.insert(out.end(), b.images.begin(), b.images.end());
            return out;
        };
        QFile svg(picture);
        QVERIFY(svg.open(QIODevice::ReadOnly));
        const auto bytes = svg.readAll().toStdString();
        QCOMPARE(images().size(), std::size_t{1});
        QVERIFY(images().front().bytes == bytes);
        w.editor()->undo_stack()->undo();
        QCOMPARE(images().size(), std::size_t{0});
        QCOMPARE(picture_objects(print->document()), 0);
        w.editor()->undo_stack()->redo();
        QCOMPARE(images().size(), std::size_t{1});
        // Saved as Markdown, the picture is a file beside it.
        QVERIFY(w.save_to(path));
        QCOMPARE(pictures_of(path).size(), 1);
        QVERIFY(pictures_of(path).front().endsWith(QStringLiteral(": A circle, a square and a triangle")));
        QFile beside(dir.filePath(QStringLiteral("shapes.svg")));
        QVERIFY(beside.open(QIODevice::ReadOnly));
        QVERIFY(beside.readAll().toStdString() == bytes);
        const auto docx = dir.filePath(QStringLiteral("inserted.docx"));
        QVERIFY(w.save_to(docx));
        const auto saved = pictures_of(docx);
        QCOMPARE(saved.size(), 1);
        QVERIFY2(saved.front().startsWith(QStringLiteral("image/svg+xml %1 bytes").arg(bytes.size())) &&
                     saved.front().endsWith(QStringLiteral(": A circle, a square and a triangle")),
                 qPrintable(saved.front()));
    }

    // Emboss Pictures as Graphics: the preview's pages are the document's
    // with each picture a graphic page, laid out by the core function the
    // CLI's --images graphics calls; off, the editor's pages again. The
    // choice is a setting kept for the next window.
    void pictures_as_graphics_lay_out_as_the_cli() {
        const auto path = dir.filePath(QStringLiteral("graphics.docx"));
        QFile::remove(path);
        QVERIFY(QFile::copy(QStringLiteral(TACTUS_TEST_DATA "/import/public/pandoc-inline_images.docx"), path));
        MainWindow w;
        QVERIFY(w.open_file_now(path));
        const auto described = w.paged().pages.size();
        const auto graphic_pages = [](const layout::PagedDocument& d) {
            return std::count_if(d.pages.begin(), d.pages.end(), [](const layout::Page& p) { return !p.graphic.empty(); });
        };
        QCOMPARE(graphic_pages(w.paged()), 0);
        w.set_picture_choice(PictureChoice::graphics);
        // The CLI's way: the file imported with its pictures, each laid out by graphic::picture_pages.
        import::ImportOptions io;
        io.images = true;
        const auto doc = import::import_file(path.toStdString(), io);
        QVERIFY(doc);
        pipeline::PipelineOptions o;
        o.tables = w.editor()->layout().tables();
        o.layout = w.editor()->layout().options();
        auto table = translate::Translator::open(o.tables);
        QVERIFY(table);
        o.graphic_pages = graphic::picture_pages(std::make_shared<const translate::Translator>(std::move(*table)),
                                                 w.profile_editor()->profile(), o.layout.geometry);
        const auto cli = pipeline::lay_out(*doc, o);
        QVERIFY(cli);
        QVERIFY(graphic_pages(*cli) > 0);
        QCOMPARE(w.paged().pages.size(), cli->pages.size());
        QCOMPARE(graphic_pages(w.paged()), graphic_pages(*cli));
        QVERIFY(w.paged().pages.size() > described);
        // And what tactus-cli layout --images graphics says of the same file.
        QProcess p;
        p.start(QStringLiteral(TACTUS_CLI), {QStringLiteral("layout"), QStringLiteral("--images"), QStringLiteral("graphics"),
                                             QStringLiteral("-t"), QString::fromStdString(o.tables),
                                             QStringLiteral("--summary"), path});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        const auto summary = QString::fromUtf8(p.readAllStandardOutput());
        const auto pages = QRegularExpression(QStringLiteral("pages: +(\\d+) braille pages")).match(summary);
        const auto graphic = QRegularExpression(QStringLiteral("graphic: +(\\d+) dots on (\\d+) graphic page")).match(summary);
        QVERIFY2(pages.hasMatch() && graphic.hasMatch(), qPrintable(summary));
        std::size_t dots = 0;
        for (const auto& page : w.paged().pages) dots += page.graphic.size();
        QCOMPARE(w.paged().pages.size(), pages.captured(1).toULongLong());
        QCOMPARE(static_cast<qulonglong>(graphic_pages(w.paged())), graphic.captured(2).toULongLong());
        QCOMPARE(static_cast<qulonglong>(dots), graphic.captured(1).toULongLong());
        QCOMPARE(QSettings().value(QStringLiteral("layout/images")).toString(), QStringLiteral("graphics"));
        {
            MainWindow next;
            QCOMPARE(next.picture_choice(), PictureChoice::graphics);
        }
        w.set_picture_choice(PictureChoice::descriptions);
        QCOMPARE(w.paged().pages.size(), described);
    }

    // A save that cannot be written says which file and why (core's atomic
    // write: the temporary copy beside the file could not be made), keeps the
    // document unsaved, and leaves nothing behind.
    void a_save_that_cannot_be_written_says_where_and_why() {
        MainWindow w;
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        QTest::keyClicks(w.editor()->print_pane(), "x");
        const auto path = dir.filePath(QStringLiteral("no such folder/saved.md"));
        QVERIFY(!w.save_to(path));
        const auto said = w.announcer()->message();
        QVERIFY2(said.startsWith(QStringLiteral("Cannot write %1: ").arg(QDir::toNativeSeparators(path))), qPrintable(said));
        QVERIFY2(said.contains(QStringLiteral("cannot create")), qPrintable(said));
        QVERIFY(w.isWindowModified());
        QVERIFY(!QFileInfo::exists(QFileInfo(path).path()));
    }

    // A text file is its text in the editor (no Markdown
    // escapes), is saved in place as text, and comes back unchanged.
    void a_text_file_is_shown_and_saved_as_it_is() {
        const QByteArray text = "Hello *world*.\n\n& and # and *\n\n- not a list\n";
        const auto path = dir.filePath(QStringLiteral("english.txt"));
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(text);
        }
        MainWindow w;
        QVERIFY(w.open_file_now(path));
        // The file's lines: its last line end shows as an empty last line.
        QCOMPARE(w.editor()->text(), QString::fromUtf8(text));
        // A screen reader hears what the lines are: the file's own, not Markdown.
        QVERIFY(w.editor()->print_pane()->accessibleDescription().startsWith(QStringLiteral("The text file's lines")));
        // Ctrl+S saves in place: Tactus writes text files.
        const auto save = [&w] { w.findChild<QAction*>(QStringLiteral("fileSave"))->trigger(); };
        save();
        QVERIFY(!w.isWindowModified());
        QFile saved(path);
        QVERIFY(saved.open(QIODevice::ReadOnly));
        QCOMPARE(saved.readAll(), text);
        saved.close();
        // Typed text stays as typed.
        auto* print = w.editor()->print_pane();
        print->moveCursor(QTextCursor::End);
        QTest::keyClick(print, Qt::Key_Return);
        QTest::keyClicks(print, "1. a_b_ <c>");
        QTest::keyClick(print, Qt::Key_Return);
        save();
        QVERIFY(saved.open(QIODevice::ReadOnly));
        QCOMPARE(saved.readAll(), text + "\n1. a_b_ <c>\n");
        saved.close();
        MainWindow again;
        QVERIFY(again.open_file_now(path));
        QCOMPARE(again.editor()->text(), w.editor()->text());
        QVERIFY(again.editor()->layout().paged().pages == w.editor()->layout().paged().pages);
    }

    // As a user meets it: a .txt opened, one character typed,
    // saved; the file differs from the original by that character only. The
    // texts hold what was lost before: a hard-wrapped paragraph's lines (the
    // editor showed them joined, saving wrote the joined line), lines of
    // spaces, CRLF line ends, a form feed before any text, Markdown-looking
    // lines.
    void a_text_file_edited_by_one_character_differs_by_it_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("line");    // where the character is typed
        QTest::addColumn<int>("column");
        QTest::addColumn<QByteArray>("expected");
        QTest::addColumn<QByteArray>("saved");  // saved before the edit
        QTest::newRow("hard-wrapped") << QByteArray("It was the best of times,\nit was the worst of times.\n\nThe end.\n")
                                      << 1 << 0 << QByteArray("It was the best of times,\nXit was the worst of times.\n\nThe end.\n")
                                      << QByteArray("It was the best of times,\nit was the worst of times.\n\nThe end.\n");
        QTest::newRow("lines of spaces") << QByteArray("one\n  \n\t\ntwo\n \n\n\nthree\n") << 0 << 3
                                         << QByteArray("oneX\n  \n\t\ntwo\n \n\n\nthree\n")
                                         << QByteArray("one\n  \n\t\ntwo\n \n\n\nthree\n");
        QTest::newRow("CRLF") << QByteArray("one\r\ntwo\r\n\r\nthree\r\n") << 2 << 0
                              << QByteArray("one\r\ntwo\r\nX\r\nthree\r\n") << QByteArray("one\r\ntwo\r\n\r\nthree\r\n");
        QTest::newRow("mixed ends: the first") << QByteArray("one\r\ntwo\nthree\r") << 0 << 0
                                               << QByteArray("Xone\r\ntwo\r\nthree\r\n")
                                               << QByteArray("one\r\ntwo\r\nthree\r\n");
        QTest::newRow("leading form feed") << QByteArray("\f\nTitle\n\n\fChapter\ntext\n\f") << 1 << 5
                                           << QByteArray("\f\nTitleX\n\n\fChapter\ntext\n\f")
                                           << QByteArray("\f\nTitle\n\n\fChapter\ntext\n\f");
        QTest::newRow("no last line end") << QByteArray("one\ntwo") << 1 << 3 << QByteArray("one\ntwoX") << QByteArray("one\ntwo");
        QTest::newRow("Markdown-looking") << QByteArray("& and # and *\n# not a heading\n1. not a list\n- nor this\n| a | b |\n> no quote\n")
                                          << 0 << 0 << QByteArray("X& and # and *\n# not a heading\n1. not a list\n- nor this\n| a | b |\n> no quote\n")
                                          << QByteArray("& and # and *\n# not a heading\n1. not a list\n- nor this\n| a | b |\n> no quote\n");
    }
    void a_text_file_edited_by_one_character_differs_by_it() {
        QFETCH(QByteArray, text);
        QFETCH(int, line);
        QFETCH(int, column);
        QFETCH(QByteArray, expected);
        QFETCH(QByteArray, saved);
        const auto path = dir.filePath(QStringLiteral("edited.txt"));
        const auto write = [&path](const QByteArray& bytes) {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(bytes);
        };
        const auto read = [&path] {
            QFile f(path);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        write(text);
        MainWindow w;
        QVERIFY(w.open_file_now(path));
        // The editor shows the file's lines as written, no escapes.
        auto shown = QString::fromUtf8(text);
        shown.replace(QStringLiteral("\r\n"), QStringLiteral("\n")).replace(QLatin1Char('\r'), QLatin1Char('\n'));
        QCOMPARE(w.editor()->text(), shown);
        const auto save = [&w] { w.findChild<QAction*>(QStringLiteral("fileSave"))->trigger(); };
        // Saved as opened: the same bytes (mixed line ends become the first).
        save();
        QVERIFY(!w.isWindowModified());
        QCOMPARE(read(), saved);
        auto* print = w.editor()->print_pane();
        QTextCursor c(print->document()->findBlockByNumber(line));
        c.setPosition(c.block().position() + column);
        print->setTextCursor(c);
        QTest::keyClicks(print, "X");
        save();
        QCOMPARE(read(), expected);
        // The braille is the importer's of the saved file (a hard-wrapped paragraph reflows).
        MainWindow again;
        QVERIFY(again.open_file_now(path));
        QCOMPARE(again.editor()->text(), w.editor()->text());
        QVERIFY(again.editor()->layout().paged().pages == w.editor()->layout().paged().pages);
        auto doc = import::import_file(path.toStdString());
        QVERIFY(doc.has_value());
        pipeline::PipelineOptions options;
        options.tables = w.editor()->layout().tables();
        options.layout = w.editor()->layout().options();
        options.allow_empty = true;
        const auto paged = pipeline::lay_out(*doc, options);
        QVERIFY(paged.has_value());
        QVERIFY(paged->pages == w.editor()->layout().paged().pages);
    }

    // A .txt is saved in its own encoding, not as UTF-8. Opened and saved it is the same bytes; edited, it is still in
    // its encoding (the bytes another program would write).
    void a_text_file_is_saved_in_its_encoding_data() {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<int>("line");  // where `typed` is typed, at the line's start
        QTest::addColumn<QString>("typed");
        QTest::addColumn<QByteArray>("expected");
        const auto hex = [](const char* h) { return QByteArray::fromHex(QByteArray(h).replace(' ', "")); };
        QTest::newRow("windows-1252")
            << hex("4361 66e9 2093 7175 6f74 6564 9420 636f 7374 7320 8035 2e0a 0a4e 61ef 7665 2072 e973 756d e92c 2066 61e7 6164 652e 0a")
            << 2 << QStringLiteral("\u00FC")
            << hex("4361 66e9 2093 7175 6f74 6564 9420 636f 7374 7320 8035 2e0a 0afc 4e61 ef76 6520 72e9 7375 6de9 2c20 6661 e761 6465 2e0a");
        QTest::newRow("UTF-16LE with BOM") << hex("fffe 4800 6500 6c00 6c00 6f00 2000 164e 4c75 0a00 0a00 6200 7900 6500 0a00")
                                           << 2 << QStringLiteral("!")
                                           << hex("fffe 4800 6500 6c00 6c00 6f00 2000 164e 4c75 0a00 0a00 2100 6200 7900 6500 0a00");
        QTest::newRow("Big5")
            << hex("ac4b af76 a4a3 c4b1 bee5 a141 b342 b342 bb44 b3da b3be a143 0aa9 5da8 d3ad b7ab 42c1 6ea1 41aa e1b8 a8aa bea6 68a4 d6a1 430a")
            << 1 << QStringLiteral("\u4E2D")
            << hex("ac4b af76 a4a3 c4b1 bee5 a141 b342 b342 bb44 b3da b3be a143 0aa4 a4a9 5da8 d3ad b7ab 42c1 6ea1 41aa e1b8 a8aa bea6 68a4 d6a1 430a");
        QTest::newRow("GB18030")
            << hex("b4ba c3df b2bb bef5 cffe a3ac b4a6 b4a6 cec5 cce4 c4f1 a1a3 0ad2 b9c0 b4b7 e7d3 eac9 f9a3 acbb a8c2 e4d6 aab6 e0c9 d9a1 a30a")
            << 1 << QStringLiteral("\u4E2D")
            << hex("b4ba c3df b2bb bef5 cffe a3ac b4a6 b4a6 cec5 cce4 c4f1 a1a3 0ad6 d0d2 b9c0 b4b7 e7d3 eac9 f9a3 acbb a8c2 e4d6 aab6 e0c9 d9a1 a30a");
    }
    void a_text_file_is_saved_in_its_encoding() {
        MainWindow w;
        open_edit_and_save(w, QStringLiteral("encoded.txt"));
    }

    // A .md is saved in its own encoding, not as UTF-8. It follows the text file's rule (edit::file_bytes): opened and
    // saved it is the same bytes; edited, it is still in its encoding.
    void a_markdown_file_is_saved_in_its_encoding_data() {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<int>("line");  // where `typed` is typed, at the line's start
        QTest::addColumn<QString>("typed");
        QTest::addColumn<QByteArray>("expected");
        const auto hex = [](const char* h) { return QByteArray::fromHex(QByteArray(h).replace(' ', "")); };
        // "# Café “quoted” costs €5\n\nNaïve résumé, *façade*.\n\n- œuvre, Ærø\n"
        QTest::newRow("windows-1252")
            << hex("2320 4361 66e9 2093 7175 6f74 6564 9420 636f 7374 7320 8035 0a0a 4e61 ef76 6520 72e9 7375 6de9 2c20 2a66 61e7 6164 652a 2e0a 0a2d 209c 7576 7265 2c20 c672 f80a")
            << 1 << QStringLiteral("\u00FC")
            << hex("2320 4361 66e9 2093 7175 6f74 6564 9420 636f 7374 7320 8035 0a0a fc4e 61ef 7665 2072 e973 756d e92c 202a 6661 e761 6465 2a2e 0a0a 2d20 9c75 7672 652c 20c6 72f8 0a");
        // BOM + "# Hello 世界\n\n**bye** now\n"
        QTest::newRow("UTF-16LE with BOM")
            << hex("fffe 2300 2000 4800 6500 6c00 6c00 6f00 2000 164e 4c75 0a00 0a00 2a00 2a00 6200 7900 6500 2a00 2a00 2000 6e00 6f00 7700 0a00")
            << 1 << QStringLiteral("!")
            << hex("fffe 2300 2000 4800 6500 6c00 6c00 6f00 2000 164e 4c75 0a00 0a00 2100 2a00 2a00 6200 7900 6500 2a00 2a00 2000 6e00 6f00 7700 0a00");
        // The same as Windows Notepad writes it: with CRLF, which it keeps.
        QTest::newRow("UTF-16LE with BOM, CRLF")
            << hex("fffe 2300 2000 4800 6500 6c00 6c00 6f00 2000 164e 4c75 0d00 0a00 0d00 0a00 2a00 2a00 6200 7900 6500 2a00 2a00 2000 6e00 6f00 7700 0d00 0a00")
            << 1 << QStringLiteral("!")
            << hex("fffe 2300 2000 4800 6500 6c00 6c00 6f00 2000 164e 4c75 0d00 0a00 0d00 0a00 2100 2a00 2a00 6200 7900 6500 2a00 2a00 2000 6e00 6f00 7700 0d00 0a00");
        // "## 春曉\n\n春眠不覺曉，處處聞啼鳥。\n\n夜來風雨聲，花落知多少。\n"
        QTest::newRow("Big5")
            << hex("2323 20ac 4bbe e50a 0aac 4baf 76a4 a3c4 b1be e5a1 41b3 42b3 42bb 44b3 dab3 bea1 430a 0aa9 5da8 d3ad b7ab 42c1 6ea1 41aa e1b8 a8aa bea6 68a4 d6a1 430a")
            << 2 << QStringLiteral("\u4E2D")
            << hex("2323 20ac 4bbe e50a 0aac 4baf 76a4 a3c4 b1be e5a1 41b3 42b3 42bb 44b3 dab3 bea1 430a 0aa4 a4a9 5da8 d3ad b7ab 42c1 6ea1 41aa e1b8 a8aa bea6 68a4 d6a1 430a");
        // "## 春晓\n\n春眠不觉晓，处处闻啼鸟。\n\n夜来风雨声，花落知多少。\n"
        QTest::newRow("GB18030")
            << hex("2323 20b4 bacf fe0a 0ab4 bac3 dfb2 bbbe f5cf fea3 acb4 a6b4 a6ce c5cc e4c4 f1a1 a30a 0ad2 b9c0 b4b7 e7d3 eac9 f9a3 acbb a8c2 e4d6 aab6 e0c9 d9a1 a30a")
            << 2 << QStringLiteral("\u4E2D")
            << hex("2323 20b4 bacf fe0a 0ab4 bac3 dfb2 bbbe f5cf fea3 acb4 a6b4 a6ce c5cc e4c4 f1a1 a30a 0ad6 d0d2 b9c0 b4b7 e7d3 eac9 f9a3 acbb a8c2 e4d6 aab6 e0c9 d9a1 a30a");
    }
    void a_markdown_file_is_saved_in_its_encoding() {
        MainWindow w;
        const auto path = open_edit_and_save(w, QStringLiteral("encoded.md"));
        if (QTest::currentTestFailed()) return;
        // Reopened, it is the text as edited, in the same encoding.
        MainWindow again;
        QVERIFY(again.open_file_now(path));
        QCOMPARE(again.editor()->text(), w.editor()->text());
        QCOMPARE(again.editor()->layout().encoding(), w.editor()->layout().encoding());
    }

    // A character the file's encoding cannot hold is never written as a
    // substitute: without an answer (no one to ask) nothing is saved, and the
    // message names the character, its line and the encoding.
    // A Markdown file the same way, by the same rule.
    void a_character_the_encoding_cannot_hold_is_not_saved_silently_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("line");  // the editor line of "naïve"
        QTest::newRow("text") << QStringLiteral("western.txt") << 2;
        QTest::newRow("Markdown") << QStringLiteral("western.md") << 1;
    }
    void a_character_the_encoding_cannot_hold_is_not_saved_silently() {
        QFETCH(QString, name);
        QFETCH(int, line);
        const auto path = dir.filePath(name);
        const auto bytes = QByteArray::fromHex("4361 66e9 0a0a 6e61 ef76 650a");  // "Café\n\nnaïve\n" in windows-1252
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(bytes);
        }
        const auto original = [&path] {
            QFile f(path);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        }();
        MainWindow w;
        QVERIFY(w.open_file_now(path));
        QCOMPARE(w.editor()->layout().encoding(), std::string("WINDOWS-1252"));
        auto* print = w.editor()->print_pane();
        QTextCursor c(print->document()->findBlockByNumber(line));
        c.insertText(QStringLiteral("\u4E2D"));
        QVERIFY(!w.save_to(path));
        QVERIFY(w.isWindowModified());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), original);
        const auto said = w.announcer()->message();
        QVERIFY2(said.contains(QStringLiteral("U+4E2D")) && said.contains(QStringLiteral("WINDOWS-1252")) &&
                     said.contains(QStringLiteral("3:1")),
                 qPrintable(said));
        // Saved under another name, text or Markdown, it is still in its
        // encoding (one rule, edit::file_bytes): refused the same way.
        for (const auto* other : {"other.md", "other.txt"}) {
            QVERIFY(!w.save_to(dir.filePath(QLatin1String(other))));
            QVERIFY(!QFileInfo::exists(dir.filePath(QLatin1String(other))));
        }

        // With someone to ask: the question, named for Orca, Cancel first
        // (nothing written), then Save as UTF-8 (the whole file, from then on).
        w.set_interactive(true);
        w.show();
        struct Seen {
            bool asked = false;
            QString name, text, buttons;
        };
        const auto answer = [](Seen& seen, bool utf8) {
            QTimer::singleShot(200, [&seen, utf8] {
                auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
                if (!box) return;
                seen.asked = box->objectName() == QLatin1String("encodingQuestion");
                seen.text = box->text() + QLatin1Char(' ') + box->informativeText();
                if (auto* a = QAccessible::queryAccessibleInterface(box)) seen.name = a->text(QAccessible::Name);
                for (auto* b : box->buttons())
                    if (auto* ba = QAccessible::queryAccessibleInterface(b)) seen.buttons += ba->text(QAccessible::Name) + QLatin1Char('|');
                (utf8 ? box->findChild<QPushButton*>(QStringLiteral("saveUtf8Button")) : box->button(QMessageBox::Cancel))->click();
            });
        };
        Seen cancel;
        answer(cancel, false);
        QVERIFY(!w.save_to(path));
        QVERIFY(cancel.asked);
        QCOMPARE(cancel.name, QStringLiteral("A character does not fit the file's encoding"));
        QVERIFY2(cancel.text.contains(QStringLiteral("WINDOWS-1252")) && cancel.text.contains(QStringLiteral("U+4E2D")) &&
                     cancel.text.contains(QStringLiteral("3:1")),
                 qPrintable(cancel.text));
        QVERIFY2(cancel.buttons.contains(QStringLiteral("Save as UTF-8")), qPrintable(cancel.buttons));
        {
            QFile again(path);
            QVERIFY(again.open(QIODevice::ReadOnly));
            QCOMPARE(again.readAll(), original);
        }
        Seen utf8;
        answer(utf8, true);
        QVERIFY(w.save_to(path));
        QVERIFY(utf8.asked);
        QFile saved(path);
        QVERIFY(saved.open(QIODevice::ReadOnly));
        QCOMPARE(saved.readAll(), QByteArray("Caf\xC3\xA9\n\n\xE4\xB8\xADna\xC3\xAFve\n"));
        QCOMPARE(w.editor()->layout().encoding(), std::string("UTF-8"));
    }

    // A hard-wrapped paragraph: each print line shows its own words' braille,
    // and typing on one line re-translates the paragraph on the lines around it.
    void a_hard_wrapped_paragraph_shows_its_braille_line_by_line() {
        const auto path = dir.filePath(QStringLiteral("wrapped.txt"));
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("one two\nthree\n\nfour\n");
        }
        MainWindow w;
        QVERIFY(w.open_file_now(path));
        auto* editor = w.editor();
        const auto braille = [editor](int line) {
            return editor->braille_pane()->document()->findBlockByNumber(line).text();
        };
        const auto cells = [editor](const std::string& print) {
            return QString::fromStdString(document::to_unicode_text(
                *editor->layout().translator().translate(utf8_to_utf32(print).value())));
        };
        QCOMPARE(braille(0), cells("one two"));
        QCOMPARE(braille(1), cells("three"));
        QCOMPARE(braille(3), cells("four"));
        QTextCursor c(editor->print_pane()->document()->findBlockByNumber(1));
        c.movePosition(QTextCursor::EndOfBlock);
        editor->print_pane()->setTextCursor(c);
        QTest::keyClicks(editor->print_pane(), " five");
        QCOMPARE(braille(0), cells("one two"));
        QCOMPARE(braille(1), cells("three five"));
        // Joining the lines (backspace at the start of the second) makes one line.
        c = QTextCursor(editor->print_pane()->document()->findBlockByNumber(1));
        editor->print_pane()->setTextCursor(c);
        QTest::keyClick(editor->print_pane(), Qt::Key_Backspace);
        QCOMPARE(editor->text(), QStringLiteral("one twothree five\n\nfour\n"));
        QCOMPARE(braille(0), cells("one twothree five"));
        QCOMPARE(braille(2), cells("four"));
    }

    // A Markdown table is a pipe table in the editor, and saved as one.
    void a_table_is_edited_and_saved_as_a_table() {
        const auto path = dir.filePath(QStringLiteral("plants.md"));
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("| Plant | Where |\n|---|---|\n| Willow | river |\n");
        }
        MainWindow w;
        QVERIFY(w.open_file_now(path));
        QCOMPARE(w.editor()->text(), QStringLiteral("| Plant | Where |\n| --- | --- |\n| Willow | river |"));
        auto* print = w.editor()->print_pane();
        print->moveCursor(QTextCursor::End);
        QTest::keyClick(print, Qt::Key_Return);
        // A new row of the table: its cells are a tab apart.
        QTest::keyClicks(print, "Fern");
        print->textCursor().insertText(QStringLiteral("\tshade"));
        w.findChild<QAction*>(QStringLiteral("fileSave"))->trigger();
        QVERIFY(!w.isWindowModified());
        MainWindow again;
        QVERIFY(again.open_file_now(path));
        QCOMPARE(again.editor()->text(), w.editor()->text());
        const auto doc = again.editor()->layout().document();
        QCOMPARE(doc.blocks.size(), std::size_t{9});  // three rows of two entries
        QCOMPARE(doc.blocks[0].level, 1);              // the header row
        QVERIFY(again.editor()->layout().paged().pages == w.editor()->layout().paged().pages);
    }

    void switching_tables_retranslates() {
        MainWindow w;
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        const auto g2 = w.editor()->braille_pane()->toPlainText();
        w.set_table(QStringLiteral("en-ueb-g1.ctb"));
        QCOMPARE(w.table_picker()->table(), QStringLiteral("en-ueb-g1.ctb"));
        const auto g1 = w.editor()->braille_pane()->toPlainText();
        QVERIFY(g1 != g2);
        QVERIFY(g1.size() > g2.size());  // uncontracted is longer
        QCOMPARE(QSettings().value(QStringLiteral("braille/table")).toString(), QStringLiteral("en-ueb-g1.ctb"));
        w.set_table(QStringLiteral("en-ueb-g2.ctb"));
        QCOMPARE(w.editor()->braille_pane()->toPlainText(), g2);
    }

    void unreadable_input_leaves_the_document_alone_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("missing") << QStringLiteral("missing.md") << QByteArray();
        QTest::newRow("broken docx") << QStringLiteral("broken.docx") << QByteArray("PK\x03\x04 not a zip at all", 24);
        QTest::newRow("bad pef") << QStringLiteral("bad.pef") << QByteArray("<pef><body><volume>");
        QTest::newRow("unknown encoding") << QStringLiteral("odd.txt")
                                          << QByteArray("\xff\xfe\x00\xd8\x00\xd8 lone surrogates", 22);
    }
    void unreadable_input_leaves_the_document_alone() {
        QFETCH(QString, name);
        QFETCH(QByteArray, bytes);
        const auto path = dir.filePath(name);
        if (!bytes.isEmpty()) {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(bytes);
        }
        MainWindow w;
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        const auto text = w.editor()->text();
        QSignalSpy failed(&w, &MainWindow::failed);
        const bool ok = w.open_file_now(path);
        if (ok) {
            // Some "bad" inputs are readable after all (encoding detection): then they
            // must at least have produced a document without crashing.
            QVERIFY(failed.isEmpty());
            return;
        }
        QCOMPARE(failed.size(), 1);
        QCOMPARE(w.editor()->text(), text);
        QVERIFY(w.announcer()->message().startsWith(QStringLiteral("Cannot open")));
        QVERIFY(w.windowTitle().startsWith(QStringLiteral("welcome.md")));
    }

    void autosave_and_recovery_after_a_crash() {
        QString autosaved;
        {
            MainWindow w;
            QVERIFY(w.open_file_now(test::sample("welcome.md")));
            auto* print = w.editor()->print_pane();
            print->moveCursor(QTextCursor::End);
            QTest::keyClicks(print, " Unsaved words.");
            QVERIFY(w.autosave_now());
            autosaved = w.editor()->text();
            // Pretend the process died: rewrite the owner to a pid that does not exist.
            QFile meta(w.autosave_path() + QStringLiteral(".json"));
            QVERIFY(meta.open(QIODevice::ReadOnly));
            auto json = QJsonDocument::fromJson(meta.readAll()).object();
            meta.close();
            json[QStringLiteral("pid")] = 999999999;
            QVERIFY(meta.open(QIODevice::WriteOnly | QIODevice::Truncate));
            meta.write(QJsonDocument(json).toJson());
            meta.close();
            // The window is destroyed without closing, as in a crash: the files stay.
        }
        const auto pending = MainWindow::pending_recoveries();
        QCOMPARE(pending.size(), 1);
        QCOMPARE(pending[0].document_path, QFileInfo(test::sample("welcome.md")).absoluteFilePath());
        QCOMPARE(pending[0].table, QStringLiteral("en-ueb-g2.ctb"));
        MainWindow w;
        QVERIFY(w.recover(pending[0]));
        QCOMPARE(w.editor()->text(), autosaved);
        QVERIFY(w.isWindowModified());  // recovered work is unsaved until saved
        QVERIFY(MainWindow::pending_recoveries().isEmpty());
        QVERIFY(!QFile::exists(pending[0].autosave_path));
    }

    // A PEF of volumes with their own page sizes and
    // single-sided sections (volume_grids.pef), edited, is autosaved as PEF;
    // recovered after a crash it exports (PEF and BRF) the same bytes as the
    // window that crashed. Before, the autosave was the editor's Markdown
    // lines: the recovery had the rows and pages but no sections, volumes,
    // grids or metadata, so its PEF was one volume of one section on one
    // grid, and its BRF lost the blank backs of the single-sided sections.
    void a_recovered_pef_exports_what_the_crashed_window_exported() {
        const QString file = QStringLiteral(TACTUS_TEST_DATA "/pef/volume_grids.pef");
        QByteArray before_pef, before_brf;
        const auto read = [](const QString& path) {
            QFile f(path);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        {
            MainWindow w;
            QVERIFY(w.open_file_now(file));
            // A row of volume 2 changed (a cell typed at its end).
            auto* print = w.editor()->print_pane();
            const auto block = print->document()->find(QStringLiteral("⠋⠕⠥⠗"));
            QVERIFY(!block.isNull());
            QTextCursor c(block);
            c.movePosition(QTextCursor::EndOfBlock);
            c.insertText(QStringLiteral("⠗"));
            QVERIFY(w.isWindowModified());
            QVERIFY(w.export_to(dir.filePath(QStringLiteral("crashed.pef"))));
            QVERIFY(w.export_to(dir.filePath(QStringLiteral("crashed.brf"))));
            before_pef = read(dir.filePath(QStringLiteral("crashed.pef")));
            before_brf = read(dir.filePath(QStringLiteral("crashed.brf")));
            QVERIFY(before_pef.contains("⠋⠕⠥⠗⠗"));
            QVERIFY(w.autosave_now());
            QVERIFY2(w.autosave_path().endsWith(QLatin1String(".pef")), qPrintable(w.autosave_path()));
            QFile meta(w.autosave_path() + QStringLiteral(".json"));
            QVERIFY(meta.open(QIODevice::ReadOnly));
            auto json = QJsonDocument::fromJson(meta.readAll()).object();
            meta.close();
            json[QStringLiteral("pid")] = 999999999;  // its process died
            QVERIFY(meta.open(QIODevice::WriteOnly | QIODevice::Truncate));
            meta.write(QJsonDocument(json).toJson());
        }
        const auto pending = MainWindow::pending_recoveries();
        QCOMPARE(pending.size(), 1);
        QVERIFY(pending[0].autosave_path.endsWith(QLatin1String(".pef")));
        MainWindow w;
        QVERIFY(w.recover(pending[0]));
        QVERIFY(w.isWindowModified());
        QVERIFY(w.export_to(dir.filePath(QStringLiteral("recovered.pef"))));
        QVERIFY(w.export_to(dir.filePath(QStringLiteral("recovered.brf"))));
        QCOMPARE(read(dir.filePath(QStringLiteral("recovered.pef"))), before_pef);
        QCOMPARE(read(dir.filePath(QStringLiteral("recovered.brf"))), before_brf);
        // Print typed into it: no longer ready-made braille, autosaved as the editor's lines.
        auto* print = w.editor()->print_pane();
        print->moveCursor(QTextCursor::End);
        QTest::keyClick(print, Qt::Key_Return);
        QTest::keyClicks(print, QStringLiteral("Print words"));
        QVERIFY(w.autosave_now());
        QVERIFY2(w.autosave_path().endsWith(QLatin1String(".md")), qPrintable(w.autosave_path()));
        QVERIFY(!QFile::exists(QFileInfo(w.autosave_path()).path() + QLatin1Char('/') +
                               QFileInfo(w.autosave_path()).completeBaseName() + QStringLiteral(".pef")));
    }

    // A CRLF text file recovered after a crash is saved with CRLF again.
    void a_recovered_text_file_keeps_its_line_ends() {
        const auto path = dir.filePath(QStringLiteral("dos.txt"));
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("one\r\ntwo\r\n");
        }
        {
            MainWindow w;
            QVERIFY(w.open_file_now(path));
            QTextCursor c(w.editor()->print_pane()->document()->findBlockByNumber(1));
            c.movePosition(QTextCursor::EndOfBlock);
            w.editor()->print_pane()->setTextCursor(c);
            QTest::keyClicks(w.editor()->print_pane(), " three");
            QVERIFY(w.autosave_now());
            QFile meta(w.autosave_path() + QStringLiteral(".json"));
            QVERIFY(meta.open(QIODevice::ReadOnly));
            auto json = QJsonDocument::fromJson(meta.readAll()).object();
            meta.close();
            json[QStringLiteral("pid")] = 999999999;
            QVERIFY(meta.open(QIODevice::WriteOnly | QIODevice::Truncate));
            meta.write(QJsonDocument(json).toJson());
        }
        const auto pending = MainWindow::pending_recoveries();
        QCOMPARE(pending.size(), 1);
        MainWindow w;
        QVERIFY(w.recover(pending[0]));
        QVERIFY(w.save_to(path));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("one\r\ntwo three\r\n"));
    }

    // A Markdown file recovered after a crash is
    // saved in its encoding and with its line ends again (Notepad's UTF-16LE
    // with a BOM and CRLF), as a text file is.
    void a_recovered_markdown_file_keeps_its_encoding_and_line_ends() {
        const auto hex = [](const char* h) { return QByteArray::fromHex(QByteArray(h).replace(' ', "")); };
        const auto path = dir.filePath(QStringLiteral("notepad.md"));
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            // "# Hello 世界\r\n\r\n**bye** now\r\n"
            f.write(hex("fffe 2300 2000 4800 6500 6c00 6c00 6f00 2000 164e 4c75 0d00 0a00 0d00 0a00 2a00 2a00 6200 7900 6500 2a00 2a00 2000 6e00 6f00 7700 0d00 0a00"));
        }
        {
            MainWindow w;
            QVERIFY(w.open_file_now(path));
            QTextCursor c(w.editor()->print_pane()->document()->findBlockByNumber(1));
            c.movePosition(QTextCursor::EndOfBlock);
            w.editor()->print_pane()->setTextCursor(c);
            QTest::keyClicks(w.editor()->print_pane(), "!");
            QVERIFY(w.autosave_now());
            QFile meta(w.autosave_path() + QStringLiteral(".json"));
            QVERIFY(meta.open(QIODevice::ReadOnly));
            auto json = QJsonDocument::fromJson(meta.readAll()).object();
            meta.close();
            json[QStringLiteral("pid")] = 999999999;
            QVERIFY(meta.open(QIODevice::WriteOnly | QIODevice::Truncate));
            meta.write(QJsonDocument(json).toJson());
        }
        const auto pending = MainWindow::pending_recoveries();
        QCOMPARE(pending.size(), 1);
        MainWindow w;
        QVERIFY(w.recover(pending[0]));
        QCOMPARE(w.editor()->layout().encoding(), std::string("UTF-16LE"));
        QVERIFY(w.save_to(path));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        // "# Hello 世界\r\n\r\n**bye** now!\r\n"
        QCOMPARE(f.readAll(), hex("fffe 2300 2000 4800 6500 6c00 6c00 6f00 2000 164e 4c75 0d00 0a00 0d00 0a00 2a00 2a00 6200 7900 6500 2a00 2a00 2000 6e00 6f00 7700 2100 0d00 0a00"));
    }

    void six_key_mapping_comes_from_the_settings() {
        QSettings().setValue(QStringLiteral("braille/six_keys"), QStringLiteral("ASDJKL"));  // dot 1 on A
        MainWindow w;
        QSettings().remove(QStringLiteral("braille/six_keys"));
        const auto& m = w.editor()->braille_pane()->chord().mapping();
        QCOMPARE(m[0], int(Qt::Key_A));
        QCOMPARE(m[2], int(Qt::Key_D));
        QCOMPARE(m[5], int(Qt::Key_L));
    }

    // A chord speaks the cell it typed and the print letter,
    // and the status bar and the preview's cell cursor stay on the new cell.
    void a_chord_is_echoed_and_the_cursor_stays_on_it() {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        auto* pane = w.editor()->braille_pane();
        pane->setFocus();
        QTextCursor c(pane->document()->findBlockByNumber(2));
        c.setPosition(c.position() + 4);
        pane->setTextCursor(c);
        QSignalSpy spoken(w.announcer(), &Announcer::announced);
        for (auto k : {Qt::Key_F, Qt::Key_D}) QTest::keyPress(pane, k);  // dots 1 2
        for (auto k : {Qt::Key_F, Qt::Key_D}) QTest::keyRelease(pane, k);
        QCOMPARE(spoken.size(), 1);
        // Contracted UEB: the lone cell b is the wordsign "but".
        QCOMPARE(spoken.front().front().toString(), QStringLiteral("dots 1 2, but"));
        QCOMPARE(pane->textCursor().positionInBlock(), 5);
        const auto pos = w.editor()->current_position();
        const auto want = w.editor()->layout().position_of(2, 5);
        QCOMPARE(pos.page, want.page);
        QCOMPARE(pos.line, want.line);
        QCOMPARE(pos.cell, want.cell);
        QRegularExpression cell(QStringLiteral(R"(\| cell (\d+) \|)"));
        const auto m = cell.match(w.status_text());
        QVERIFY2(m.hasMatch(), qPrintable(w.status_text()));
        QCOMPARE(m.captured(1).toInt(), pos.cell + 1);
        QCOMPARE(w.preview_panel()->preview()->cursor_page(), pos.page);
        QCOMPARE(w.preview_panel()->preview()->cursor_line(), pos.line);
        QCOMPARE(w.preview_panel()->preview()->cursor_cell(), pos.cell);
    }

    void keyboard_reaches_everything_with_names() {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        // Every action has a shortcut and appears in the shortcut list.
        const auto rows = w.shortcut_rows();
        for (auto* a : w.all_actions()) QVERIFY2(!a->shortcut().isEmpty(), qPrintable(a->text()));
        QVERIFY(rows.size() >= w.all_actions().size());
        // No two actions share a key: Qt then runs neither ("Ambiguous
        // shortcut overload") and the key does nothing.
        QHash<QString, QString> owner;
        for (auto* a : w.findChildren<QAction*>()) {
            for (const auto& key : a->shortcuts()) {
                const auto k = key.toString();
                const auto name = a->text().remove(QLatin1Char('&'));
                QVERIFY2(!owner.contains(k) || owner[k] == name,
                         qPrintable(QStringLiteral("%1 is both %2 and %3").arg(k, owner.value(k), name)));
                owner[k] = name;
            }
        }
        // Tab moves through the focusable widgets; each has an accessible name.
        w.editor()->print_pane()->setFocus();
        QSet<QWidget*> seen;
        for (int i = 0; i < 400; ++i) {
            QWidget* f = QApplication::focusWidget();
            QVERIFY(f);
            if (i > 0 && f == w.editor()->print_pane()) break;  // round the whole chain
            if (qEnvironmentVariableIsSet("TACTUS_TRACE_FOCUS"))
                qInfo("%d %s %s", i, f->metaObject()->className(), qPrintable(f->objectName()));
            seen.insert(f);
            auto* a = QAccessible::queryAccessibleInterface(f);
            QVERIFY2(a && !a->text(QAccessible::Name).isEmpty(), f->metaObject()->className());
            QTest::keyClick(f, Qt::Key_Tab);
        }
        QVERIFY(seen.contains(w.editor()->braille_pane()));
        QVERIFY(seen.contains(w.preview_panel()->preview()));
        QVERIFY(seen.contains(w.table_picker()));
        // Shortcuts go straight to the panes.
        QTest::keyClick(&w, Qt::Key_3, Qt::ControlModifier);
        QCOMPARE(QApplication::focusWidget(), w.preview_panel()->preview());
        QTest::keyClick(&w, Qt::Key_B, Qt::ControlModifier | Qt::AltModifier);
        QCOMPARE(w.preview_panel()->preview()->mode(), SideMode::back);
    }
};

QTEST_MAIN(MainWindowTest)
#include "main_window_test.moc"
