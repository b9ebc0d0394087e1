// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The plan stage: laid-out pages -> passes, strikes, moves and steps, timed.
// A Planner keeps the machine state (carriage, feed, clock, sweep direction)
// from sheet to sheet, so a long book can be planned one sheet at a time in
// constant memory; plan_job collects every sheet for small documents.
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "common/result.hpp"
#include "estimate/tune.hpp"
#include "layout/page.hpp"
#include "machine/firmware_tables.hpp"
#include "plan/plan.hpp"
#include "motion/steps.hpp"
#include "profile/profile.hpp"

namespace tactus::plan {

struct PlanOptions {
    // Check the layout against the profile (lines and cells per page, interpoint).
    bool check_layout = true;
    // Plan for the reference firmware (protocol v3): every move a table move
    // of its ramp tables, the feed before the carriage (never overlapped),
    // the strike timing of profile::strike_timing, the backlash rule the
    // firmware applies (after HOME the carriage last moved toward home), and
    // its start gap before each move (FirmwareTables::start_gap_ticks). The
    // plan's step times are then the firmware's, to the machine cycle, and
    // the residuals are estimated on those step trains.
    std::optional<machine::FirmwareTables> firmware;
    // plan_job stops, failing with where == kTooManyPassesWhere, as soon as
    // the plan has more passes than this (0: no limit), so a job that cannot
    // be sent costs the memory of this many passes, not of the whole book.
    std::size_t max_passes = 0;
    // Firmware mode: share the residuals of table moves with every other
    // Planner of the process that plans with the same carriage table, strike
    // settle and head model (TableEstimates below). Off: this planner
    // estimates each table move itself. The plan is the same either way.
    bool share_table_estimates = true;
};
inline constexpr const char* kTooManyPassesWhere = "passes";

// Firmware mode's residual estimates of table moves, shared across plans.
// Estimating a table move runs every head model of the band over its step
// train (Ringing::prepare_step_train), and gives the same numbers plan after
// plan: in the sanitizer build, where that costs most, tests plan the same
// tables again and again. An entry is keyed by everything the estimate reads: the
// carriage ramp table, the strike settle, steps per mm, the head dynamics,
// the vibration band and tolerance, and the hammer dwell; a profile or a
// table that differs in any of them gets its own entry, never another's.
// The entries are shared by the planners that use them; the cache keeps the
// last kMaxKeys keys. Thread-safe.
class TableEstimates {
public:
    struct Key {
        machine::RampTable carriage;
        std::uint32_t settle_ticks = 0;
        double steps_per_mm = 0;
        profile::Dynamics dynamics;
        profile::Vibration vibration;
        double dwell_s = 0;
        bool operator==(const Key&) const = default;
    };
    struct Entry;
    static constexpr std::size_t kMaxKeys = 8;
    static Key key_for(const profile::PrinterProfile& p, const machine::FirmwareTables& t);
    // The entry for `key`, made empty when there is none.
    static std::shared_ptr<Entry> entry(const Key& key);
    // Looks up / stores the estimate of a `steps`-step table move in `e`.
    static std::optional<estimate::TuneChoice> find(Entry& e, std::uint32_t steps);
    static void store(Entry& e, const estimate::TuneChoice& c);
    // How many keys the cache holds; how many moves their entries hold.
    static std::size_t keys();
    static std::size_t moves();
    static void clear();
};

class Planner {
public:
    static Result<Planner> create(const profile::PrinterProfile& p, const PlanOptions& o = {});

    // Plans the next sheet of `doc` (sheets must come in order).
    Result<SheetPlan> plan_sheet(const layout::PagedDocument& doc, std::size_t sheet_number);
    // Running totals over the sheets planned so far (sheets left empty).
    [[nodiscard]] const JobPlan& totals() const { return totals_; }
    [[nodiscard]] estimate::MoveTuner& tuner() { return *tuner_; }
    [[nodiscard]] const profile::PrinterProfile& profile() const { return p_; }

    // Internal to planner.cpp (declared here for its free functions).
    struct Hit;
    struct HitTable;

private:
    friend class SheetQueue;
    Planner(const profile::PrinterProfile& p, const PlanOptions& o);
    // The sheet's dots, sorted (a buffer of this thread), after the checks plan_sheet makes.
    Result<const std::vector<Hit>*> sheet_hits(const layout::PagedDocument& doc, std::size_t sheet_number);
    // plan_sheet on those dots.
    Result<SheetPlan> plan_hits(std::size_t sheet_number, const std::vector<Hit>& h);
    // The hammer dwell, as the plan's clock counts it.
    [[nodiscard]] double dwell_time() const;
    Result<motion::StepMove> carriage_steps(std::uint32_t steps, const motion::MoveShape& shape);
    Result<std::pair<const motion::StepMove*, const motion::MoveShape*>> feed_move(std::uint32_t steps);
    const estimate::TuneChoice& table_move_choice(std::uint32_t steps, const motion::StepMove& m);

