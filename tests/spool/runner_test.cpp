// SPDX-License-Identifier: GPL-3.0-or-later
// The runner against the simulated controller (in-process line, virtual time):
// jobs complete with every sheet struck exactly once, faults pause the job with
// their reason and resume from the first unfinished sheet, cables come and go,
// and a document that no longer fits its printer is kept, not lost.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <chrono>
#include <thread>

#include "controller/builtin_sim.hpp"
#include "import/import.hpp"
#include "encode/messages.hpp"
#include "pipeline/pipeline.hpp"
#include "profile/page_geometry.hpp"
#include "transport/device.hpp"
#include "profile/controller_config.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile.hpp"
#include "profile/profile_json.hpp"
#include "spool/print_job.hpp"
#include "spool/printing.hpp"
#include "spool/runner.hpp"
#include "spool/snapshot.hpp"
#include "spool/strike_check.hpp"
#include "sim_rig.hpp"
#include "spool_fixtures.hpp"
#include "strike_audit.hpp"

namespace tactus::spool {
namespace {

using test::SimPrinter;
using test::TempDir;

std::string profile_text(const profile::PrinterProfile& p = profile::default_profile()) {
    return profile::to_json(p).dump();
}

struct Bench {
    TempDir dir;
    std::filesystem::path db = dir / "spool.db";
    Spool spool;
    std::atomic<bool> stop{false};

    Bench() : spool(*Spool::open(db)) {
        EXPECT_TRUE(spool.add_printer("lab", "sim", profile_text()));
    }
    JobId submit(std::size_t pages, std::size_t copies = 1) {
        auto id = spool.submit(test::submission("lab", pages, copies));
        EXPECT_TRUE(id) << id.error().to_string();
        return *id;
    }
    plan::JobPlan plan_of(JobId id) {
        auto doc = from_snapshot(*spool.document_snapshot(id));
        auto plan = plan_copies(*doc, profile::default_profile(), spool.job(id)->copies);
        EXPECT_TRUE(plan) << plan.error().to_string();
        return *plan;
    }
    std::string audit(JobId id, SimPrinter& printer) {
        return test::audit_strikes(plan_of(id), printer.controller->strike_log(), *spool.progress(id)).problems;
    }
    std::vector<std::string> kinds(JobId id) {
        std::vector<std::string> k;
        const auto events = *spool.events(id, 1000);
        for (const auto& e : events) k.push_back(e.kind);
        return k;
    }
};

RunnerOptions fast_options() {
    RunnerOptions o;
    o.retry_backoff = std::chrono::milliseconds(0);
    o.poll = std::chrono::milliseconds(5);
    o.link.fault_wait = std::chrono::milliseconds(2000);  // virtual seconds: instant
    o.link.reconnect_deadline = std::chrono::milliseconds(3000);
    return o;
}

std::optional<RunEnd> run_next(Runner& r, std::atomic<bool>& stop) {
    auto end = r.run_next(stop);
    EXPECT_TRUE(end) << end.error().to_string();
    return end ? *end : std::nullopt;
}

TEST(Runner, EmbossesEveryCopyExactlyOnceAndRecordsEachSheet) {
    Bench b;
    SimPrinter printer;
    const JobId id = b.submit(5, 2);  // 3 sheets x 2 copies
    Runner r(b.db, "lab", printer.connect(), fast_options());
    ASSERT_TRUE(r.start());
    EXPECT_EQ(run_next(r, b.stop), RunEnd::completed);
    const auto job = *b.spool.job(id);
    EXPECT_EQ(job.state, JobState::completed);
    const auto progress = *b.spool.progress(id);
    ASSERT_EQ(progress.size(), 6u);
    for (const auto& p : progress) EXPECT_TRUE(p.done()) << "sheet " << p.sheet;
    EXPECT_EQ(printer.controller->strike_log().size(), b.plan_of(id).strikes);
    EXPECT_EQ(b.audit(id, printer), "");
    EXPECT_EQ(b.kinds(id).back(), "completed");
    EXPECT_FALSE(run_next(r, b.stop));  // nothing left
}

TEST(Runner, PaperOutPausesWithTheReasonAndResumesAtTheFirstUnfinishedSheet) {
    Bench b;
    SimPrinter printer;
    printer.controller->inject_paper_out_at_sheet(2);
    const JobId id = b.submit(6);
    Runner r(b.db, "lab", printer.connect(fast_options().link), fast_options());
    ASSERT_TRUE(r.start());
    EXPECT_EQ(run_next(r, b.stop), RunEnd::paused);
    auto job = *b.spool.job(id);
    EXPECT_EQ(job.state, JobState::paused);
    EXPECT_NE(job.reason.find("paper out"), std::string::npos) << job.reason;
    auto progress = *b.spool.progress(id);
    EXPECT_TRUE(progress[0].done());
    EXPECT_EQ(progress[1].passes_done, 0u);
    // Nothing runs while it waits for the operator.
    EXPECT_FALSE(run_next(r, b.stop));
    printer.controller->load_paper();
    ASSERT_TRUE(b.spool.act(id, Action::resume));
    EXPECT_EQ(run_next(r, b.stop), RunEnd::completed);
    EXPECT_EQ(b.audit(id, printer), "");
}

TEST(Runner, HammerFaultMidSheetDiscardsThatSheetAndEmbossesItAgainOnce) {
    Bench b;
    SimPrinter printer;
    const JobId id = b.submit(6);
    const auto plan = b.plan_of(id);
    // Half-way through sheet 2.
    std::size_t strikes_sheet1 = 0, strikes_sheet2 = 0;
    for (const auto& p : plan.sheets[0].passes) strikes_sheet1 += p.strikes.size();
    for (const auto& p : plan.sheets[1].passes) strikes_sheet2 += p.strikes.size();
    printer.controller->inject_hammer_fault_at_strike(strikes_sheet1 + strikes_sheet2 / 2);
    Runner r(b.db, "lab", printer.connect(), fast_options());
    ASSERT_TRUE(r.start());
    EXPECT_EQ(run_next(r, b.stop), RunEnd::paused);
    auto job = *b.spool.job(id);
    EXPECT_NE(job.reason.find("hammer"), std::string::npos) << job.reason;
    auto progress = *b.spool.progress(id);
    EXPECT_TRUE(progress[0].done());
    EXPECT_GT(progress[1].passes_done, 0u);
    EXPECT_FALSE(progress[1].done());
    ASSERT_TRUE(b.spool.act(id, Action::resume));
    EXPECT_EQ(run_next(r, b.stop), RunEnd::completed);
    progress = *b.spool.progress(id);
    EXPECT_EQ(progress[1].spoiled, 1u);
    const auto audit = test::audit_strikes(plan, printer.controller->strike_log(), progress);
    EXPECT_EQ(audit.problems, "");
    EXPECT_EQ(audit.partial_attempts, 1u);
    const auto kinds = b.kinds(id);
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), "spoiled"), kinds.end());
}

