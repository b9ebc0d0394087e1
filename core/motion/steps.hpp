// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// From millimetres to what the 89C52 executes: whole motor steps and their timing.
#include <cstdint>
#include <span>
#include <vector>

#include "common/result.hpp"
#include "motion/motion.hpp"
#include "machine/limits.hpp"
#include "motion/step_move.hpp"

namespace tactus::motion {

// Absolute position in whole steps. Every move is planned between absolute step
// positions (the DDA's accumulated error is carried from move to move instead of
// being rounded away per move), so a job never drifts: after any number of moves
// the carriage stands exactly where the last target rounds to.
class StepAxis {
public:
    explicit StepAxis(double steps_per_mm) : steps_per_mm_(steps_per_mm) {}
    [[nodiscard]] std::int32_t steps_for(double mm) const;
    [[nodiscard]] double mm_for(std::int32_t steps) const { return steps / steps_per_mm_; }
    [[nodiscard]] double steps_per_mm() const { return steps_per_mm_; }

private:
    double steps_per_mm_;
};

// Ideal firing time of each of `steps` steps (in timer ticks from the move
// start) for `shape` travelling steps/steps_per_mm: step k fires when the
// commanded position crosses the middle of step k.
std::vector<double> step_times_ticks(const MoveShape& shape, std::uint32_t steps,
                                     double steps_per_mm);

// Compresses ideal step times into Q16.16 (interval, count, add) segments whose
// reconstruction by the controller's arithmetic (expand_steps) fires every step
// within `tolerance_ticks` of its ideal time (one value for every step, or one
// per step; never below 1). Fails when an interval does not fit the
// controller's 16-bit timer.
Result<std::vector<StepSegment>> compress_steps(std::span<const double> ticks,
                                                double tolerance_ticks = 1.0);
Result<std::vector<StepSegment>> compress_steps(std::span<const double> ticks,
                                                std::span<const double> tolerance_ticks);

// Per-step tolerances for a move's ideal step times: `fraction` of the shorter
// interval next to each step, at least one tick, and one tick for the last step.
// A step fired within a fraction f of its interval leaves the commanded
// position within f of a step of the ideal trajectory (docs/motion.md).
// fraction 0 gives one tick everywhere.
std::vector<double> step_tolerances(std::span<const double> ticks, double fraction);
// The integer firing times (ticks from the move start) the controller will
// produce: the reference for the simulated controller and for the tests.
std::vector<std::int64_t> expand_steps(std::span<const StepSegment> segments);

// A complete StepMove for a move of `steps` (signed) along an axis, its steps
// within step_tolerances(..., tolerance_fraction) of the ideal.
Result<StepMove> encode_move(const MoveShape& shape, std::int32_t steps, double steps_per_mm,
                             double tolerance_fraction = 0.0);

}  // namespace tactus::motion
