// SPDX-License-Identifier: GPL-3.0-or-later
#include "machine/controller_config.hpp"

#include <algorithm>

#include "machine/limits.hpp"

namespace tactus::machine {

ControllerConfig controller_config(const MachineDimensions& m) {
    ControllerConfig c;
    c.carriage_steps_per_m = static_cast<std::uint32_t>(m.carriage_steps_per_mm * 1000 + 0.5);
    c.feed_steps_per_m = static_cast<std::uint32_t>(m.feed_steps_per_mm * 1000 + 0.5);
    c.carriage_travel_steps =
        static_cast<std::int32_t>(m.carriage_travel_mm * m.carriage_steps_per_mm);
    // Homing and seeking at a gentle 40 mm/s.
    c.home_interval_ticks = static_cast<std::uint16_t>(
        std::clamp(kTickHz / (40.0 * m.carriage_steps_per_mm), 1.0, 65535.0));
    c.hammer_ticks =
        static_cast<std::uint16_t>(std::clamp(m.hammer_dwell_s * kTickHz, 1.0, 65535.0));
    return c;
}

}  // namespace tactus::machine
