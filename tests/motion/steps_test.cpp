// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "motion/shaper.hpp"
#include "motion/steps.hpp"

using namespace tactus;
using namespace tactus::motion;

TEST(Steps, NoDriftOverThousandsOfMoves) {
    // 10 000 moves of 1.2345 mm (98.76 steps each): rounding each move would lose
    // 0.24 steps per move, 2400 steps (30 mm) over the run. Planning between
    // absolute positions keeps every stop within half a step of its target.
    const StepAxis axis(80.0);
    std::int64_t motor = 0, naive = 0;
    double target = 0;
    for (int i = 0; i < 10000; ++i) {
        const double next = target + (i % 3 == 2 ? -1.2345 : 1.2345);
        const std::int32_t steps = axis.steps_for(next) - axis.steps_for(target);
        motor += steps;
        naive += std::lround((next - target) * 80.0);
        target = next;
        ASSERT_LE(std::fabs(static_cast<double>(motor) - target * 80.0), 0.5);
    }
    EXPECT_EQ(motor, axis.steps_for(target));
    EXPECT_NE(naive, motor);  // the per-move rounding it replaces does drift
}

TEST(Steps, TimingAMoveLongerThan2To19SecondsEnds) {
    // v_max 1e-5 mm/s: 10 mm take 10^6 s; with a and j tiny as well the move
    // lasts far past 2^19 s, where halving an interval stops changing it.
    const Limits lim{1e-5, 1e-9, 1e-13};
    const auto m = make_move(tactus::profile::ProfileShape::scurve, 10.0, lim);
    ASSERT_GT(m.duration, 524288.0);
    const auto t = step_times_ticks(m, 800, 80.0);
    ASSERT_EQ(t.size(), 800U);
    for (std::size_t i = 1; i < t.size(); ++i) ASSERT_GE(t[i], t[i - 1]);
}

TEST(Steps, EncodedScheduleWithinOneTick) {
    const Limits lim{250, 20000, 4e6};
    const double spm = 80.0;
    std::size_t steps_total = 0, segments_total = 0;
    for (double d : {0.0125, 0.5, 2.5, 3.5, 6.0, 14.0, 60.0, 180.0}) {
        for (auto shape : {tactus::profile::ProfileShape::trapezoid, tactus::profile::ProfileShape::scurve,
                           tactus::profile::ProfileShape::jerk}) {
            for (auto k : {tactus::profile::ShaperKind::none, tactus::profile::ShaperKind::ei}) {
                const auto n = static_cast<std::int32_t>(std::lround(d * spm));
                const auto m = shape_move(make_move(shape, n / spm, lim), design_shaper(k, 90, 0.3));
                const auto ideal = step_times_ticks(m, static_cast<std::uint32_t>(n), spm);
                auto seg = compress_steps(ideal);
                ASSERT_TRUE(seg.has_value()) << seg.error().to_string();
                const auto got = expand_steps(*seg);
                ASSERT_EQ(got.size(), ideal.size());
                for (std::size_t i = 0; i < got.size(); ++i)
                    ASSERT_LE(std::fabs(static_cast<double>(got[i]) - ideal[i]), 1.0) << "step " << i;
                // The planned profile is reproduced in time too: the last step fires
                // before the move ends and within a step period of it.
                EXPECT_LE(static_cast<double>(got.back()), m.duration * machine::kTickHz + 1);
                steps_total += got.size();
                segments_total += seg->size();
                auto enc = encode_move(m, -n, spm);
                ASSERT_TRUE(enc.has_value());
                EXPECT_EQ(enc->steps, -n);
                EXPECT_EQ(enc->segments, *seg);
            }
        }
    }
    // Compression is what makes the schedule fit the link: with Q16.16 intervals
    // a segment covers dozens of steps on average (whole-tick intervals gave ~5).
    EXPECT_GT(static_cast<double>(steps_total) / static_cast<double>(segments_total), 20.0);
}

