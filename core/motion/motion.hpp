// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Point-to-point move profiles, from rest to rest, as piecewise polynomials.
// Each piece stores the position and its first five derivatives at its start;
// the fifth (crackle) is constant inside a piece, which is enough to represent
// exactly: the trapezoid (constant acceleration pieces), the 7-segment
// jerk-limited move (constant jerk), the sources' S-curve (smoothstep
// acceleration, a cubic) and any input-shaped sum of time-shifted copies of them.
#include <array>
#include <vector>

#include "profile/profile.hpp"

namespace tactus::motion {

struct Limits {
    double v = 0;  // mm/s
    double a = 0;  // mm/s^2
    double j = 0;  // mm/s^3
};

// Derivatives 0..5 of position at some instant: p, v, a, jerk, snap, crackle.
using Derivs = std::array<double, 6>;

struct Piece {
    double t0 = 0;
    double dt = 0;
    Derivs d{};  // at t0; d[5] holds for the whole piece
};

struct MoveShape {
    std::vector<Piece> pieces;  // contiguous, from t = 0
    double distance = 0;        // mm, >= 0 (direction is applied by the planner)
    double duration = 0;        // s

    // Derivatives at time t (clamped: before 0 at rest at 0, after the end at rest at `distance`).
    [[nodiscard]] Derivs at(double t) const;
    [[nodiscard]] double position(double t) const { return at(t)[0]; }
    // Earliest time at which the position reaches `p` (0 <= p <= distance);
    // moves are monotone, so this is well defined.
    [[nodiscard]] double time_at(double p) const;
};

// Advances derivatives by tau inside one piece (exact: crackle is constant).
Derivs advance_derivs(const Derivs& d, double tau);

// Constant acceleration a up to v, then back down: jerk is not limited.
MoveShape trapezoid_move(double distance, const Limits& lim);
// The sources' five-interval S-curve: acceleration rises and falls as a
// smoothstep over two intervals of dt_a each, cruise dt_c, then the mirror image.
// Chosen as the fastest such curve whose peak velocity, acceleration and jerk
// (1.5 alpha_d / dt_a, the smoothstep's steepest slope) stay within `lim`.
MoveShape scurve_move(double distance, const Limits& lim);
// The same curve with the sources' own parameters (peak acceleration alpha_d,
// accelerating interval dt_a, cruise dt_c); distance follows from them.
MoveShape scurve_move(double alpha_d, double dt_a, double dt_c);
// The time-optimal rest-to-rest move under velocity, acceleration and jerk limits
// (7 segments: jerk +j, 0, -j, cruise, -j, 0, +j; some may vanish).
MoveShape jerk_move(double distance, const Limits& lim);
// Duration of jerk_move without building it: the lower bound of one move.
double jerk_min_time(double distance, const Limits& lim);

MoveShape make_move(profile::ProfileShape shape, double distance, const Limits& lim);

}  // namespace tactus::motion
