// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "motion/shaper.hpp"

using namespace tactus::motion;
using tactus::profile::ShaperKind;

namespace {
// Residual vibration of a damped mode after the impulse train, relative to one
// unit impulse: |sum A_i exp((zeta w + j w_d) t_i)| (the standard shaper measure).
double vibration_ratio(const Shaper& s, double f_hz, double zeta) {
    const double w = 2 * std::acos(-1.0) * f_hz, wd = w * std::sqrt(1 - zeta * zeta);
    std::complex<double> sum = 0;
    for (const auto& i : s.impulses)
        sum += i.a * std::exp(std::complex<double>(zeta * w * i.t, wd * i.t));
    return std::abs(sum) * std::exp(-zeta * w * s.duration());
}
}  // namespace

TEST(Shaper, AmplitudesSumToOneAndCancelTheDesignFrequency) {
    for (double zeta : {0.0, 0.1, 0.5, 0.8}) {
        for (auto k : {ShaperKind::zv, ShaperKind::mzv, ShaperKind::zvd, ShaperKind::ei}) {
            const auto s = design_shaper(k, 90.0, zeta);
            SCOPED_TRACE(std::string(tactus::profile::to_string(k)) + " zeta " + std::to_string(zeta));
            double sum = 0;
            for (const auto& i : s.impulses) {
                sum += i.a;
                EXPECT_GT(i.a, 0);
            }
            EXPECT_NEAR(sum, 1.0, 1e-12);
            if (k == ShaperKind::ei) {
                // EI trades exact cancellation for width: it leaves its design tolerance.
                if (zeta == 0.0) {
                    EXPECT_NEAR(vibration_ratio(s, 90.0, zeta), kEiVibrationTolerance, 1e-12);
                }
            } else {
                EXPECT_NEAR(vibration_ratio(s, 90.0, zeta), 0.0, 1e-12);
            }
            // Away from the design frequency it does not cancel.
            EXPECT_GT(vibration_ratio(s, 45.0, zeta) * std::exp(2 * std::acos(-1.0) * 45 * zeta * s.duration()), 0.01);
        }
    }
}

TEST(Shaper, PublishedTimesAndAmplitudes) {
    // Undamped ZV at 50 Hz: two equal impulses half a period apart.
    const auto zv = design_shaper(ShaperKind::zv, 50.0, 0.0);
    ASSERT_EQ(zv.impulses.size(), 2u);
    EXPECT_NEAR(zv.impulses[1].t, 0.01, 1e-15);
    EXPECT_NEAR(zv.impulses[0].a, 0.5, 1e-15);
    // Undamped ZVD: 1/4, 1/2, 1/4 over one period.
    const auto zvd = design_shaper(ShaperKind::zvd, 50.0, 0.0);
    EXPECT_NEAR(zvd.impulses[1].a, 0.5, 1e-15);
    EXPECT_NEAR(zvd.duration(), 0.02, 1e-15);
    // MZV: 3/4 of a period.
    EXPECT_NEAR(design_shaper(ShaperKind::mzv, 50.0, 0.0).duration(), 0.015, 1e-15);
}

TEST(Shaper, ShapedMoveIsTheSumOfShiftedCopies) {
    const Limits lim{250, 20000, 4e6};
    const auto base = jerk_move(6.0, lim);
    const auto s = design_shaper(ShaperKind::zvd, 80.0, 0.1);
    const auto m = shape_move(base, s);
    EXPECT_NEAR(m.duration, base.duration + s.duration(), 1e-15);
    for (int i = 0; i <= 200; ++i) {
        const double t = m.duration * i / 200.0;
        double want = 0, want_v = 0;
        for (const auto& imp : s.impulses) {
            want += imp.a * base.position(t - imp.t);
            want_v += imp.a * base.at(t - imp.t)[1];
        }
        EXPECT_NEAR(m.position(t), want, 1e-9);
        EXPECT_NEAR(m.at(t)[1], want_v, 1e-6);
        EXPECT_LE(std::fabs(m.at(t)[1]), lim.v * (1 + 1e-9));
    }
    EXPECT_NEAR(m.position(m.duration), 6.0, 1e-12);
}
