// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The head on its belt as a linear state-space model, from commanded position u
// (what the step sequence asks for) to head position y:
//   x' = A x + B u,  y = C x.
// One inertia: the head (mass m) pulled toward the command through the belt
// (stiffness k), damped with ratio zeta:  y'' = w^2 (u - y) - 2 zeta w y'.
// Two inertias (when the profile gives rotor inertia, pulley radius and motor
// stiffness): the rotor, held to the command by the stepper's magnetic
// stiffness, drives the head through the belt; each of the two modes gets the
// profile's damping ratio (modal damping). Units: mm and s (the model is linear
// and A only depends on stiffness/mass ratios).
#include <vector>

#include "profile/profile.hpp"

namespace tactus::estimate {

struct StateSpace {
    int n = 0;
    std::vector<double> a;  // n x n, row-major
    std::vector<double> b;  // n
    std::vector<double> c;  // n
};

struct ModelVariant {
    double damping_scale = 1.0;    // multiplies every modal damping ratio
    double frequency_scale = 1.0;  // multiplies every natural frequency
};

StateSpace build_model(const profile::Dynamics& d, ModelVariant v = {});

// Undamped natural frequencies of the model's modes, ascending, in Hz.
std::vector<double> natural_frequencies_hz(const profile::Dynamics& d);
// The sources' design figure sqrt(k/m) (belt stiffness over head mass), rad/s.
double sqrt_k_over_m(const profile::Dynamics& d);
// The mode that dominates the head's motion (the lowest), in Hz: what shapers are designed for.
double dominant_frequency_hz(const profile::Dynamics& d);

}  // namespace tactus::estimate
