// SPDX-License-Identifier: GPL-3.0-or-later
// The main() of every test executable: GoogleTest's, after the check every
// main() that may start translation workers makes first (on Windows a worker
// is the executable started again: pipeline/translation_workers.hpp).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "pipeline/translation_workers.hpp"

int main(int argc, char** argv) {
    // A test makes a worker crash at the block of this source line (it sets
    // the variable, the workers it starts inherit it).
    const char* crash_line = std::getenv("TACTUS_TEST_WORKER_CRASH_LINE");
    const int crash_at = crash_line ? std::atoi(crash_line) : 0;
    const auto crash = [crash_at](const tactus::document::Block& b) {
        if (crash_at > 0 && b.source_line == crash_at) std::abort();
    };
    if (const auto worker = tactus::pipeline::run_translation_worker(argc, argv, crash)) return *worker;
    testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
