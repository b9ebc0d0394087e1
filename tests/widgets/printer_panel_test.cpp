// SPDX-License-Identifier: GPL-3.0-or-later
// The printer panel over core's link to the built-in simulator: a job runs and
// every strike the simulated controller makes is checked against the plan; an
// embosser that disappears mid-job stops that job with a plain message and
// leaves the queue alone; resume from a page, cancel.
#include <QProgressBar>
#include <QTableWidget>
#include <QtTest>

#include "embosser.hpp"
#include "gui_test_support.hpp"
#include "live_layout.hpp"
#include "printer_panel.hpp"

using namespace tactus;
using namespace tactus::gui;

namespace {

layout::PagedDocument book(int paragraphs) {
    auto l = LiveLayout::create("en-ueb-g2.ctb", {});
    l->reset(test::synthetic_book(paragraphs));
    return l->paged();
}

}  // namespace

class PrinterPanelTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void simulator_is_always_listed_first() {
        const auto devices = list_devices();
        QVERIFY(!devices.empty());
        QCOMPARE(devices.front().device, std::string("sim"));
        PrinterPanel panel;
        QCOMPARE(panel.selected_device(), QStringLiteral("sim"));
    }

    void faults_in_plain_words() {
        QVERIFY(QString::fromStdString(explain_faults(encode::fault::paper_out)).contains(QStringLiteral("put paper")));
        QVERIFY(QString::fromStdString(explain_faults(encode::fault::hammer)).contains(QStringLiteral("hammer")));
        QVERIFY(explain_faults(0).empty());
    }

    void embosses_and_checks_every_strike() {
        PrinterPanel panel;
        QVERIFY(panel.connect_device(QStringLiteral("sim"), profile::default_profile()));
        QSignalSpy finished(&panel, &PrinterPanel::job_finished);
        const auto pages = book(40);
        panel.enqueue(QStringLiteral("book"), pages, profile::default_profile());
        QVERIFY(finished.wait(120000));
        QVERIFY2(finished[0][1].toBool(), qPrintable(finished[0][2].toString()));
        QVERIFY2(finished[0][2].toString().contains(QStringLiteral("strikes checked against the plan")),
                 qPrintable(finished[0][2].toString()));
        const auto& job = panel.jobs().front();
        QCOMPARE(job.state, QueuedJob::State::done);
        QVERIFY(job.passes_total > 0);
        auto* bar = qobject_cast<QProgressBar*>(panel.findChild<QTableWidget*>(QStringLiteral("jobQueue"))->cellWidget(0, 2));
        QCOMPARE(bar->value(), 100);
        QVERIFY(panel.log_text().contains(QStringLiteral("frames sent")));
    }

    void embosser_disappearing_mid_job_leaves_the_queue() {
        PrinterPanel panel;
        QVERIFY(panel.connect_device(QStringLiteral("sim"), profile::default_profile()));
        // The cable is pulled 2 s (simulated) into the job, for longer than the link waits.
        panel.embosser()->simulate_unplug_after(2.0, 3600);
        QSignalSpy finished(&panel, &PrinterPanel::job_finished);
        const auto pages = book(40);
        panel.enqueue(QStringLiteral("first"), pages, profile::default_profile());
        panel.enqueue(QStringLiteral("second"), pages, profile::default_profile());
        QVERIFY(finished.wait(180000));
        QCOMPARE(finished[0][1].toBool(), false);
        QCOMPARE(panel.jobs()[0].state, QueuedJob::State::failed);
        QCOMPARE(panel.jobs()[1].state, QueuedJob::State::queued);  // untouched, not failed with it
        QVERIFY(panel.fault_text().contains(QStringLiteral("stopped at sheet")));
        QVERIFY(panel.fault_text().contains(QStringLiteral("resume from sheet")));
        // A new connection: the second job runs; the first can resume from its sheet.
        QVERIFY(panel.connect_device(QStringLiteral("sim"), profile::default_profile()));
        QVERIFY(finished.wait(120000));
        QCOMPARE(panel.jobs()[1].state, QueuedJob::State::done);
    }

    void resume_from_a_page_embosses_only_the_rest() {
        PrinterPanel panel;
        QVERIFY(panel.connect_device(QStringLiteral("sim"), profile::default_profile()));
        QSignalSpy finished(&panel, &PrinterPanel::job_finished);
        const auto pages = book(40);
        QVERIFY(pages.sheet_count() >= 3);
        panel.enqueue(QStringLiteral("book"), pages, profile::default_profile());
        panel.cancel_job();
        QVERIFY(finished.wait(60000));
        QCOMPARE(panel.jobs()[0].state, QueuedJob::State::cancelled);
        panel.findChild<QTableWidget*>(QStringLiteral("jobQueue"))->selectRow(0);
        panel.resume_from_page(5);  // page 5 is the front of sheet 3
        QCOMPARE(panel.jobs().size(), std::size_t{2});
        QCOMPARE(panel.jobs()[1].start_sheet, std::size_t{3});
        QVERIFY(finished.wait(120000));
        QVERIFY2(finished[1][1].toBool(), qPrintable(finished[1][2].toString()));
        QVERIFY(finished[1][2].toString().contains(QStringLiteral("checked against the plan")));
    }

    void unknown_device_is_a_clear_error() {
        PrinterPanel panel;
        QSignalSpy messages(&panel, &PrinterPanel::message);
        QVERIFY(!panel.connect_device(QStringLiteral("serial:/dev/does-not-exist"), profile::default_profile()));
        QVERIFY(!panel.connected());
        QVERIFY(panel.fault_text().contains(QStringLiteral("Cannot connect to serial:/dev/does-not-exist")));
        QVERIFY(!messages.isEmpty());
    }
};

QTEST_MAIN(PrinterPanelTest)
#include "printer_panel_test.moc"
