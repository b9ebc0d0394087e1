// SPDX-License-Identifier: GPL-3.0-or-later
// The whole print path as the user runs it: `emboss --queue`, `serve`, `queue`
// commands and the simulated controller behind a real pseudo-terminal, with
// faults injected by the simulator. Every run ends with the exactly-once audit
// of the simulator's strike log.
#include <gtest/gtest.h>

#include "e2e_rig.hpp"

namespace tactus::spool {
namespace {

using test::E2E;
using test::PtySim;

TEST(ServeE2E, QueuedJobIsEmbossedExactlyOnceAndServeStopsCleanly) {
    E2E e;
    PtySim sim(e.dir.path(), "sim");
    ASSERT_FALSE(sim.path().empty());
    ASSERT_EQ(e.cli({"queue", "printer", "add", "lab", "--device", sim.device()}).first, 0);
    const JobId id = e.queue_text(test::kText, {"--copies", "2"});
    auto serve = e.serve();
    ASSERT_TRUE(e.wait_state(id, JobState::completed)) << e.history(id);
    serve->signal(SIGTERM);
    EXPECT_EQ(serve->wait(), 0);
    const auto audit = e.audit(id, sim);
    EXPECT_EQ(audit.problems, "");
    EXPECT_EQ(audit.partial_attempts, 0u);
    const auto [code, shown] = e.cli({"queue", "show", std::to_string(id)});
    EXPECT_EQ(code, 0);
    EXPECT_NE(shown.find("state:      completed"), std::string::npos) << shown;
}

// A job for an embosser that is not there is queued and
// waits, as it would for a busy one; once the printer is reachable (here: its
// device set to a running simulator) it is embossed, exactly once, without
// anyone resuming it.
TEST(ServeE2E, AJobForAnEmbosserThatIsNotThereWaitsInTheQueue) {
    E2E e;
    const std::string missing = "pty:/dev/pts/" + std::to_string(100000 + getpid() % 100000);
    const JobId id = e.queue_text(test::kText, {"--device", missing});
    ASSERT_NE(id, 0);
    auto serve = e.serve({"--max-retries", "1"});
    // More attempts than the retry limit, and the job is still waiting.
    JobRecord job;
    ASSERT_TRUE(e.wait_for(
        [&](const JobRecord& j) {
            int waits = 0;
            if (auto events = e.spool().events(id, 1000))
                for (const auto& ev : *events) waits += ev.message.find("waiting for printer") != std::string::npos;
            job = j;
            // Between attempts it is back in the queue (a runner holds it
            // only for the moment of an attempt).
            return waits >= 4 && j.state == JobState::queued;
        },
        id))
        << e.history(id);
    EXPECT_EQ(job.retries, 0);
    EXPECT_NE(job.reason.find(missing.substr(4)), std::string::npos) << job.reason;
    const auto [code, listed] = e.cli({"queue", "list"});
    EXPECT_EQ(code, 0);
    EXPECT_NE(listed.find("queued"), std::string::npos) << listed;

    PtySim sim(e.dir.path(), "sim");
    ASSERT_FALSE(sim.path().empty());
    const auto printer = e.spool().printer(job.printer_id)->name;
    ASSERT_EQ(e.cli({"queue", "printer", "set", printer, "--device", sim.device()}).first, 0);
    ASSERT_TRUE(e.wait_state(id, JobState::completed)) << e.history(id);
    serve->signal(SIGTERM);
    EXPECT_EQ(serve->wait(), 0);
    EXPECT_EQ(e.audit(id, sim).problems, "");
}

TEST(ServeE2E, PaperOutWaitsForPaperThenCarriesOn) {
    E2E e;
    PtySim sim(e.dir.path(), "sim", {"--paper-out-at", "2", "--paper-reload", "2000"});
    ASSERT_EQ(e.cli({"queue", "printer", "add", "lab", "--device", sim.device()}).first, 0);
    const JobId id = e.queue_text(test::kText, {"--copies", "2"});
    auto serve = e.serve();
    ASSERT_TRUE(e.wait_state(id, JobState::completed)) << e.history(id);
    EXPECT_NE(e.history(id).find("paper out"), std::string::npos) << e.history(id);
    EXPECT_EQ(e.audit(id, sim).problems, "");
}

TEST(ServeE2E, PowerLossPausesTheJobUntilTheOperatorResumes) {
    E2E e;
    PtySim sim(e.dir.path(), "sim", {"--power-loss-at-strike", "150"});
    ASSERT_EQ(e.cli({"queue", "printer", "add", "lab", "--device", sim.device()}).first, 0);
    const JobId id = e.queue_text(test::kText, {"--copies", "3"});
    auto serve = e.serve();
    ASSERT_TRUE(e.wait_state(id, JobState::paused)) << e.history(id);
    EXPECT_NE(e.spool().job(id)->reason.find("lost power"), std::string::npos) << e.spool().job(id)->reason;
    const auto [code, out] = e.cli({"queue", "resume", std::to_string(id)});
    EXPECT_EQ(code, 0) << out;
    ASSERT_TRUE(e.wait_state(id, JobState::completed)) << e.history(id);
    const auto audit = e.audit(id, sim);
    EXPECT_EQ(audit.problems, "");
    EXPECT_EQ(audit.partial_attempts, 1u);
}

TEST(ServeE2E, ControllerResetMidSheetIsRiddenThrough) {
    E2E e;
    PtySim sim(e.dir.path(), "sim", {"--reset-at-strike", "120"});
    ASSERT_EQ(e.cli({"queue", "printer", "add", "lab", "--device", sim.device()}).first, 0);
    const JobId id = e.queue_text(test::kText, {"--copies", "2"});
    auto serve = e.serve();
    ASSERT_TRUE(e.wait_state(id, JobState::completed)) << e.history(id);
    const auto audit = e.audit(id, sim);
    EXPECT_EQ(audit.problems, "");
}

TEST(ServeE2E, ACableDisconnectIsSurvived) {
    E2E e;
    PtySim sim(e.dir.path(), "sim", {"--disconnect-at", "1.5", "--disconnect-for", "1.5"});
    ASSERT_EQ(e.cli({"queue", "printer", "add", "lab", "--device", sim.device()}).first, 0);
    const JobId id = e.queue_text(test::kText, {"--copies", "4"});
    auto serve = e.serve();
    ASSERT_TRUE(e.wait_state(id, JobState::completed)) << e.history(id);
    EXPECT_EQ(e.audit(id, sim).problems, "");
}

TEST(ServeE2E, OperatorPausesResumesAndCancelsFromOtherProcesses) {
    E2E e;
    PtySim sim(e.dir.path(), "sim", {}, 100);
    ASSERT_EQ(e.cli({"queue", "printer", "add", "lab", "--device", sim.device()}).first, 0);
    const JobId id = e.queue_text(test::kText, {"--copies", "20"});
    auto serve = e.serve();
    ASSERT_TRUE(e.wait_for([](const JobRecord& j) { return j.state == JobState::running; }, id));
    ASSERT_TRUE(e.wait_for([&](const JobRecord&) { return !sim.strikes().empty(); }, id));
    ASSERT_EQ(e.cli({"queue", "pause", std::to_string(id)}).first, 0);
    ASSERT_TRUE(e.wait_state(id, JobState::paused)) << e.history(id);
    // Stopped: after the pass under way ends, no more dots.
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const auto at_pause = sim.strikes().size();
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
    EXPECT_EQ(sim.strikes().size(), at_pause);
    ASSERT_EQ(e.cli({"queue", "resume", std::to_string(id)}).first, 0);
    ASSERT_TRUE(e.wait_for([&](const JobRecord&) { return sim.strikes().size() > at_pause; }, id));
    ASSERT_EQ(e.cli({"queue", "cancel", std::to_string(id)}).first, 0);
    ASSERT_TRUE(e.wait_state(id, JobState::cancelled)) << e.history(id);
    const auto audit = e.audit(id, sim, /*require_all=*/false);
    EXPECT_EQ(audit.problems, "");
}

TEST(ServeE2E, ConcurrentClientsAddAndCancelWhileServing) {
    E2E e;
    PtySim sim(e.dir.path(), "sim");
    ASSERT_EQ(e.cli({"queue", "printer", "add", "lab", "--device", sim.device()}).first, 0);
    const auto file = e.dir / "doc.txt";
    std::ofstream(file) << test::kText;
    auto serve = e.serve();
    // Four clients at once, each queueing two jobs and cancelling its second.
    std::vector<std::unique_ptr<test::Process>> clients;
    for (int c = 0; c < 4; ++c) {
        const std::string script =
            "for i in 1 2; do " + test::kCli + " emboss --queue '" + file.string() + "' --db '" + e.db.string() +
            "' --title c" + std::to_string(c) + "-$i || exit 1; done; id=$(" + test::kCli + " queue list --db '" +
            e.db.string() + "' | awk '$7==\"c" + std::to_string(c) + "-2\"{print $1}'); [ -z \"$id\" ] || " +
            test::kCli + " queue cancel $id --db '" + e.db.string() + "' || true";
        clients.push_back(std::make_unique<test::Process>(std::vector<std::string>{"/bin/sh", "-c", script},
                                                          (e.dir / "clients.log").string()));
    }
    for (auto& c : clients) {
        const auto out = c->read_all();
        EXPECT_EQ(c->wait(), 0) << out << test::read_text(e.dir / "clients.log");
    }
    auto s = e.spool();
    const auto jobs = *s.jobs(true);
    ASSERT_EQ(jobs.size(), 8u);
    for (const auto& j : jobs)
        EXPECT_TRUE(e.wait_for([](const JobRecord& r) { return is_terminal(r.state); }, j.id)) << j.id;
    int completed = 0;
    const auto finished = *e.spool().jobs(true);
    for (const auto& j : finished) completed += j.state == JobState::completed;
    EXPECT_GE(completed, 4);  // a cancel may come too late for a job already done
    // Every job's log starts with its submission and ends with its outcome.
    for (const auto& j : finished) {
        const auto events = *s.events(j.id, 1000);
        ASSERT_FALSE(events.empty());
        EXPECT_EQ(events.front().kind, "submitted");
        const auto& last = events.back().kind;
        if (j.state == JobState::completed)
            EXPECT_EQ(last, "completed") << j.id;
        else
            EXPECT_TRUE(last == "cancel" || last == "cancelled") << j.id << ": " << last;
    }
    EXPECT_TRUE(s.check());
}

}  // namespace
}  // namespace tactus::spool
