// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Hand-built plans for link tests: consistent step moves (accelerate, cruise,
// decelerate) between strikes, alternating sweep directions, both hammers.
#include <cstdlib>
#include <random>

#include "plan/plan.hpp"
#include "motion/steps.hpp"

namespace tactus::test {

inline motion::StepMove make_move(std::int32_t steps) {
    motion::StepMove m;
    m.steps = steps;
    const auto d = static_cast<std::uint16_t>(std::abs(steps));
    if (d == 0) return m;
    const auto a = static_cast<std::uint16_t>(std::min<int>(20, d / 2));
    // Q16.16: accelerate from 400 ticks per step by -7.5 per step, cruise at 240.25, decelerate.
    constexpr std::uint32_t one = 1U << machine::kStepFractionBits;
    if (a > 0) m.segments.push_back({400 * one, a, -static_cast<std::int32_t>(15 * one / 2)});
    if (d - 2 * a > 0) m.segments.push_back({240 * one + one / 4, static_cast<std::uint16_t>(d - 2 * a), 0});
    if (a > 0) m.segments.push_back({400 * one - a * (15 * one / 2), a, static_cast<std::int32_t>(15 * one / 2)});
    const auto t = motion::expand_steps(m.segments);
    m.duration_s = static_cast<double>(t.back()) / machine::kTickHz;
    return m;
}

// `sheets` sheets of `passes` dot rows, up to `strikes` dots per row.
inline plan::JobPlan make_plan(std::size_t sheets, std::size_t passes, std::size_t strikes,
                               unsigned seed = 1) {
    std::mt19937 rng(seed);
    plan::JobPlan job;
    std::int32_t carriage = 0;
    double t = 0;
    for (std::size_t s = 1; s <= sheets; ++s) {
        plan::SheetPlan sheet;
        sheet.index = s;
        std::int32_t feed = 0;
        for (std::size_t p = 0; p < passes; ++p) {
            plan::Pass pass;
            pass.sheet = s;
            pass.side = p % 2 ? plan::Side::back : plan::Side::front;
            pass.direction = p % 2 ? -1 : +1;
            const std::int32_t feed_steps = p == 0 ? 400 : 100;
            pass.feed = make_move(feed_steps);
            feed += feed_steps;
            pass.feed_step = feed;
            pass.y_mm = feed / 40.0;
            const std::size_t n = 1 + rng() % strikes;
            for (std::size_t i = 0; i < n; ++i) {
                const std::int32_t col = static_cast<std::int32_t>(i) * 200 + 800;
                const std::int32_t target =
                    pass.direction > 0 ? col : 800 + static_cast<std::int32_t>(n - 1 - i) * 200;
                pass.moves.push_back(make_move(target - carriage));
                carriage = target;
                plan::Strike k;
                k.hammer = rng() % 3 == 0 ? plan::Hammer::concave : plan::Hammer::convex;
                k.side = k.hammer == plan::Hammer::convex ? plan::Side::front : plan::Side::back;
                k.carriage_step = target;
                k.x_mm = target / 80.0;
                k.y_mm = pass.y_mm;
                t += pass.moves.back().duration_s + 0.002;
                k.time_s = t;
                pass.strikes.push_back(k);
                ++job.strikes;
            }
            sheet.passes.push_back(std::move(pass));
        }
        job.sheets.push_back(std::move(sheet));
    }
    job.duration_s = t;
    return job;
}

}  // namespace tactus::test
