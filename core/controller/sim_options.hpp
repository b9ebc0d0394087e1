// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the simulated 89C52 is built with (SimOptions) and what it records of
// each dot it strikes (LoggedStrike), shared by its session layer, both
// protocols and the callers that compare a strike log with a plan.
#include <cstdint>
#include <optional>
#include <vector>

#include "machine/firmware_tables.hpp"
#include "plan/plan.hpp"

namespace tactus::controller {

// One dot embossed, in the controller's own units.
struct LoggedStrike {
    std::uint16_t sheet = 0;
    plan::Side side = plan::Side::front;
    plan::Hammer hammer = plan::Hammer::convex;
    std::int32_t carriage_step = 0;
    std::int32_t feed_step = 0;
    std::uint16_t pass_index = 0;
    std::uint16_t job_id = 0;  // the controller job (JOB_BEGIN's id) it belongs to
    double time_s = 0;  // simulated time
    double x_mm = 0;    // carriage_step mapped back with the configured steps/mm
    double y_mm = 0;
    // Time (and the job id) are not part of identity: a retried job strikes
    // later and under another id, not differently.
    bool operator==(const LoggedStrike& o) const {
        return sheet == o.sheet && side == o.side && hammer == o.hammer &&
               carriage_step == o.carriage_step && feed_step == o.feed_step;
    }
};

// The strikes a plan asks for, in the form the controller logs them.
std::vector<LoggedStrike> planned_strikes(const plan::JobPlan& plan);

struct SimOptions {
    bool paper_present = true;
    // Scale factor between controller time and keep-alive time (a pty server
    // running motion 20x faster keeps the host's keep-alive in wall time).
    double keepalive_scale = 1.0;
    // Execute motion instantly (link-efficiency benchmark: the link is the only limit).
    bool instant_motion = false;
    // After a paper-out fault, the operator loads paper this many seconds later
    // (negative: never; load_paper() does it).
    double reload_paper_after_s = -1;
    double sheet_load_s = 0.8;  // pick up and position a sheet
    double sheet_eject_s = 0.8;
    // Speak protocol 3 as the reference firmware built with these ramp tables
    // (its build/ramp.json, profile::load_firmware_tables) does; nullopt:
    // protocol 2. The sheet load and eject times above are v2's: the v3
    // firmware loads and ejects in no time, as the emulated chip does.
    std::optional<machine::FirmwareTables> firmware;
};

}  // namespace tactus::controller
