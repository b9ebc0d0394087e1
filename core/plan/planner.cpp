// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "estimate/step_train.hpp"
#include "machine/limits.hpp"
#include "motion/motion.hpp"
#include "motion/table_move.hpp"
#include "plan/geometry.hpp"
#include "plan/planner_internal.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile_json.hpp"
#include "common/try.hpp"

namespace tactus::plan {

using Hit = Planner::Hit;

std::int32_t head_move(std::int32_t& prev, std::int32_t& cur, std::int32_t& aimed, std::int32_t dot,
                       std::int32_t aim, std::int32_t backlash) {
    std::int32_t target = cur;
    if (dot != cur - aimed && dot != cur) target = dot + (dot > cur ? aim : -aim);
    aimed = target - dot;
    if (target == cur) return 0;
    const bool reversal = static_cast<std::int64_t>(cur - prev) * static_cast<std::int64_t>(target - cur) < 0;
    const int dir = target > cur ? 1 : -1;
    const std::int32_t n = target - cur + (reversal ? dir * backlash : 0);
    prev = cur;
    cur = target;
    return n;
}

namespace {

constexpr std::uint64_t kMaxSettleTicks = static_cast<std::uint64_t>(0.5 * machine::kTickHz);  // half a second

motion::Limits limits(const profile::Axis& a) { return {a.v_max_mm_s, a.a_max_mm_s2, a.j_max_mm_s3}; }

profile::ProfileShape feed_shape(const profile::PrinterProfile& p) {
    // The paper axis has no vibration model: automatic means the time-optimal jerk-limited move.
    return p.motion.shape == profile::ProfileShape::automatic ? profile::ProfileShape::jerk
                                                              : p.motion.shape;
}

}  // namespace

Planner::Planner(const profile::PrinterProfile& p, const PlanOptions& o)
    : p_(p),
      o_(o),
      tuner_(std::make_unique<estimate::MoveTuner>(p)),
      ringing_(std::make_unique<estimate::Ringing>(p)),
      carriage_axis_(p.carriage.steps_per_mm),
      feed_axis_(p.feed.steps_per_mm) {
    if (o_.firmware) {
        // The firmware's HOME leaves the carriage last moving toward home, so
        // the first move away from it takes up the backlash.
        head_prev_ = 1;
        strike_ = profile::strike_timing(p_);
        if (o_.share_table_estimates) shared_choice_ = TableEstimates::entry(TableEstimates::key_for(p_, *o_.firmware));
    }
}

Result<Planner> Planner::create(const profile::PrinterProfile& p, const PlanOptions& o) {
    TACTUS_TRY_VOID(profile::validate(p));
    if (o.firmware)
        TACTUS_TRY_VOID(profile::check_firmware_tables(*o.firmware, p));
    return Planner(p, o);
}

Result<motion::StepMove> Planner::carriage_steps(std::uint32_t steps, const motion::MoveShape& shape) {
    if (steps >= carriage_cache_.size()) carriage_cache_.resize(steps + 1);
    auto& known = carriage_cache_[steps];
    if (!known && shared_moves_) {
        const std::lock_guard lock(shared_moves_->mutex);
        if (auto it = shared_moves_->moves.find(steps); it != shared_moves_->moves.end()) known = it->second;
    }
    if (known) return *known;
    if (o_.firmware) {
        known = motion::table_move(o_.firmware->carriage, static_cast<std::int32_t>(steps), strike_.settle_ticks);
    } else {
        auto m = motion::encode_move(shape, static_cast<std::int32_t>(steps), p_.carriage.steps_per_mm,
                             p_.motion.step_tolerance);
        if (!m) return std::unexpected(located(m.error(), "carriage"));
        known = std::move(*m);
    }
    if (shared_moves_) {
        // The same move whoever encodes it (its tuned shape is the same): the first one stays.
        const std::lock_guard lock(shared_moves_->mutex);
        shared_moves_->moves.emplace(steps, *known);
    }
    return *known;
}

const estimate::TuneChoice& Planner::table_move_choice(std::uint32_t steps, const motion::StepMove& m) {
    auto it = table_choice_.find(steps);
    if (it != table_choice_.end()) return it->second;
    if (shared_choice_)
        if (auto c = TableEstimates::find(*shared_choice_, steps)) return table_choice_.emplace(steps, std::move(*c)).first->second;
    // The head model runs on the step train the firmware fires (its table's
    // step times, the settle at rest after them), not on an ideal S-curve.
    estimate::TuneChoice c;
    c.steps = steps;
    c.distance_mm = steps / p_.carriage.steps_per_mm;
    c.duration_s = m.duration_s;
    c.settle_s = static_cast<double>(m.settle_ticks) / machine::kTickHz;
    if (steps > 0) {
        // The step train (estimate::step_train_shape) by runs of equal intervals.
        const auto& ringing = tuner_->ringing();
        const auto res =
            ringing.from_rest(*ringing.prepare_step_train(m.segments, p_.carriage.steps_per_mm, m.duration_s));
        c.residual_um = res.nominal_um;
        c.worst_residual_um = res.worst_um;
    }
    c.within_tolerance = c.worst_residual_um <= p_.vibration.tolerance_um;
    c.why = "the firmware's table move (its ramp table, no choice)";
    if (shared_choice_) TableEstimates::store(*shared_choice_, c);
    return table_choice_.emplace(steps, std::move(c)).first->second;
}

Result<std::pair<const motion::StepMove*, const motion::MoveShape*>> Planner::feed_move(std::uint32_t steps) {
    auto it = feed_cache_.find(steps);
    if (it == feed_cache_.end() && o_.firmware) {
        // A table move; its shape is only a duration (the feed has no vibration model).
        auto m = motion::table_move(o_.firmware->feed, static_cast<std::int32_t>(steps), 0);
        motion::MoveShape shape;
        shape.distance = steps / p_.feed.steps_per_mm;
        shape.duration = m.duration_s;
        it = feed_cache_.emplace(steps, std::pair{std::move(m), std::move(shape)}).first;
    } else if (it == feed_cache_.end()) {
        auto shape = motion::make_move(feed_shape(p_), steps / p_.feed.steps_per_mm, limits(p_.feed));
        auto m = motion::encode_move(shape, static_cast<std::int32_t>(steps), p_.feed.steps_per_mm,
                             p_.motion.step_tolerance);
        if (!m) return std::unexpected(located(m.error(), "feed"));
        it = feed_cache_.emplace(steps, std::pair{std::move(*m), std::move(shape)}).first;
    }
    return std::pair{&it->second.first, &it->second.second};
}

Result<const std::vector<Hit>*> Planner::sheet_hits(const layout::PagedDocument& doc, std::size_t sheet_number) {
    if (o_.check_layout && doc.geometry.interpoint != p_.geometry.interpoint)
        return fail(ErrorKind::input, doc.geometry.interpoint ? "the document is laid out interpoint but the profile is single-sided"
                                            : "the document is laid out single-sided but the profile is interpoint",
                    "field geometry.interpoint");
    if (!hit_table_) hit_table_ = std::make_shared<const HitTable>(p_, carriage_axis_, feed_axis_);
    return collect_hits(p_, doc, sheet_number, carriage_axis_, feed_axis_, o_.check_layout, hit_table_.get());
}

double Planner::dwell_time() const {
    return o_.firmware ? static_cast<double>(strike_.hammer_ticks) / machine::kTickHz : p_.head.dwell_s;
}

Result<SheetPlan> Planner::plan_sheet(const layout::PagedDocument& doc, std::size_t sheet_number) {
    auto hits = sheet_hits(doc, sheet_number);
    if (!hits) return std::unexpected(hits.error());
    return plan_hits(sheet_number, **hits);
}

Result<SheetPlan> Planner::plan_hits(std::size_t sheet_number, const std::vector<Hit>& h) {
    SheetPlan sheet;
    sheet.index = sheet_number;
    const auto backlash = carriage_axis_.steps_for(p_.carriage.backlash_mm);
    const motion::Limits carriage_lim = limits(p_.carriage), feed_lim = limits(p_.feed);
    const auto ticks = [](double n) { return n / machine::kTickHz; };
    // v3: the firmware starts each move START_GAP cycles after the last timer
    // event before it, and times settle and hammer from the timer too
    // (docs/protocol.md, "Timing"), so these sums are its clock.
    const double gap = o_.firmware ? ticks(o_.firmware->start_gap_ticks) : 0.0;
    const double dwell = dwell_time();
    std::int32_t feed_pos = 0;  // each sheet starts with its top edge at the hammer line
    // Loading a sheet takes seconds: the head starts each sheet at rest.
    ringing_->reset();
    for (std::size_t first = 0; first < h.size();) {
        std::size_t end = first;
        while (end < h.size() && h[end].feed_step == h[first].feed_step) ++end;
        Pass pass;
        pass.sheet = sheet_number;
        pass.side = h[first].side;
        pass.y_mm = h[first].place.paper_y_mm;
        pass.feed_step = h[first].feed_step;
        pass.direction = p_.motion.bidirectional ? next_direction_ : +1;
        if (p_.motion.bidirectional) next_direction_ = -next_direction_;

        const auto feed_steps = static_cast<std::uint32_t>(pass.feed_step - feed_pos);
        TACTUS_TRY(fm, feed_move(feed_steps));
        pass.feed = *fm.first;
        pass.segments += pass.feed.segments.size();
        feed_pos = pass.feed_step;
        const double feed_time = fm.second->duration + (feed_steps > 0 ? gap : 0.0);
        const double feed_bound = motion::jerk_min_time(feed_steps / p_.feed.steps_per_mm, feed_lim);

        const double t0 = clock_s_;
        double t = t0;
        pass.moves.reserve(end - first);
        pass.strikes.reserve(end - first);
        for (std::size_t k = 0; k < end - first; ++k) {
            const Hit& hit = pass.direction > 0 ? h[first + k] : h[end - 1 - k];
            // The command stops aim_steps past the dot (head_move); the lower
            // bound moves dot to dot.
            const std::int32_t dot = hit.head_step, dot_cur = head_cur_ - aim_cur_;
            const std::int32_t aim_steps = o_.firmware ? 0 : tuner_->aim_steps();
            const auto head_steps = static_cast<std::uint32_t>(std::abs(dot - dot_cur));
            const double head_mm = head_steps / p_.carriage.steps_per_mm;
            const std::int32_t n = head_move(head_prev_, head_cur_, aim_cur_, dot, aim_steps, backlash);
            // Where the command rests past the dot: the residual is |head - dot|.
            const double off_mm = aim_cur_ / p_.carriage.steps_per_mm;
            motor_step_ += n;
            // Table moves (v3) are not tuned (no shape to choose); their
            // residual is estimated on the table's step train.
            double residual_um = 0, worst_residual_um = 0;
            bool within_tolerance = true;
            Result<motion::StepMove> sm;
            double move_time = 0;
            if (o_.firmware) {
                sm = carriage_steps(static_cast<std::uint32_t>(std::abs(n)), {});
                if (sm) {
                    move_time = sm->duration_s + (n != 0 ? gap : 0.0);
                    const auto& choice = table_move_choice(static_cast<std::uint32_t>(std::abs(n)), *sm);
                    residual_um = choice.residual_um;
                    worst_residual_um = choice.worst_residual_um;
                    within_tolerance = choice.within_tolerance;
                }
            } else {
                const auto steps = static_cast<std::uint32_t>(std::abs(n));
                if (steps >= tuned_.size()) tuned_.resize(steps + 1, nullptr);
                if (!tuned_[steps]) {
                    TACTUS_TRY(tuned, tuner_->carriage(steps));
                    tuned_[steps] = tuned;
                }
                const estimate::TunedMove& tm = *tuned_[steps];
                sm = carriage_steps(static_cast<std::uint32_t>(std::abs(n)), tm.shape);
                if (!sm) return std::unexpected(sm.error());
                // Carry the ringing through the move and the tuned settle (found
                // with the head at rest before the move); when the head as it
                // really is needs more, the shortest rest that is enough follows.
                const double aim = tuner_->target_um();
                std::int64_t settle = tm.choice.settle_ticks;
                if (n != 0) ringing_->move(*tm.settled, n > 0 ? 1 : -1);
                else ringing_->rest_ticks(static_cast<std::uint64_t>(settle));
                auto res = ringing_->residual(off_mm);
                if (res.worst_um > aim) {
                    const auto more = ringing_->settle_ticks(aim, 0, kMaxSettleTicks, off_mm);
                    if (more < 0)
                        return fail(ErrorKind::input, "the head does not settle within " + std::to_string(p_.vibration.tolerance_um) +
                                        " um before strike " + std::to_string(k + 1) + " of the pass at " +
                                        std::to_string(pass.y_mm) + " mm",
                                    "field vibration.tolerance_um");
                    ringing_->rest_ticks(static_cast<std::uint64_t>(more));
                    settle += more;
                    res = ringing_->residual(off_mm);
                }
                move_time = tm.base_duration_s + static_cast<double>(settle) / machine::kTickHz;
                if (k == 0 && feed_time > move_time) {
                    // The carriage waits for the paper at rest: that wait settles it too.
                    ringing_->rest(feed_time - move_time);
                    res = ringing_->residual(off_mm);
                    if (res.worst_um > p_.vibration.tolerance_um) {
                        // Seldom: the ringing after the longer wait is not within tolerance.
                        const auto more = ringing_->settle_ticks(aim, 0, kMaxSettleTicks, off_mm);
                        if (more < 0)
                            return fail(ErrorKind::input, "the head does not settle before the first strike of the pass at " +
                                            std::to_string(pass.y_mm) + " mm",
                                        "field vibration.tolerance_um");
                        ringing_->rest_ticks(static_cast<std::uint64_t>(more));
                        res = ringing_->residual(off_mm);
                        move_time = feed_time + static_cast<double>(more) / machine::kTickHz;
                        settle = static_cast<std::int64_t>(
                            std::ceil((move_time - tm.base_duration_s) * machine::kTickHz));
                    }
                }
                residual_um = res.nominal_um;
                worst_residual_um = res.worst_um;
                within_tolerance = res.worst_um <= p_.vibration.tolerance_um;
                ringing_->dwell();
                // The controller waits `settle` ticks at rest after the move's last step.
                sm->settle_ticks = sm->settle_ticks - tm.choice.settle_ticks + static_cast<std::uint32_t>(settle);
                sm->duration_s = tm.base_duration_s + static_cast<double>(settle) / machine::kTickHz;
            }
            if (!sm) return std::unexpected(sm.error());
            sm->steps = n;
            pass.segments += sm->segments.size();
            // The time-optimal move dot to dot, by its length in steps (the same function of it).
            if (head_steps >= bound_cache_.size()) bound_cache_.resize(head_steps + 1, -1.0);
            double& bound = bound_cache_[head_steps];
            if (bound < 0) bound = motion::jerk_min_time(head_mm, carriage_lim);
            double lead = 0;  // what the clock advances before the strike
            if (k == 0 && o_.firmware) {
                // The firmware feeds first, then moves the carriage.
                lead = feed_time + move_time;
                pass.lower_bound_s += std::max(feed_bound, bound);
            } else if (k == 0) {
                // The feed and the carriage's first move run at the same time.
                lead = std::max(feed_time, move_time);
                pass.lower_bound_s += std::max(feed_bound, bound);
            } else {
                lead = move_time;
                pass.lower_bound_s += bound;
            }
            t += lead;
            if (leads_) leads_->push_back(lead);
            pass.lower_bound_s += dwell;
            Strike s;
            s.hammer = hammer_for(hit.side);
            s.side = hit.side;
            s.x_mm = hit.place.read_x_mm;
            s.y_mm = hit.place.read_y_mm;
            s.paper_x_mm = hit.place.paper_x_mm;
            s.paper_y_mm = hit.place.paper_y_mm;
            s.carriage_step = motor_step_;
            s.time_s = t;
            s.residual_um = residual_um;
            s.worst_residual_um = worst_residual_um;
            totals_.max_residual_um = std::max(totals_.max_residual_um, s.residual_um);
            totals_.max_worst_residual_um = std::max(totals_.max_worst_residual_um, s.worst_residual_um);
            if (!within_tolerance) ++totals_.strikes_over_tolerance;
            pass.moves.push_back(std::move(*sm));
            pass.strikes.push_back(s);
            t += dwell;
        }
        pass.duration_s = t - t0;
        clock_s_ = t;
        sheet.duration_s += pass.duration_s;
        sheet.lower_bound_s += pass.lower_bound_s;
        totals_.strikes += pass.strikes.size();
        totals_.segments += pass.segments;
        sheet.passes.push_back(std::move(pass));
        first = end;
    }
    totals_.duration_s += sheet.duration_s;
    totals_.lower_bound_s += sheet.lower_bound_s;
    return sheet;
}


}  // namespace tactus::plan