TEST(Runner, ControllerWarmResetMidSheetIsRidThroughWithoutADoubleDot) {
    Bench b;
    SimPrinter printer;
    const JobId id = b.submit(4);
    printer.controller->reset_at_strike(40, /*keep_ram=*/true);
    Runner r(b.db, "lab", printer.connect(), fast_options());
    ASSERT_TRUE(r.start());
    EXPECT_EQ(run_next(r, b.stop), RunEnd::completed);
    EXPECT_EQ(printer.controller->resets(), 1u);
    const auto audit = test::audit_strikes(b.plan_of(id), printer.controller->strike_log(), *b.spool.progress(id));
    EXPECT_EQ(audit.problems, "");
    EXPECT_EQ(audit.partial_attempts, 0u);
}

TEST(Runner, ControllerPowerLossPausesThenTheSheetIsEmbossedAgain) {
    Bench b;
    SimPrinter printer;
    const JobId id = b.submit(4);
    printer.controller->reset_at_strike(60, /*keep_ram=*/false);
    Runner r(b.db, "lab", printer.connect(), fast_options());
    ASSERT_TRUE(r.start());
    EXPECT_EQ(run_next(r, b.stop), RunEnd::paused);
    EXPECT_NE(b.spool.job(id)->reason.find("lost power"), std::string::npos) << b.spool.job(id)->reason;
    ASSERT_TRUE(b.spool.act(id, Action::resume));
    EXPECT_EQ(run_next(r, b.stop), RunEnd::completed);
    EXPECT_EQ(b.audit(id, printer), "");
}

