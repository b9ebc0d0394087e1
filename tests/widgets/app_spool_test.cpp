// SPDX-License-Identifier: GPL-3.0-or-later
// The main window over the spool (issue 16): Connect configures the controller
// with the profile being edited (the simulator's CONFIGURE checked byte for
// byte), Ctrl+P stores the job in the spool, and quitting while it embosses
// asks first, in a dialog a keyboard answers; the job is still in the spool
// after the window is gone.
#include <QApplication>
#include <QDoubleSpinBox>
#include <QMessageBox>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

#include "controller/builtin_sim.hpp"
#include "encode/messages.hpp"
#include "gui_test_support.hpp"
#include "main_window.hpp"
#include "printer_panel.hpp"
#include "profile/controller_config.hpp"
#include "profile/profile_json.hpp"
#include "profile_editor.hpp"
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
