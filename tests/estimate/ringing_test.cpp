// SPDX-License-Identifier: GPL-3.0-or-later
// The ringing carried from strike to strike, against one exact simulation of
// the whole sequence of moves as a single command (MoveSimulator), which
// shares nothing with the carrying but the model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "estimate/dynamics.hpp"
#include "estimate/ringing.hpp"
#include "estimate/simulate.hpp"
#include "machine/limits.hpp"
#include "estimate/step_train.hpp"
#include "motion/motion.hpp"
#include "motion/steps.hpp"

using namespace tactus;
using namespace tactus::estimate;

namespace {

struct Step {
    motion::MoveShape move;
    int dir = 1;
    std::uint64_t rest_ticks = 0;
};

// The whole sequence as one command: each move from where the last ended, its
// rest, then the dwell; the strike instants (33 per dwell) and the command there.
struct Sequence {
    motion::MoveShape command;
    std::vector<double> times;
    std::vector<double> targets;
};

Sequence as_one_command(const std::vector<Step>& steps, double dwell) {
    Sequence s;
    double t = 0, at = 0;
    auto hold = [&](double dt) {
        if (dt <= 0) return;
        s.command.pieces.push_back({t, dt, motion::Derivs{at, 0, 0, 0, 0, 0}});
        t += dt;
    };
    for (const auto& st : steps) {
        for (const auto& p : st.move.pieces) {
            motion::Derivs d = p.d;
            for (auto& x : d) x *= st.dir;
            d[0] += at;
            s.command.pieces.push_back({t + p.t0, p.dt, d});
        }
        t += st.move.duration;
        at += st.dir * st.move.distance;
        hold(static_cast<double>(st.rest_ticks) / machine::kTickHz);
        for (int i = 0; i <= 32; ++i) {
            s.times.push_back(t + dwell * i / 32);
            s.targets.push_back(at);
        }
        hold(dwell);
    }
    s.command.duration = t;
    s.command.distance = at;  // held after the end
    return s;
}

std::vector<double> residuals_um(MoveSimulator& sim, const Sequence& s) {
    const auto y = sim.head_positions(s.command, s.times);
    std::vector<double> out;
    for (std::size_t k = 0; k < y.size(); k += 33) {
        double worst = 0;
        for (std::size_t i = k; i < k + 33; ++i) worst = std::max(worst, std::fabs(y[i] - s.targets[i]));
        out.push_back(worst * 1000.0);
    }
    return out;
}

// Short moves back and forth on a lightly damped machine: every strike still
// rings from the moves before it.
std::vector<Step> random_steps(std::mt19937& rng, int n) {
    std::uniform_int_distribution<int> len(1, 700);
    std::uniform_int_distribution<int> rest(0, 3000);
    std::bernoulli_distribution back(0.4);
    const motion::Limits lim{250, 20000, 4e6};
    std::vector<Step> out;
    for (int i = 0; i < n; ++i)
        out.push_back({motion::jerk_move(len(rng) / 80.0, lim), back(rng) ? -1 : 1,
                       static_cast<std::uint64_t>(rest(rng))});
    return out;
}

}  // namespace

TEST(Ringing, CarriedFromStrikeToStrikeEqualsOneSimulationOfTheWholeSequence) {
    auto p = profile::default_profile();
    p.dynamics.damping_ratio = 0.05;
    std::mt19937 rng(12);
    const auto steps = random_steps(rng, 40);
    Ringing r(p);
    std::vector<Ringing::Residual> carried;
    for (const auto& st : steps) {
        r.move(*r.prepare(st.move), st.dir);
        r.rest_ticks(st.rest_ticks);
        carried.push_back(r.residual());
        r.dwell();
    }
    const auto seq = as_one_command(steps, p.head.dwell_s);
    MoveSimulator nominal(build_model(p.dynamics));
    const auto want = residuals_um(nominal, seq);
    std::vector<double> worst(steps.size(), 0.0);
    for (const auto& v : band_variants(p.vibration)) {
        MoveSimulator sim(build_model(p.dynamics, v));
        const auto band = residuals_um(sim, seq);
        for (std::size_t k = 0; k < band.size(); ++k) worst[k] = std::max(worst[k], band[k]);
    }
    MoveSimulator alone(build_model(p.dynamics));
    int differs = 0;
    for (std::size_t k = 0; k < steps.size(); ++k) {
        EXPECT_NEAR(carried[k].nominal_um, want[k], 1e-6 * std::max(1.0, want[k])) << "strike " << k;
        EXPECT_NEAR(carried[k].worst_um, worst[k], 1e-6 * std::max(1.0, worst[k])) << "strike " << k;
        // And it matters: from rest, the same move would have rung differently.
        const double from_rest = r.from_rest(*r.prepare(steps[k].move),
                                             static_cast<double>(steps[k].rest_ticks) / machine::kTickHz)
                                     .nominal_um;
        if (std::fabs(from_rest - want[k]) > 1.0) ++differs;
    }
    EXPECT_GT(differs, 20);
}

TEST(Ringing, FromRestIsTheSimulatorsResidual) {
    const auto p = profile::default_profile();
    Ringing r(p);
    MoveSimulator sim(build_model(p.dynamics));
    for (double mm : {0.0125, 2.5, 3.5, 8.5, 60.0}) {
        const auto m = motion::jerk_move(mm, {250, 20000, 4e6});
        EXPECT_NEAR(r.from_rest(*r.prepare(m)).nominal_um, 1000.0 * sim.residual_mm(m, p.head.dwell_s), 1e-6) << mm;
    }
}

