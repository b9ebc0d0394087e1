// SPDX-License-Identifier: GPL-3.0-or-later
#include "encode/controller_config.hpp"

#include <algorithm>

#include "plan/plan.hpp"

namespace tactus::encode {

ControllerConfig controller_config(const profile::PrinterProfile& p) {
    ControllerConfig c;
    c.carriage_steps_per_m = static_cast<std::uint32_t>(p.carriage.steps_per_mm * 1000 + 0.5);
    c.feed_steps_per_m = static_cast<std::uint32_t>(p.feed.steps_per_mm * 1000 + 0.5);
    c.carriage_travel_steps = static_cast<std::int32_t>(
        (p.paper.width_mm + p.head.concave_offset_mm) * p.carriage.steps_per_mm);
    // Homing and seeking at a gentle 40 mm/s.
    c.home_interval_ticks = static_cast<std::uint16_t>(
        std::clamp(plan::kTickHz / (40.0 * p.carriage.steps_per_mm), 1.0, 65535.0));
    c.hammer_ticks =
        static_cast<std::uint16_t>(std::clamp(p.head.dwell_s * plan::kTickHz, 1.0, 65535.0));
    return c;
}

}  // namespace tactus::encode
