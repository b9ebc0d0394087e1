// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>

#include "estimate/simulate.hpp"
#include "estimate/vibration.hpp"
#include "motion/shaper.hpp"

using namespace tactus;
using namespace tactus::estimate;

namespace {
const double kPi = std::acos(-1.0);

profile::Dynamics one_inertia(double m, double k, double zeta) {
    profile::Dynamics d;
    d.head_mass_kg = m;
    d.belt_stiffness_n_m = k;
    d.damping_ratio = zeta;
    d.rotor_inertia_kg_m2 = 0;
    return d;
}
}  // namespace

TEST(Dynamics, StepOvershootMatchesTheClosedForm) {
    for (double zeta : {0.1, 0.3, 0.5, 0.7, 0.8}) {
        const auto m = step_response(build_model(one_inertia(0.25, 90000, zeta)));
        const double want = 100 * std::exp(-zeta * kPi / std::sqrt(1 - zeta * zeta));
        EXPECT_NEAR(m.overshoot_pct, want, 1e-4 * want + 1e-6) << "zeta " << zeta;
        // Peak time pi / w_d.
        const double wn = std::sqrt(90000 / 0.25);
        EXPECT_NEAR(m.peak_time_s, kPi / (wn * std::sqrt(1 - zeta * zeta)), 2 * kPi / wn / 1000);
    }
}

TEST(Dynamics, SettlingAndRiseOfAKnownSecondOrderSystem) {
    // zeta = 1/sqrt(2): rise 10-90 % = 2.1487 / wn (tabulated for this zeta).
    const double wn = 600;
    const auto m = step_response(build_model(one_inertia(1.0, wn * wn, 1 / std::sqrt(2.0))));
    EXPECT_NEAR(m.rise_time_s * wn, 2.1487, 2e-3);
    ASSERT_TRUE(m.settling_time_s.has_value());
    // Its envelope 1 + e^-(zeta wn t)/sqrt(1-zeta^2) reaches 2 % near 4.4/(zeta wn);
    // the actual last exit lies below the envelope's.
    EXPECT_LT(*m.settling_time_s, std::log(0.02 * std::sqrt(0.5)) / (-wn / std::sqrt(2.0)));
    EXPECT_GT(*m.settling_time_s, 2.0 / wn);
}

TEST(Dynamics, UndampedNeverSettles) {
    const auto m = step_response(build_model(one_inertia(0.25, 90000, 0.0)));
    EXPECT_NEAR(m.overshoot_pct, 100.0, 1e-3);
    EXPECT_FALSE(m.settling_time_s.has_value());
}

TEST(Dynamics, DefaultMachineMeetsTheSourcesTargets) {
    const auto r = vibration_report(profile::default_profile());
    EXPECT_TRUE(r.two_inertia);
    EXPECT_LT(r.step.overshoot_pct, 2.0);
    EXPECT_LT(r.step.rise_time_s, 0.005);
    ASSERT_TRUE(r.step.settling_time_s.has_value());
    EXPECT_LT(*r.step.settling_time_s, 0.010);
    EXPECT_TRUE(r.all_ok());
    EXPECT_GT(r.sqrt_k_over_m, 170.0);
    EXPECT_DOUBLE_EQ(r.sqrt_k_over_m, std::sqrt(90000 / 0.25));
    ASSERT_EQ(r.natural_hz.size(), 2u);
    // The belt mode of a rotor held by a stiff motor: below sqrt(k/m) of the belt alone.
    EXPECT_LT(r.natural_hz[0], r.sqrt_k_over_m / (2 * kPi));
    // A soft belt misses them, and the report says so.
    auto p = profile::default_profile();
    p.dynamics.belt_stiffness_n_m = 20000;
    EXPECT_FALSE(vibration_report(p).all_ok());
}

TEST(Dynamics, TwoInertiaFrequenciesFromTheEigenproblem) {
    auto d = profile::default_profile().dynamics;
    const double r2 = d.pulley_radius_m * d.pulley_radius_m;
    const double m1 = d.rotor_inertia_kg_m2 / r2, m2 = d.head_mass_kg;
    const double k1 = d.motor_stiffness_nm_rad / r2, k2 = d.belt_stiffness_n_m;
    // det(K - w^2 M) = 0 for the chain ground-k1-m1-k2-m2.
    const double a = m1 * m2, b = -(m1 * k2 + m2 * (k1 + k2)), c = k1 * k2;
    const double w_lo = std::sqrt((-b - std::sqrt(b * b - 4 * a * c)) / (2 * a));
    const double w_hi = std::sqrt((-b + std::sqrt(b * b - 4 * a * c)) / (2 * a));
    const auto f = natural_frequencies_hz(d);
    EXPECT_NEAR(f[0], w_lo / (2 * kPi), 1e-9 * f[0]);
    EXPECT_NEAR(f[1], w_hi / (2 * kPi), 1e-9 * f[1]);
}