TEST(Ringing, SettleIsTheFirstTickThatPasses) {
    // The default machine's heavily damped corner creeps onto the dot after a
    // time-optimal move: the settle found is the first tick at which every
    // machine of the band is within target (one tick less is not).
    const auto p = profile::default_profile();
    Ringing r(p);
    for (double mm : {2.5, 3.5, 6.0, 60.0}) {
        const auto mv = r.prepare(motion::jerk_move(mm, {250, 20000, 4e6}));
        const auto ticks = r.settle_after(*mv, 49.9, machine::kTickHz);
        ASSERT_GT(ticks, 0) << mm;
        EXPECT_LE(r.from_rest(*mv, static_cast<double>(ticks) / machine::kTickHz).worst_um, 49.9) << mm;
        EXPECT_GT(r.from_rest(*mv, static_cast<double>(ticks - 1) / machine::kTickHz).worst_um, 49.9) << mm;
        // The same search on the carried state (the head at rest before the move).
        r.reset();
        r.move(*mv, -1);
        EXPECT_EQ(r.settle_ticks(49.9, 0, static_cast<std::uint64_t>(machine::kTickHz)), ticks);
        EXPECT_TRUE(r.within_after(static_cast<std::uint64_t>(ticks), 49.9));
        EXPECT_FALSE(r.within_after(static_cast<std::uint64_t>(ticks - 1), 49.9));
    }
}

TEST(Ringing, BandIsAGridWithItsCornersAndTheNominalMachine) {
    profile::Vibration v;
    const auto b = band_variants(v);
    EXPECT_EQ(b.size(), 45u);
    const auto has = [&](double d, double f) {
        return std::any_of(b.begin(), b.end(), [&](const ModelVariant& x) {
            return std::fabs(x.damping_scale - d) < 1e-12 && std::fabs(x.frequency_scale - f) < 1e-12;
        });
    };
    EXPECT_TRUE(has(0.5, 0.8));
    EXPECT_TRUE(has(1.5, 0.8));
    EXPECT_TRUE(has(0.5, 1.2));
    EXPECT_TRUE(has(1.5, 1.2));
    EXPECT_TRUE(has(1.0, 1.0));
}

// prepare_step_train (runs of equal intervals raised by squaring) is the
// piecewise simulation of step_train_shape (a piece per step), to rounding:
// on table-like trains (a ramp of distinct intervals, a long cruise of one,
// the mirror ramp), on the encoder's Q16.16 trains (fractional intervals,
// carries), with and without a rest after the last step; from rest, and
// carried through a sequence of moves on every machine of the band.
TEST(Ringing, StepTrainByRunsIsThePiecewiseSimulation) {
    auto p = profile::default_profile();
    p.dynamics.damping_ratio = 0.1;  // lively: rounding or a wrong piece would show
    Ringing r(p);
    const double spm = p.carriage.steps_per_mm;
    std::vector<motion::StepMove> moves;
    for (std::uint16_t cruise : {std::uint16_t{1}, std::uint16_t{7}, std::uint16_t{2000}}) {
        motion::StepMove m;
        std::uint32_t n = 0;
        for (std::uint32_t iv : {250u, 90u, 61u, 50u, 45u, 43u}) m.segments.push_back({iv << 16, 1, 0}), ++n;
        m.segments.push_back({40u << 16, cruise, 0});
        n += cruise;
        for (std::uint32_t iv : {43u, 45u, 50u, 61u, 90u, 250u}) m.segments.push_back({iv << 16, 1, 0}), ++n;
        m.steps = static_cast<std::int32_t>(n);
        m.duration_s = 0.25;  // a rest after the last step
        moves.push_back(m);
    }
    for (double mm : {0.0125, 2.5, 6.0, 60.0}) {
        auto m = motion::encode_move(motion::jerk_move(mm, {250, 20000, 4e6}), static_cast<std::int32_t>(mm * spm), spm,
                                     0.5);
        ASSERT_TRUE(m) << m.error().to_string();
        moves.push_back(*m);
        m->duration_s = 0;  // no rest: the train ends at its last half step
        moves.push_back(*m);
    }
    Ringing carried_runs(p), carried_pieces(p);
    int dir = 1;
    for (const auto& m : moves) {
        const auto runs = r.prepare_step_train(m.segments, spm, m.duration_s);
        const auto pieces = r.prepare(step_train_shape(m.segments, spm, m.duration_s));
        const auto a = r.from_rest(*runs), b = r.from_rest(*pieces);
        EXPECT_NEAR(a.nominal_um, b.nominal_um, 1e-6) << m.steps;
        EXPECT_NEAR(a.worst_um, b.worst_um, 1e-6) << m.steps;
        EXPECT_GT(b.worst_um, 0.0);
        carried_runs.move(*runs, dir);
        carried_pieces.move(*pieces, dir);
        const auto c = carried_runs.residual(), d = carried_pieces.residual();
        EXPECT_NEAR(c.nominal_um, d.nominal_um, 1e-6) << m.steps;
        EXPECT_NEAR(c.worst_um, d.worst_um, 1e-6) << m.steps;
        carried_runs.dwell();
        carried_pieces.dwell();
        dir = -dir;
    }
}
