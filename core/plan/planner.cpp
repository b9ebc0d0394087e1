// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <mutex>

#include "plan/geometry.hpp"
#include "motion/motion.hpp"
#include "motion/table_move.hpp"
#include "estimate/step_train.hpp"
#include "machine/limits.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile_json.hpp"

namespace tactus::plan {

// One dot to strike, with where the feed and the head must stand for it.
struct Planner::Hit {
    std::int32_t feed_step = 0;
    std::int32_t head_step = 0;
    Side side = Side::front;
    DotPlace place;
};

namespace {
using Hit = Planner::Hit;

Result<void> check_page(const profile::PrinterProfile& p, const layout::Page& page, std::size_t index) {
    const auto& g = p.geometry;
    const std::string where = "page " + std::to_string(index + 1);
    if (page.lines.size() > static_cast<std::size_t>(g.lines_per_page))
        return fail("has " + std::to_string(page.lines.size()) + " lines, the profile allows " +
                        std::to_string(g.lines_per_page) + " (geometry.lines_per_page)",
                    where);
    for (std::size_t l = 0; l < page.lines.size(); ++l) {
        const auto& line = page.lines[l];
        const auto lw = where + " line " + std::to_string(l + 1);
        if (line.size() > static_cast<std::size_t>(g.cells_per_line))
            return fail("has " + std::to_string(line.size()) + " cells, the profile allows " +
                            std::to_string(g.cells_per_line) + " (geometry.cells_per_line)",
                        lw);
        if (!g.eight_dot)
            for (std::size_t c = 0; c < line.size(); ++c)
                if (line[c].dots & 0xC0)
                    return fail("cell " + std::to_string(c + 1) +
                                    " has dot 7 or 8 but the profile is six-dot (geometry.eight_dot)",
                                lw);
    }
    return {};
}

Hit make_hit(const profile::PrinterProfile& p, const motion::StepAxis& carriage, const motion::StepAxis& feed,
             Side side, int line, int cell, int dot) {
    const auto place = dot_place(p, side, line, cell, dot);
    return {feed.steps_for(place.paper_y_mm),
            carriage.steps_for(carriage_target_mm(p, hammer_for(side), place.paper_x_mm)), side, place};
}

}  // namespace

// Every dot position of the profile's page on either side, computed once per
// planner (the same make_hit, so the same numbers): a sheet's dots are then
// looked up, not placed again.
struct Planner::HitTable {
    int lines = 0, cells = 0;
    std::vector<Hit> hits[2];  // [side][(line * cells + cell) * 8 + dot - 1]
    HitTable(const profile::PrinterProfile& p, const motion::StepAxis& carriage, const motion::StepAxis& feed)
        : lines(std::max(0, p.geometry.lines_per_page)), cells(std::max(0, p.geometry.cells_per_line)) {
        const int dots = p.geometry.eight_dot ? 8 : 6;
        for (Side side : {Side::front, Side::back}) {
            auto& v = hits[side == Side::front ? 0 : 1];
            v.resize(static_cast<std::size_t>(lines) * static_cast<std::size_t>(cells) * 8);
            for (int l = 0; l < lines; ++l)
                for (int c = 0; c < cells; ++c)
                    for (int d = 1; d <= dots; ++d)
                        v[static_cast<std::size_t>((l * cells + c) * 8 + d - 1)] =
                            make_hit(p, carriage, feed, side, l, c, d);
        }
    }
    // The dot's hit; nullptr outside the profile's page (a layout not checked against it).
    [[nodiscard]] const Hit* find(Side side, std::size_t line, std::size_t cell, int dot) const {
        if (line >= static_cast<std::size_t>(lines) || cell >= static_cast<std::size_t>(cells) || dot < 1 || dot > 8)
            return nullptr;
        return &hits[side == Side::front ? 0 : 1][(line * static_cast<std::size_t>(cells) + cell) * 8 +
                                                  static_cast<std::size_t>(dot - 1)];
    }
};

namespace {

// Every dot of one sheet, sorted by feed position then carriage position.
// Returns a reference to a buffer of this thread that the next call reuses
// (a sheet's dots without a reallocation per sheet).
Result<const std::vector<Hit>*> collect_hits(const profile::PrinterProfile& p, const layout::PagedDocument& doc,
                                             std::size_t sheet_number, const motion::StepAxis& carriage,
                                             const motion::StepAxis& feed, bool check,
                                             const Planner::HitTable* table = nullptr) {
    thread_local std::vector<Hit> hits, sorted;
    struct Key {
        std::int32_t feed_step, head_step;
        std::uint32_t index;
    };
    thread_local std::vector<Key> keys;
    hits.clear();
    const layout::Sheet sheet = doc.sheet(sheet_number);
    const int dots = p.geometry.eight_dot ? 8 : 6;
    for (const auto& [side, page] : {std::pair{Side::front, sheet.front}, std::pair{Side::back, sheet.back}}) {
        if (!page) continue;
        const auto index = static_cast<std::size_t>(page - doc.pages.data());
        if (check)
            if (auto r = check_page(p, *page, index); !r) return std::unexpected(r.error());
        for (std::size_t l = 0; l < page->lines.size(); ++l) {
            const auto& line = page->lines[l];
            for (std::size_t c = 0; c < line.size(); ++c) {
                const document::Cell cell = line[c];
                if (cell.blank()) continue;
                for (int d = 1; d <= dots; ++d) {
                    if (!cell.has_dot(d)) continue;
                    if (const Hit* known = table ? table->find(side, l, c, d) : nullptr)
                        hits.push_back(*known);
                    else
                        hits.push_back(make_hit(p, carriage, feed, side, static_cast<int>(l), static_cast<int>(c), d));
                }
            }
        }
    }
    // By feed position, then carriage position. The sort runs on 12-byte keys
    // carrying the dot's index, then the dots are gathered: std::sort's moves
    // depend only on its comparisons, which give the same answers as on the
    // dots, so the order is the same, ties included.
    keys.resize(hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i)
        keys[i] = {hits[i].feed_step, hits[i].head_step, static_cast<std::uint32_t>(i)};
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
        return a.feed_step != b.feed_step ? a.feed_step < b.feed_step : a.head_step < b.head_step;
    });
    sorted.resize(hits.size());
    for (std::size_t i = 0; i < keys.size(); ++i) sorted[i] = hits[keys[i].index];
    return &sorted;
}

