// SPDX-License-Identifier: GPL-3.0-or-later
// The built-in simulator (device `sim`) runs a job in the time the machine
// would take, so a technician can reach Pause while a sheet is embossed
// (unpaced it would run about 100 times faster than the plan);
// `sim?speed=N` runs it at most N times faster and `sim?speed=max` as fast as
// the computer can. The checks are lower bounds the pacing guarantees (the
// wall clock never falls behind simulated time / speed), not timings.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "link/link.hpp"
#include "machine/controller_config.hpp"
#include "transport/byte_stream.hpp"
#include "../common/test_plans.hpp"

namespace tactus::link {
namespace {

struct Run {
    double wall_s = 0;     // from opening the device to the job's end
    double sim_s = 0;      // the simulator's clock then
    JobEnd end = JobEnd::failed;
};

Run emboss(const std::string& device, const plan::JobPlan& plan) {
    Run r;
    const auto start = std::chrono::steady_clock::now();
    auto link = Link::open(device);
    EXPECT_TRUE(link) << link.error().to_string();
    if (!link) return r;
    EXPECT_TRUE(link->hello());
    EXPECT_TRUE(link->configure(machine::ControllerConfig{}));
    CancelToken cancel;
    auto out = link->send_job(plan, 1, [](const Progress&) {}, cancel);
    EXPECT_TRUE(out) << out.error().to_string();
    if (out) r.end = out->end;
    r.sim_s = link->stream().now();
    r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

TEST(SimSpeed, TheBuiltInSimulatorTakesThePlansOwnTimeByDefault) {
    const auto plan = test::make_plan(1, 3, 6);
    const auto r = emboss("sim", plan);
    ASSERT_EQ(r.end, JobEnd::completed);
    // The controller spent at least the plan's time on it, and so did the wall clock.
    EXPECT_GE(r.sim_s, plan.duration_s);
    EXPECT_GE(r.wall_s, r.sim_s) << "the simulator ran ahead of real time";
    EXPECT_GE(r.wall_s, plan.duration_s);
}

TEST(SimSpeed, ASpeedOptionRunsItFasterByAtMostThatFactor) {
    const auto plan = test::make_plan(1, 3, 6);
    const auto r = emboss("sim?speed=4", plan);
    ASSERT_EQ(r.end, JobEnd::completed);
    EXPECT_GE(r.wall_s, r.sim_s / 4);
    // As fast as possible: the same job, the same simulated time.
    const auto fast = emboss("sim?speed=max", plan);
    ASSERT_EQ(fast.end, JobEnd::completed);
    EXPECT_GE(fast.sim_s, plan.duration_s);
}

TEST(SimSpeed, ASpeedThatIsNotAboveZeroIsAUsageError) {
    for (const std::string dev : {"sim?speed=0", "sim?speed=-2", "sim?speed=fast"}) {
        SCOPED_TRACE(dev);
        auto link = Link::open(dev);
        ASSERT_FALSE(link);
        EXPECT_EQ(link.error().kind, ErrorKind::usage);
        EXPECT_EQ(link.error().where, "sim option speed");
    }
}

}  // namespace
}  // namespace tactus::link
