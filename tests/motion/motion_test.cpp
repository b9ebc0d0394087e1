// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>

#include "motion/motion.hpp"

using namespace tactus::motion;

namespace {
// Position at the end of the last piece, integrated from the pieces themselves
// (not the stored distance), and the largest |v|, |a|, |jerk| sampled densely.
struct Peaks {
    double end = 0, v = 0, a = 0, j = 0;
};
Peaks peaks(const MoveShape& m) {
    Peaks p;
    const auto& last = m.pieces.back();
    p.end = advance_derivs(last.d, last.dt)[0];
    for (const auto& pc : m.pieces)
        for (int i = 0; i <= 64; ++i) {
            const auto d = advance_derivs(pc.d, pc.dt * i / 64.0);
            p.v = std::max(p.v, std::fabs(d[1]));
            p.a = std::max(p.a, std::fabs(d[2]));
            p.j = std::max(p.j, std::fabs(d[3]));
        }
    return p;
}
}  // namespace

TEST(Motion, SourcesNormalisedSCurveLastsSixAndTravelsFour) {
    const auto m = scurve_move(1.0, 1.0, 2.0);  // alpha_d = omega_d = 1, dt_a = 1, dt_c = 2
    EXPECT_DOUBLE_EQ(m.duration, 6.0);
    const auto p = peaks(m);
    EXPECT_NEAR(p.end, 4.0, 1e-12);
    EXPECT_NEAR(p.v, 1.0, 1e-12);   // omega_d
    EXPECT_NEAR(p.a, 1.0, 1e-12);   // alpha_d, at the end of the first interval
    EXPECT_NEAR(p.j, 1.5, 1e-3);    // the smoothstep's steepest slope
    EXPECT_NEAR(m.at(1.0)[2], 1.0, 1e-12);
    EXPECT_NEAR(m.at(0.5)[2], 0.5, 1e-12);  // smoothstep(0.5) = 0.5
    EXPECT_NEAR(m.at(3.0)[1], 1.0, 1e-12);  // cruising
    EXPECT_NEAR(m.at(3.0)[0], 2.0, 1e-12);  // 1 accelerating + 1 cruising
    EXPECT_NEAR(m.at(5.0)[2], -1.0, 1e-12);
}

TEST(Motion, JerkLimitedMinimumTimeClosedForms) {
    const Limits lim{100, 1000, 1e5};
    // Reaches v: T = d/v + v/a + a/j.
    EXPECT_NEAR(jerk_min_time(50, lim), 50.0 / 100 + 100.0 / 1000 + 1000 / 1e5, 1e-12);
    // Reaches a, not v: T = a/j + sqrt((a/j)^2 + 4d/a).
    EXPECT_NEAR(jerk_min_time(5, lim), 0.01 + std::sqrt(1e-4 + 4 * 5.0 / 1000), 1e-12);
    // Reaches neither: T = 4 (d / 2j)^(1/3).
    EXPECT_NEAR(jerk_min_time(0.01, lim), 4 * std::cbrt(0.01 / 2e5), 1e-12);
    // Velocity limit hit before full acceleration: T = d/v + 2 sqrt(v/j).
    const Limits low_v{5, 1000, 1e5};
    EXPECT_NEAR(jerk_min_time(10, low_v), 10.0 / 5 + 2 * std::sqrt(5 / 1e5), 1e-12);
    EXPECT_EQ(jerk_min_time(0, lim), 0.0);
}

TEST(Motion, EveryProfileArrivesAndRespectsItsLimits) {
    const Limits lim{250, 20000, 4e6};
    for (double d : {0.0125, 0.1, 1.0, 2.5, 3.5, 6.0, 12.0, 50.0, 185.0}) {
        for (auto shape : {tactus::profile::ProfileShape::trapezoid, tactus::profile::ProfileShape::scurve,
                           tactus::profile::ProfileShape::jerk}) {
            const auto m = make_move(shape, d, lim);
            const auto p = peaks(m);
            SCOPED_TRACE(std::to_string(d) + " mm " + tactus::profile::to_string(shape));
            EXPECT_NEAR(p.end, d, 1e-9 * d);
            EXPECT_NEAR(advance_derivs(m.pieces.back().d, m.pieces.back().dt)[1], 0, 1e-9);
            EXPECT_LE(p.v, lim.v * (1 + 1e-9));
            EXPECT_LE(p.a, lim.a * (1 + 1e-9));
            if (shape != tactus::profile::ProfileShape::trapezoid) {
                EXPECT_LE(p.j, lim.j * (1 + 1e-6));
            }
            // Monotone: time_at inverts position.
            for (double f : {0.1, 0.5, 0.9})
                EXPECT_NEAR(m.position(m.time_at(f * d)), f * d, 1e-9 * d);
        }
        // The 7-segment move is the time-optimal one; the S-curve honours the same
        // limits with a gentler jerk, so it cannot be faster.
        EXPECT_NEAR(jerk_move(d, lim).duration, jerk_min_time(d, lim), 1e-12);
        EXPECT_GE(scurve_move(d, lim).duration, jerk_min_time(d, lim));
        EXPECT_LE(trapezoid_move(d, lim).duration, jerk_min_time(d, lim));
    }
}

TEST(Motion, TrapezoidClosedForm) {
    const Limits lim{100, 1000, 1e9};
    const auto m = trapezoid_move(20, lim);  // ta = 0.1 s, 10 mm accelerating+braking, 0.1 s cruise
    EXPECT_NEAR(m.duration, 0.3, 1e-12);
    const auto tri = trapezoid_move(2.5, lim);  // triangle: ta = sqrt(d/a)
    EXPECT_NEAR(tri.duration, 2 * std::sqrt(2.5 / 1000), 1e-12);
}
