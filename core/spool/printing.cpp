// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/printing.hpp"

#include <algorithm>
#include <cmath>

#include "plan/planner.hpp"

namespace tactus::spool {

plan::JobPlan repeat_plan(const plan::JobPlan& one, std::size_t copies) {
    plan::JobPlan all = one;
    all.sheets.clear();
    all.sheets.reserve(one.sheets.size() * copies);
    const std::size_t per_copy = one.sheets.size();
    for (std::size_t c = 0; c < copies; ++c)
        for (const auto& sheet : one.sheets) {
            plan::SheetPlan s = sheet;
            s.index = sheet.index + c * per_copy;
            for (auto& pass : s.passes) pass.sheet = s.index;
            all.sheets.push_back(std::move(s));
        }
    const auto n = static_cast<double>(copies);
    all.duration_s = one.duration_s * n;
    all.lower_bound_s = one.lower_bound_s * n;
    all.strikes = one.strikes * copies;
    return all;
}

Result<plan::JobPlan> plan_copies(const PagedDocument& doc, const profile::PrinterProfile& profile,
                                  std::size_t copies) {
    auto one = plan::plan_job(doc, profile);
    if (!one) return std::unexpected(one.error());
    if (copies <= 1) return std::move(*one);
    return repeat_plan(*one, copies);
}

encode::ControllerConfig controller_config(const profile::PrinterProfile& p) {
    auto clamp16 = [](double v) {
        return static_cast<std::uint16_t>(std::clamp(std::lround(v), 1L, 65535L));
    };
    encode::ControllerConfig c;
    c.carriage_steps_per_m = static_cast<std::uint32_t>(std::lround(p.carriage.steps_per_mm * 1000));
    c.feed_steps_per_m = static_cast<std::uint32_t>(std::lround(p.feed.steps_per_mm * 1000));
    // The carriage must reach every paper x with either hammer; beyond that the
    // limit switch is real.
    c.carriage_travel_steps = static_cast<std::int32_t>(
        std::lround((p.paper.width_mm + 2 * p.head.concave_offset_mm) * p.carriage.steps_per_mm));
    // Homing and seeks at a fifth of the top speed: slow enough to stop on the switch.
    c.home_interval_ticks = clamp16(plan::kTickHz / (p.carriage.v_max_mm_s / 5 * p.carriage.steps_per_mm));
    c.hammer_ticks = clamp16(p.head.dwell_s / 2 * plan::kTickHz);
    return c;
}

}  // namespace tactus::spool
