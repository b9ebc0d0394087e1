// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

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
    sorted.resize(hits.size());
    // First as one 64-bit integer per dot (feed, carriage, index, from the
    // smallest of each): when no two dots share both positions, the order is
    // the only one sorted by position, whatever sorts it.
    thread_local std::vector<std::uint64_t> packed;
    if (!hits.empty() && hits.size() < (std::size_t{1} << 24)) {
        std::int32_t feed_min = hits[0].feed_step, feed_max = feed_min, head_min = hits[0].head_step,
                     head_max = head_min;
        for (const auto& h : hits) {
            feed_min = std::min(feed_min, h.feed_step), feed_max = std::max(feed_max, h.feed_step);
            head_min = std::min(head_min, h.head_step), head_max = std::max(head_max, h.head_step);
        }
        constexpr std::int64_t kRange = std::int64_t{1} << 20;
        if (std::int64_t{feed_max} - feed_min < kRange && std::int64_t{head_max} - head_min < kRange) {
            packed.resize(hits.size());
            for (std::size_t i = 0; i < hits.size(); ++i)
                packed[i] = static_cast<std::uint64_t>(hits[i].feed_step - feed_min) << 44 |
                            static_cast<std::uint64_t>(hits[i].head_step - head_min) << 24 | i;
            std::sort(packed.begin(), packed.end());
            bool tie = false;
            for (std::size_t i = 1; i < packed.size() && !tie; ++i) tie = packed[i] >> 24 == packed[i - 1] >> 24;
            if (!tie) {
                for (std::size_t i = 0; i < packed.size(); ++i) sorted[i] = hits[packed[i] & 0xFFFFFF];
                return &sorted;
            }
        }
    }
    // Dots that share both positions: their order is what std::sort leaves
    // them in, as it always was.
    keys.resize(hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i)
        keys[i] = {hits[i].feed_step, hits[i].head_step, static_cast<std::uint32_t>(i)};
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
        return a.feed_step != b.feed_step ? a.feed_step < b.feed_step : a.head_step < b.head_step;
    });
    for (std::size_t i = 0; i < keys.size(); ++i) sorted[i] = hits[keys[i].index];
    return &sorted;
}

// The carriage steps from the stop `cur` to the next, for `dot`: the command
// stops `aim` steps past the dot in the direction it moves
// (MoveTuner::aim_steps; 0 for table moves: on the dot), a head lagging
// behind it reaching the dot sooner; it does not move when it is on (or
// aimed at) the dot already. The sources' reversal test on the last,
// current and next stops (a reversal takes up the backlash). Moves the stops
// on (prev, cur) when the head moves, and sets `aimed` to cur less the dot.
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

