// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Exact discretisation of the head model under a commanded move. The command is
// piecewise polynomial (motion/motion.hpp), so the model is augmented with the
// command's derivatives as states driven by the (piecewise constant) fifth
// derivative; the matrix exponential of that augmented system advances the
// state over a whole piece with no integration error (no Euler, no sub-steps).
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "estimate/dynamics.hpp"
#include "motion/motion.hpp"

namespace tactus::estimate {

class MoveSimulator {
public:
    explicit MoveSimulator(const StateSpace& model);
    ~MoveSimulator();
    MoveSimulator(MoveSimulator&&) noexcept;
    MoveSimulator& operator=(MoveSimulator&&) noexcept;

    // The head's largest distance from the move's end point while the hammer is
    // down: from the end of the move through `dwell_s`, sampled at `samples`+1
    // instants. The head starts at rest. Millimetres.
    double residual_mm(const motion::MoveShape& move, double dwell_s, int samples = 32);
    // The model's state (positions and velocities, StateSpace order) at the
    // end of `move`, the head at rest at 0 before it.
    std::vector<double> end_state(const motion::MoveShape& move);
    // Head position at each of `times` (ascending, s from the move start).
    std::vector<double> head_positions(const motion::MoveShape& move, std::span<const double> times);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

struct StepMetrics {
    double overshoot_pct = 0;
    double rise_time_s = 0;                // 10 % -> 90 %
    std::optional<double> settling_time_s;  // last exit from the 2 % band; none if it never settles
    double peak_time_s = 0;
};

// Response of the head to a unit step of the command, sampled exactly.
StepMetrics step_response(const StateSpace& model);

struct FrequencyPoint {
    double frequency_hz = 0;
    double magnitude = 0;  // |Y/U|
    double magnitude_db = 0;
    double phase_deg = 0;  // unwrapped, continuous from the lowest frequency
};

// Head position versus command, at `points` log-spaced frequencies.
std::vector<FrequencyPoint> frequency_response(const StateSpace& model, double f_lo_hz,
                                               double f_hi_hz, int points);

}  // namespace tactus::estimate
