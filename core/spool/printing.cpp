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
    // The same mapping as `tactus-cli emboss` (app/cli/cmd_emboss.cpp), so a
    // queued job and a direct one configure the controller identically.
    encode::ControllerConfig c;
    c.carriage_steps_per_m = static_cast<std::uint32_t>(p.carriage.steps_per_mm * 1000 + 0.5);
    c.feed_steps_per_m = static_cast<std::uint32_t>(p.feed.steps_per_mm * 1000 + 0.5);
    c.carriage_travel_steps = static_cast<std::int32_t>(
        (p.paper.width_mm + p.head.concave_offset_mm) * p.carriage.steps_per_mm);
    // Homing and seeking at a gentle 40 mm/s.
    c.home_interval_ticks = static_cast<std::uint16_t>(
        std::clamp(plan::kTickHz / (40.0 * p.carriage.steps_per_mm), 1.0, 65535.0));
    c.hammer_ticks = static_cast<std::uint16_t>(std::clamp(p.head.dwell_s * plan::kTickHz, 1.0, 65535.0));
    return c;
}

}  // namespace tactus::spool
