// SPDX-License-Identifier: GPL-3.0-or-later
// The head model run on the controller's step train itself: step timing
// tolerance must not cost accuracy at the strike.
#include <gtest/gtest.h>

#include "estimate/dynamics.hpp"
#include "estimate/simulate.hpp"
#include "estimate/step_train.hpp"
#include "estimate/tune.hpp"
#include "motion/steps.hpp"
#include "profile/profile_json.hpp"

using namespace tactus;

TEST(StepTrain, FollowsTheFiredSteps) {
    const std::vector<motion::StepSegment> segs{{400U << 16, 4, 0}};  // a step every 400 ticks
    const auto s = estimate::step_train_shape(segs, 80.0, 0.01);
    EXPECT_DOUBLE_EQ(s.distance, 4 / 80.0);
    EXPECT_DOUBLE_EQ(s.duration, 0.01);
    for (int k = 1; k <= 4; ++k)
        EXPECT_NEAR(s.position(400.0 * k / machine::kTickHz), (k - 0.5) / 80.0, 1e-12) << k;
    EXPECT_NEAR(s.position(0.0099), 4 / 80.0, 1e-12);
    EXPECT_NEAR(s.at(0.0099)[1], 0.0, 1e-12);  // at rest on the target
}

TEST(StepTrain, ToleranceDoesNotMoveTheHeadAtTheStrike) {
    // Default machine: the residual while the hammer is down, simulated on the
    // step trains at one-tick timing and at half-interval timing, for the move
    // lengths a page uses most (dot, cell and cell-plus-dot pitches).
    const auto p = profile::default_profile();
    estimate::MoveTuner tuner(p);
    estimate::MoveSimulator sim(estimate::build_model(p.dynamics));
    for (const std::uint32_t steps : {200U, 280U, 480U, 960U, 2400U}) {
        const auto tuned = tuner.carriage(steps);
        ASSERT_TRUE(tuned);
        const auto& shape = (*tuned)->shape;
        const auto residual = [&](double fraction) {
            const auto m = motion::encode_move(shape, static_cast<std::int32_t>(steps), p.carriage.steps_per_mm, fraction);
            EXPECT_TRUE(m.has_value());
            return sim.residual_mm(estimate::step_train_shape(m->segments, p.carriage.steps_per_mm, shape.duration),
                                   p.head.dwell_s) * 1000.0;
        };
        const double exact = residual(0.0), loose = residual(0.5);
        const double ideal = sim.residual_mm(shape, p.head.dwell_s) * 1000.0;
        EXPECT_NEAR(loose, exact, 0.05) << steps << " steps";
        // The step train itself stays close to the ideal move and far inside tolerance.
        EXPECT_NEAR(exact, ideal, 0.5) << steps << " steps";
        EXPECT_LT(loose, p.vibration.tolerance_um / 10);
    }
}
