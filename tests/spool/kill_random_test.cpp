// SPDX-License-Identifier: GPL-3.0-or-later
// kill -9 at random moments: `tactus-cli serve` is SIGKILLed while it
// embosses over a pseudo-terminal, restarted each time, and the simulator's
// strike log must show every sheet embossed exactly once (partial sheets only
// where the spool reported them). Four shards of 50 kills, each with its own
// seed (printed; TACTUS_KILL_SEED=<seed> repeats shard 0's run, seed+1 shard
// 1's, ...), so one ctest run delivers at least 200 kills and ctest -j runs
// the shards side by side. Bounded in time; the kill count is then checked.
// The soak benchmark (bench/spool/bench_kill) runs the same loop 2,000 times.
#include <gtest/gtest.h>

#include "kill_rig.hpp"

namespace tactus::spool {
namespace {

class KillTest : public ::testing::TestWithParam<int> {};

TEST_P(KillTest, SigkillAtRandomPointsNeverLosesOrRepeatsASheet) {
    constexpr int kKills = 50;
    test::TempDir dir;
    test::KillOptions o;
    o.cli = TACTUS_CLI;
    o.dir = dir.path();
    o.kills = kKills;
    o.seed = test::kill_seed(static_cast<std::uint32_t>(GetParam()));
    o.text = "The spool keeps every page.\n\nA teacher queues a book and walks away; the technician clears a jam.\n";
    std::cout << "[ kill test ] shard " << GetParam() << " seed " << o.seed << std::endl;
    SCOPED_TRACE("seed " + std::to_string(o.seed));
    const auto r = test::kill_loop(o);
    EXPECT_EQ(r.problems, "");
    EXPECT_GE(r.kills, kKills) << "the time budget ran out";
    std::cout << "[ kill test ] shard " << GetParam() << ": " << r.kills << " SIGKILLs over " << r.rounds
              << " jobs, " << r.sheets << " sheets audited, " << r.partial_sheets
              << " partial sheets (all reported), seed " << o.seed << "\n";
}

INSTANTIATE_TEST_SUITE_P(Shards, KillTest, ::testing::Range(0, 4));

// A power cut of the whole bench: `serve` and the controller die together at
// random moments, and a fresh controller (which has lost its count of the
// sheet in its paper path) takes the old one's place. Every partly embossed
// sheet, however few strikes it got before the cut, must be reported as
// discarded, so the paper count a teacher reads is the paper used.
TEST(KillTogether, ServeAndTheControllerKilledTogetherReportEveryPartialSheet) {
    constexpr int kKills = 30;
    test::TempDir dir;
    test::KillOptions o;
    o.cli = TACTUS_CLI;
    o.dir = dir.path();
    o.kills = kKills;
    o.seed = test::kill_seed(100);
    o.controller_kill_percent = 50;
    // Slower sheets and later kills than the shards above, so most kills land
    // with a sheet in the machine; a few kills per job, so the loop also
    // starts, finishes and audits several jobs.
    o.time_scale = "100";
    o.max_delay_ms = 1500;
    o.kills_per_job = 8;
    o.text = "The spool keeps every page.\n\nA teacher queues a book and walks away; the technician clears a jam.\n";
    std::cout << "[ kill test ] serve and controller, seed " << o.seed << std::endl;
    SCOPED_TRACE("seed " + std::to_string(o.seed));
    const auto r = test::kill_loop(o);
    EXPECT_EQ(r.problems, "");
    EXPECT_GE(r.kills, kKills) << "the time budget ran out";
    EXPECT_GT(r.controller_kills, kKills / 5) << "too few kills took the controller down to test anything";
    EXPECT_GT(r.partial_sheets, 0u) << "no kill landed mid-sheet";
    std::cout << "[ kill test ] serve and controller: " << r.kills << " SIGKILLs (" << r.controller_kills
              << " with the controller) over " << r.rounds << " jobs, " << r.sheets << " sheets audited, "
              << r.partial_sheets << " partial sheets (all reported), seed " << o.seed << "\n";
}

}  // namespace
}  // namespace tactus::spool
