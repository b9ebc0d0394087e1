// SPDX-License-Identifier: GPL-3.0-or-later
// Sheets planned ahead on worker threads, handed out in order (plan/planner.hpp, SheetQueue).
#include <algorithm>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "plan/planner.hpp"
#include "plan/planner_internal.hpp"

namespace tactus::plan {

using Hit = Planner::Hit;

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
        return fail(ErrorKind::internal, "sheet " + std::to_string(job->sheet) +
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


}  // namespace tactus::plan