    profile::PrinterProfile p_;
    PlanOptions o_;
    std::shared_ptr<const HitTable> hit_table_;  // where each dot of a page is struck, computed once
    std::unique_ptr<estimate::MoveTuner> tuner_;
    // The head's ringing on every model of the band, carried from strike to
    // strike (not for table moves, whose residuals are not estimated).
    std::unique_ptr<estimate::Ringing> ringing_;
    std::vector<const estimate::TunedMove*> tuned_;  // by carriage steps: the tuner's choices, looked up once
    motion::StepAxis carriage_axis_, feed_axis_;
    std::vector<std::optional<motion::StepMove>> carriage_cache_;  // by carriage steps
    std::vector<double> bound_cache_;  // the lower bound's carriage move time by steps dot to dot (-1: not yet)
    // A SheetQueue's planners share the carriage moves they encode (thread-safe).
    struct MoveCache;
    std::shared_ptr<MoveCache> shared_moves_;
    std::unordered_map<std::uint32_t, std::pair<motion::StepMove, motion::MoveShape>> feed_cache_;
    std::unordered_map<std::uint32_t, estimate::TuneChoice> table_choice_;  // v3: residuals of table moves
    std::shared_ptr<TableEstimates::Entry> shared_choice_;                  // v3: the same, shared across plans
    JobPlan totals_;
    // Machine state carried across passes and sheets.
    double clock_s_ = 0;
    std::int32_t motor_step_ = 0;   // the controller's carriage step counter
    std::int32_t head_prev_ = -1;   // P1 of the reversal rule: homing ends moving +x (v3: toward home)
    std::int32_t head_cur_ = 0;     // P2: where the head stands (in carriage steps)
    std::int32_t aim_cur_ = 0;      // head_cur_ less the dot struck there (the command stops past it: tune.hpp)
    int next_direction_ = +1;
    machine::StrikeTiming strike_;  // v3 only
    // SheetQueue's workers: what the clock advances before each strike, in
    // order (the same doubles the serial plan adds), to time the sheet later.
    std::vector<double>* leads_ = nullptr;
};

// Plans the sheets of `doc` ahead on worker threads and hands them out in
// order: next() returns what planner.plan_sheet(doc, n) would have, byte for
// byte, and leaves the planner as that call would (its machine state, clock
// and totals), so plan_sheet may go on where a queue stopped (or a queue
// start where plan_sheet stopped; not both at once). Sheets are nearly independent:
// the head starts each one at rest and the feed at its top edge. What
// crosses sheets is cheap to carry ahead (the carriage's last two stops for
// the backlash rule, its step counter, the sweep direction), except the
// clock: a worker records what its clock advances before each strike, and
// next() adds those to the planner's clock in order, as plan_sheet would.
// Memory stays bounded: at most kAheadPerThread sheets per thread are planned ahead.
// With one thread (or fewer than kMinSheets sheets) next() is plan_sheet. Tuning new moves
// stays on the calling thread, in the serial plan's order (the tuner's
// decisions are the serial plan's). `doc` and `planner` must outlive the queue.
class SheetQueue {
public:
    // threads: 0 for std::thread::hardware_concurrency().
    SheetQueue(Planner& planner, const layout::PagedDocument& doc, std::size_t first_sheet = 1,
               unsigned threads = 0);
    ~SheetQueue();
    SheetQueue(const SheetQueue&) = delete;
    SheetQueue& operator=(const SheetQueue&) = delete;
    // The next sheet (first_sheet, then each after it, up to doc.sheet_count()).
    Result<SheetPlan> next();
    // Fewer sheets than this are planned on the calling thread.
    static constexpr std::size_t kMinSheets = 4;
    static constexpr std::size_t kAheadPerThread = 8;
    // Worker threads in use (0: planning on the calling thread).
    [[nodiscard]] unsigned threads() const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

// Every sheet of `doc` (through a SheetQueue: `threads` as there).
Result<JobPlan> plan_job(const layout::PagedDocument& doc, const profile::PrinterProfile& p,
                         const PlanOptions& o = {}, unsigned threads = 0);

// The naive plan for comparison: one sweep direction (+x), the carriage stopping
// at every dot column of the line whether or not a dot is struck there. Only its
// duration is computed. Uses the same tuned moves as the real plan.
Result<double> naive_duration(const layout::PagedDocument& doc, const profile::PrinterProfile& p);

}  // namespace tactus::plan