TEST(Steps, KnownConstantRateCompressesToOneSegment) {
    // Steps every 100 ticks exactly: one segment, add 0.
    std::vector<double> t;
    for (int i = 1; i <= 500; ++i) t.push_back(100.0 * i);
    auto seg = compress_steps(t);
    ASSERT_TRUE(seg.has_value());
    ASSERT_EQ(seg->size(), 1u);
    EXPECT_EQ((*seg)[0], (StepSegment{100u << 16, 500, 0}));
    // A constant change of interval (+3 ticks per step) is also one segment.
    t.clear();
    double now = 0;
    for (int i = 0; i < 200; ++i) t.push_back(now += 50 + 3 * i);
    seg = compress_steps(t);
    ASSERT_TRUE(seg.has_value());
    ASSERT_EQ(seg->size(), 1u);
    EXPECT_EQ(expand_steps(*seg).back(), static_cast<std::int64_t>(t.back()));
    // A fractional rate (38.4 ticks per step) is one segment too: whole-tick
    // intervals would need a new segment every few steps.
    t.clear();
    for (int i = 1; i <= 1000; ++i) t.push_back(38.4 * i);
    seg = compress_steps(t);
    ASSERT_TRUE(seg.has_value());
    EXPECT_EQ(seg->size(), 1u);
    const auto fired = expand_steps(*seg);
    for (std::size_t i = 0; i < t.size(); ++i) ASSERT_LE(std::fabs(static_cast<double>(fired[i]) - t[i]), 1.0);
}

// The controller's arithmetic, worked by hand: interval 2.5 ticks, add 0.25.
TEST(Steps, ExpandIsTheControllersFixedPointArithmetic) {
    const std::vector<StepSegment> segs{{(5u << 16) / 2, 4, 1 << 14}, {3u << 16, 2, 0}};
    // Intervals 2.5, 2.75, 3.0, 3.25: cumulative 2.5, 5.25, 8.25, 11.5 -> 2, 5, 8, 11;
    // the next segment starts from tick 11 with a fresh fraction: 14, 17.
    EXPECT_EQ(expand_steps(segs), (std::vector<std::int64_t>{2, 5, 8, 11, 14, 17}));
}

TEST(Steps, IntervalBeyondTheTimerIsAnError) {
    std::vector<double> t{100.0, 70000.0 + 100.0};
    auto seg = compress_steps(t);
    ASSERT_FALSE(seg.has_value());
    EXPECT_NE(seg.error().message.find("16-bit"), std::string::npos);
}

TEST(Steps, FractionalToleranceHoldsEveryStepWithinItsShareOfAnInterval) {
    const Limits lim{250, 20000, 4e6};
    const double spm = 80.0;
    std::size_t tight = 0, loose = 0;
    for (double d : {0.0125, 0.5, 2.5, 6.0, 14.0, 60.0, 180.0}) {
        for (auto shape : {tactus::profile::ProfileShape::trapezoid, tactus::profile::ProfileShape::scurve,
                           tactus::profile::ProfileShape::jerk}) {
            const auto n = static_cast<std::int32_t>(std::lround(d * spm));
            const auto m = make_move(shape, n / spm, lim);
            const auto ideal = step_times_ticks(m, static_cast<std::uint32_t>(n), spm);
            const auto tol = step_tolerances(ideal, 0.5);
            for (std::size_t i = 0; i < ideal.size(); ++i) {
                // Half the shorter neighbouring interval, never under a tick.
                double iv = i + 1 < ideal.size() ? ideal[i + 1] - ideal[i] : 0;
                iv = std::min(iv, i == 0 ? ideal[0] : ideal[i] - ideal[i - 1]);
                const double expected = i + 1 == ideal.size() ? 1.0 : std::max(1.0, 0.5 * iv);
                ASSERT_DOUBLE_EQ(tol[i], expected) << "step " << i;
            }
            auto enc = encode_move(m, n, spm, 0.5);
            ASSERT_TRUE(enc.has_value()) << enc.error().to_string();
            const auto got = expand_steps(enc->segments);
            ASSERT_EQ(got.size(), ideal.size());
            for (std::size_t i = 0; i < got.size(); ++i)
                ASSERT_LE(std::fabs(static_cast<double>(got[i]) - ideal[i]), tol[i]) << "step " << i;
            // The move still ends on time: the last step within a tick, the rest
            // until the planned end waited out before the strike.
            EXPECT_LE(std::fabs(static_cast<double>(got.back()) - ideal.back()), 1.0);
            EXPECT_EQ(static_cast<std::int64_t>(enc->settle_ticks) + got.back(), std::llround(m.duration * machine::kTickHz));
            loose += enc->segments.size();
            tight += encode_move(m, n, spm, 0.0)->segments.size();
        }
    }
    // What the tolerance buys: well under half the segments of one-tick timing.
    EXPECT_LT(loose * 2, tight) << loose << " vs " << tight;
}

TEST(Steps, OneToleranceForEveryStepOrNone) {
    const std::vector<double> t{100, 200, 300};
    const std::vector<double> two{1, 1};
    EXPECT_FALSE(compress_steps(t, two));
}
