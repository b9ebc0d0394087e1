// SPDX-License-Identifier: GPL-3.0-or-later
// kill -9 exactly at the pass-completion edge. The simulated controller has
// executed a pass and its acknowledgement has not reached `serve` when serve
// is SIGKILLed: `tactus-cli sim --mute-after-pass N` holds the controller's
// replies from the moment pass N is executed (as if the ACK were still on the
// wire when the host died) and says "muted" on stdout; the test kills serve
// then, waits until the controller has come to rest on its own ("at rest":
// the job ran to its end, or the keep-alive watchdog paused it), restarts
// serve and audits the strike log against the plan.
//
// Round 1 always kills at the last pass of the job's last sheet: the
// controller then finishes the job by itself, and a runner that only read the
// count of a job still active would emboss that sheet again.
#include <gtest/gtest.h>

#include <random>

#include "e2e_rig.hpp"
#include "kill_rig.hpp"

namespace tactus::spool {
namespace {

using namespace std::chrono_literals;
using test::E2E;
using test::PtySim;

// The job-wide pass count when each sheet is finished.
std::vector<std::size_t> sheet_ends(const plan::JobPlan& plan) {
    std::vector<std::size_t> ends;
    std::size_t n = 0;
    for (const auto& s : plan.sheets) {
        n += s.passes.size();
        ends.push_back(n);
    }
    return ends;
}

std::size_t recorded_passes(E2E& e, JobId id) {
    std::size_t n = 0;
    const auto progress = *e.spool().progress(id);
    for (const auto& p : progress) n += p.passes_done;
    return n;
}

TEST(KillTest, SigkillAtThePassCompletionEdgeNeverEmbossesASheetTwice) {
    const auto seed = test::kill_seed();
    std::cout << "[ kill edge ] seed " << seed << " (TACTUS_KILL_SEED=" << seed << " repeats it)" << std::endl;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    E2E e;
    // Any device for now: each round points the printer at its own simulator.
    ASSERT_EQ(e.cli({"queue", "printer", "add", "lab", "--device", "pty:/dev/null"}).first, 0);
    constexpr int kRounds = 4;
    for (int round = 1; round <= kRounds; ++round) {
        const JobId id = e.queue_text(test::kText, {"--copies", "4"});
        const auto ends = sheet_ends(e.plan_of(id));
        ASSERT_GE(ends.size(), 2U);
        // 1: the job's last pass. 2: the last pass of a random sheet (the next
        // sheet's first passes are buffered and run on). 3, 4: any pass.
        std::size_t at = ends.back();
        if (round == 2) at = ends[rng() % ends.size()];
        if (round >= 3) at = 1 + rng() % ends.back();
        SCOPED_TRACE("round " + std::to_string(round) + ": killed when pass " + std::to_string(at) + " of " +
                     std::to_string(ends.back()) + " was executed");
        PtySim sim(e.dir.path(), "edge" + std::to_string(round), {"--mute-after-pass", std::to_string(at)});
        ASSERT_FALSE(sim.path().empty());
        ASSERT_EQ(e.cli({"queue", "printer", "set", "lab", "--device", sim.device()}).first, 0);

        auto serve = e.serve();
        const auto muted = sim.next_line(60s);
        ASSERT_EQ(muted.rfind("muted", 0), 0U) << "the simulator said '" << muted << "'\n" << e.history(id);
        serve->signal(SIGKILL);
        EXPECT_EQ(serve->wait(), 128 + SIGKILL);
        const auto rest = sim.next_line(60s);
        ASSERT_EQ(rest.rfind("at rest", 0), 0U) << "the simulator said '" << rest << "'";
        // The kill landed in the window: the controller executed pass `at`,
        // the spool never heard of it.
        ASSERT_LT(recorded_passes(e, id), at) << e.history(id);

        auto again = e.serve();
        ASSERT_TRUE(e.wait_state(id, JobState::completed)) << e.history(id);
        again->signal(SIGTERM);
        EXPECT_EQ(again->wait(), 0);
        const auto audit = e.audit(id, sim);
        // The first doubled or lost sheet ends the test: the later rounds would only repeat it.
        ASSERT_EQ(audit.problems, "") << "controller: " << rest << "\n" << e.history(id);
    }
}

}  // namespace
}  // namespace tactus::spool
