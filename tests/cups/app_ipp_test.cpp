// SPDX-License-Identifier: GPL-3.0-or-later
// The desktop app prints to a Tactus CUPS queue, against a
// real private cupsd on loopback (cups_rig.hpp): the printer picker lists the
// server's Tactus queues as network queues, beside the cables, and no other
// queue; Ctrl+P to one sends the document over IPP, the server embosses it
// exactly as planned, and the job view follows the job there to its end,
// announced once; a job cancelled from the app, or on the server, shows as
// cancelled. The widgets run offscreen, as in tests/widgets.
//
// The tests use the widgets as a user does (the picker's items, the job
// view's cells, the Cancel button, the panel's messages), so they build
// against an app that cannot print to CUPS, and fail there.
#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <regex>

#include "cups_rig.hpp"
#include "import/import.hpp"
#include "ipp/remote_queues.hpp"
#include "pipeline/pipeline.hpp"
#include "profile/page_geometry.hpp"
#include "profile/profile_json.hpp"
#include "spool/snapshot.hpp"
#include "main_window.hpp"
#include "printer_panel.hpp"

namespace tactus::cups {
namespace {

using namespace std::chrono_literals;
using spool::JobState;
using test::CupsRig;
using test::PtySim;

QString qs(const std::string& s) { return QString::fromStdString(s); }

// Runs the app's event loop until `pred` holds; false after `timeout` (a
// bound, not a timing assertion).
template <typename Pred>
bool pump_until(Pred pred, std::chrono::seconds timeout = 180s) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (!pred()) {
        if (std::chrono::steady_clock::now() > end) return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        std::this_thread::sleep_for(20ms);
    }
    return true;
}

std::string items_of(const QComboBox* box) {
    std::string out;
    for (int i = 0; i < box->count(); ++i) out += box->itemText(i).toStdString() + "\n";
    return out;
}

// The job view's row for document `title` (-1: none), and a cell of it.
int row_of(const QTableWidget* view, const QString& title) {
    for (int r = 0; r < view->rowCount(); ++r)
        if (const auto* item = view->item(r, 1); item && item->text() == title) return r;
    return -1;
}
QString cell(const QTableWidget* view, int row, int column) {
    const auto* item = view->item(row, column);
    return item ? item->text() : QString();
}
constexpr int kJobColumn = 0, kPrinterColumn = 2, kStateColumn = 3;

// What the panel said (its messages go to the screen reader) and how its jobs ended.
struct Heard {
    QObject context;  // the connections end with this
    QStringList said;
    std::vector<std::pair<bool, QString>> finished;
    explicit Heard(gui::PrinterPanel* panel) {
        QObject::connect(panel, &gui::PrinterPanel::message, &context,
                         [this](const QString& text, bool) { said << text; });
        QObject::connect(panel, &gui::PrinterPanel::job_finished, &context,
                         [this](qint64, bool completed, const QString& text) { finished.emplace_back(completed, text); });
    }
    [[nodiscard]] long count(const QString& part) const {
        return std::count_if(said.begin(), said.end(), [&](const QString& s) { return s.contains(part); });
    }
};

class CupsAppE2E : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        if (!test::have_cupsd()) return;
        rig_ = std::make_unique<CupsRig>();
        rig_->use_in_this_process();
    }
    static void TearDownTestSuite() { rig_.reset(); }
    void SetUp() override {
        if (!test::have_cupsd()) GTEST_SKIP() << "cupsd, lpadmin, lp, lpstat not installed";
        ASSERT_TRUE(rig_->started()) << rig_->error_log();
        before_ = rig_->last_spool_job();
        // The app's own spool, apart from the server's; no remembered embosser.
        static int n = 0;
        ::setenv("TACTUS_SPOOL_DB", (rig_->e.dir / ("app-spool-" + std::to_string(++n) + ".db")).c_str(), 1);
        QSettings().clear();
    }
    static CupsRig& rig() { return *rig_; }

    // The queue `name` on `sim`, the app with a lesson of `paragraphs`
    // paragraphs open as `file`, the queue chosen in the picker and Ctrl+P
    // pressed; what its printer panel says is heard from before.
    struct App {
        std::unique_ptr<gui::MainWindow> window = std::make_unique<gui::MainWindow>();
        gui::PrinterPanel* panel = window->printer_panel();
        QTableWidget* view = panel->findChild<QTableWidget*>(QStringLiteral("jobQueue"));
        Heard heard{panel};
        bool sent = false;
    };
    std::unique_ptr<App> emboss_on(const PtySim& sim, const std::string& name, const std::string& file,
                                   int paragraphs) {
        EXPECT_TRUE(rig().add_queue(sim, name)) << rig().error_log();
        const auto doc = rig().lesson_file(file, paragraphs);
        auto app = std::make_unique<App>();
        app->window->set_interactive(false);
        EXPECT_TRUE(app->window->open_file_now(qs(doc.string())));
        EXPECT_NE(app->view, nullptr);
        app->panel->select_device(qs(rig().queue_uri(name)));
        app->sent = app->window->emboss();
        return app;
    }

    spool::JobId before_ = 0;
    static inline std::unique_ptr<CupsRig> rig_;
};