struct Planner::MoveCache {
    std::mutex mutex;
    std::unordered_map<std::uint32_t, motion::StepMove> moves;  // by carriage steps
};

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
        return fail(doc.geometry.interpoint ? "the document is laid out interpoint but the profile is single-sided"
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

struct SheetQueue::Impl {
    // What crosses sheets, but the clock: the carriage's last two stops (the
    // backlash rule), its step counter, the next pass's sweep direction.
    struct Machine {
        std::int32_t head_prev = 0, head_cur = 0, motor_step = 0;
        int next_direction = +1;
        std::int32_t aim_cur = 0;
        bool operator==(const Machine&) const = default;
    };
    struct Job {
        std::size_t sheet = 0;
        Machine start, end;
        std::vector<Hit> hits;
        std::optional<Error> error;  // collecting its dots failed
        // The tuned moves it uses (tuned on the calling thread).
        std::vector<std::pair<std::uint32_t, const estimate::TunedMove*>> tuned;
        bool taken = false, done = false;
        std::optional<Result<SheetPlan>> result;
        std::vector<double> leads;  // what the clock advances before each strike
        JobPlan totals;             // this sheet's part of the totals
        Machine after;              // the worker's machine state after it
    };

    Planner& planner;
    const layout::PagedDocument& doc;
    std::size_t next_sheet;     // the next to hand out
    std::size_t next_queued;    // the next to collect and queue
    Machine ahead;              // the machine after the last sheet queued
    std::size_t window = 0;     // sheets queued ahead at most
    std::vector<std::uint8_t> seen;  // by carriage steps: listed for the job being queued
    std::mutex mutex;
    std::condition_variable work, finished;
    std::deque<std::unique_ptr<Job>> jobs;  // queued, in sheet order
    bool stopping = false;
    std::vector<std::jthread> workers;  // last: stopped and joined before the rest goes

    Impl(Planner& pl, const layout::PagedDocument& d, std::size_t first)
        : planner(pl), doc(d), next_sheet(first), next_queued(first) {
        ahead = state_of(planner);
    }

    static Machine state_of(const Planner& p) {
        return {p.head_prev_, p.head_cur_, p.motor_step_, p.next_direction_, p.aim_cur_};
    }

    // Collects the next sheet's dots, carries the machine state through its
    // passes (the same head_move, the same pass order as plan_hits), tunes
    // the moves it needs that are new, in the serial plan's order, and queues it.
    void queue_next() {
        auto job = std::make_unique<Job>();
        job->sheet = next_queued++;
        job->start = ahead;
        auto hits = planner.sheet_hits(doc, job->sheet);
        if (!hits) {
            job->error = hits.error();
        } else {
            job->hits = **hits;
            const auto& h = job->hits;
            const auto backlash = planner.carriage_axis_.steps_for(planner.p_.carriage.backlash_mm);
            const bool bidirectional = planner.p_.motion.bidirectional;
            const bool tuned = !planner.o_.firmware;
            const std::int32_t aim = tuned ? planner.tuner_->aim_steps() : 0;
            auto& table = planner.tuned_;
            for (std::size_t first = 0; first < h.size();) {
                std::size_t end = first;
                while (end < h.size() && h[end].feed_step == h[first].feed_step) ++end;
                const int direction = bidirectional ? ahead.next_direction : +1;
                if (bidirectional) ahead.next_direction = -ahead.next_direction;
                for (std::size_t k = 0; k < end - first; ++k) {
                    const Hit& hit = direction > 0 ? h[first + k] : h[end - 1 - k];
                    const std::int32_t n =
                        head_move(ahead.head_prev, ahead.head_cur, ahead.aim_cur, hit.head_step, aim, backlash);
                    ahead.motor_step += n;
                    if (!tuned) continue;
                    const auto steps = static_cast<std::uint32_t>(std::abs(n));
                    if (steps >= table.size()) table.resize(steps + 1, nullptr);
                    if (!table[steps]) {
                        // A move that cannot be tuned is left to the worker, which fails on it where plan_sheet does.
                        if (auto t = planner.tuner_->carriage(steps)) table[steps] = *t;
                        else continue;
                    }
                    if (steps >= seen.size()) seen.resize(steps + 1, 0);
                    if (!seen[steps]) {
                        seen[steps] = 1;
                        job->tuned.emplace_back(steps, table[steps]);
                    }
                }
                first = end;
            }
            for (const auto& [steps, move] : job->tuned) seen[steps] = 0;
        }
        job->end = ahead;
        {
            const std::lock_guard lock(mutex);
            jobs.push_back(std::move(job));
        }
        work.notify_one();
    }

    void run() {
        std::optional<Planner> own;  // made on this thread
        for (;;) {
            Job* job = nullptr;
            {
                std::unique_lock lock(mutex);
                work.wait(lock, [&] {
                    if (stopping) return true;
                    for (const auto& j : jobs)
                        if (!j->taken) return true;
                    return false;
                });
                if (stopping) return;
                for (const auto& j : jobs)
                    if (!j->taken) {
                        job = j.get();
                        break;
                    }
                job->taken = true;
            }
            if (!own) {
                own.emplace(Planner(planner.p_, planner.o_));
                own->shared_moves_ = planner.shared_moves_;
            }
            Planner& w = *own;
            w.head_prev_ = job->start.head_prev;
            w.head_cur_ = job->start.head_cur;
            w.motor_step_ = job->start.motor_step;
            w.next_direction_ = job->start.next_direction;
            w.aim_cur_ = job->start.aim_cur;
            w.clock_s_ = 0;
            w.totals_ = {};
            for (const auto& [steps, move] : job->tuned) {
                if (steps >= w.tuned_.size()) w.tuned_.resize(steps + 1, nullptr);
                w.tuned_[steps] = move;
            }
            w.leads_ = &job->leads;
            Result<SheetPlan> r = job->error ? Result<SheetPlan>(std::unexpected(*job->error))
                                             : w.plan_hits(job->sheet, job->hits);
            w.leads_ = nullptr;
            job->totals = w.totals_;
            job->after = state_of(w);
            job->hits = {};
            {
                const std::lock_guard lock(mutex);
                job->result = std::move(r);
                job->done = true;
            }
            finished.notify_all();
        }
    }

    void stop() {
        {
            const std::lock_guard lock(mutex);
            stopping = true;
        }
        work.notify_all();
        workers.clear();  // joins
    }
};

SheetQueue::SheetQueue(Planner& planner, const layout::PagedDocument& doc, std::size_t first_sheet,
                       unsigned threads)
    : impl_(std::make_unique<Impl>(planner, doc, first_sheet)) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t sheets = doc.sheet_count() >= first_sheet ? doc.sheet_count() - first_sheet + 1 : 0;
    // A few sheets are not worth a planner per thread (each tunes nothing,
    // but sets up its own head models): plan_sheet on the calling thread.
    if (threads < 2 || sheets < kMinSheets) return;
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, sheets));
    if (!planner.shared_moves_) planner.shared_moves_ = std::make_shared<Planner::MoveCache>();
    // Enough sheets ahead that the workers go on while the caller (or the
    // thread handing out sheets) waits for a core on a busy machine; a
    // sheet's plan is well under a megabyte.
    impl_->window = kAheadPerThread * static_cast<std::size_t>(threads);
    for (unsigned i = 0; i < threads; ++i) impl_->workers.emplace_back([this] { impl_->run(); });
}

