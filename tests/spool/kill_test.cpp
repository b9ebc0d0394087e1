// SPDX-License-Identifier: GPL-3.0-or-later
// kill -9 at random moments: `tactus-cli serve` is killed with SIGKILL at
// least 50 times while it embosses over a pseudo-terminal, restarted each
// time, and the simulator's strike log must show every sheet embossed exactly
// once (partial sheets only where the spool reported them). Bounded in time:
// the loop stops at its budget and the kill count is then checked.
#include <gtest/gtest.h>

#include <random>

#include "e2e_rig.hpp"

namespace tactus::spool {
namespace {

using test::E2E;
using test::PtySim;

TEST(KillTest, SigkillAtRandomPointsNeverLosesOrRepeatsASheet) {
    constexpr int kKills = 50;
    const auto budget = std::chrono::seconds(240);
    const auto seed = std::random_device{}();
    std::mt19937 rng(seed);
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto start = std::chrono::steady_clock::now();
    int kills = 0, rounds = 0;
    std::size_t partials = 0, sheets = 0;
    E2E e;
    while (kills < kKills && std::chrono::steady_clock::now() - start < budget) {
        ++rounds;
        // A fresh simulator per round, so each strike log holds one job.
        PtySim sim(e.dir.path(), "round" + std::to_string(rounds));
        ASSERT_FALSE(sim.path().empty());
        const auto verb = rounds == 1 ? "add" : "set";
        ASSERT_EQ(e.cli({"queue", "printer", verb, "lab", "--device", sim.device()}).first, 0);
        const JobId id = e.queue_text(test::kText, {"--copies", "4"});
        for (;;) {
            auto serve = e.serve();
            // Anywhere from "still starting" to "several sheets in".
            std::this_thread::sleep_for(std::chrono::milliseconds(std::uniform_int_distribution<int>(0, 700)(rng)));
            if (e.spool().job(id)->state == JobState::completed || kills >= kKills) {
                ASSERT_TRUE(e.wait_state(id, JobState::completed)) << e.history(id);
                serve->signal(SIGTERM);
                EXPECT_EQ(serve->wait(), 0);
                break;
            }
            serve->signal(SIGKILL);
            EXPECT_EQ(serve->wait(), 128 + SIGKILL);
            ++kills;
        }
        const auto audit = e.audit(id, sim);
        EXPECT_EQ(audit.problems, "") << "round " << rounds << "\n" << e.history(id);
        partials += audit.partial_attempts;
        sheets += audit.sheets_checked;
    }
    EXPECT_GE(kills, kKills) << "the time budget ran out";
    std::cout << "[ kill test ] " << kills << " SIGKILLs over " << rounds << " jobs, " << sheets
              << " sheets audited, " << partials << " partial sheets (all reported), seed " << seed << "\n";
}

}  // namespace
}  // namespace tactus::spool