TEST(Runner, AnUnpluggedCableIsRetriedAndNothingIsLostOrRepeated) {
    Bench b;
    SimPrinter printer;
    const JobId id = b.submit(6);
    Runner r(b.db, "lab", printer.connect(fast_options().link), fast_options());
    ASSERT_TRUE(r.start());
    // Pulled for good (longer than the reconnect deadline) once the first
    // sheet is recorded: virtual time runs only while the link talks, so the
    // cut is timed by progress, from another thread as a person would.
    std::atomic<bool> done{false};
    std::thread cutter([&] {
        auto watch = Spool::open(b.db);
        while (!done) {
            auto p = watch->progress(id);
            if (p && !p->empty() && (*p)[0].done()) {
                *printer.cut = true;
                return;
            }
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
    });
    const auto first = run_next(r, b.stop);
    done = true;
    cutter.join();
    if (first == RunEnd::completed) GTEST_SKIP() << "the job finished before the cable could be cut";
    EXPECT_EQ(first, RunEnd::requeued);
    auto job = *b.spool.job(id);
    EXPECT_EQ(job.state, JobState::queued);
    EXPECT_EQ(job.retries, 1);
    EXPECT_NE(job.reason.find("retry 1 of 5"), std::string::npos) << job.reason;
    // Still unplugged: the next try cannot connect, so the job waits for the
    // printer (not counted as a retry of the job).
    EXPECT_EQ(run_next(r, b.stop), RunEnd::requeued);
    EXPECT_EQ(b.spool.job(id)->retries, 1);
    EXPECT_NE(b.spool.job(id)->reason.find("waiting for printer 'lab'"), std::string::npos)
        << b.spool.job(id)->reason;
    *printer.cut = false;  // plugged back in
    EXPECT_EQ(run_next(r, b.stop), RunEnd::completed);
    EXPECT_EQ(b.audit(id, printer), "");
}

// A job for an embosser that cannot be reached waits in the
// queue as it would for a busy one, however many attempts that takes; it is
// not paused as if the job were at fault (it used to be, after the retry limit).
TEST(Runner, AJobForAnUnreachablePrinterWaitsInTheQueueUntilItIsBack) {
    Bench b;
    SimPrinter printer;
    *printer.cut = true;
    const JobId id = b.submit(2);
    auto options = fast_options();
    options.max_retries = 2;
    Runner r(b.db, "lab", printer.connect(), options);
    ASSERT_TRUE(r.start());
    for (int attempt = 1; attempt <= 5; ++attempt) {
        SCOPED_TRACE("attempt " + std::to_string(attempt));
        EXPECT_EQ(run_next(r, b.stop), RunEnd::requeued);
        const auto job = *b.spool.job(id);
        EXPECT_EQ(job.state, JobState::queued);
        EXPECT_EQ(job.retries, 0);
        EXPECT_NE(job.reason.find("waiting for printer 'lab'"), std::string::npos) << job.reason;
        EXPECT_NE(job.reason.find("no such device"), std::string::npos) << job.reason;
    }
    EXPECT_TRUE(printer.controller->strike_log().empty());
    // Plugged in: the job runs without anyone resuming it.
    *printer.cut = false;
    EXPECT_EQ(run_next(r, b.stop), RunEnd::completed);
    EXPECT_EQ(b.audit(id, printer), "");
}

// A printer that stops answering mid-job (the line goes
// silent for good). The link gives up after 30 s without acknowledged
// progress, and the job waits in the queue for the printer (not a retry of
// the job, not a fault for the operator). On the old code the link never gave
// up: the watchdog stops the runner after 20 wall seconds, so the test fails
// ("stopped") instead of hanging.
TEST(Runner, APrinterThatStopsAnsweringMidJobRequeuesTheJobAsWaitingForThePrinter) {
    Bench b;
    SimPrinter printer;
    const JobId id = b.submit(6);
    printer.line->silence_between(5.0, 1e12);  // virtual seconds: inside sheet 1
    Runner r(b.db, "lab", printer.connect(), fast_options());
    ASSERT_TRUE(r.start());
    std::atomic<bool> stop{false}, done{false};
    std::thread watchdog([&] {
        const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (!done && std::chrono::steady_clock::now() < until)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        if (!done) stop = true;
    });
    const auto first = run_next(r, stop);
    done = true;
    watchdog.join();
    EXPECT_EQ(first, RunEnd::requeued);
    auto job = *b.spool.job(id);
    EXPECT_EQ(job.state, JobState::queued);
    EXPECT_EQ(job.retries, 0);  // the job is not at fault
    EXPECT_NE(job.reason.find("waiting for printer 'lab'"), std::string::npos) << job.reason;
    EXPECT_NE(job.reason.find("stopped answering"), std::string::npos) << job.reason;
    EXPECT_GT(printer.line->now(), 5.0 + 30.0 - 3.5);
    EXPECT_LT(printer.line->now(), 5.0 + 30.0 + 3.5);
    // Still silent: the next try cannot open a session; the job keeps waiting.
    EXPECT_EQ(run_next(r, b.stop), RunEnd::requeued);
    EXPECT_EQ(b.spool.job(id)->retries, 0);
    EXPECT_NE(b.spool.job(id)->reason.find("waiting for printer 'lab'"), std::string::npos)
        << b.spool.job(id)->reason;
    // Back: the job runs on by itself, every sheet exactly once.
    printer.line->silence_between(-1, -1);
    EXPECT_EQ(run_next(r, b.stop), RunEnd::completed);
    EXPECT_EQ(b.audit(id, printer), "");
}

TEST(Runner, ADocumentThatNoLongerFitsTheProfileFailsClearlyAndIsKept) {
    Bench b;
    SimPrinter printer;
    const JobId id = b.submit(4);
    auto narrow = profile::default_profile();
    narrow.geometry.cells_per_line = 8;  // the document's lines have 10 cells
    ASSERT_TRUE(b.spool.update_printer("lab", {}, profile_text(narrow)));
    Runner r(b.db, "lab", printer.connect(), fast_options());
    ASSERT_TRUE(r.start());
    EXPECT_EQ(run_next(r, b.stop), RunEnd::failed);
    auto job = *b.spool.job(id);
    EXPECT_EQ(job.state, JobState::failed);
    EXPECT_NE(job.reason.find("no longer lays out with printer 'lab''s current profile"), std::string::npos)
        << job.reason;
    EXPECT_NE(job.reason.find("the job is kept"), std::string::npos);
    EXPECT_TRUE(printer.controller->strike_log().empty());
    EXPECT_TRUE(from_snapshot(*b.spool.document_snapshot(id)));
    ASSERT_TRUE(b.spool.update_printer("lab", {}, profile_text()));
    ASSERT_TRUE(b.spool.act(id, Action::retry));
    EXPECT_EQ(run_next(r, b.stop), RunEnd::completed);
    EXPECT_EQ(b.audit(id, printer), "");
}

TEST(Runner, OperatorCanRestartFromAChosenSheet) {
    Bench b;
    SimPrinter printer;
    const JobId id = b.submit(6);
    // Sheet 1 was embossed elsewhere: start at sheet 2 (page 3).
    ASSERT_TRUE(b.spool.act(id, Action::pause));
    ASSERT_TRUE(b.spool.act(id, Action::resume, 2));
    Runner r(b.db, "lab", printer.connect(), fast_options());
    ASSERT_TRUE(r.start());
    EXPECT_EQ(run_next(r, b.stop), RunEnd::completed);
    const auto log = printer.controller->strike_log();
    ASSERT_FALSE(log.empty());
    for (const auto& s : log) EXPECT_GE(s.sheet, 2u);
    const auto progress = *b.spool.progress(id);
    EXPECT_FALSE(progress[0].done());
    EXPECT_TRUE(progress[1].done());
    EXPECT_EQ(test::audit_strikes(b.plan_of(id), log, progress, /*require_all=*/false).problems, "");
    const auto kinds = b.kinds(id);
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), "resume-point"), kinds.end());
}