constexpr std::uint64_t kMaxSettleTicks = static_cast<std::uint64_t>(0.5 * machine::kTickHz);  // half a second

motion::Limits limits(const profile::Axis& a) { return {a.v_max_mm_s, a.a_max_mm_s2, a.j_max_mm_s3}; }

profile::ProfileShape feed_shape(const profile::PrinterProfile& p) {
    // The paper axis has no vibration model: automatic means the time-optimal jerk-limited move.
    return p.motion.shape == profile::ProfileShape::automatic ? profile::ProfileShape::jerk
                                                              : p.motion.shape;
}

}  // namespace

struct TableEstimates::Entry {
    std::mutex mutex;
    std::unordered_map<std::uint32_t, estimate::TuneChoice> moves;
};

namespace {
struct SharedTableEstimates {
    std::mutex mutex;
    std::vector<std::pair<TableEstimates::Key, std::shared_ptr<TableEstimates::Entry>>> entries;  // oldest first
};
SharedTableEstimates& shared_table_estimates() {
    static SharedTableEstimates s;
    return s;
}
}  // namespace

TableEstimates::Key TableEstimates::key_for(const profile::PrinterProfile& p, const machine::FirmwareTables& t) {
    Key k;
    k.carriage = t.carriage;
    k.settle_ticks = profile::strike_timing(p).settle_ticks;
    k.steps_per_mm = p.carriage.steps_per_mm;
    k.dynamics = p.dynamics;
    k.vibration = p.vibration;
    k.dwell_s = p.head.dwell_s;
    return k;
}

std::shared_ptr<TableEstimates::Entry> TableEstimates::entry(const Key& key) {
    auto& s = shared_table_estimates();
    const std::lock_guard lock(s.mutex);
    for (const auto& [k, e] : s.entries)
        if (k == key) return e;
    if (s.entries.size() >= kMaxKeys) s.entries.erase(s.entries.begin());
    s.entries.emplace_back(key, std::make_shared<Entry>());
    return s.entries.back().second;
}

std::optional<estimate::TuneChoice> TableEstimates::find(Entry& e, std::uint32_t steps) {
    const std::lock_guard lock(e.mutex);
    if (auto it = e.moves.find(steps); it != e.moves.end()) return it->second;
    return std::nullopt;
}

void TableEstimates::store(Entry& e, const estimate::TuneChoice& c) {
    const std::lock_guard lock(e.mutex);
    e.moves.emplace(c.steps, c);
}

std::size_t TableEstimates::keys() {
    auto& s = shared_table_estimates();
    const std::lock_guard lock(s.mutex);
    return s.entries.size();
}

std::size_t TableEstimates::moves() {
    auto& s = shared_table_estimates();
    const std::lock_guard lock(s.mutex);
    std::size_t n = 0;
    for (const auto& [k, e] : s.entries) {
        const std::lock_guard l(e->mutex);
        n += e->moves.size();
    }
    return n;
}

void TableEstimates::clear() {
    auto& s = shared_table_estimates();
    const std::lock_guard lock(s.mutex);
    s.entries.clear();
}

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
    if (auto v = profile::validate(p); !v) return std::unexpected(v.error());
    if (o.firmware)
        if (auto t = profile::check_firmware_tables(*o.firmware, p); !t) return std::unexpected(t.error());
    return Planner(p, o);
}

