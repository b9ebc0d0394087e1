// SPDX-License-Identifier: GPL-3.0-or-later
#include "motion/table_move.hpp"

#include <cstdlib>

#include "machine/limits.hpp"
#include "motion/steps.hpp"

namespace tactus::motion {

StepMove table_move(const machine::RampTable& table, std::int32_t steps, std::uint32_t settle_ticks) {
    StepMove m;
    m.steps = steps;
    m.settle_ticks = settle_ticks;
    const auto n = static_cast<std::uint32_t>(std::abs(steps));
    for (std::uint32_t k = 1; k <= n; ++k) {
        const std::uint32_t iv = static_cast<std::uint32_t>(table.interval(k, n)) << machine::kStepFractionBits;
        if (!m.segments.empty() && m.segments.back().interval_q16 == iv && m.segments.back().count < 0xFFFF)
            ++m.segments.back().count;
        else
            m.segments.push_back({iv, 1, 0});
    }
    m.duration_s = static_cast<double>(table.move_ticks(n) + settle_ticks) / machine::kTickHz;
    return m;
}

bool is_table_move(const machine::RampTable& table, const StepMove& m) {
    const auto n = static_cast<std::uint32_t>(std::abs(m.steps));
    const auto times = expand_steps(m.segments);
    if (times.size() != n) return false;
    std::int64_t t = 0;
    for (std::uint32_t k = 1; k <= n; ++k) {
        t += table.interval(k, n);
        if (times[k - 1] != t) return false;
    }
    return true;
}

}  // namespace tactus::motion
