// SPDX-License-Identifier: GPL-3.0-or-later
// Kill soak: `tactus-cli serve` SIGKILLed 2,000 times (by default) at random
// moments while it embosses over a pseudo-terminal to `tactus-cli sim --pty`,
// restarted after each kill; every finished job's strike log is audited
// against its plan. The figure that matters is zero: sheets lost, sheets
// embossed twice. Usage: bench_kill [KILLS] [SEED] [KILLS_PER_JOB]; TACTUS_KILL_SEED
// works too.
#include <cstdio>
#include <iostream>
#include <string>

#include "kill_rig.hpp"

int main(int argc, char** argv) {
    using namespace tactus::spool;
    test::TempDir dir;
    test::KillOptions o;
    o.cli = TACTUS_CLI;
    o.dir = dir.path();
    o.kills = argc > 1 ? std::stoi(argv[1]) : 2000;
    o.seed = argc > 2 ? static_cast<std::uint32_t>(std::stoul(argv[2])) : test::kill_seed();
    o.budget = std::chrono::seconds(6 * 3600);
    // At most 10 kills per job, then it runs to its end: many jobs, many sheets audited.
    o.kills_per_job = argc > 3 ? std::stoi(argv[3]) : 10;
    o.text = "The spool keeps every page.\n\nA teacher queues a book and walks away; the technician clears a jam.\n";
    std::printf("kill soak: %d SIGKILLs of `serve`, seed %u\n", o.kills, o.seed);
    std::fflush(stdout);
    int rounds = 0;
    o.progress = [&](const std::string& line) {
        if (++rounds % 25 == 0) std::printf("  %s\n", line.c_str()), std::fflush(stdout);
    };
    const auto r = test::kill_loop(o);
    std::printf("  %d SIGKILLs over %d jobs in %.0f s (%.2f s per kill)\n", r.kills, r.rounds, r.seconds,
                r.kills > 0 ? r.seconds / r.kills : 0.0);
    std::printf("  %zu sheets audited; %zu partial sheets, every one reported as discarded\n", r.sheets,
                r.partial_sheets);
    std::printf("  sheets lost: %zu; sheets embossed twice: %zu\n", r.lost, r.doubled);
    if (!r.problems.empty()) {
        std::printf("PROBLEMS (seed %u):\n%s", o.seed, r.problems.c_str());
        return 1;
    }
    return r.kills >= o.kills ? 0 : 1;
}
