// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated controller callers hold: the protocol's class picked from the
// firmware it runs, and swapped when another is flashed.
#include "controller/sim_controller.hpp"

#include <utility>

namespace tactus::controller {

std::vector<LoggedStrike> planned_strikes(const plan::JobPlan& plan) {
    std::vector<LoggedStrike> out;
    std::uint16_t index = 0;
    for (const auto& sheet : plan.sheets) {
        for (const auto& pass : sheet.passes) {
            for (const auto& s : pass.strikes) {
                LoggedStrike l;
                l.sheet = static_cast<std::uint16_t>(sheet.index);
                l.side = s.side;
                l.hammer = s.hammer;
                l.carriage_step = s.carriage_step;
                l.feed_step = pass.feed_step;
                l.pass_index = index;
                l.time_s = s.time_s;
                l.x_mm = s.x_mm;
                l.y_mm = s.y_mm;
                out.push_back(l);
            }
            ++index;
        }
    }
    return out;
}

namespace {

std::unique_ptr<SimSession> speaking(SimOptions options) {
    if (options.firmware) return std::make_unique<SimControllerV3>(std::move(options));
    return std::make_unique<SimControllerV2>(std::move(options));
}

}  // namespace

SimController::SimController(SimOptions options) : s_(speaking(std::move(options))) {}

void SimController::reflash(std::optional<machine::FirmwareTables> firmware, double now) {
    s_->advance(now);
    // The other protocol's firmware: its class takes over the session layer
    // (the strike log, the statistics, the paper and the injected faults);
    // what only the old protocol's executor held is gone with it.
    const bool v3 = firmware.has_value();
    if (v3 && s_->protocol() != encode::kProtocolV3)
        s_ = std::make_unique<SimControllerV3>(std::move(*s_));
    else if (!v3 && s_->protocol() != encode::kProtocolVersion)
        s_ = std::make_unique<SimControllerV2>(std::move(*s_));
    s_->flashed(std::move(firmware), now);
}

}  // namespace tactus::controller