// The controller is configured from each job's own PrintJob. The
// printer's profile changes while the runner stays connected (a technician's
// new calibration): the next job's CONFIGURE carries it, without a reconnect.
// (The runner used to configure only when it connected: the second job was
// planned with the new profile but embossed with the old configuration.)
TEST(Runner, AProfileChangedWhileConnectedReachesTheControllerWithTheNextJob) {
    Bench b;
    SimPrinter printer;
    auto calibrated = profile::default_profile();
    calibrated.head.dwell_s = 0.0123;
    calibrated.carriage.steps_per_mm *= 2;
    const auto first = encode::encode_config(profile::controller_config(profile::default_profile()));
    const auto second = encode::encode_config(profile::controller_config(calibrated));
    ASSERT_NE(first, second);

    Runner r(b.db, "lab", printer.connect(), fast_options());
    ASSERT_TRUE(r.start());
    const JobId one = b.submit(2);
    EXPECT_EQ(run_next(r, b.stop), RunEnd::completed);
    EXPECT_EQ(encode::encode_config(printer.controller->config()), first);

    ASSERT_TRUE(b.spool.update_printer("lab", {}, profile_text(calibrated)));
    const JobId two = b.submit(2);
    EXPECT_EQ(run_next(r, b.stop), RunEnd::completed);
    EXPECT_EQ(printer.connects, 1) << "the runner reconnected: this test is about a link that stays open";
    // What the simulated controller was sent in CONFIGURE, byte for byte.
    EXPECT_EQ(encode::encode_config(printer.controller->config()), second);
    // Both jobs embossed as planned, each with its own profile.
    const auto audit = [&](JobId id, const profile::PrinterProfile& p) {
        auto doc = from_snapshot(*b.spool.document_snapshot(id));
        auto plan = plan_copies(*doc, p, 1);
        EXPECT_TRUE(plan) << plan.error().to_string();
        const auto job = *b.spool.job(id);
        std::vector<controller::LoggedStrike> strikes;
        for (const auto& s : printer.controller->strike_log())
            if (job.link_job && s.job_id == *job.link_job) strikes.push_back(s);
        return test::audit_strikes(*plan, strikes, *b.spool.progress(id)).problems;
    };
    EXPECT_EQ(audit(one, profile::default_profile()), "");
    EXPECT_EQ(audit(two, calibrated), "");
}

