// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The plan: what the controller executes for a job. Produced by the plan stage,
// timed by estimate, encoded into frames by encode, executed by the (simulated)
// 89C52. The host plans everything; the controller only counts steps and fires.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "machine/limits.hpp"
#include "motion/step_move.hpp"

namespace tactus::plan {

enum class Side : std::uint8_t { front, back };
// The convex hammer raises dots toward the front side, the concave one toward the back.
enum class Hammer : std::uint8_t { convex, concave };

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
    double residual_um = 0;        // the head's distance from the dot while the hammer is down, nominal machine
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
    motion::StepMove feed;                 // paper feed from the previous pass
    std::vector<motion::StepMove> moves;   // moves[i] brings the carriage to strikes[i]
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
