// SPDX-License-Identifier: GPL-3.0-or-later
// The embosser shared through a real cupsd (private, loopback only): a queue
// on a tactus: URI to the simulated controller behind a pty, jobs sent with
// `lp` by another user, laid out by the tactus-layout filter and embossed by
// the tactus backend through the Tactus spool. Every run that embosses ends
// with the exactly-once audit of the simulator's strike log against the plan.
#include <gtest/gtest.h>


#include "cups_rig.hpp"

namespace tactus::cups {
namespace {

using spool::JobState;
using test::CupsRig;
using test::PtySim;

using test::lesson;

#define REQUIRE_CUPS(rig)                                                               \
    if (!test::have_cupsd()) GTEST_SKIP() << "cupsd, lpadmin, lp, lpstat not installed"; \
    ASSERT_TRUE((rig).started()) << (rig).error_log()

// Three copies of a lesson sent with lp to a slow simulator, embossing: the
// CUPS job and the spool job once 100 strikes are in (the kill tests' start).
void start_mid_job(CupsRig& rig, PtySim& sim, int& cups_id, spool::JobId& id) {
    ASSERT_TRUE(rig.add_queue(sim));
    const auto doc = rig.lesson_file("lesson.md", 4);
    std::string out;
    cups_id = rig.lp(doc, {"-n", "3"}, out);
    ASSERT_GT(cups_id, 0) << out;
    id = rig.spool_job();
    ASSERT_NE(id, 0) << rig.error_log();
    ASSERT_TRUE(rig.e.wait_for([&](const spool::JobRecord&) { return sim.strikes().size() > 100; }, id));
}

TEST(CupsE2E, AnotherUsersJobIsEmbossedExactlyAsPlanned) {
    CupsRig rig;
    REQUIRE_CUPS(rig);
    PtySim sim(rig.e.dir.path(), "sim");
    ASSERT_TRUE(rig.add_queue(sim)) << rig.error_log();
    const auto doc = rig.lesson_file("lesson.md", 3);
    std::string out;
    const int cups_id = rig.lp(doc, {"-o", "braille-table=en-ueb-g1", "-o", "interpoint=true", "-n", "2"}, out);
    ASSERT_GT(cups_id, 0) << out;
    const auto id = rig.spool_job();
    ASSERT_NE(id, 0) << rig.error_log();
    ASSERT_TRUE(rig.e.wait_state(id, JobState::completed, std::chrono::seconds(90))) << rig.e.history(id);
    ASSERT_TRUE(rig.wait_cups_job_gone(cups_id)) << rig.error_log();
    const auto job = *rig.e.spool().job(id);
    EXPECT_EQ(job.copies, 2u);
    EXPECT_EQ(job.user, test::is_root() ? test::kTeacher : job.user);
    const auto audit = rig.e.audit(id, sim);
    EXPECT_EQ(audit.problems, "");
    EXPECT_EQ(audit.partial_attempts, 0u);
    EXPECT_EQ(audit.sheets_checked, job.total_sheets());
    // The backend told cupsd about every sheet once: CUPS 2.4 totals the
    // job's PAGE: lines in one page_log line.
    const auto pages = spool::test::read_text((rig.cups_dir / "log/page_log").string());
    EXPECT_NE(pages.find(" total " + std::to_string(job.total_sheets()) + " "), std::string::npos) << pages;
    if (test::is_root()) {
        EXPECT_EQ(pages.rfind("Embosser " + test::kTeacher + " ", 0), 0u) << pages;
    }
    EXPECT_NE(rig.printer_status().find("idle"), std::string::npos) << rig.printer_status();
}

TEST(CupsE2E, CancelInCupsAbortsOnTheController) {
    CupsRig rig;
    REQUIRE_CUPS(rig);
    // Ten times the machine's speed: the five copies take about 400 s at the
    // machine's pace, so 40 s here, long after the cancel (cupsd's cancel reaches the
    // backend within seconds even on a loaded machine; at 100 times the job
    // could end first).
    PtySim sim(rig.e.dir.path(), "sim", {}, 10);
    ASSERT_TRUE(rig.add_queue(sim));
    const auto doc = rig.lesson_file("lesson.md", 6);
    std::string out;
    const int cups_id = rig.lp(doc, {"-n", "5"}, out);
    ASSERT_GT(cups_id, 0) << out;
    const auto id = rig.spool_job();
    ASSERT_NE(id, 0) << rig.error_log();
    ASSERT_TRUE(rig.e.wait_for([&](const spool::JobRecord&) { return sim.strikes().size() > 20; }, id));
    const auto [code, msg] = rig.client({"cancel", "Embosser-" + std::to_string(cups_id)});
    ASSERT_EQ(code, 0) << msg;
    ASSERT_TRUE(rig.e.wait_state(id, JobState::cancelled)) << rig.e.history(id) << rig.error_log();
    EXPECT_NE(rig.e.history(id).find("aborted on the controller"), std::string::npos) << rig.e.history(id);
    // Stopped on the controller: no more dots after the abort.
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const auto at_cancel = sim.strikes().size();
    std::this_thread::sleep_for(std::chrono::milliseconds(1000));
    EXPECT_EQ(sim.strikes().size(), at_cancel);
    EXPECT_LT(at_cancel, rig.e.plan_of(id).strikes);
    EXPECT_EQ(rig.e.audit(id, sim, /*require_all=*/false).problems, "");
    EXPECT_TRUE(rig.wait_cups_job_gone(cups_id));
}

TEST(CupsE2E, PaperOutShowsInLpstatThenTheJobCarriesOn) {
    CupsRig rig;
    REQUIRE_CUPS(rig);
    PtySim sim(rig.e.dir.path(), "sim", {"--paper-out-at", "2", "--paper-reload", "4000"});
    ASSERT_TRUE(rig.add_queue(sim));
    const auto doc = rig.lesson_file("lesson.md", 3);
    std::string out;
    const int cups_id = rig.lp(doc, {"-n", "2"}, out);
    ASSERT_GT(cups_id, 0) << out;
    const auto id = rig.spool_job();
    ASSERT_NE(id, 0) << rig.error_log();
    bool seen = false;
    for (int i = 0; i < 600 && !seen; ++i) {
        const auto status = rig.printer_status();
        seen = status.find("Paper out") != std::string::npos && status.find("media-empty-error") != std::string::npos;
        if (!seen) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    EXPECT_TRUE(seen) << rig.printer_status() << rig.e.history(id);
    ASSERT_TRUE(rig.e.wait_state(id, JobState::completed, std::chrono::seconds(90))) << rig.e.history(id);
    ASSERT_TRUE(rig.wait_cups_job_gone(cups_id));
    const auto after = rig.printer_status();
    EXPECT_EQ(after.find("media-empty"), std::string::npos) << after;
    EXPECT_EQ(rig.e.audit(id, sim).problems, "");
}

TEST(CupsE2E, CupsdKilledMidJobLosesNoSheetAndDoublesNone) {
    CupsRig rig;
    REQUIRE_CUPS(rig);
    PtySim sim(rig.e.dir.path(), "sim", {}, 60);  // the three copies last about 3 s: still running when killed
    int cups_id = 0;
    spool::JobId id = 0;
    ASSERT_NO_FATAL_FAILURE(start_mid_job(rig, sim, cups_id, id));
    rig.kill_cupsd();
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    ASSERT_TRUE(rig.restart_cupsd()) << rig.error_log();
    ASSERT_TRUE(rig.e.wait_state(id, JobState::completed, std::chrono::seconds(120))) << rig.e.history(id);
    ASSERT_TRUE(rig.wait_cups_job_gone(cups_id)) << rig.error_log();
    const auto audit = rig.e.audit(id, sim);
    EXPECT_EQ(audit.problems, "") << rig.e.history(id);
    EXPECT_EQ(audit.sheets_checked, rig.e.spool().job(id)->total_sheets());
    // One spool job however often CUPS ran the backend.
    EXPECT_EQ(rig.e.spool().jobs(true)->size(), 1u);
}

TEST(CupsE2E, BackendKilledMidJobResumesWithoutLossOrDoubles) {
    CupsRig rig;
    REQUIRE_CUPS(rig);
    PtySim sim(rig.e.dir.path(), "sim", {}, 60);  // the three copies last about 3 s: still running when killed
    int cups_id = 0;
    spool::JobId id = 0;
    ASSERT_NO_FATAL_FAILURE(start_mid_job(rig, sim, cups_id, id));
    // The runner token names the backend's pid: kill exactly that process.
    const auto runner = rig.e.spool().job(id)->runner;
    ASSERT_NE(runner.find(':'), std::string::npos) << runner;
    const pid_t backend = std::stoi(runner.substr(runner.rfind(':') + 1));
    ASSERT_EQ(::kill(backend, SIGKILL), 0);
    // cupsd takes a backend killed by SIGKILL for one it stopped itself and
    // marks the CUPS job done; the spool job stays open with its write-ahead
    // record. The next runner for the embosser (the next CUPS job's backend,
    // or `tactus-cli serve` as here) takes over from the dead one, reconciles
    // with the controller and finishes it.
    ASSERT_TRUE(rig.wait_cups_job_gone(cups_id)) << rig.error_log();
    EXPECT_EQ(rig.e.spool().job(id)->state, JobState::running);
    auto serve = rig.e.serve();
    ASSERT_TRUE(rig.e.wait_state(id, JobState::completed, std::chrono::seconds(120))) << rig.e.history(id);
    const auto audit = rig.e.audit(id, sim);
    EXPECT_EQ(audit.problems, "") << rig.e.history(id);
    EXPECT_EQ(rig.e.spool().jobs(true)->size(), 1u);
}

TEST(CupsE2E, AnUnknownTableFailsTheJobWithAClearErrorAndEmbossesNothing) {
    CupsRig rig;
    REQUIRE_CUPS(rig);
    PtySim sim(rig.e.dir.path(), "sim");
    ASSERT_TRUE(rig.add_queue(sim));
    const auto doc = rig.lesson_file("lesson.md", 1);
    std::string out;
    const int cups_id = rig.lp(doc, {"-o", "braille-table=no-such-table"}, out);
    ASSERT_GT(cups_id, 0) << out;
    std::string status;
    // A deadline, not a count of polls: under load each lpstat takes longer,
    // and cupsd may start the filter late (it failed once beside the ASan run).
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(90);
    while (std::chrono::steady_clock::now() < deadline) {
        status = rig.client({"lpstat", "-l", "-W", "all", "-o", "Embosser"}).second + rig.printer_status();
        if (status.find("no-such-table") != std::string::npos) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    EXPECT_NE(status.find("'no-such-table' is not an installed braille table"), std::string::npos) << status;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    EXPECT_TRUE(sim.strikes().empty());
    if (std::filesystem::exists(rig.e.db)) {
        EXPECT_TRUE(rig.e.spool().jobs(true)->empty());
    }
}

}  // namespace
}  // namespace tactus::cups
