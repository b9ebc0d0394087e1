// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli vibration: the head's step response against the sources' targets,
// its natural frequencies and the frequency response of head versus command.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "command.hpp"
#include "estimate/vibration.hpp"
#include "profile_arg.hpp"

namespace tactus::cli {
namespace {

struct VibrationArgs {
    std::string profile;
    bool json = false;
    int points = 41;
};

nlohmann::json to_json(const estimate::VibrationReport& r) {
    using nlohmann::json;
    json resp = json::array();
    for (const auto& f : r.response)
        resp.push_back({{"frequency_hz", f.frequency_hz},
                        {"magnitude", f.magnitude},
                        {"magnitude_db", f.magnitude_db},
                        {"phase_deg", f.phase_deg}});
    json settle = r.step.settling_time_s ? json(*r.step.settling_time_s) : json(nullptr);
    return {
        {"model", r.two_inertia ? "two-inertia" : "one-inertia"},
        {"step_response",
         {{"overshoot_pct", r.step.overshoot_pct},
          {"rise_time_s", r.step.rise_time_s},
          {"settling_time_s", settle},
          {"peak_time_s", r.step.peak_time_s}}},
        {"targets",
         {{"overshoot_pct", r.targets.overshoot_pct},
          {"rise_time_s", r.targets.rise_time_s},
          {"settling_time_s", r.targets.settling_time_s}}},
        {"pass",
         {{"overshoot", r.overshoot_ok},
          {"rise_time", r.rise_ok},
          {"settling_time", r.settling_ok},
          {"all", r.all_ok()}}},
        {"natural_frequencies_hz", r.natural_hz},
        {"sqrt_k_over_m", r.sqrt_k_over_m},
        {"damping_ratio", r.damping_ratio},
        {"frequency_response", resp},
    };
}

void print_text(const estimate::VibrationReport& r) {
    auto verdict = [](bool ok) { return ok ? "pass" : "FAIL"; };
    std::printf("model:            %s\n", r.two_inertia ? "two inertias (rotor + belt + head)" : "one inertia (head on belt)");
    std::printf("sqrt(k/m):        %.1f rad/s (the sources' design figure; above ~170 meets the targets)\n", r.sqrt_k_over_m);
    std::printf("natural freq.:   ");
    for (double f : r.natural_hz) std::printf(" %.2f Hz", f);
    std::printf("\ndamping ratio:    %.3f\n", r.damping_ratio);
    std::printf("step response        value      target   verdict\n");
    std::printf("  overshoot      %8.3f %%   < %.0f %%     %s\n", r.step.overshoot_pct, r.targets.overshoot_pct, verdict(r.overshoot_ok));
    std::printf("  rise 10-90 %%   %8.3f ms  < %.0f ms     %s\n", r.step.rise_time_s * 1e3, r.targets.rise_time_s * 1e3, verdict(r.rise_ok));
    if (r.step.settling_time_s)
        std::printf("  settling 2 %%   %8.3f ms  < %.0f ms    %s\n", *r.step.settling_time_s * 1e3, r.targets.settling_time_s * 1e3, verdict(r.settling_ok));
    else
        std::printf("  settling 2 %%      never     < %.0f ms    FAIL\n", r.targets.settling_time_s * 1e3);
    std::printf("frequency response (head position / command)\n   f [Hz]    |H|      |H| [dB]   phase [deg]\n");
    for (const auto& f : r.response)
        std::printf("%9.2f  %9.5f  %9.3f  %9.2f\n", f.frequency_hz, f.magnitude, f.magnitude_db, f.phase_deg);
}

}  // namespace

void add_vibration_command(CLI::App& app) {
    static VibrationArgs a;
    auto* cmd = app.add_subcommand("vibration", "Step response, natural frequency and frequency response of the head");
    cmd->add_option("--profile,-p", a.profile, "Printer profile JSON (default: the bundled one)");
    cmd->add_flag("--json", a.json, "Machine-readable output");
    cmd->add_option("--points", a.points, "Frequency-response points")->check(CLI::Range(2, 10000))->capture_default_str();
    cmd->callback([] {
        const auto p = load_profile_arg(a.profile);
        const auto r = estimate::vibration_report(p, a.points);
        if (a.json) std::cout << to_json(r).dump(2) << '\n';
        else print_text(r);
    });
}

}  // namespace tactus::cli
