// SPDX-License-Identifier: GPL-3.0-or-later
// Property: on random pages, every strike of the plan is within the
// vibration tolerance on every machine of the band (random damping and
// frequency inside it, and its corners), the head ringing on from move to
// move. Checked by one exact simulation of each sheet's whole carriage
// command, rebuilt from the plan's own strike times and moves: nothing of the
// planner's ringing estimate is reused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "estimate/dynamics.hpp"
#include "estimate/simulate.hpp"
#include "hand_pages.hpp"
#include "plan/planner.hpp"

using namespace tactus;

namespace {

layout::Page random_page(std::mt19937& rng, const profile::PrinterProfile& p) {
    std::uniform_int_distribution<int> cells(0, p.geometry.cells_per_line);
    std::uniform_int_distribution<int> dots(0, 63);
    std::bernoulli_distribution blank_line(0.2), blank_cell(0.3);
    std::vector<std::u32string> lines;
    for (int l = 0; l < p.geometry.lines_per_page; ++l) {
        std::u32string line;
        if (!blank_line(rng)) {
            const int n = cells(rng);
            for (int c = 0; c < n; ++c) line += static_cast<char32_t>(0x2800 + (blank_cell(rng) ? 0 : dots(rng)));
        }
        lines.push_back(line);
    }
    return test::page_of(lines);
}

// One sheet's carriage command and the strike instants, rebuilt from the plan.
struct Timeline {
    motion::MoveShape command;
    std::vector<double> times, targets;
};

Timeline timeline(const plan::SheetPlan& sheet, plan::Planner& planner, double t_start) {
    const auto& p = planner.profile();
    const double spm = p.carriage.steps_per_mm, dwell = p.head.dwell_s;
    Timeline tl;
    double t = 0;  // from the sheet's start
    const auto& first = sheet.passes.front();
    double at = (first.strikes.front().carriage_step - first.moves.front().steps) / spm;
    auto hold_to = [&](double t1) {
        if (t1 > t) tl.command.pieces.push_back({t, t1 - t, motion::Derivs{at, 0, 0, 0, 0, 0}});
        t = std::max(t, t1);
    };
    double move_start = 0;
    for (const auto& pass : sheet.passes)
        for (std::size_t k = 0; k < pass.strikes.size(); ++k) {
            const auto& move = pass.moves[k];
            const auto& strike = pass.strikes[k];
            const double t_strike = strike.time_s - t_start;
            hold_to(move_start);
            if (move.steps != 0) {
                auto tuned = planner.tuner().carriage(static_cast<std::uint32_t>(std::abs(move.steps)));
                EXPECT_TRUE(tuned.has_value());
                const int dir = move.steps > 0 ? 1 : -1;
                const double base = (*tuned)->base_duration_s;
                EXPECT_LE(move_start + base, t_strike + 1e-12);
                for (const auto& pc : (*tuned)->shape.pieces) {
                    if (pc.t0 >= base) break;  // the tuned settle: this strike's own rest follows
                    motion::Derivs d = pc.d;
                    for (auto& x : d) x *= dir;
                    d[0] += at;
                    tl.command.pieces.push_back({t + pc.t0, std::min(pc.dt, base - pc.t0), d});
                }
                t += base;
                at += dir * (*tuned)->shape.distance;
            }
            EXPECT_NEAR(at, strike.carriage_step / spm, 1e-9);
            hold_to(t_strike);
            for (int i = 0; i <= 32; ++i) {
                tl.times.push_back(t_strike + dwell * i / 32);
                tl.targets.push_back(at);
            }
            move_start = t_strike + dwell;
        }
    hold_to(move_start);
    tl.command.duration = t;
    tl.command.distance = at;
    return tl;
}

}  // namespace

TEST(ResidualProperty, EveryStrikeWithinToleranceAcrossTheBand) {
    const auto p = profile::default_profile();
    std::mt19937 rng(2026);
    std::uniform_real_distribution<double> damping(1 - p.vibration.damping_band, 1 + p.vibration.damping_band);
    std::uniform_real_distribution<double> frequency(1 - p.vibration.frequency_band, 1 + p.vibration.frequency_band);
    std::vector<estimate::ModelVariant> machines{{1 - p.vibration.damping_band, 1 - p.vibration.frequency_band},
                                                 {1 - p.vibration.damping_band, 1 + p.vibration.frequency_band},
                                                 {1 + p.vibration.damping_band, 1 - p.vibration.frequency_band},
                                                 {1 + p.vibration.damping_band, 1 + p.vibration.frequency_band},
                                                 {1, 1}};
    for (int i = 0; i < 16; ++i) machines.push_back({damping(rng), frequency(rng)});
    double worst_seen = 0;
    std::size_t strikes = 0;
    for (int doc_index = 0; doc_index < 3; ++doc_index) {
        const auto doc = test::doc_of({random_page(rng, p), random_page(rng, p), random_page(rng, p)});
        auto planner = plan::Planner::create(p);
        ASSERT_TRUE(planner.has_value());
        double t_start = 0;
        for (std::size_t s = 1; s <= doc.sheet_count(); ++s) {
            auto sheet = planner->plan_sheet(doc, s);
            ASSERT_TRUE(sheet.has_value()) << sheet.error().to_string();
            if (sheet->passes.empty()) continue;
            const auto tl = timeline(*sheet, *planner, t_start);
            for (const auto& v : machines) {
                estimate::MoveSimulator sim(estimate::build_model(p.dynamics, v));
                const auto y = sim.head_positions(tl.command, tl.times);
                for (std::size_t i = 0; i < y.size(); ++i) {
                    const double err = std::fabs(y[i] - tl.targets[i]) * 1000.0;
                    worst_seen = std::max(worst_seen, err);
                    EXPECT_LE(err, p.vibration.tolerance_um)
                        << "strike " << i / 33 << " of sheet " << s << ", damping x" << v.damping_scale
                        << ", frequency x" << v.frequency_scale;
                }
            }
            strikes += tl.times.size() / 33;
            const auto& last = sheet->passes.back();
            t_start = last.strikes.back().time_s + p.head.dwell_s;
        }
    }
    EXPECT_GT(strikes, 1000u);
    // Tight: the plan spends no more settle than the band needs.
    EXPECT_GT(worst_seen, 0.9 * p.vibration.tolerance_um);
    RecordProperty("worst_residual_um", std::to_string(worst_seen));
}
