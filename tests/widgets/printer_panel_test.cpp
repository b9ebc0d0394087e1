// SPDX-License-Identifier: GPL-3.0-or-later
// The printer panel as a spool client, against a real SQLite spool file, the
// app's runner (core's spool::Runner on a thread) and the built-in simulator:
// Ctrl+P's job is stored in the spool and embossed with every strike checked
// against the plan; `tactus-cli queue list` and the panel show the same jobs;
// pause, resume, cancel and resume-from-page go through the spool; a printer
// held by another runner is only watched; any device string can be typed and a
// bad one is refused with the reason; faults injected into the simulator are
// ridden through; the built-in simulator takes the plan's own time unless
// its speed option says otherwise.
#include <QComboBox>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "../common/process.hpp"
#include "controller/builtin_sim.hpp"
#include "controller/device_choices.hpp"
#include "edit/live_layout.hpp"
#include "gui_test_support.hpp"
#include "link/fault_words.hpp"
#include "printer_panel.hpp"
#include "profile/profile_json.hpp"
#include "spool/printing.hpp"
#include "spool/spool.hpp"

using namespace tactus;
using namespace tactus::gui;
using tactus::test::wait_until;

namespace {

const std::string kCli = TACTUS_CLI;
// The built-in simulator as fast as it goes: the tests that emboss whole books.
const QString kFastSim = QStringLiteral("sim?speed=max");

layout::PagedDocument book(int paragraphs) {
    auto l = edit::LiveLayout::create("en-ueb-g2.ctb", {});
    l->reset(test::synthetic_book(paragraphs));
    return l->paged();
}

}  // namespace