// The reference firmware (protocol 3) behind the spool: the runner plans the
// job with the tables the profile makes, and every sheet of every copy is
// struck exactly as that plan says.
TEST(Runner, OnProtocol3EveryCopyIsStruckExactlyAsTheFirmwarePlanSays) {
    Bench b;
    auto tables = profile::make_firmware_tables(profile::default_profile());
    ASSERT_TRUE(tables) << tables.error().to_string();
    controller::SimOptions options;
    options.firmware = *tables;
    SimPrinter printer(options);
    const JobId id = b.submit(9, 2);  // 5 sheets x 2 copies
    Runner r(b.db, "lab", printer.connect(), fast_options());
    ASSERT_TRUE(r.start());
    EXPECT_EQ(run_next(r, b.stop), RunEnd::completed);
    EXPECT_EQ(printer.controller->protocol(), encode::kProtocolV3);
    auto doc = from_snapshot(*b.spool.document_snapshot(id));
    auto plan = plan_copies(*doc, profile::default_profile(), 2, &*tables);
    ASSERT_TRUE(plan) << plan.error().to_string();
    const auto& log = printer.controller->strike_log();
    EXPECT_EQ(log.size(), plan->strikes);
    EXPECT_EQ(test::audit_strikes(*plan, log, *b.spool.progress(id)).problems, "");
}

