// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A move in whole motor steps with its step timing: what the planner produces,
// the estimate replays and the encoder sends.
#include <cstdint>
#include <vector>

namespace tactus::motion {

// Klipper-style step compression: `count` steps, the first `interval` timer ticks
// after the previous step, each following interval `add` ticks longer (negative:
// shorter). Ticks are the 89C52 timer clock (machine::kTickHz).
//
// interval and add are fixed point with 16 fractional bits (Q16.16): a carriage
// cruising at 38.4 ticks per step, or an acceleration ramp whose interval shrinks
// by 0.3 ticks per step, is then one segment instead of one every few steps
// (whole-tick intervals made the schedule larger than a 115200-baud link can
// carry). The controller still only adds: per step it adds the 16-bit fraction of
// `interval` into a fraction accumulator that starts at 0 with each segment, loads
// its timer with the integer part plus the carry, and adds `add` (32-bit) to
// `interval`. expand_steps() in motion/steps.hpp is that arithmetic, exactly.
struct StepSegment {
    std::uint32_t interval_q16 = 0;  // ticks << 16; integer part 1..65535
    std::uint16_t count = 0;
    std::int32_t add_q16 = 0;  // ticks << 16 added to the interval after each step
    bool operator==(const StepSegment&) const = default;
};

// One axis move in whole motor steps, with its step timing.
struct StepMove {
    std::int32_t steps = 0;  // signed: direction is the sign
    std::vector<StepSegment> segments;
    double duration_s = 0;
    // Ticks at rest between the last step and the end of duration_s: the
    // planned settle before a strike, which the controller waits out.
    std::uint32_t settle_ticks = 0;
    bool operator==(const StepMove&) const = default;
};

}  // namespace tactus::motion
