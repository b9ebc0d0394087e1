// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The motion the controller actually commands: its integer step times turned
// back into a position-versus-time command, so the head model can be run on the
// step train itself instead of on the ideal move it approximates.
#include <span>

#include "motion/motion.hpp"
#include "motion/step_move.hpp"

namespace tactus::estimate {

// The command through the middle of each step at the tick the controller fires
// it (motion::expand_steps), straight between steps (the motor moves one step per
// pulse, not instantly), from rest at 0 to rest at the move's end, held until
// `duration_s`. Pieces of constant velocity.
motion::MoveShape step_train_shape(std::span<const motion::StepSegment> segments, double steps_per_mm,
                                 double duration_s);

}  // namespace tactus::estimate
