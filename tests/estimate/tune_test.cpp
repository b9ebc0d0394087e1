// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "estimate/tune.hpp"

using namespace tactus;
using namespace tactus::estimate;

TEST(Tune, DefaultMachinePicksTheFastestMoveWithinTolerance) {
    const auto p = profile::default_profile();
    MoveTuner tuner(p);
    auto t = tuner.carriage(200);  // 2.5 mm
    ASSERT_TRUE(t.has_value());
    const auto& c = (*t)->choice;
    EXPECT_LE(c.worst_residual_um, 50.0);
    EXPECT_LE(c.residual_um, c.worst_residual_um);
    EXPECT_NEAR((*t)->shape.distance, 2.5, 1e-12);
    // The time-optimal move itself rings beyond tolerance somewhere in the
    // band (the heavily damped corner is still creeping onto the dot)...
    const motion::Limits lim{250, 20000, 4e6};
    EXPECT_GT(tuner.worst_residual_um(motion::jerk_move(2.5, lim)), 50.0);
    EXPECT_GE(c.duration_s, motion::jerk_min_time(2.5, lim));
    // ...and the choice is no slower than any single alternative that passes.
    for (auto k : {profile::ShaperKind::zv, profile::ShaperKind::zvd, profile::ShaperKind::ei}) {
        const auto alt = motion::shape_move(motion::jerk_move(2.5, lim), tuner.design_shaper(k));
        if (tuner.worst_residual_um(alt) <= 50.0) {
            EXPECT_LE(c.duration_s, alt.duration + 1e-12);
        }
    }
    EXPECT_NE(c.why.find("faster rejected"), std::string::npos);
    // Cached: the same object comes back.
    EXPECT_EQ(*tuner.carriage(200), *t);
}

TEST(Tune, LightlyDampedMachineGetsShapedOrSlowerMoves) {
    auto p = profile::default_profile();
    p.dynamics.damping_ratio = 0.05;
    p.vibration.tolerance_um = 20;
    MoveTuner tuner(p);
    for (std::uint32_t steps : {200u, 280u, 480u, 2000u}) {
        auto t = tuner.carriage(steps);
        ASSERT_TRUE(t.has_value()) << t.error().to_string();
        const auto& c = (*t)->choice;
        EXPECT_LE(c.worst_residual_um, 20.0);
        // The unshaped time-optimal move rings beyond tolerance on this machine...
        const auto plain = motion::jerk_move(steps / 80.0, {250, 20000, 4e6});
        EXPECT_GT(tuner.worst_residual_um(plain), 20.0);
        // ...so the choice is something else, and says why.
        EXPECT_TRUE(c.shaper != profile::ShaperKind::none || c.speed_scale < 1.0 ||
                    c.shape != profile::ProfileShape::jerk);
        EXPECT_NE(c.why.find("faster rejected"), std::string::npos) << c.why;
    }
}

TEST(Tune, FixedProfileIsReportedNotTuned) {
    auto p = profile::default_profile();
    p.dynamics.damping_ratio = 0.02;
    p.motion.shape = profile::ProfileShape::trapezoid;
    p.motion.shaper = profile::ShaperKind::none;
    MoveTuner tuner(p);
    auto t = tuner.carriage(280);
    ASSERT_TRUE(t.has_value());
    EXPECT_EQ((*t)->choice.shape, profile::ProfileShape::trapezoid);
    EXPECT_FALSE((*t)->choice.within_tolerance);
    EXPECT_NE((*t)->choice.why.find("fixed by the profile"), std::string::npos);
}
