// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Input shaping: the command is convolved with a few impulses whose amplitudes
// and delays cancel (or, for EI, bound) the residual vibration of one mode.
// Formulas as published with Klipper (klippy/extras/shaper_defs.py).
#include <vector>

#include "motion/motion.hpp"
#include "profile/profile.hpp"

namespace tactus::motion {

struct Impulse {
    double t = 0;  // s
    double a = 0;  // amplitude; the amplitudes of a shaper sum to 1
};

struct Shaper {
    profile::ShaperKind kind = profile::ShaperKind::none;
    std::vector<Impulse> impulses{{0.0, 1.0}};
    [[nodiscard]] double duration() const { return impulses.back().t; }
};

// EI leaves this fraction of the vibration at its design frequency, in exchange
// for a wider band of frequencies it suppresses (Klipper's 1/20).
inline constexpr double kEiVibrationTolerance = 0.05;

// Designed for the mode at `frequency_hz` (undamped natural frequency) with damping ratio `zeta` < 1.
Shaper design_shaper(profile::ShaperKind kind, double frequency_hz, double zeta);

// The shaped move: sum over impulses of a * base(t - t_i). Stays within the base
// move's velocity and acceleration limits (a convex combination) and lasts
// base.duration + shaper.duration().
MoveShape shape_move(const MoveShape& base, const Shaper& shaper);

}  // namespace tactus::motion