class PrinterPanelTest : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;
    std::string db_;

    // A job's record as another process sees it (its own connection).
    spool::JobRecord job(spool::JobId id) {
        auto s = spool::Spool::open(db_, {.create = false});
        return *s->job(id);
    }
    std::string history(spool::JobId id) {
        return test::run({kCli, "queue", "history", std::to_string(id), "--db", db_, "--limit", "1000"}).second;
    }

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    // Each test gets its own spool file, and the picker starts on plain "sim".
    void init() {
        db_ = test::fresh_spool(dir_.path());
        QSettings().remove(QStringLiteral("printer/last"));
    }

    void simulator_is_always_listed_first() {
        const auto devices = controller::list_devices();
        QVERIFY(!devices.empty());
        QCOMPARE(devices.front().device, std::string("sim"));
        PrinterPanel panel;
        QCOMPARE(panel.selected_device(), QStringLiteral("sim"));
        QCOMPARE(panel.spool_path().string(), db_);
    }

    void faults_in_plain_words() {
        QVERIFY(QString::fromStdString(link::explain_faults(encode::fault::paper_out)).contains(QStringLiteral("put paper")));
        QVERIFY(QString::fromStdString(link::explain_faults(encode::fault::hammer)).contains(QStringLiteral("hammer")));
        QVERIFY(link::explain_faults(0).empty());
    }

    void a_queued_job_is_stored_in_the_spool_and_embossed_with_every_strike_checked() {
        PrinterPanel panel;
        panel.select_device(kFastSim);
        QSignalSpy finished(&panel, &PrinterPanel::job_finished);
        const auto id = panel.submit(QStringLiteral("book"), book(40), profile::default_profile());
        QVERIFY(id > 0);
        // In the spool at once, on a printer set up for the device, named after it.
        QCOMPARE(job(id).printer, std::string("sim"));
        QCOMPARE(job(id).title, std::string("book"));
        QVERIFY(panel.runs_printer());
        QVERIFY(finished.wait(120000));
        QCOMPARE(finished[0][0].toLongLong(), id);
        QVERIFY2(finished[0][1].toBool(), qPrintable(finished[0][2].toString()));
        QVERIFY2(finished[0][2].toString().contains(QStringLiteral("strikes checked against the plan")),
                 qPrintable(finished[0][2].toString()));
        QCOMPARE(job(id).state, spool::JobState::completed);
        auto* table = panel.findChild<QTableWidget*>(QStringLiteral("jobQueue"));
        QCOMPARE(table->rowCount(), 1);
        QCOMPARE(table->item(0, 0)->text(), QString::number(id));
        QCOMPARE(qobject_cast<QProgressBar*>(table->cellWidget(0, 4))->value(), 100);
        QVERIFY(panel.log_text().contains(QStringLiteral("completed: all")));
    }

    // The State column must not read "done: all 1453 strikes check…". Every
    // cell but the stretched title is as wide as its text.
    void the_job_queue_shows_each_state_whole() {
        const auto file = (dir_.path() + QStringLiteral("/whole.txt")).toStdString();
        std::ofstream(file) << "A job that stops with a long reason.\n";
        QCOMPARE(test::run({kCli, "queue", "printer", "add", "far", "--device", "pty:/dev/pts/424244", "--db", db_}).first, 0);
        QCOMPARE(test::run({kCli, "emboss", "--queue", file, "--printer", "far", "--title", "whole", "--db", db_}).first, 0);
        PrinterPanel panel;
        panel.resize(900, 600);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QSignalSpy finished(&panel, &PrinterPanel::job_finished);
        {
            auto s = spool::Spool::open(db_, {.create = false});
            QVERIFY(s.has_value());
            QVERIFY(s->set_state(panel.jobs().front().id, spool::JobState::failed,
                                 link::explain_faults(encode::fault::hammer), "failed", "hammer fault")
                        .has_value());
        }
        QVERIFY(finished.wait(10000));
        QTest::qWait(50);  // the view lays out its new texts
        auto* table = panel.findChild<QTableWidget*>(QStringLiteral("jobQueue"));
        const QAbstractItemView* view = table;  // QTableView hides sizeHintForColumn
        QCOMPARE(table->rowCount(), 1);
        QVERIFY2(table->item(0, 3)->text().contains(QStringLiteral("hammer")), qPrintable(table->item(0, 3)->text()));
        for (int col = 0; col < table->columnCount(); ++col) {
            if (col == 1 || !table->item(0, col)) continue;  // the title stretches; the progress is a bar
            QVERIFY2(view->sizeHintForColumn(col) <= table->columnWidth(col),
                     qPrintable(QStringLiteral("column %1 \"%2\" needs %3 px, has %4")
                                    .arg(col)
                                    .arg(table->item(0, col)->text())
                                    .arg(view->sizeHintForColumn(col))
                                    .arg(table->columnWidth(col))));
        }
    }

    // A job that stops is announced once (were the fault label and the
    // message each to announce it, Orca would say it twice).
    void a_stopped_job_is_announced_once() {
        const auto file = (dir_.path() + QStringLiteral("/stop.txt")).toStdString();
        std::ofstream(file) << "A job that stops.\n";
        QCOMPARE(test::run({kCli, "queue", "printer", "add", "far", "--device", "pty:/dev/pts/424243", "--db", db_}).first, 0);
        QCOMPARE(test::run({kCli, "emboss", "--queue", file, "--printer", "far", "--title", "stops", "--db", db_}).first, 0);
        PrinterPanel panel;
        QSignalSpy messages(&panel, &PrinterPanel::message);
        QSignalSpy finished(&panel, &PrinterPanel::job_finished);
        {
            auto s = spool::Spool::open(db_, {.create = false});
            QVERIFY(s.has_value());
            const auto id = panel.jobs().front().id;
            QVERIFY(s->set_state(id, spool::JobState::failed, "hammer fault", "failed", "hammer fault").has_value());
        }
        QVERIFY(finished.wait(10000));
        QTest::qWait(500);  // any second announcement would follow at once
        int stopped = 0;
        for (const auto& m : messages)
            if (m[0].toString().contains(QStringLiteral("stops stopped"))) ++stopped;
        QCOMPARE(stopped, 1);
        QVERIFY(panel.fault_text().contains(QStringLiteral("hammer fault")));
    }

    void queue_list_and_the_panel_show_the_same_jobs() {
        // Two jobs from the CLI on a printer nobody serves, one from the panel.
        const auto file = (dir_.path() + QStringLiteral("/cli.txt")).toStdString();
        std::ofstream(file) << "Queued from the command line.\n";
        QCOMPARE(test::run({kCli, "queue", "printer", "add", "lab", "--device", "pty:/dev/pts/424242", "--db", db_}).first, 0);
        for (const char* title : {"first from cli", "second from cli"})
            QCOMPARE(test::run({kCli, "emboss", "--queue", file, "--printer", "lab", "--title", title, "--db", db_}).first, 0);
        PrinterPanel panel;
        QCOMPARE(panel.jobs().size(), std::size_t{2});  // jobs there before the window opened
        panel.select_device(kFastSim);
        QSignalSpy finished(&panel, &PrinterPanel::job_finished);
        const auto id = panel.submit(QStringLiteral("from the app"), book(5), profile::default_profile());
        QVERIFY(finished.wait(120000));
        // The CLI cancels one of its jobs; the panel sees it without being told.
        QCOMPARE(test::run({kCli, "queue", "cancel", "2", "--db", db_}).first, 0);
        QVERIFY(wait_until([&] {
            const auto& jobs = panel.jobs();
            return std::any_of(jobs.begin(), jobs.end(),
                               [](const auto& j) { return j.id == 2 && j.state == spool::JobState::cancelled; });
        }, 10000));
        // `queue list --all`: ID STATE PRI PRINTER SHEETS USER TITLE.
        const auto [code, listed] = test::run({kCli, "queue", "list", "--all", "--db", db_});
        QCOMPARE(code, 0);
        std::set<std::string> cli_rows, panel_rows;
        std::istringstream lines(listed);
        std::string line;
        std::getline(lines, line);  // header
        const std::regex row(R"(^(\d+)\s+(\w+)\s+-?\d+\s+(\S+)\s+\S+\s+\S*\s+(.*?)\s*$)");
        while (std::getline(lines, line)) {
            std::smatch m;
            if (std::regex_search(line, m, row)) cli_rows.insert(m[1].str() + "|" + m[2].str() + "|" + m[3].str());
        }
        auto* table = panel.findChild<QTableWidget*>(QStringLiteral("jobQueue"));
        for (int r = 0; r < table->rowCount(); ++r) {
            const auto& j = panel.jobs()[static_cast<std::size_t>(r)];
            QCOMPARE(table->item(r, 0)->text(), QString::number(j.id));
            QCOMPARE(table->item(r, 2)->text(), QString::fromStdString(j.printer));
            panel_rows.insert(std::to_string(j.id) + "|" + spool::to_string(j.state) + "|" + j.printer);
        }
        QCOMPARE(panel_rows.size(), std::size_t{3});
        QVERIFY2(cli_rows == panel_rows, qPrintable(QString::fromStdString(listed)));
        QVERIFY(panel_rows.count(std::to_string(id) + "|completed|sim"));
        QVERIFY(panel_rows.count("1|queued|lab"));
        QVERIFY(panel_rows.count("2|cancelled|lab"));
    }

    void pause_resume_cancel_and_resume_from_page_act_on_the_spool() {
        PrinterPanel panel;
        panel.select_device(kFastSim);
        QSignalSpy finished(&panel, &PrinterPanel::job_finished);
        const auto pages = book(400);
        QVERIFY(pages.sheet_count() >= 10);
        const auto id = panel.submit(QStringLiteral("long"), pages, profile::default_profile());
        QVERIFY(wait_until([&] { return job(id).state == spool::JobState::running; }));
        panel.select_job(id);
        panel.pause_job();
        QVERIFY2(wait_until([&] { return job(id).state == spool::JobState::paused && job(id).control == spool::Control::none; }),
                 history(id).c_str());
        QVERIFY(panel.embossing().has_value());  // held on the machine, paused
        // Paused means paused: no pass is executed while it lasts.
        const auto passes = [&] {
            auto s = spool::Spool::open(db_, {.create = false});
            const auto progress = *s->progress(id);
            std::size_t n = 0;
            for (const auto& p : progress) n += p.passes_done;
            return n;
        };
        const auto at_pause = passes();
        QTest::qWait(1500);
        QCOMPARE(passes(), at_pause);
        QCOMPARE(job(id).state, spool::JobState::paused);
        panel.resume_job();
        QVERIFY(wait_until([&] { return job(id).state == spool::JobState::running; }));
        panel.cancel_job();
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished[0][1].toBool(), false);
        QVERIFY2(finished[0][2].toString().contains(QStringLiteral("long cancelled")), qPrintable(finished[0][2].toString()));
        QCOMPARE(job(id).state, spool::JobState::cancelled);
        // Page 5 is the front of sheet 3: the same job runs again from there.
        panel.select_job(id);
        panel.resume_from_page(5);
        QVERIFY(finished.wait(240000));
        QVERIFY2(finished[1][1].toBool(), qPrintable(finished[1][2].toString()));
        QVERIFY2(finished[1][2].toString().contains(QStringLiteral("of sheets 3 to")), qPrintable(finished[1][2].toString()));
        QCOMPARE(job(id).state, spool::JobState::completed);
        QVERIFY2(history(id).find("starting at sheet 3 as the operator chose") != std::string::npos, history(id).c_str());
        // A page the job does not have is refused with the reason.
        QSignalSpy messages(&panel, &PrinterPanel::message);
        panel.select_job(id);
        panel.resume_from_page(100000);
        QVERIFY(!messages.isEmpty());
        QVERIFY(messages.last()[0].toString().contains(QStringLiteral("is not in the job")));
    }

    void any_device_string_can_be_typed_and_a_bad_one_is_refused_with_the_reason() {
        PrinterPanel panel;
        panel.select_device(QStringLiteral("pty:/dev/pts/424242?baud=57600"));
        QCOMPARE(panel.selected_device(), QStringLiteral("pty:/dev/pts/424242?baud=57600"));
        QSignalSpy messages(&panel, &PrinterPanel::message);
        panel.select_device(QStringLiteral("serial:/dev/ttyUSB0?baud=fast"));
        QCOMPARE(panel.submit(QStringLiteral("x"), book(1), profile::default_profile()), spool::JobId{0});
        QVERIFY2(panel.fault_text().contains(QStringLiteral("is not a device Tactus can open")), qPrintable(panel.fault_text()));
        QVERIFY2(panel.fault_text().contains(QStringLiteral("baud")), qPrintable(panel.fault_text()));
        QVERIFY(!messages.isEmpty());
        panel.select_device(QStringLiteral("telnet:printer"));
        QVERIFY(!panel.connect_device(panel.selected_device(), profile::default_profile()));
        QVERIFY(panel.fault_text().contains(QStringLiteral("telnet:printer")));
        QVERIFY(!std::filesystem::exists(db_));  // nothing was set up for a bad string
        // A well-formed device that is not there: Connect says so...
        panel.select_device(QStringLiteral("pty:/dev/pts/424242?baud=57600"));
        QVERIFY(!panel.connect_device(panel.selected_device(), profile::default_profile()));
        QVERIFY2(panel.fault_text().contains(QStringLiteral("Cannot connect to pty:/dev/pts/424242")), qPrintable(panel.fault_text()));
        // ...and a job for it is queued and waits, as for a busy embosser.
        const auto id = panel.submit(QStringLiteral("waits"), book(1), profile::default_profile());
        QVERIFY(id > 0);
        QCOMPARE(job(id).printer, std::string("pts-424242"));
        // Waiting for a printer that is not there is not a failed try (no retry is counted).
        QVERIFY2(wait_until([&] { return history(id).find("waiting for printer") != std::string::npos; }, 60000),
                 history(id).c_str());
        QCOMPARE(job(id).state, spool::JobState::queued);
        panel.disconnect_device();
        QCOMPARE(job(id).state, spool::JobState::queued);
    }

    void a_printer_another_runner_holds_is_only_watched() {
        // A live process holds the printer (as `tactus-cli serve` would).
        test::Process holder({"sleep", "60"});
        {
            auto s = spool::Spool::open(db_);
            QVERIFY(s);
            auto p = s->add_printer("sim", "sim", profile::to_json(profile::default_profile()).dump());
            QVERIFY(p);
            char host[256] = {};
            gethostname(host, sizeof host - 1);
            QVERIFY(s->claim_printer(p->id, std::string(host) + ":" + std::to_string(holder.pid())));
        }
        PrinterPanel panel;
        const auto id = panel.submit(QStringLiteral("watched"), book(1), profile::default_profile());
        QVERIFY(id > 0);
        QVERIFY(panel.connected());
        QVERIFY(!panel.runs_printer());
        QVERIFY2(panel.status_text().contains(QStringLiteral("run by ")), qPrintable(panel.status_text()));
        QTest::qWait(500);
        QCOMPARE(job(id).state, spool::JobState::queued);  // this window did not run it
        holder.signal(SIGKILL);
        holder.wait();
    }

    void faults_injected_into_the_simulator_are_ridden_through() {
        PrinterPanel panel;
        panel.select_device(kFastSim);
        QSignalSpy finished(&panel, &PrinterPanel::job_finished);
        QSignalSpy messages(&panel, &PrinterPanel::message);
        const auto id = panel.submit(QStringLiteral("faults"), book(400), profile::default_profile());
        QVERIFY(wait_until([&] { return job(id).state == spool::JobState::running; }));
        auto* box = panel.findChild<QWidget*>(QStringLiteral("simulatorFaults"));
        QVERIFY(box->isEnabled());
        // Each fault through its button, each seen in the spool's history before the next.
        const auto press = [&](const char* name) { panel.findChild<QPushButton*>(QString::fromLatin1(name))->click(); };
        press("injectPaperOut");
        QVERIFY2(wait_until([&] { return history(id).find("paper out") != std::string::npos; }), history(id).c_str());
        // The user hears it, once, and hears the job go on (a fault the runner
        // rides through in a blink must still be said).
        const auto said = [&](const QString& what) {
            int n = 0;
            for (const auto& m : messages)
                if (m[0].toString().contains(what, Qt::CaseInsensitive)) ++n;
            return n;
        };
        QVERIFY(wait_until([&] { return said(QStringLiteral("running again")) > 0; }));
        QCOMPARE(said(QStringLiteral("paper out")), 1);
        QCOMPARE(said(QStringLiteral("running again")), 1);
        press("injectReset");
        QVERIFY2(wait_until([&] { return history(id).find("controller restarted") != std::string::npos; }), history(id).c_str());
        press("injectPulledCable");
        // The link reconnects, or the runner waits for the printer to come back.
        QVERIFY2(wait_until([&] {
                     const auto h = history(id);
                     return h.find("reconnect") != std::string::npos || h.find("waiting for printer") != std::string::npos;
                 }),
                 history(id).c_str());
        press("injectNoise");
        QVERIFY(finished.wait(240000));
        QVERIFY2(finished[0][1].toBool(), qPrintable(finished[0][2].toString() + QString::fromStdString(history(id))));
        QVERIFY2(finished[0][2].toString().contains(QStringLiteral("strikes checked against the plan")),
                 qPrintable(finished[0][2].toString()));
    }
    // Unpaced, the app's simulator runs about 100 times faster than the
    // plan, so Pause is barely reachable. By default a job takes at least
    // the plan's own time (a lower bound the pacing guarantees, not a timing);
    // `sim?speed=max`, chosen in the panel, lets the simulated clock run ahead
    // of the wall clock.
    void the_simulator_takes_the_plans_own_time_unless_told_to_go_faster() {
        const auto pages = book(1);
        QCOMPARE(pages.sheet_count(), std::size_t{1});
        const auto plan = spool::plan_copies(pages, profile::default_profile(), 1);
        QVERIFY(plan);
        QVERIFY(plan->duration_s > 1);
        using Clock = std::chrono::steady_clock;
        const auto seconds = [](Clock::duration d) { return std::chrono::duration<double>(d).count(); };

        PrinterPanel panel;
        QCOMPARE(panel.selected_device(), QStringLiteral("sim"));
        QSignalSpy finished(&panel, &PrinterPanel::job_finished);
        auto start = Clock::now();
        const double sim_start = panel.simulator().now();
        QVERIFY(panel.submit(QStringLiteral("real"), pages, profile::default_profile()) > 0);
        QVERIFY(finished.wait(static_cast<int>(plan->duration_s * 1000) * 20 + 60000));
        const double wall = seconds(Clock::now() - start), simulated = panel.simulator().now() - sim_start;
        QVERIFY2(finished[0][1].toBool(), qPrintable(finished[0][2].toString()));
        QVERIFY2(finished[0][2].toString().contains(QStringLiteral("strikes checked against the plan")),
                 qPrintable(finished[0][2].toString()));
        QVERIFY2(simulated >= plan->duration_s, qPrintable(QStringLiteral("simulated %1 s, plan %2 s").arg(simulated).arg(plan->duration_s)));
        QVERIFY2(wall >= plan->duration_s, qPrintable(QStringLiteral("took %1 s, the plan %2 s").arg(wall).arg(plan->duration_s)));

        // The speed choice writes the device string's option (and follows one typed in).
        auto* speed = panel.findChild<QComboBox*>(QStringLiteral("simulatorSpeed"));
        QVERIFY(speed && speed->isEnabled());
        QVERIFY(!speed->accessibleName().isEmpty());
        QCOMPARE(speed->currentData().toString(), QString());
        const auto choose = [&](const char* value) {
            const int i = speed->findData(QString::fromLatin1(value));
            QVERIFY(i >= 0);
            speed->setCurrentIndex(i);
            Q_EMIT speed->activated(i);  // as the user's choice does
        };
        choose("10");
        QCOMPARE(panel.selected_device(), QStringLiteral("sim?speed=10"));
        panel.select_device(QStringLiteral("sim?noise=0&speed=3"));
        QCOMPARE(speed->currentData().toString(), QStringLiteral("3"));
        QVERIFY(speed->currentText().contains(QStringLiteral("3")));
        choose("");
        QCOMPARE(panel.selected_device(), QStringLiteral("sim?noise=0"));
        choose("max");
        QCOMPARE(panel.selected_device(), QStringLiteral("sim?noise=0&speed=max"));

        start = Clock::now();
        const double sim_again = panel.simulator().now();
        QVERIFY(panel.submit(QStringLiteral("fast"), pages, profile::default_profile()) > 0);
        QVERIFY(finished.wait(120000));
        const double wall_fast = seconds(Clock::now() - start), simulated_fast = panel.simulator().now() - sim_again;
        QVERIFY2(finished[1][1].toBool(), qPrintable(finished[1][2].toString()));
        QVERIFY2(simulated_fast >= plan->duration_s, qPrintable(QString::number(simulated_fast)));
        // At full speed the simulated machine runs ahead of the wall clock,
        // which the plan's own speed never lets it do.
        QVERIFY2(simulated_fast > wall_fast,
                 qPrintable(QStringLiteral("%1 simulated s in %2 s").arg(simulated_fast).arg(wall_fast)));
    }
};

QTEST_MAIN(PrinterPanelTest)
#include "printer_panel_test.moc"
