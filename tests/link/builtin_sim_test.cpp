// SPDX-License-Identifier: GPL-3.0-or-later
// The app's built-in simulator (controller::BuiltInSimulator) through the link:
// one controller for many connections, so its job count survives a dropped
// connection as on the real machine; every logged strike names the controller
// job it belongs to; and the technician's faults reach the line and the
// controller while a job streams from another thread.
#include <gtest/gtest.h>

#include <thread>

#include "../common/test_plans.hpp"
#include "controller/builtin_sim.hpp"
#include "link/link.hpp"

namespace tactus {
namespace {

struct Sent {
    link::JobOutcome outcome;
    std::vector<std::string> notes;
};

Sent send(link::Link& l, const plan::JobPlan& plan, std::uint16_t job_id,
          const std::function<void(std::size_t)>& on_pass = {}) {
    Sent out;
    link::CancelToken cancel;
    std::size_t passes = 0;
    auto r = l.send_job(plan, 1, [&](const link::Progress& p) {
        if (p.executed && on_pass) on_pass(++passes);
        if (!p.note.empty()) out.notes.push_back(p.note);
    }, cancel, job_id);
    EXPECT_TRUE(r) << r.error().to_string();
    if (r) out.outcome = *r;
    return out;
}

// As `sim?speed=max` connects (the plan's own speed is the printer panel's test).
link::Link connect(controller::BuiltInSimulator& sim) {
    transport::SimSettings fastest;
    fastest.speed = 0;
    auto l = link::Link::over(sim.connect(fastest));
    EXPECT_TRUE(l.hello());
    EXPECT_TRUE(l.configure({}));
    return l;
}

bool noted(const Sent& s, const std::string& what) {
    for (const auto& n : s.notes)
        if (n.find(what) != std::string::npos) return true;
    return false;
}

TEST(BuiltInSimulator, TheControllerOutlivesAConnectionAndEveryStrikeNamesItsJob) {
    controller::BuiltInSimulator sim;
    const auto plan = test::make_plan(2, 3, 4);
    {
        auto first = connect(sim);
        EXPECT_EQ(send(first, plan, 0x8001).outcome.end, link::JobEnd::completed);
    }
    const auto planned = controller::planned_strikes(plan);
    auto strikes = sim.strikes();
    ASSERT_EQ(strikes.size(), planned.size());
    for (const auto& s : strikes) EXPECT_EQ(s.job_id, 0x8001);
    EXPECT_EQ(strikes, planned);
    // A new connection meets the same controller: it still reports the last job.
    auto second = connect(sim);
    auto st = second.status();
    ASSERT_TRUE(st);
    EXPECT_EQ(st->ack.job_id, 0x8001);
    EXPECT_EQ(send(second, plan, 0x8002).outcome.end, link::JobEnd::completed);
    strikes = sim.strikes();
    ASSERT_EQ(strikes.size(), 2 * planned.size());
    for (std::size_t i = planned.size(); i < strikes.size(); ++i) EXPECT_EQ(strikes[i].job_id, 0x8002);
}

// Each fault is injected from another thread while the job streams, as the
// printer panel's buttons do while the app's runner embosses (joined before
// the stream goes on, so where it lands is the same on every run).
TEST(BuiltInSimulator, FaultsFromAnotherThreadReachTheRunningJob) {
    controller::BuiltInSimulator sim;
    const auto plan = test::make_plan(6, 4, 6);
    struct Case {
        const char* name;
        std::function<void()> inject;
        const char* note;  // what the link says about it (empty: only its statistics)
    };
    const std::vector<Case> cases{
        {"paper out", [&] { sim.paper_out(); }, "paper out"},
        {"controller reset", [&] { sim.reset_controller(); }, "controller restarted"},
        {"pulled cable", [&] { sim.pull_cable(5); }, "reconnected"},
        {"noise", [&] { sim.noise(60, 0.02); }, ""},
    };
    std::uint16_t id = 0x8100;
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        auto l = connect(sim);
        const auto before = sim.strikes().size();
        bool injected = false;
        const auto sent = send(l, plan, ++id, [&](std::size_t passes) {
            if (passes != 3 || injected) return;
            // From another thread, finished before the stream goes on: the
            // fault lands at the line's next moment, wherever the job is then.
            std::thread technician(c.inject);
            technician.join();
            injected = true;
        });
        EXPECT_TRUE(injected);
        EXPECT_EQ(sent.outcome.end, link::JobEnd::completed) << sent.outcome.error.to_string();
        if (*c.note) EXPECT_TRUE(noted(sent, c.note));
        else EXPECT_GT(sent.outcome.stats.frames_resent + sent.outcome.stats.crc_errors + sent.outcome.stats.naks, 0u);
        // Ridden through: every planned dot struck once, under this job's id.
        const auto all = sim.strikes();
        std::vector<controller::LoggedStrike> got(all.begin() + static_cast<std::ptrdiff_t>(before), all.end());
        for (const auto& s : got) EXPECT_EQ(s.job_id, id);
        EXPECT_EQ(got, controller::planned_strikes(plan));
    }
}

}  // namespace
}  // namespace tactus