SheetQueue::~SheetQueue() { impl_->stop(); }

unsigned SheetQueue::threads() const { return static_cast<unsigned>(impl_->workers.size()); }

Result<SheetPlan> SheetQueue::next() {
    auto& q = *impl_;
    const std::size_t last = q.doc.sheet_count();
    if (q.workers.empty() || q.next_sheet > last) return q.planner.plan_sheet(q.doc, q.next_sheet++);
    while (q.next_queued <= last && q.next_queued < q.next_sheet + q.window) q.queue_next();
    std::unique_ptr<Impl::Job> job;
    {
        std::unique_lock lock(q.mutex);
        q.finished.wait(lock, [&] { return q.jobs.front()->done; });
        job = std::move(q.jobs.front());
        q.jobs.pop_front();
    }
    ++q.next_sheet;
    // Keep the workers busy while the caller uses this sheet.
    if (q.next_queued <= last) q.queue_next();
    auto& r = *job->result;
    if (!r) return std::unexpected(r.error());
    if (job->after != job->end)
        return fail("sheet " + std::to_string(job->sheet) +
                        ": planned ahead from a machine state its sheets before did not leave (a bug)",
                    "plan");
    // The clock, as plan_hits advances it: pass by pass, strike by strike.
    Planner& p = q.planner;
    SheetPlan& sheet = *r;
    const double dwell = p.dwell_time();
    std::size_t i = 0;
    sheet.duration_s = 0;
    for (auto& pass : sheet.passes) {
        const double t0 = p.clock_s_;
        double t = t0;
        for (auto& s : pass.strikes) {
            t += job->leads[i++];
            s.time_s = t;
            t += dwell;
        }
        pass.duration_s = t - t0;
        p.clock_s_ = t;
        sheet.duration_s += pass.duration_s;
    }
    const JobPlan& part = job->totals;
    p.totals_.strikes += part.strikes;
    p.totals_.segments += part.segments;
    p.totals_.strikes_over_tolerance += part.strikes_over_tolerance;
    p.totals_.max_residual_um = std::max(p.totals_.max_residual_um, part.max_residual_um);
    p.totals_.max_worst_residual_um = std::max(p.totals_.max_worst_residual_um, part.max_worst_residual_um);
    p.totals_.duration_s += sheet.duration_s;
    p.totals_.lower_bound_s += sheet.lower_bound_s;
    p.head_prev_ = job->end.head_prev;
    p.head_cur_ = job->end.head_cur;
    p.motor_step_ = job->end.motor_step;
    p.next_direction_ = job->end.next_direction;
    p.aim_cur_ = job->end.aim_cur;
    return std::move(r);
}

Result<JobPlan> plan_job(const layout::PagedDocument& doc, const profile::PrinterProfile& p,
                         const PlanOptions& o, unsigned threads) {
    auto planner = Planner::create(p, o);
    if (!planner) return std::unexpected(planner.error());
    std::vector<SheetPlan> sheets;
    std::size_t passes = 0;
    SheetQueue queue(*planner, doc, 1, threads);
    for (std::size_t s = 1; s <= doc.sheet_count(); ++s) {
        auto sheet = queue.next();
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
