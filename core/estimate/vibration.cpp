// SPDX-License-Identifier: GPL-3.0-or-later
#include "estimate/vibration.hpp"

#include "estimate/dynamics.hpp"

namespace tactus::estimate {

VibrationReport vibration_report(const profile::PrinterProfile& p, int response_points) {
    VibrationReport r;
    const auto model = build_model(p.dynamics);
    r.step = step_response(model);
    r.overshoot_ok = r.step.overshoot_pct < r.targets.overshoot_pct;
    r.rise_ok = r.step.rise_time_s < r.targets.rise_time_s;
    r.settling_ok = r.step.settling_time_s && *r.step.settling_time_s < r.targets.settling_time_s;
    r.two_inertia = model.n == 4;
    r.natural_hz = natural_frequencies_hz(p.dynamics);
    r.sqrt_k_over_m = sqrt_k_over_m(p.dynamics);
    r.damping_ratio = p.dynamics.damping_ratio;
    // Two decades below the first mode to one decade above the last.
    r.response = frequency_response(model, r.natural_hz.front() / 100, r.natural_hz.back() * 10,
                                    response_points);
    return r;
}

}  // namespace tactus::estimate
