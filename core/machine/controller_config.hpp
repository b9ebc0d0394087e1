// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The controller's configuration in its own units, and the one mapping from
// machine dimensions onto it. The profile stage feeds it a printer profile;
// the encoder sends it in CONFIGURE; the simulated controller runs on it.
#include <cstdint>

namespace tactus::machine {

struct ControllerConfig {
    std::uint32_t carriage_steps_per_m = 80'000;  // 80 steps/mm
    std::uint32_t feed_steps_per_m = 40'000;
    std::int32_t carriage_travel_steps = 24'000;  // soft limit: beyond it the limit switch trips
    std::uint16_t home_interval_ticks = 300;      // constant rate for HOME and SEEK
    std::uint16_t hammer_ticks = 1843;            // hammer pulse, 2 ms
    std::uint16_t keepalive_ms = 2000;            // 0: no keep-alive watchdog
    bool operator==(const ControllerConfig&) const = default;
};

// What the mapping needs to know of the machine, in millimetres and seconds.
struct MachineDimensions {
    double carriage_steps_per_mm = 80;
    double feed_steps_per_mm = 40;
    double carriage_travel_mm = 300;  // from home to the far soft limit
    double hammer_dwell_s = 0.002;
};

ControllerConfig controller_config(const MachineDimensions& m);

}  // namespace tactus::machine
