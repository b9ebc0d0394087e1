// SPDX-License-Identifier: GPL-3.0-or-later
// The main window over the spool: Connect configures the controller
// with the profile being edited (the simulator's CONFIGURE checked byte for
// byte), Ctrl+P stores the job in the spool, and quitting while it embosses
// asks first, in a dialog a keyboard answers; the job is still in the spool
// after the window is gone.
#include <QAccessible>
#include <QApplication>
#include <QLabel>
#include <QDoubleSpinBox>
#include <QMessageBox>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>

#include <bit>
#include <fstream>

#include "controller/builtin_sim.hpp"
#include "encode/messages.hpp"
#include "gui_test_support.hpp"
#include "editor_widget.hpp"
#include "main_window.hpp"
#include "printer_panel.hpp"
#include "profile/controller_config.hpp"
#include "profile/profile_json.hpp"
#include "profile_editor.hpp"
#include "spool/print_job.hpp"
#include "spool/snapshot.hpp"
#include "spool/spool.hpp"

using namespace tactus;
using namespace tactus::gui;

using test::wait_until;

class AppSpoolTest : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    std::string db_;

    spool::JobRecord job(spool::JobId id) { return *spool::Spool::open(db_, {.create = false})->job(id); }

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }
    void init() { db_ = test::fresh_spool(dir_.path()); }

    void connect_configures_the_controller_with_the_profile_being_edited() {
        MainWindow w;
        w.set_interactive(false);
        // The technician edits the profile as a user does, in its spin boxes.
        auto* dwell = w.profile_editor()->field(QStringLiteral("head.dwell_s"));
        auto* steps = w.profile_editor()->field(QStringLiteral("carriage.steps_per_mm"));
        QVERIFY(dwell && steps);
        dwell->setValue(0.0123);
        steps->setValue(steps->value() * 2);
        const auto edited = w.profile_editor()->profile();
        QCOMPARE(edited.head.dwell_s, 0.0123);
        const auto want = encode::encode_config(profile::controller_config(edited));
        QVERIFY(want != encode::encode_config(profile::controller_config(profile::default_profile())));
        auto* panel = w.printer_panel();
        panel->select_device(QStringLiteral("sim"));
        panel->findChild<QPushButton*>(QStringLiteral("connectButton"))->click();
        QVERIFY2(panel->connected(), qPrintable(panel->fault_text()));
        // What the simulated controller was sent in CONFIGURE, byte for byte.
        QCOMPARE(encode::encode_config(panel->simulator().config()), want);
        QVERIFY2(panel->status_text().contains(QStringLiteral("configured")), qPrintable(panel->status_text()));
        // The spool printer carries the same profile, so the runner configures and plans with it too.
        auto s = spool::Spool::open(db_, {.create = false});
        const auto printer = s->printer("sim");
        QVERIFY(printer);
        QCOMPARE(printer->profile_json, profile::to_json(edited).dump());
    }

    // A PEF whose page (40 cells x 25 lines) is larger than the printer
    // profile's (27 x 24 by default) is not laid out on the profile's page
    // and queued without a word: the app asks first,
    // in a dialog a screen reader reads (question, sizes, both buttons), with
    // the same rule as the CLI's exit 5 (layout::find_braille_misfit): Stop
    // queues nothing, Reflow queues the braille laid out on the printer's page.
    void a_pef_larger_than_the_printers_page_asks_before_embossing() {
        const auto pef = dir_.path() + QStringLiteral("/wide.pef");
        QString row;
        for (int w = 0; w < 8; ++w) row += QStringLiteral("⠁⠃⠉⠙") + (w < 7 ? QStringLiteral("⠀") : QStringLiteral("⠼"));
        QCOMPARE(row.size(), 40);
        {
            QFile f(pef);
            QVERIFY(f.open(QIODevice::WriteOnly));
            QString xml = QStringLiteral(
                "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                "<pef version=\"2008-1\" xmlns=\"http://www.daisy.org/ns/2008/pef\"><head>"
                "<meta xmlns:dc=\"http://purl.org/dc/elements/1.1/\"><dc:format>application/x-pef+xml</dc:format>"
                "<dc:identifier>wide</dc:identifier></meta></head><body>"
                "<volume cols=\"40\" rows=\"25\" rowgap=\"0\" duplex=\"true\"><section>");
            for (int p = 0; p < 2; ++p) {
                xml += QStringLiteral("<page>");
                for (int r = 0; r < 25; ++r) xml += QStringLiteral("<row>") + row + QStringLiteral("</row>");
                xml += QStringLiteral("</page>");
            }
            xml += QStringLiteral("</section></volume></body></pef>\n");
            f.write(xml.toUtf8());
        }
        MainWindow w;
        w.set_interactive(true);
        w.show();
        QVERIFY(w.open_file_now(pef));
        QCOMPARE(w.profile_editor()->profile().geometry.cells_per_line, 27);
        w.printer_panel()->select_device(QStringLiteral("sim"));

        struct Seen {
            bool asked = false;
            QString text, name, description, buttons, button_names;  // description: the labels' text
        };
        const auto answer = [](Seen& seen, const char* button) {
            QTimer::singleShot(200, [&seen, button] {
                auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
                if (!box) return;
                seen.asked = box->objectName() == QLatin1String("pageTooSmallQuestion");
                seen.text = box->text() + QLatin1Char(' ') + box->informativeText();
                auto* a = QAccessible::queryAccessibleInterface(box);
                seen.name = a ? a->text(QAccessible::Name) : QString();
                // What Orca reads after the name: the box's labels, through AT-SPI.
                for (int i = 0; a && i < a->childCount(); ++i)
                    if (auto* c = a->child(i); c && c->role() == QAccessible::StaticText)
                        seen.description += c->text(QAccessible::Name) + QLatin1Char(' ');
                for (auto* b : box->buttons()) {
                    seen.buttons += b->text() + QLatin1Char('|');
                    if (auto* ba = QAccessible::queryAccessibleInterface(b))
                        seen.button_names += ba->text(QAccessible::Name) + QLatin1Char('|');
                }
                box->findChild<QPushButton*>(QLatin1String(button))->click();
            });
        };

        Seen stop;
        answer(stop, "stopButton");
        QVERIFY(!w.emboss());
        QVERIFY(stop.asked);
        QVERIFY2(stop.text.contains(QStringLiteral("too small")), qPrintable(stop.text));
        QVERIFY2(stop.text.contains(QStringLiteral("The pages of wide.pef are 40 cells by 25 lines")), qPrintable(stop.text));
        QVERIFY2(stop.text.contains(QStringLiteral("27 cells by 24 lines")), qPrintable(stop.text));
        QCOMPARE(stop.buttons, QStringLiteral("&Reflow|&Stop|"));
        // What AT-SPI hands Orca: the dialog's name and the whole question, each button by name.
        QCOMPARE(stop.name, QStringLiteral("The printer's page is too small"));
        QVERIFY2(stop.description.contains(QStringLiteral("Lay the braille out again")), qPrintable(stop.description));
        QVERIFY2(stop.description.contains(QStringLiteral("27 cells by 24 lines")), qPrintable(stop.description));
        QCOMPARE(stop.button_names, QStringLiteral("Reflow|Stop|"));
        QVERIFY(w.printer_panel()->jobs().empty());
        // Nothing in the spool (the spool file is made by the first job: none yet here).
        if (auto s = spool::Spool::open(db_, {.create = false})) {
            const auto none = s->jobs(true);
            QVERIFY2(none, none ? "" : none.error().to_string().c_str());
            QVERIFY(none->empty());
        }

        // Export asks the same question.
        Seen stop_export;
        answer(stop_export, "stopButton");
        QVERIFY(!w.export_to(dir_.path() + QStringLiteral("/wide-again.pef")));
        QVERIFY(stop_export.asked);
        QVERIFY(!QFile::exists(dir_.path() + QStringLiteral("/wide-again.pef")));

        Seen reflow;
        answer(reflow, "reflowButton");
        QVERIFY(w.emboss());
        QVERIFY(reflow.asked);
        const auto& paged = w.editor()->layout().paged();
        QCOMPARE(paged.geometry.cells_per_line, 27);
        std::size_t cells = 0;
        for (const auto& page : paged.pages)
            for (const auto& line : page.lines) {
                QVERIFY(line.size() <= 27);
                for (auto c : line) cells += c.dots != 0 ? 1 : 0;
            }
        // Laid out again, nothing lost: every cell of the 2 x 25 rows of 33 raised cells.
        QCOMPARE(cells, std::size_t{2 * 25 * 33});
        auto s = spool::Spool::open(db_, {.create = false});
        QVERIFY(s);
        const auto jobs = s->jobs(true);
        QVERIFY2(jobs, jobs ? "" : jobs.error().to_string().c_str());
        QCOMPARE(jobs->size(), std::size_t{1});
        QCOMPARE(jobs->front().sheets_per_copy, paged.sheet_count());
        QVERIFY(paged.pages.size() > 2);  // 50 long rows do not fit on 2 pages of 24 lines
    }

    // A PEF of a duplex section of three pages, then a
    // single-sided section of two, embossed from the app on interpoint paper,
    // goes through the spool as the file's pages: the second section starts
    // on a new sheet (sheet 2's back is blank), each page of the single-sided
    // section has a sheet of its own, and no blank back is struck. Before, the
    // app laid the five pages out as one stream: 3 sheets, page 4 on the back
    // of sheet 2 and page 5 on the front of sheet 3.
    void a_single_sided_section_starts_on_a_new_sheet_and_its_backs_are_not_struck() {
        MainWindow w;
        w.set_interactive(false);
        QVERIFY(w.open_file_now(QStringLiteral(TACTUS_TEST_DATA "/pef/single_sided_section.pef")));
        QVERIFY(w.profile_editor()->profile().geometry.interpoint);
        w.printer_panel()->select_device(QStringLiteral("sim"));
        QVERIFY(w.emboss());
        auto s = spool::Spool::open(db_, {.create = false});
        QVERIFY(s);
        const auto jobs = s->jobs(true);
        QVERIFY2(jobs, jobs ? "" : jobs.error().to_string().c_str());
        QCOMPARE(jobs->size(), std::size_t{1});
        QCOMPARE(jobs->front().sheets_per_copy, std::size_t{4});
        // The pages the spool holds, planned as the runner plans them.
        const auto snapshot = s->document_snapshot(jobs->front().id);
        QVERIFY(snapshot);
        const auto pages = spool::from_snapshot(*snapshot);
        QVERIFY2(pages, pages ? "" : pages.error().to_string().c_str());
        QCOMPARE(pages->pages.size(), std::size_t{8});
        const auto job = spool::make_print_job(*pages, w.profile_editor()->profile(), "");
        QVERIFY2(job, job ? "" : job.error().to_string().c_str());
        const auto& sheets = job->plan.sheets;
        QCOMPARE(sheets.size(), std::size_t{4});
        std::vector<std::size_t> front(4), back(4);
        for (std::size_t i = 0; i < sheets.size(); ++i)
            for (const auto& pass : sheets[i].passes)
                for (const auto& strike : pass.strikes) ++(strike.side == plan::Side::front ? front : back)[i];
        // Sheet 1: pages 1 and 2; sheet 2: page 3 and a blank back; sheets 3
        // and 4: pages 4 and 5, one side each.
        for (std::size_t i = 0; i < 4; ++i) QVERIFY2(front[i] > 0, qPrintable(QStringLiteral("sheet %1 front").arg(i + 1)));
        QVERIFY(back[0] > 0);
        QCOMPARE(back[1], std::size_t{0});
        QCOMPARE(back[2], std::size_t{0});
        QCOMPARE(back[3], std::size_t{0});
        // The strikes are the file's dots: "one two three" then "four", "five".
        const auto dots = [](const char* utf8) {
            std::size_t n = 0;
            for (const auto c : QString::fromUtf8(utf8)) n += static_cast<std::size_t>(std::popcount(c.unicode() - 0x2800u));
            return n;
        };
        QCOMPARE(front[0], dots("⠕⠝⠑"));
        QCOMPARE(back[0], dots("⠞⠺⠕"));
        QCOMPARE(front[1], dots("⠞⠓⠗⠑⠑"));
        QCOMPARE(front[2], dots("⠋⠕⠥⠗"));
        QCOMPARE(front[3], dots("⠋⠊⠧⠑"));
    }

    void quitting_while_a_job_embosses_asks_first_and_the_job_stays_queued() {
        const auto doc = dir_.path() + QStringLiteral("/long.md");
        {
            std::ofstream out(doc.toStdString());
            for (const auto& paragraph : test::synthetic_book(400)) out << paragraph << "\n\n";
        }
        spool::JobId id = 0;
        {
            MainWindow w;
            w.set_interactive(true);
            w.show();
            QVERIFY(w.open_file_now(doc));
            w.printer_panel()->select_device(QStringLiteral("sim"));
            QVERIFY(w.emboss());
            id = w.printer_panel()->jobs().empty() ? 0 : w.printer_panel()->selected_job().value_or(0);
            QVERIFY(id > 0);
            QVERIFY(wait_until([&] { return w.printer_panel()->embossing().has_value(); }));
            // First answer: Escape keeps the window (and the job) going.
            QString asked, buttons;
            QTimer::singleShot(300, [&] {
                auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
                if (!box) return;
                asked = box->text() + QLatin1Char(' ') + box->informativeText();
                for (auto* b : box->buttons()) buttons += b->text() + QLatin1Char('|');
                QTest::keyClick(box, Qt::Key_Escape);
            });
            w.close();
            QVERIFY2(asked.contains(QStringLiteral("is being embossed. Quit anyway?")), qPrintable(asked));
            QVERIFY2(asked.contains(QStringLiteral("stays in the print queue")), qPrintable(asked));
            QCOMPARE(buttons, QStringLiteral("&Quit|&Keep embossing|"));
            QVERIFY(w.isVisible());
            QVERIFY(w.printer_panel()->runs_printer());
            // Second answer: Alt+Q quits; the window's runner lets go of the printer.
            QTimer::singleShot(300, [&] {
                if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()))
                    QTest::keyClick(box, Qt::Key_Q, Qt::AltModifier);
            });
            w.close();
            QVERIFY(!w.isVisible());
            QVERIFY(!w.printer_panel()->runs_printer());
        }
        // The job survived the window: back in the queue, progress kept, no runner.
        const auto j = job(id);
        QCOMPARE(j.state, spool::JobState::queued);
        QVERIFY(j.runner.empty());
        auto s = spool::Spool::open(db_, {.create = false});
        QVERIFY(s->printer("sim")->runner.empty());
    }
};

QTEST_MAIN(AppSpoolTest)
#include "app_spool_test.moc"
