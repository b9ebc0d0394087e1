// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The technician's vibration sheet for one profile: step response against the
// sources' targets, natural frequencies, and the frequency response.
#include <vector>

#include "estimate/simulate.hpp"
#include "profile/profile.hpp"

namespace tactus::estimate {

// The sources' design targets for one positioning move of the head.
struct Targets {
    double overshoot_pct = 2.0;
    double rise_time_s = 0.005;
    double settling_time_s = 0.010;
};

struct VibrationReport {
    StepMetrics step;
    Targets targets;
    bool overshoot_ok = false;
    bool rise_ok = false;
    bool settling_ok = false;
    [[nodiscard]] bool all_ok() const { return overshoot_ok && rise_ok && settling_ok; }
    bool two_inertia = false;
    std::vector<double> natural_hz;  // undamped, per mode, ascending
    double sqrt_k_over_m = 0;        // rad/s, the sources' design figure (above ~170 meets the targets)
    double damping_ratio = 0;
    std::vector<FrequencyPoint> response;
};

VibrationReport vibration_report(const profile::PrinterProfile& p, int response_points = 41);

}  // namespace tactus::estimate