// First in the suite (and alone under ctest): the private server has no queue yet.
TEST_F(CupsAppE2E, AServerWithoutQueuesListsNoneAndIsNoError) {
    Result<std::vector<ipp::RemoteQueue>> q = std::vector<ipp::RemoteQueue>{};
    std::thread([&] { q = ipp::visible_tactus_queues(std::chrono::milliseconds(0)); }).join();
    ASSERT_TRUE(q) << q.error().to_string();
    EXPECT_TRUE(q->empty());
}

TEST_F(CupsAppE2E, ThePickerListsTheServersTactusQueueAsANetworkQueueAndNoOtherQueue) {
    PtySim sim(rig().e.dir.path(), "sim-picker");
    ASSERT_TRUE(rig().add_queue(sim, "EmbosserPick")) << rig().error_log();
    // A queue that is not a Tactus one (CUPS's ipp backend to a printer nobody answers).
    std::error_code ec;
    std::filesystem::create_symlink("/usr/lib/cups/backend/ipp", rig().cups_dir / "bin/backend/ipp", ec);
    const auto [code, msg] =
        rig().client({"lpadmin", "-p", "Laser", "-E", "-v", "ipp://127.0.0.1:9/ipp/print", "-m", "raw"});
    ASSERT_EQ(code, 0) << msg;

    gui::PrinterPanel panel;
    auto* picker = panel.findChild<QComboBox*>(QStringLiteral("devicePicker"));
    ASSERT_NE(picker, nullptr);
    const auto uri = qs(rig().queue_uri("EmbosserPick"));
    ASSERT_TRUE(pump_until([&] { return picker->findData(uri) >= 0; }, 60s)) << items_of(picker);
    const int i = picker->findData(uri);
    // Seen and heard as a network queue, not a cable.
    EXPECT_TRUE(picker->itemText(i).contains(QStringLiteral("Network queue EmbosserPick on ") + qs(rig().server())))
        << picker->itemText(i).toStdString();
    EXPECT_EQ(picker->itemData(i, Qt::AccessibleTextRole).toString(),
              QStringLiteral("Network queue EmbosserPick on the CUPS server ") + qs(rig().server()));
    EXPECT_TRUE(picker->itemData(i, Qt::AccessibleDescriptionRole).toString().contains(QStringLiteral("another computer")));
    const int sim_item = picker->findData(QStringLiteral("sim"));
    ASSERT_GE(sim_item, 0);
    EXPECT_TRUE(picker->itemData(sim_item, Qt::AccessibleDescriptionRole).toString().contains(QStringLiteral("this computer")));
    // The plain printer is on the server, and not in the picker.
    EXPECT_EQ(rig().client({"lpstat", "-p", "Laser"}).first, 0);
    for (int k = 0; k < picker->count(); ++k) EXPECT_FALSE(picker->itemText(k).contains(QStringLiteral("Laser"))) << items_of(picker);
    // Choosing it chooses its address.
    picker->setCurrentIndex(i);
    EXPECT_EQ(panel.selected_device(), uri);
}

