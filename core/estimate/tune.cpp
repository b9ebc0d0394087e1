// SPDX-License-Identifier: GPL-3.0-or-later
#include "estimate/tune.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "estimate/dynamics.hpp"
#include "machine/limits.hpp"

namespace tactus::estimate {
namespace {

using profile::ProfileShape;
using profile::ShaperKind;

constexpr std::int64_t kMaxSettleTicks = static_cast<std::int64_t>(0.5 * machine::kTickHz);  // half a second

// Fixed-point with `digits` decimals (snprintf needs a literal format under -Wformat=2).
std::string fmt(int digits, double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

std::string describe(ProfileShape s, ShaperKind k, double scale, double settle) {
    return std::string(profile::to_string(s)) + "/" + profile::to_string(k) + " at " +
           fmt(0, scale * 100) + "% speed" +
           (settle > 0 ? " + " + fmt(1, settle * 1000) + " ms settle" : std::string());
}

struct Candidate {
    ProfileShape shape;
    ShaperKind shaper;
    double scale;
    double settle;
    motion::MoveShape move;  // with its settle
    std::uint32_t settle_ticks = 0;
    double base_duration = 0;
    std::shared_ptr<const Ringing::Move> effect;  // the move without its settle, once prepared
};

// The move followed by `settle` seconds at rest on the target before the strike.
motion::MoveShape with_settle(motion::MoveShape m, double settle) {
    if (settle <= 0 || m.pieces.empty()) return m;
    m.pieces.push_back(motion::Piece{m.duration, settle, motion::Derivs{m.distance, 0, 0, 0, 0, 0}});
    m.duration += settle;
    return m;
}

}  // namespace

MoveTuner::MoveTuner(const profile::PrinterProfile& p) : p_(p), ringing_(p) {
    const double f = dominant_frequency_hz(p.dynamics);
    for (auto k : {ShaperKind::none, ShaperKind::zv, ShaperKind::mzv, ShaperKind::zvd, ShaperKind::ei})
        shapers_.push_back(motion::design_shaper(k, f, p.dynamics.damping_ratio));
    if (p.motion.shape == ProfileShape::automatic || p.motion.shaper == ShaperKind::automatic)
        aim_steps_ = choose_aim_steps();
}

std::int32_t MoveTuner::choose_aim_steps() {
    // Measured on the move that wins on heavily damped machines, the
    // time-optimal one and the shortest settle after it: whichever aim the
    // choice lands on, every move is then tuned (and checked) with it.
    const auto& g = p_.geometry;
    const double spm = p_.carriage.steps_per_mm;
    const motion::Limits lim{p_.carriage.v_max_mm_s, p_.carriage.a_max_mm_s2, p_.carriage.j_max_mm_s3};
    std::vector<std::shared_ptr<const Ringing::Move>> moves;
    std::vector<std::int64_t> lengths;
    for (double mm : {g.dot_pitch_mm, g.cell_pitch_mm - g.dot_pitch_mm, g.cell_pitch_mm}) {
        const auto steps = std::lround(std::max(0.0, mm) * spm);
        if (steps <= 0 || std::find(lengths.begin(), lengths.end(), steps) != lengths.end()) continue;
        lengths.push_back(steps);
        moves.push_back(ringing_.prepare(motion::jerk_move(static_cast<double>(steps) / spm, lim)));
    }
    std::int32_t best = 0;
    std::int64_t best_ticks = -1;
    for (std::int32_t aim = 0; 1000.0 * aim / spm < target_um(); ++aim) {
        std::int64_t total = 0;
        for (const auto& m : moves) {
            const auto t = ringing_.settle_after(*m, target_um(), kMaxSettleTicks, aim / spm);
            if (t < 0) {
                total = -1;
                break;
            }
            total += t;
        }
        if (total >= 0 && (best_ticks < 0 || total < best_ticks)) best_ticks = total, best = aim;
    }
    return best;
}

const motion::Shaper& MoveTuner::design_shaper(ShaperKind k) const {
    const auto i = static_cast<std::size_t>(k);
    return shapers_[i < shapers_.size() ? i : 0];
}

double MoveTuner::nominal_residual_um(const motion::MoveShape& m) {
    return ringing_.from_rest(*ringing_.prepare(m)).nominal_um;
}

double MoveTuner::worst_residual_um(const motion::MoveShape& m) {
    return ringing_.from_rest(*ringing_.prepare(m)).worst_um;
}

Result<const TunedMove*> MoveTuner::carriage(std::uint32_t steps) {
    if (auto it = cache_.find(steps); it != cache_.end()) return &it->second;
    const double distance = steps / p_.carriage.steps_per_mm;
    const bool auto_shape = p_.motion.shape == ProfileShape::automatic;
    const bool auto_shaper = p_.motion.shaper == ShaperKind::automatic;
    // Automatic shape choice keeps to the profiles that honour j_max; the
    // trapezoid (unbounded jerk) is used only when the profile asks for it.
    std::vector<ProfileShape> shapes = auto_shape ? std::vector{ProfileShape::jerk, ProfileShape::scurve}
                                                  : std::vector{p_.motion.shape};
    std::vector<ShaperKind> kinds = auto_shaper ? std::vector{ShaperKind::none, ShaperKind::zv,
                                                              ShaperKind::mzv, ShaperKind::zvd,
                                                              ShaperKind::ei}
                                                : std::vector{p_.motion.shaper};
    std::vector<double> scales = (auto_shape || auto_shaper)
                                     ? std::vector{1.0, 0.8, 0.64, 0.5, 0.4, 0.3, 0.2, 0.1, 0.05}
                                     : std::vector{1.0};
    std::vector<Candidate> cands;
    const bool tuned = auto_shape || auto_shaper;
    for (double s : scales) {
        const motion::Limits lim{p_.carriage.v_max_mm_s * s, p_.carriage.a_max_mm_s2 * s * s,
                               p_.carriage.j_max_mm_s3 * s * s * s};
        for (auto shape : shapes) {
            const auto base = motion::make_move(shape, distance, lim);
            for (auto k : kinds) {
                Candidate c{shape, k, s, 0.0, motion::shape_move(base, design_shaper(k)), 0, 0.0, nullptr};
                c.base_duration = c.move.duration;
                // At full speed, each unshaped move also with the shortest rest before the
                // strike (to the tick) that brings the band's worst case within
                // target: a head whose damping may be far above nominal creeps onto
                // the target after the command stops, and a rest can be cheaper
                // than a shaper or a slower move.
                if (tuned && s == 1.0 && steps > 0 && k == ShaperKind::none) {
                    Candidate r = c;
                    r.effect = ringing_.prepare(r.move);
                    const auto ticks = ringing_.settle_after(*r.effect, target_um(), kMaxSettleTicks, aim_mm());
                    if (ticks > 0) {
                        r.settle_ticks = static_cast<std::uint32_t>(ticks);
                        r.settle = static_cast<double>(ticks) / machine::kTickHz;
                        r.move = with_settle(r.move, r.settle);
                        cands.push_back(std::move(r));
                    }
                }
                cands.push_back(std::move(c));
            }
        }
    }
    std::stable_sort(cands.begin(), cands.end(), [](const Candidate& a, const Candidate& b) {
        return a.move.duration < b.move.duration;
    });
    const double tol = p_.vibration.tolerance_um;
    std::string rejected;
    int n_rejected = 0;
    double best_worst = 1e300;
    std::string best_name;
    for (std::size_t i = 0; i < cands.size(); ++i) {
        auto& c = cands[i];
        if (!c.effect) c.effect = ringing_.prepare(c.move);  // no settle: the move is the base
        Ringing::Residual res;
        if (steps > 0) {
            res = ringing_.from_rest(*c.effect, c.settle_ticks > 0 ? c.settle : 0.0, aim_mm());
        }
        const double worst = res.worst_um;
        const bool last = i + 1 == cands.size();
        const bool fixed = !(auto_shape || auto_shaper);
        if (worst <= target_um() || fixed) {
            TunedMove t;
            t.choice.steps = steps;
            t.choice.distance_mm = distance;
            t.choice.shape = c.shape;
            t.choice.shaper = c.shaper;
            t.choice.speed_scale = c.scale;
            t.choice.settle_s = c.settle;
            t.choice.settle_ticks = c.settle_ticks;
            t.choice.duration_s = c.move.duration;
            t.choice.residual_um = res.nominal_um;
            t.choice.worst_residual_um = worst;
            t.choice.within_tolerance = worst <= tol;
            if (fixed) {
                t.choice.why = "fixed by the profile (motion.profile, motion.shaper); worst case " +
                               fmt(1, worst) + " um against a tolerance of " + fmt(1, tol) + " um";
            } else {
                t.choice.why = "fastest of " + std::to_string(cands.size()) +
                               " candidates whose worst-case residual (" + fmt(1, worst) +
                               " um) is within " + fmt(1, tol) + " um";
                if (n_rejected > 0)
                    t.choice.why += "; " + std::to_string(n_rejected) + " faster rejected: " + rejected;
                if (aim_steps_ > 0)
                    t.choice.why += "; the command stops " + std::to_string(aim_steps_) + " steps (" +
                                    fmt(1, 1000.0 * aim_mm()) + " um) past the dot";
            }
            t.shape = std::move(c.move);
            t.base_duration_s = c.base_duration;
            t.effect = std::move(c.effect);
            t.settled = c.settle_ticks > 0 ? ringing_.then_rest(*t.effect, c.settle_ticks) : t.effect;
            return &cache_.emplace(steps, std::move(t)).first->second;
        }
        if (worst < best_worst) best_worst = worst, best_name = describe(c.shape, c.shaper, c.scale, c.settle);
        if (n_rejected < 3)
            rejected += (n_rejected ? ", " : "") + describe(c.shape, c.shaper, c.scale, c.settle) + " " +
                        fmt(1, worst) + " um";
        ++n_rejected;
        if (last) break;
    }
    return fail(ErrorKind::input, "no profile, shaper or speed keeps the worst-case residual of a " +
                    fmt(3, distance) + " mm carriage move within " + fmt(3, tol) +
                    " um (best: " + best_name + ", " + fmt(1, best_worst) +
                    " um): unreachable at any speed",
                "field vibration.tolerance_um");
}

}  // namespace tactus::estimate