TEST(Dynamics, FrequencyResponseOfOneMode) {
    const double zeta = 0.3, wn = 600;
    const auto model = build_model(one_inertia(1.0, wn * wn, zeta));
    const double fn = wn / (2 * kPi);
    const auto r = frequency_response(model, fn / 100, fn, 3);  // fn/100, fn/10, fn
    EXPECT_NEAR(r[0].magnitude, 1.0, 1e-3);
    EXPECT_NEAR(r[0].phase_deg, 0.0, 0.5);
    EXPECT_NEAR(r[2].magnitude, 1 / (2 * zeta), 1e-9);  // resonance peak at wn
    EXPECT_NEAR(r[2].phase_deg, -90.0, 1e-9);
    EXPECT_NEAR(r[2].magnitude_db, 20 * std::log10(1 / (2 * zeta)), 1e-9);
    // Two modes with modal damping: four poles and one zero, so far above both
    // modes the phase tends to -270 degrees (unwrapped) and the gain falls.
    const auto two = frequency_response(build_model(profile::default_profile().dynamics), 1, 1e5, 60);
    EXPECT_NEAR(two.front().magnitude, 1.0, 1e-3);
    EXPECT_NEAR(two.back().phase_deg, -270, 5);
    EXPECT_LT(two.back().magnitude, 1e-3);
}

TEST(Dynamics, ResidualAfterTrapezoidOnUndampedMode) {
    // (4a/w^2) |sin(w Ta / 2)| |sin(w (Ta + Tc) / 2)|, for several move lengths.
    const double wn = 600;
    MoveSimulator sim(build_model(one_inertia(1.0, wn * wn, 0.0)));
    const motion::Limits lim{250, 20000, 1e12};
    for (double d : {0.5, 2.5, 3.5, 6.0, 20.0}) {
        const auto move = motion::trapezoid_move(d, lim);
        const double ta = move.pieces[0].dt;
        const double tc = move.pieces.size() == 3 ? move.pieces[1].dt : 0.0;
        const double want = 4 * lim.a / (wn * wn) * std::fabs(std::sin(wn * ta / 2)) *
                            std::fabs(std::sin(wn * (ta + tc) / 2));
        // Sampled over one full period, the largest error is the amplitude.
        const double got = sim.residual_mm(move, 2 * kPi / wn, 2048);
        EXPECT_NEAR(got, want, 1e-5 * 4 * lim.a / (wn * wn)) << d << " mm";
    }
}

TEST(Dynamics, ShapedMovesLeaveNoResidualAtTheDesignFrequency) {
    const double wn = 600, fn = wn / (2 * kPi);
    MoveSimulator sim(build_model(one_inertia(1.0, wn * wn, 0.0)));
    const motion::Limits lim{250, 20000, 4e6};
    const auto base = motion::jerk_move(3.5, lim);
    const double unshaped = sim.residual_mm(base, 2 * kPi / wn, 256);
    EXPECT_GT(unshaped, 0.01);
    for (auto k : {profile::ShaperKind::zv, profile::ShaperKind::mzv, profile::ShaperKind::zvd}) {
        const auto shaped = motion::shape_move(base, motion::design_shaper(k, fn, 0.0));
        EXPECT_LT(sim.residual_mm(shaped, 2 * kPi / wn, 256), 1e-9) << profile::to_string(k);
    }
    const auto ei = motion::shape_move(base, motion::design_shaper(profile::ShaperKind::ei, fn, 0.0));
    EXPECT_NEAR(sim.residual_mm(ei, 2 * kPi / wn, 2048), motion::kEiVibrationTolerance * unshaped,
                1e-4 * unshaped);
}

TEST(Dynamics, HeadLagsByTheClosedFormWhileCruising) {
    // One mode damped to ground: at constant velocity v the head trails the
    // command by 2 zeta v / wn; it then arrives on the target.
    const double wn = 600, zeta = 0.5, v = 100;
    MoveSimulator sim(build_model(one_inertia(1.0, wn * wn, zeta)));
    const auto move = motion::trapezoid_move(60.0, {v, 20000, 1e12});  // 0.58 s of cruise
    const std::vector<double> t{0.3, move.duration + 0.1};
    const auto y = sim.head_positions(move, t);
    EXPECT_NEAR(move.position(t[0]) - y[0], 2 * zeta * v / wn, 1e-9);
    EXPECT_NEAR(y[1], 60.0, 1e-9);
}
