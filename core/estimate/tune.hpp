// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Auto-tune: for each carriage move length, the fastest profile/shaper/speed
// whose worst-case residual at the strike stays within the profile's tolerance,
// the worst case taken over a band of damping and natural frequency around the
// nominal machine (real machines drift). Moves of equal length are identical,
// so each length is tuned once and cached.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "estimate/ringing.hpp"
#include "estimate/simulate.hpp"
#include "motion/motion.hpp"
#include "motion/shaper.hpp"
#include "profile/profile.hpp"

namespace tactus::estimate {

struct TuneChoice {
    std::uint32_t steps = 0;
    double distance_mm = 0;
    profile::ProfileShape shape = profile::ProfileShape::jerk;
    profile::ShaperKind shaper = profile::ShaperKind::none;
    double speed_scale = 1.0;  // v, a, j scaled by s, s^2, s^3 (the same move, slowed in time)
    double settle_s = 0;       // rest before the strike, included in duration_s
    std::uint32_t settle_ticks = 0;  // the same in controller timer ticks (settle_s = ticks / kTickHz)
    double duration_s = 0;
    double residual_um = 0;        // nominal machine
    double worst_residual_um = 0;  // over the damping/frequency band
    bool within_tolerance = true;
    std::string why;
};

struct TunedMove {
    motion::MoveShape shape;  // the move and its settle
    TuneChoice choice;
    double base_duration_s = 0;  // the move alone, without the settle
    // The move alone (no settle), and the move and its settle, on every head
    // model, for carrying the ringing.
    std::shared_ptr<const Ringing::Move> effect, settled;
};

class MoveTuner {
public:
    explicit MoveTuner(const profile::PrinterProfile& p);
    // The move for `steps` carriage steps; fails (naming vibration.tolerance_um)
    // only when auto-tuning finds nothing within tolerance.
    Result<const TunedMove*> carriage(std::uint32_t steps);
    [[nodiscard]] const std::map<std::uint32_t, TunedMove>& decisions() const { return cache_; }
    [[nodiscard]] const motion::Shaper& design_shaper(profile::ShaperKind k) const;

    // Where auto-tune has the command stop: this many carriage steps past the
    // dot, in the direction of the move (0 with the profile's shape and shaper
    // fixed). Chosen once per profile (choose_aim_steps), the same for every
    // move: a strike's residual is |head - dot|, and a head that lags behind
    // the command (a heavily damped machine creeping onto it) reaches a dot
    // the command overshoots sooner. docs/motion.md, "Aim past the dot".
    [[nodiscard]] std::int32_t aim_steps() const { return aim_steps_; }
    [[nodiscard]] double aim_mm() const { return aim_steps_ / p_.carriage.steps_per_mm; }

    // Residual of an arbitrary move on the nominal machine and its band worst
    // case (band_variants), um, the head at rest before the move, the command
    // stopping on the dot (no aim offset).
    double nominal_residual_um(const motion::MoveShape& m);
    double worst_residual_um(const motion::MoveShape& m);
    // What auto-tune aims the band's worst case at: the tolerance less 0.1 um.
    [[nodiscard]] double target_um() const { return p_.vibration.tolerance_um - kMarginUm; }
    static constexpr double kMarginUm = 0.1;
    [[nodiscard]] const Ringing& ringing() const { return ringing_; }

private:
    // The aim (0, 1, 2, ... steps, while within target_um) for which the
    // settles after the time-optimal moves of the sheet's typical lengths (dot
    // pitch, cell pitch less dot pitch, cell pitch) add up to least; ties to
    // the smaller.
    std::int32_t choose_aim_steps();
    profile::PrinterProfile p_;
    std::int32_t aim_steps_ = 0;
    Ringing ringing_;
    std::vector<motion::Shaper> shapers_;  // indexed by ShaperKind
    std::map<std::uint32_t, TunedMove> cache_;
};

}  // namespace tactus::estimate
