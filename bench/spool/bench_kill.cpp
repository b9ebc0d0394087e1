// SPDX-License-Identifier: GPL-3.0-or-later
// Kill soak: `tactus-cli serve` SIGKILLed 2,000 times (by default) at random
// moments while it embosses over a pseudo-terminal to `tactus-cli sim --pty`,
// restarted after each kill; every finished job's strike log is audited
// against its plan. The kills are spread over several seeds (each its own
// spool, simulator and random moments, each printed) and, within a seed, over
// many jobs (at most KILLS_PER_JOB each, then the job runs to its end). The
// figures that matter are zero: sheets lost, sheets embossed twice.
//
// Usage: bench_kill [KILLS] [SEED] [KILLS_PER_JOB] [SEEDS]
//   defaults 2000, a fresh seed (or TACTUS_KILL_SEED), 10, 10; seed i of the
//   run is SEED+i, so `bench_kill 200 SEED+i 10 1` repeats one of them.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "kill_rig.hpp"

int main(int argc, char** argv) {
    using namespace tactus::spool;
    const int kills = argc > 1 ? std::stoi(argv[1]) : 2000;
    const auto seed = argc > 2 ? static_cast<std::uint32_t>(std::stoul(argv[2])) : test::kill_seed();
    const int per_job = argc > 3 ? std::stoi(argv[3]) : 10;
    const int seeds = std::max(1, argc > 4 ? std::stoi(argv[4]) : 10);
    std::printf("kill soak: %d SIGKILLs of `serve` over %d seeds (%u to %u), at most %d per job\n", kills, seeds,
                seed, seed + static_cast<std::uint32_t>(seeds - 1), per_job);
    std::fflush(stdout);
    const auto start = std::chrono::steady_clock::now();
    test::KillReport total;
    std::string problems;
    for (int i = 0; i < seeds && problems.empty(); ++i) {
        test::TempDir dir;
        test::KillOptions o;
        o.cli = TACTUS_CLI;
        o.dir = dir.path();
        // The kills shared out: the first seeds take the remainder.
        o.kills = kills / seeds + (i < kills % seeds ? 1 : 0);
        o.seed = seed + static_cast<std::uint32_t>(i);
        o.budget = std::chrono::seconds(6 * 3600);
        o.kills_per_job = per_job;
        o.text = "The spool keeps every page.\n\nA teacher queues a book and walks away; the technician clears a jam.\n";
        const auto r = test::kill_loop(o);
        std::printf("  seed %u: %d SIGKILLs over %d jobs, %zu sheets audited, %zu partial (reported), lost %zu, "
                    "twice %zu, %.0f s\n",
                    o.seed, r.kills, r.rounds, r.sheets, r.partial_sheets, r.lost, r.doubled, r.seconds);
        std::fflush(stdout);
        total.kills += r.kills;
        total.rounds += r.rounds;
        total.sheets += r.sheets;
        total.partial_sheets += r.partial_sheets;
        total.lost += r.lost;
        total.doubled += r.doubled;
        if (!r.problems.empty()) problems = "seed " + std::to_string(o.seed) + ":\n" + r.problems;
        if (r.kills < o.kills && problems.empty()) problems = "seed " + std::to_string(o.seed) + ": too few kills\n";
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("kills %d, jobs %d, sheets audited %zu, partial sheets %zu (every one reported as discarded)\n",
                total.kills, total.rounds, total.sheets, total.partial_sheets);
    std::printf("sheets lost %zu, sheets embossed twice %zu\n", total.lost, total.doubled);
    std::printf("wall time %.0f s (%.2f s per kill, job ends included)\n", seconds,
                total.kills > 0 ? seconds / total.kills : 0.0);
    if (!problems.empty()) {
        std::printf("PROBLEMS\n%s", problems.c_str());
        return 1;
    }
    return total.kills >= kills ? 0 : 1;
}