// As the desktop app embosses: its built-in simulator on `sim?protocol=3`
// (the firmware the printer's profile makes), a real laid-out multi-sheet
// document, the operator pausing and resuming through the spool mid-job.
TEST(Runner, TheBuiltInSimulatorOnProtocol3StrikesAMultiSheetJobExactly) {
    TempDir dir;
    const auto db = dir / "spool.db";
    auto spool = *Spool::open(db);
    ASSERT_TRUE(spool.add_printer("lab", "sim?protocol=3&speed=max", profile_text()));
    std::string text;
    for (int i = 0; i < 300; ++i)
        text += "Paragraph " + std::to_string(i + 1) + ". " +
                std::string(3, ' ').replace(0, 3, "") +
                "The embosser strikes each dot with a small hammer, and the reader feels the raised dots with "
                "the fingertips. The embosser strikes each dot with a small hammer, and the reader feels the "
                "raised dots with the fingertips.\n\n";
    auto imported = import::import_bytes(text, "sheets.md");
    ASSERT_TRUE(imported) << imported.error().to_string();
    pipeline::PipelineOptions po;
    po.layout.geometry = profile::page_geometry(profile::default_profile());
    po.layout.geometry.interpoint = true;
    auto laid = pipeline::lay_out(*imported, po);
    ASSERT_TRUE(laid) << laid.error().to_string();
    JobSubmission sub;
    sub.printer = "lab";
    sub.title = "sheets";
    sub.document = to_snapshot(*laid);
    sub.sheets_per_copy = laid->sheet_count();
    sub.copies = 1;
    sub.user = "teacher";
    const JobId id = *spool.submit(sub);
    ASSERT_GE(laid->sheet_count(), 5u);

    controller::BuiltInSimulator sim;
    ConnectFn connect = [&sim](const PrinterRecord& p) -> Result<link::Link> {
        auto spec = transport::parse_device(p.device);
        auto settings = transport::sim_settings(*spec);
        auto stream = sim.connect(*settings, printer_firmware_tables(p));
        if (!stream) return std::unexpected(stream.error());
        return link::Link::over(std::move(*stream), {});
    };
    Runner r(db, "lab", connect, fast_options());
    ASSERT_TRUE(r.start());
    std::atomic<bool> stop{false};
    std::thread op([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        (void)spool.act(id, Action::pause);
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        (void)spool.act(id, Action::resume);
    });
    // The operator's pause may land before the runner takes the job (it then
    // waits, paused, for the resume) or while it runs.
    std::optional<RunEnd> end;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (end != RunEnd::completed && std::chrono::steady_clock::now() < deadline) {
        end = run_next(r, stop);
        if (!end) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    op.join();
    EXPECT_EQ(end, RunEnd::completed);
    EXPECT_EQ(sim.protocol(), encode::kProtocolV3);
    const auto firmware = sim.firmware();
    ASSERT_TRUE(firmware);
    auto plan = plan_copies(*laid, profile::default_profile(), 1, &*firmware);
    ASSERT_TRUE(plan);
    const auto job = *spool.job(id);
    std::vector<controller::LoggedStrike> got;
    for (const auto& s : sim.strikes())
        if (job.link_job && s.job_id == *job.link_job) got.push_back(s);
    EXPECT_EQ(got.size(), plan->strikes);
    EXPECT_EQ(test::audit_strikes(*plan, got, *spool.progress(id)).problems, "");

    // The app's check of a finished job (plans it again from the stored
    // document and the printer's profile): it agrees on what was struck, and
    // one strike moved by a step, or lost, is a disagreement.
    const auto snapshot = spool.document_snapshot(id);
    const auto printer = spool.printer(job.printer_id);
    ASSERT_TRUE(snapshot && printer);
    const auto logged = sim.strikes();
    auto check = check_strikes(job, *snapshot, printer->profile_json, logged, &*firmware);
    ASSERT_TRUE(check) << check.error().to_string();
    EXPECT_TRUE(check->agrees);
    EXPECT_EQ(check->embossed, plan->strikes);
    EXPECT_EQ(check->planned, plan->strikes);
    EXPECT_EQ(check->first_sheet, 1u);
    EXPECT_EQ(check->last_sheet, laid->sheet_count());
    auto moved = logged;
    moved[moved.size() / 2].carriage_step += 1;
    check = check_strikes(job, *snapshot, printer->profile_json, moved, &*firmware);
    ASSERT_TRUE(check);
    EXPECT_FALSE(check->agrees);
    auto lost = logged;
    lost.pop_back();
    check = check_strikes(job, *snapshot, printer->profile_json, lost, &*firmware);
    ASSERT_TRUE(check);
    EXPECT_FALSE(check->agrees);
    EXPECT_EQ(check->embossed + 1, check->planned);
    auto never_sent = job;
    never_sent.link_job.reset();
    EXPECT_FALSE(check_strikes(never_sent, *snapshot, printer->profile_json, logged, &*firmware));
    const auto broken = check_strikes(job, *snapshot, "{ not a profile", logged, &*firmware);
    ASSERT_FALSE(broken);
    EXPECT_NE(broken.error().where.find("profile"), std::string::npos) << broken.error().to_string();
}

}  // namespace
}  // namespace tactus::spool
