// SPDX-License-Identifier: GPL-3.0-or-later
#include "profile/controller_config.hpp"

namespace tactus::profile {

machine::ControllerConfig controller_config(const PrinterProfile& p) {
    machine::MachineDimensions m;
    m.carriage_steps_per_mm = p.carriage.steps_per_mm;
    m.feed_steps_per_mm = p.feed.steps_per_mm;
    // The head travels the paper's width plus the concave hammer's offset.
    m.carriage_travel_mm = p.paper.width_mm + p.head.concave_offset_mm;
    m.hammer_dwell_s = p.head.dwell_s;
    return machine::controller_config(m);
}

}  // namespace tactus::profile