Result<motion::StepMove> Planner::carriage_steps(std::uint32_t steps, const motion::MoveShape& shape) {
    if (steps >= carriage_cache_.size()) carriage_cache_.resize(steps + 1);
    auto& known = carriage_cache_[steps];
    if (!known && o_.firmware) {
        known = motion::table_move(o_.firmware->carriage, static_cast<std::int32_t>(steps), strike_.settle_ticks);
    } else if (!known) {
        auto m = motion::encode_move(shape, static_cast<std::int32_t>(steps), p_.carriage.steps_per_mm,
                             p_.motion.step_tolerance);
        if (!m) return std::unexpected(located(m.error(), "carriage"));
        known = std::move(*m);
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

Result<SheetPlan> Planner::plan_sheet(const layout::PagedDocument& doc, std::size_t sheet_number) {
    if (o_.check_layout && doc.geometry.interpoint != p_.geometry.interpoint)
        return fail(doc.geometry.interpoint ? "the document is laid out interpoint but the profile is single-sided"
                                            : "the document is laid out single-sided but the profile is interpoint",
                    "field geometry.interpoint");
    if (!hit_table_) hit_table_ = std::make_shared<const HitTable>(p_, carriage_axis_, feed_axis_);
    auto hits = collect_hits(p_, doc, sheet_number, carriage_axis_, feed_axis_, o_.check_layout, hit_table_.get());
    if (!hits) return std::unexpected(hits.error());
    SheetPlan sheet;
    sheet.index = sheet_number;
    const auto backlash = carriage_axis_.steps_for(p_.carriage.backlash_mm);
    const motion::Limits carriage_lim = limits(p_.carriage), feed_lim = limits(p_.feed);
    const auto ticks = [](double n) { return n / machine::kTickHz; };
    // v3: the firmware starts each move START_GAP cycles after the last timer
    // event before it, and times settle and hammer from the timer too
    // (firmware/PROTOCOL-v3.md, "Timing"), so these sums are its clock.
    const double gap = o_.firmware ? ticks(o_.firmware->start_gap_ticks) : 0.0;
    const double dwell = o_.firmware ? ticks(strike_.hammer_ticks) : p_.head.dwell_s;
    std::int32_t feed_pos = 0;  // each sheet starts with its top edge at the hammer line
    // Loading a sheet takes seconds: the head starts each sheet at rest.
    ringing_->reset();
    const auto& h = **hits;
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
        auto fm = feed_move(feed_steps);
        if (!fm) return std::unexpected(fm.error());
        pass.feed = *fm->first;
        pass.segments += pass.feed.segments.size();
        feed_pos = pass.feed_step;
        const double feed_time = fm->second->duration + (feed_steps > 0 ? gap : 0.0);
        const double feed_bound = motion::jerk_min_time(feed_steps / p_.feed.steps_per_mm, feed_lim);

        const double t0 = clock_s_;
        double t = t0;
        pass.moves.reserve(end - first);
        pass.strikes.reserve(end - first);
        for (std::size_t k = 0; k < end - first; ++k) {
            const Hit& hit = pass.direction > 0 ? h[first + k] : h[end - 1 - k];
            // The command stops aim_steps past the dot, in the direction of the
            // move (MoveTuner::aim_steps; 0 for table moves): a head lagging
            // behind it reaches the dot sooner. No move when the head is on
            // (or aimed at) the dot already. The lower bound moves dot to dot.
            const std::int32_t dot = hit.head_step, dot_cur = head_cur_ - aim_cur_;
            const std::int32_t aim_steps = o_.firmware ? 0 : tuner_->aim_steps();
            std::int32_t target = head_cur_;
            if (dot != dot_cur && dot != head_cur_) target = dot + (dot > head_cur_ ? aim_steps : -aim_steps);
            std::int32_t n = 0;
            const double head_mm = std::abs(dot - dot_cur) / p_.carriage.steps_per_mm;
            if (target != head_cur_) {
                // The sources' reversal test on the last, current and next stops.
                const bool reversal = static_cast<std::int64_t>(head_cur_ - head_prev_) *
                                          static_cast<std::int64_t>(target - head_cur_) < 0;
                const int dir = target > head_cur_ ? 1 : -1;
                n = target - head_cur_ + (reversal ? dir * backlash : 0);
                head_prev_ = head_cur_;
                head_cur_ = target;
            }
            aim_cur_ = head_cur_ - dot;
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
                    auto tuned = tuner_->carriage(steps);
                    if (!tuned) return std::unexpected(tuned.error());
                    tuned_[steps] = *tuned;
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
                        return fail("the head does not settle within " + std::to_string(p_.vibration.tolerance_um) +
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
                            return fail("the head does not settle before the first strike of the pass at " +
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
            const double bound = motion::jerk_min_time(head_mm, carriage_lim);
            if (k == 0 && o_.firmware) {
                // The firmware feeds first, then moves the carriage.
                t += feed_time + move_time;
                pass.lower_bound_s += std::max(feed_bound, bound);
            } else if (k == 0) {
                // The feed and the carriage's first move run at the same time.
                t += std::max(feed_time, move_time);
                pass.lower_bound_s += std::max(feed_bound, bound);
            } else {
                t += move_time;
                pass.lower_bound_s += bound;
            }
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

Result<JobPlan> plan_job(const layout::PagedDocument& doc, const profile::PrinterProfile& p,
                         const PlanOptions& o) {
    auto planner = Planner::create(p, o);
    if (!planner) return std::unexpected(planner.error());
    std::vector<SheetPlan> sheets;
    std::size_t passes = 0;
    for (std::size_t s = 1; s <= doc.sheet_count(); ++s) {
        auto sheet = planner->plan_sheet(doc, s);
        if (!sheet) return std::unexpected(sheet.error());
        passes += sheet->passes.size();
        if (o.max_passes && passes > o.max_passes)
            return fail(std::to_string(passes) + " passes in the first " + std::to_string(s) + " of " +
                            std::to_string(doc.sheet_count()) + " sheets, over the limit of " +
                            std::to_string(o.max_passes),
                        kTooManyPassesWhere);
        sheets.push_back(std::move(*sheet));
    }
    JobPlan job = planner->totals();
    job.sheets = std::move(sheets);
    return job;
}

Result<double> naive_duration(const layout::PagedDocument& doc, const profile::PrinterProfile& p) {
    if (auto v = profile::validate(p); !v) return std::unexpected(v.error());
    estimate::MoveTuner tuner(p);
    const motion::StepAxis carriage(p.carriage.steps_per_mm), feed(p.feed.steps_per_mm);
    const auto backlash = carriage.steps_for(p.carriage.backlash_mm);
    // Every dot column of each side, as carriage stops for that side's hammer.
    std::vector<std::int32_t> columns[2];
    for (Side side : {Side::front, Side::back}) {
        auto& cols = columns[side == Side::front ? 0 : 1];
        for (int c = 0; c < p.geometry.cells_per_line; ++c)
            for (int dot : {1, 4})
                cols.push_back(carriage.steps_for(
                    carriage_target_mm(p, hammer_for(side), dot_place(p, side, 0, c, dot).paper_x_mm)));
        std::sort(cols.begin(), cols.end());
    }
    auto move_time = [&](std::int32_t steps) -> Result<double> {
        auto t = tuner.carriage(static_cast<std::uint32_t>(std::abs(steps)));
        if (!t) return std::unexpected(t.error());
        return (*t)->shape.duration;
    };
    double total = 0;
    std::int32_t head = 0;
    for (std::size_t s = 1; s <= doc.sheet_count(); ++s) {
        auto hits = collect_hits(p, doc, s, carriage, feed, false);
        if (!hits) return std::unexpected(hits.error());
        const auto& h = **hits;
        std::int32_t feed_pos = 0;
        for (std::size_t first = 0; first < h.size();) {
            std::size_t end = first;
            bool sides[2] = {false, false};
            while (end < h.size() && h[end].feed_step == h[first].feed_step)
                sides[h[end++].side == Side::front ? 0 : 1] = true;
            std::vector<std::int32_t> stops;
            for (int i = 0; i < 2; ++i)
                if (sides[i]) stops.insert(stops.end(), columns[i].begin(), columns[i].end());
            std::sort(stops.begin(), stops.end());
            stops.erase(std::unique(stops.begin(), stops.end()), stops.end());
            const auto feed_steps = h[first].feed_step - feed_pos;
            feed_pos = h[first].feed_step;
            const double feed_time = motion::jerk_min_time(feed_steps / p.feed.steps_per_mm,
                                                   {p.feed.v_max_mm_s, p.feed.a_max_mm_s2, p.feed.j_max_mm_s3});
            // Return to the first column (a reversal: backlash), then step right column by column.
            auto back = move_time(std::abs(stops.front() - head) + (head != stops.front() ? backlash : 0));
            if (!back) return std::unexpected(back.error());
            total += std::max(feed_time, *back);
            for (std::size_t i = 1; i < stops.size(); ++i) {
                auto m = move_time(stops[i] - stops[i - 1] + (i == 1 ? backlash : 0));
                if (!m) return std::unexpected(m.error());
                total += *m;
            }
            head = stops.back();
            total += static_cast<double>(end - first) * p.head.dwell_s;
            first = end;
        }
    }
    return total;
}

}  // namespace tactus::plan
