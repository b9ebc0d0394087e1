// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The plan: what the controller executes for a job. Produced by the plan stage,
// timed by estimate, encoded into frames by encode, executed by the (simulated)
// 89C52. The host plans everything; the controller only counts steps and fires.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tactus::plan {

enum class Side : std::uint8_t { front, back };
// The convex hammer raises dots toward the front side, the concave one toward the back.
enum class Hammer : std::uint8_t { convex, concave };

// Klipper-style step compression: `count` steps, the first `interval` timer ticks
// after the previous step, each following interval `add` ticks longer (negative:
// shorter). Ticks are the 89C52 timer clock, 11.0592 MHz / 12 = 921600 Hz.
//
// interval and add are fixed point with 16 fractional bits (Q16.16): a carriage
// cruising at 38.4 ticks per step, or an acceleration ramp whose interval shrinks
// by 0.3 ticks per step, is then one segment instead of one every few steps
// (whole-tick intervals made the schedule larger than a 115200-baud link can
// carry). The controller still only adds: per step it adds the 16-bit fraction of
// `interval` into a fraction accumulator that starts at 0 with each segment, loads
// its timer with the integer part plus the carry, and adds `add` (32-bit) to
// `interval`. expand_steps() in plan/steps.hpp is that arithmetic, exactly.
struct StepSegment {
    std::uint32_t interval_q16 = 0;  // ticks << 16; integer part 1..65535
    std::uint16_t count = 0;
    std::int32_t add_q16 = 0;  // ticks << 16 added to the interval after each step
    bool operator==(const StepSegment&) const = default;
};

inline constexpr int kStepFractionBits = 16;
// Segment intervals and adds lie on a grid of 2^0..2^15 Q16.16 units: the planner
// picks the coarsest that fits, the protocol omits the zero low bits.
inline constexpr unsigned kMaxGridShift = 15;

inline constexpr double kTickHz = 11'059'200.0 / 12.0;

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

struct Strike {
    Hammer hammer = Hammer::convex;
    Side side = Side::front;
    double x_mm = 0;  // dot position on the paper, in that side's reading coordinates
    double y_mm = 0;
    std::int32_t carriage_step = 0;  // absolute carriage position when it fires
    double time_s = 0;               // from the start of the job
    // Added by the plan stage for estimate and preview:
    double paper_x_mm = 0;  // the dot in paper coordinates: the sheet as it runs
    double paper_y_mm = 0;  // through the machine, front side up
    double residual_um = 0;        // head position error while the hammer is down, nominal machine
    double worst_residual_um = 0;  // the same, worst case over the damping/frequency band
    bool operator==(const Strike&) const = default;
};

// One paper position (dot row) and the strikes of either hammer made there.
struct Pass {
    std::size_t sheet = 0;  // 1-based
    Side side = Side::front;
    double y_mm = 0;               // paper position of this dot row
    std::int32_t feed_step = 0;    // absolute paper-feed position
    int direction = +1;            // carriage sweep direction, +1 or -1
    StepMove feed;                 // paper feed from the previous pass
    std::vector<StepMove> moves;   // moves[i] brings the carriage to strikes[i]
    std::vector<Strike> strikes;
    double duration_s = 0;
    // Added by the plan stage:
    double lower_bound_s = 0;    // time-optimal jerk-limited moves, same limits, dwell and feed
    std::size_t segments = 0;    // encoded step segments (feed + carriage) of this pass
    bool operator==(const Pass&) const = default;
};

struct SheetPlan {
    std::size_t index = 0;  // 1-based
    std::vector<Pass> passes;
    double duration_s = 0;
    double lower_bound_s = 0;
};

struct JobPlan {
    std::vector<SheetPlan> sheets;
    double duration_s = 0;
    double lower_bound_s = 0;
    std::size_t strikes = 0;
    double max_residual_um = 0;
    // Added by the plan stage:
    double max_worst_residual_um = 0;      // over the damping/frequency band
    std::size_t strikes_over_tolerance = 0;  // only with a fixed (not auto-tuned) profile/shaper
    std::size_t segments = 0;
};

}  // namespace tactus::plan
