// SPDX-License-Identifier: GPL-3.0-or-later
// The app as a spool client, end to end: `tactus --emboss` (offscreen)
// queues a document on a printer it sets up for the device, its own runner
// starts embossing it over a real pseudo-terminal to `tactus-cli sim --pty`,
// the app is told to quit mid-job, and `tactus-cli serve` finishes the job.
// The simulator's strike log is audited against the plan: every sheet struck
// exactly once in full, and any partial sheet reported as discarded.
#include <gtest/gtest.h>

#include <cstdlib>

#include "e2e_rig.hpp"

namespace tactus::spool {
namespace {

using test::E2E;
using test::Process;
using test::read_text;
using test::PtySim;

const std::string kApp = TACTUS_GUI;

std::size_t passes_recorded(Spool s, JobId id) {
    std::size_t n = 0;
    if (auto p = s.progress(id); p)
        for (const auto& sheet : *p) n += sheet.passes_done;
    return n;
}

TEST(AppE2E, AJobTheAppQueuedOutlivesTheAppAndServeFinishesItExactlyOnce) {
    E2E e;
    // Slow enough that the app is still embossing when it is told to quit.
    PtySim sim(e.dir.path(), "sim", {}, 100);
    ASSERT_FALSE(sim.path().empty());
    const auto doc = e.dir / "lesson.txt";
    {
        std::ofstream out(doc);
        for (int i = 0; i < 12; ++i) out << test::kText << '\n';
    }
    setenv("TACTUS_SPOOL_DB", e.db.c_str(), 1);
    setenv("XDG_CONFIG_HOME", (e.dir / "config").c_str(), 1);
    setenv("QT_QPA_PLATFORM", "offscreen", 1);
    Process app({kApp, "--no-recovery", "--device", sim.device(), "--emboss", doc.string()},
                (e.dir / "app.log").string());
    const JobId id = 1;
    ASSERT_TRUE(e.wait_for([&](const JobRecord& j) { return j.state == JobState::running; }, id))
        << read_text((e.dir / "app.log").string());
    ASSERT_TRUE(e.wait_for([&](const JobRecord&) { return passes_recorded(e.spool(), id) > 0; }, id));
    const auto job = e.spool().job(id);
    ASSERT_TRUE(job);
    EXPECT_EQ(job->printer, "pts-" + sim.path().substr(sim.path().rfind('/') + 1));
    EXPECT_EQ(job->title, "lesson.txt");
    ASSERT_GE(job->total_sheets(), 2u);

    // Quit (SIGTERM, as at logout): the app's runner aborts and lets go.
    app.signal(SIGTERM);
    EXPECT_EQ(app.wait(), 0) << read_text((e.dir / "app.log").string());
    const auto left = e.spool().job(id);
    EXPECT_EQ(left->state, JobState::queued) << e.history(id);
    EXPECT_TRUE(left->runner.empty());
    // It was stopped mid-stream, not finished: serve has work left.
    EXPECT_NE(e.history(id).find("the print server stopped"), std::string::npos) << e.history(id);
    EXPECT_TRUE(e.spool().printer(left->printer)->runner.empty());

    auto serve = e.serve();
    ASSERT_TRUE(e.wait_state(id, JobState::completed, std::chrono::seconds(180))) << e.history(id);
    serve->signal(SIGTERM);
    EXPECT_EQ(serve->wait(), 0);
    const auto audit = e.audit(id, sim);
    EXPECT_EQ(audit.problems, "") << e.history(id);
    EXPECT_EQ(audit.sheets_checked, job->total_sheets());
    std::cout << "sheets " << audit.sheets_checked << ", partial sheets discarded " << audit.partial_attempts << '\n';
    // `queue list` shows the app's job like any other.
    const auto [code, listed] = e.cli({"queue", "list", "--all"});
    EXPECT_EQ(code, 0);
    EXPECT_NE(listed.find("lesson.txt"), std::string::npos) << listed;
}

}  // namespace
}  // namespace tactus::spool
