// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Hand-built plans for link tests: consistent step moves (accelerate, cruise,
// decelerate) between strikes, alternating sweep directions, both hammers.
#include <cstdlib>
#include <random>

#include "machine/firmware_tables.hpp"
#include "motion/steps.hpp"
#include "motion/table_move.hpp"
#include "plan/plan.hpp"

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
// A strike at `carriage_step` on the line at `y_mm`, a random hammer (one in
// three concave) on its side, struck at `time_s`.
inline plan::Strike random_strike(std::mt19937& rng, std::int32_t carriage_step, double y_mm, double time_s) {
    plan::Strike k;
    k.hammer = rng() % 3 == 0 ? plan::Hammer::concave : plan::Hammer::convex;
    k.side = k.hammer == plan::Hammer::convex ? plan::Side::front : plan::Side::back;
    k.carriage_step = carriage_step;
    k.x_mm = carriage_step / 80.0;
    k.y_mm = y_mm;
    k.time_s = time_s;
    return k;
}

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
                t += pass.moves.back().duration_s + 0.002;
                pass.strikes.push_back(random_strike(rng, target, pass.y_mm, t));
                ++job.strikes;
            }
            sheet.passes.push_back(std::move(pass));
        }
        job.sheets.push_back(std::move(sheet));
    }
    job.duration_s = t;
    return job;
}

// The same shape of job for protocol 3: every move the firmware's table move,
// distances on its dot grids, positions counted the firmware's way (after
// HOME the carriage last moved toward home; a reversal adds the backlash).
// Strikes are 0 to 6 grid units apart (0: the other hammer on the same spot),
// sweeps alternate, so entries of one byte, reversals and backlash all occur.
inline plan::JobPlan make_firmware_plan(const machine::FirmwareTables& t, const machine::StrikeTiming& timing,
                                        std::size_t sheets, std::size_t passes, std::size_t strikes,
                                        unsigned seed = 1) {
    std::mt19937 rng(seed);
    plan::JobPlan job;
    const auto grid = static_cast<std::int32_t>(t.carriage.grid_steps);
    const auto fgrid = static_cast<std::int32_t>(t.feed.grid_steps);
    std::int32_t carriage = 0;
    bool c_neg = true;
    double time = 0;
    // A move of `units` grid units (signed) from where the carriage is.
    auto carriage_move = [&](std::int32_t units) {
        if (units == 0) return motion::table_move(t.carriage, 0, timing.settle_ticks);
        const bool neg = units < 0;
        std::int32_t motor = std::abs(units) * grid;
        if (neg != c_neg) motor += static_cast<std::int32_t>(t.carriage.backlash_steps);
        c_neg = neg;
        carriage += neg ? -motor : motor;
        return motion::table_move(t.carriage, neg ? -motor : motor, timing.settle_ticks);
    };
    for (std::size_t s = 1; s <= sheets; ++s) {
        plan::SheetPlan sheet;
        sheet.index = s;
        std::int32_t feed = 0;
        for (std::size_t p = 0; p < passes; ++p) {
            plan::Pass pass;
            pass.sheet = s;
            pass.side = p % 2 ? plan::Side::back : plan::Side::front;
            pass.direction = p % 2 ? -1 : +1;
            const std::int32_t feed_steps = (p == 0 ? 8 : 2) * fgrid;
            pass.feed = motion::table_move(t.feed, feed_steps, 0);
            feed += feed_steps;
            pass.feed_step = feed;
            pass.y_mm = feed / 40.0;
            const std::size_t n = 1 + rng() % strikes;
            std::vector<std::int32_t> gaps(n, 0);
            std::int32_t span = 0;
            for (std::size_t i = 1; i < n; ++i) span += gaps[i] = static_cast<std::int32_t>(rng() % 7);
            // Start where the sweep fits: from column 40 forward, or back from its end.
            const std::int32_t start = pass.direction > 0 ? 40 * grid : 40 * grid + span * grid + 4 * grid;
            for (std::size_t i = 0; i < n; ++i) {
                const std::int32_t units = i == 0 ? (start - carriage) / grid : pass.direction * gaps[i];
                pass.moves.push_back(carriage_move(units));
                time += static_cast<double>(t.carriage.move_ticks(static_cast<std::uint32_t>(
                            std::abs(pass.moves.back().steps))) + timing.settle_ticks + timing.hammer_ticks) /
                        machine::kTickHz;
                pass.strikes.push_back(random_strike(rng, carriage, pass.y_mm, time));
                ++job.strikes;
            }
            sheet.passes.push_back(std::move(pass));
        }
        job.sheets.push_back(std::move(sheet));
    }
    job.duration_s = time;
    return job;
}

}  // namespace tactus::test