TEST_F(CupsAppE2E, CtrlPToANetworkQueueEmbossesOnTheServerAsPlannedAndTheJobViewFollowsIt) {
    PtySim sim(rig().e.dir.path(), "sim-app");
    const auto app = emboss_on(sim, "EmbosserApp", "app-lesson.md", 3);
    const auto* panel = app->panel;
    const auto* view = app->view;
    const auto& heard = app->heard;
    ASSERT_TRUE(app->sent) << panel->fault_text().toStdString();
    ASSERT_TRUE(pump_until([&] { return !heard.finished.empty(); })) << panel->log_text().toStdString() << rig().error_log();
    EXPECT_TRUE(heard.finished.front().first) << heard.finished.front().second.toStdString();

    // The server laid the document out and embossed it through its spool: the
    // strike log equals the plan, every sheet once.
    const auto id = rig().newest_spool_job(before_);
    ASSERT_NE(id, 0) << rig().error_log();
    ASSERT_TRUE(rig().e.wait_state(id, JobState::completed)) << rig().e.history(id);
    const auto job = *rig().e.spool().job(id);
    EXPECT_EQ(job.title, "app-lesson.md");
    const auto audit = rig().e.audit(id, sim);
    EXPECT_EQ(audit.problems, "");
    EXPECT_EQ(audit.sheets_checked, job.total_sheets());
    EXPECT_GT(job.total_sheets(), 0u);

    // The job view shows the server's job, by its CUPS name, as done.
    const int row = row_of(view, QStringLiteral("app-lesson.md"));
    ASSERT_GE(row, 0);
    EXPECT_TRUE(std::regex_match(cell(view, row, kJobColumn).toStdString(), std::regex("EmbosserApp-[0-9]+")))
        << cell(view, row, kJobColumn).toStdString();
    EXPECT_EQ(cell(view, row, kPrinterColumn), QStringLiteral("EmbosserApp at 127.0.0.1"));
    EXPECT_TRUE(cell(view, row, kStateColumn).startsWith(QStringLiteral("done"))) << cell(view, row, kStateColumn).toStdString();
    // Its start and its end are each said once; it is not a local job.
    EXPECT_EQ(heard.count(QStringLiteral("Embossing app-lesson.md on EmbosserApp")), 1) << heard.said.join('\n').toStdString();
    EXPECT_EQ(heard.count(QStringLiteral("Embossed app-lesson.md on EmbosserApp")), 1) << heard.said.join('\n').toStdString();
    EXPECT_EQ(heard.finished.size(), 1u);
    EXPECT_TRUE(panel->jobs().empty());
}

// A PEF of volumes with their own page sizes and
// single-sided sections (volume_grids.pef) sent from the app to a Tactus
// queue is embossed on the server as the file's own pages: the server's job
// has exactly the pages tactus-cli lays the file out on for the server's
// profile (its rows on its pages, each section on a new sheet, a blank back
// for each page of a single-sided section), and the strikes are that plan.
// Before, the app sent the editor's Markdown, which has the rows and pages
// but no sections: the server laid the file's 8 pages out as one stream, 4
// sheets where the file asks for 7.
TEST_F(CupsAppE2E, APefSentToANetworkQueueIsEmbossedAsTheFilesOwnPages) {
    PtySim sim(rig().e.dir.path(), "sim-app-pef");
    ASSERT_TRUE(rig().add_queue(sim, "EmbosserPef")) << rig().error_log();
    const std::string file = TACTUS_TEST_DATA "/pef/volume_grids.pef";
    App app;
    app.window->set_interactive(false);
    ASSERT_TRUE(app.window->open_file_now(qs(file)));
    app.panel->select_device(qs(rig().queue_uri("EmbosserPef")));
    ASSERT_TRUE(app.window->emboss()) << app.panel->fault_text().toStdString();
    ASSERT_TRUE(pump_until([&] { return !app.heard.finished.empty(); }))
        << app.panel->log_text().toStdString() << rig().error_log();
    EXPECT_TRUE(app.heard.finished.front().first) << app.heard.finished.front().second.toStdString();

    const auto id = rig().newest_spool_job(before_);
    ASSERT_NE(id, 0) << rig().error_log();
    ASSERT_TRUE(rig().e.wait_state(id, JobState::completed)) << rig().e.history(id);
    auto s = rig().e.spool();
    const auto embossed = spool::from_snapshot(*s.document_snapshot(id));
    ASSERT_TRUE(embossed) << embossed.error().to_string();
    const auto profile = profile::parse_profile(*s.profile_snapshot(id));
    ASSERT_TRUE(profile) << profile.error().to_string();
    pipeline::PipelineOptions options;
    options.layout.geometry = profile::page_geometry(*profile);
    const auto source = import::import_file(file);
    ASSERT_TRUE(source) << source.error().to_string();
    const auto expected = pipeline::lay_out(*source, options);
    ASSERT_TRUE(expected) << expected.error().to_string();
    ASSERT_TRUE(expected->geometry.interpoint);
    EXPECT_EQ(embossed->pages.size(), expected->pages.size());
    EXPECT_EQ(embossed->sheet_count(), expected->sheet_count());
    EXPECT_EQ(embossed->sheet_count(), 7u);  // 14 pages on interpoint paper, 4 of them blank backs
    for (std::size_t p = 0; p < std::min(embossed->pages.size(), expected->pages.size()); ++p)
        EXPECT_EQ(embossed->pages[p].lines, expected->pages[p].lines) << "page " << p + 1;
    const auto audit = rig().e.audit(id, sim);
    EXPECT_EQ(audit.problems, "");
    EXPECT_EQ(audit.sheets_checked, s.job(id)->total_sheets());
}

