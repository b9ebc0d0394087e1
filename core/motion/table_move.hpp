// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A table move: the reference firmware's moves (protocol v3), which walk the
// ramp table in flash up to cruise and back down its mirror. As a StepMove its
// segments are the table's intervals exactly (runs of equal intervals, add 0),
// so the estimate replays and the simulated controller executes the very step
// train the firmware fires.
#include <cstdint>

#include "machine/firmware_tables.hpp"
#include "motion/step_move.hpp"

namespace tactus::motion {

// `steps` signed (direction is the sign); settle_ticks at rest after the last step.
StepMove table_move(const machine::RampTable& table, std::int32_t steps, std::uint32_t settle_ticks);

// True when `m`'s step times are exactly the table move's of m.steps steps.
bool is_table_move(const machine::RampTable& table, const StepMove& m);

}  // namespace tactus::motion