TEST_F(CupsAppE2E, AJobCancelledInTheAppIsCancelledOnTheServerAndShownCancelled) {
    PtySim sim(rig().e.dir.path(), "sim-app-cancel", {}, 100);  // slow: still embossing when cancelled
    const auto app = emboss_on(sim, "EmbosserAppC", "app-cancel.md", 12);
    const auto* panel = app->panel;
    const auto* view = app->view;
    const auto& heard = app->heard;
    ASSERT_TRUE(app->sent) << panel->fault_text().toStdString();
    ASSERT_TRUE(pump_until([&] { return sim.strikes().size() > 20; })) << panel->log_text().toStdString() << rig().error_log();
    const auto id = rig().newest_spool_job(before_);
    ASSERT_NE(id, 0);

    // The new job is the selected row; Cancel (Alt+N) cancels it on the server.
    auto* cancel = panel->findChild<QPushButton*>(QStringLiteral("cancelJob"));
    ASSERT_NE(cancel, nullptr);
    ASSERT_TRUE(pump_until([&] { return cancel->isEnabled(); }, 30s));
    cancel->click();
    ASSERT_TRUE(pump_until([&] { return !heard.finished.empty(); })) << panel->log_text().toStdString();
    EXPECT_FALSE(heard.finished.front().first);
    EXPECT_EQ(heard.finished.front().second.toStdString(), "app-cancel.md cancelled on EmbosserAppC at 127.0.0.1")
        << panel->log_text().toStdString();
    const int row = row_of(view, QStringLiteral("app-cancel.md"));
    ASSERT_GE(row, 0);
    EXPECT_TRUE(cell(view, row, kStateColumn).startsWith(QStringLiteral("cancelled"))) << cell(view, row, kStateColumn).toStdString();
    EXPECT_EQ(heard.count(QStringLiteral("app-cancel.md cancelled on")), 1) << heard.said.join('\n').toStdString();
    EXPECT_FALSE(cancel->isEnabled());
    // On the server: the spool job is cancelled and the controller stopped short of the plan.
    ASSERT_TRUE(rig().e.wait_state(id, JobState::cancelled)) << rig().e.history(id);
    EXPECT_LT(sim.strikes().size(), rig().e.plan_of(id).strikes);
}

TEST_F(CupsAppE2E, AJobCancelledOnTheServerShowsCancelledInTheApp) {
    PtySim sim(rig().e.dir.path(), "sim-app-server-cancel", {}, 100);
    const auto app = emboss_on(sim, "EmbosserAppS", "server-cancel.md", 12);
    const auto* panel = app->panel;
    const auto* view = app->view;
    const auto& heard = app->heard;
    ASSERT_TRUE(app->sent) << panel->fault_text().toStdString();
    ASSERT_TRUE(pump_until([&] { return sim.strikes().size() > 20; })) << panel->log_text().toStdString();
    int row = -1;
    ASSERT_TRUE(pump_until([&] {
        row = row_of(view, QStringLiteral("server-cancel.md"));
        return row >= 0 && cell(view, row, kStateColumn).startsWith(QStringLiteral("embossing"));
    }));
    const auto cups_job = cell(view, row, kJobColumn).toStdString();  // "EmbosserAppS-N", as lpstat names it
    const auto [code, msg] = rig().client({"cancel", cups_job});
    ASSERT_EQ(code, 0) << cups_job << ": " << msg;
    ASSERT_TRUE(pump_until([&] { return !heard.finished.empty(); })) << panel->log_text().toStdString();
    EXPECT_FALSE(heard.finished.front().first);
    row = row_of(view, QStringLiteral("server-cancel.md"));
    EXPECT_TRUE(cell(view, row, kStateColumn).startsWith(QStringLiteral("cancelled"))) << cell(view, row, kStateColumn).toStdString();
    EXPECT_EQ(heard.count(QStringLiteral("server-cancel.md cancelled on EmbosserAppS")), 1) << heard.said.join('\n').toStdString();
}

}  // namespace
}  // namespace tactus::cups

// Widgets need a QApplication; offscreen unless the caller chose a platform.
int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("tactus-tests"));
    QCoreApplication::setApplicationName(QStringLiteral("cups_app_test"));
    QStandardPaths::setTestModeEnabled(true);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
