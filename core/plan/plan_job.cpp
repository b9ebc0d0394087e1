// SPDX-License-Identifier: GPL-3.0-or-later
// A whole job's plan, and the naive plan it is compared with.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "motion/motion.hpp"
#include "plan/geometry.hpp"
#include "plan/planner.hpp"
#include "plan/planner_internal.hpp"
#include "profile/profile_json.hpp"
#include "common/try.hpp"

namespace tactus::plan {

Result<JobPlan> plan_job(const layout::PagedDocument& doc, const profile::PrinterProfile& p,
                         const PlanOptions& o, unsigned threads) {
    TACTUS_TRY(planner, Planner::create(p, o));
    std::vector<SheetPlan> sheets;
    std::size_t passes = 0;
    SheetQueue queue(planner, doc, 1, threads);
    for (std::size_t s = 1; s <= doc.sheet_count(); ++s) {
        TACTUS_TRY(sheet, queue.next());
        passes += sheet.passes.size();
        if (o.max_passes && passes > o.max_passes)
            return fail(ErrorKind::input, std::to_string(passes) + " passes in the first " + std::to_string(s) + " of " +
                            std::to_string(doc.sheet_count()) + " sheets, over the limit of " +
                            std::to_string(o.max_passes),
                        kTooManyPassesWhere);
        sheets.push_back(std::move(sheet));
    }
    JobPlan job = planner.totals();
    job.sheets = std::move(sheets);
    return job;
}

Result<double> naive_duration(const layout::PagedDocument& doc, const profile::PrinterProfile& p) {
    TACTUS_TRY_VOID(profile::validate(p));
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
        TACTUS_TRY(t, tuner.carriage(static_cast<std::uint32_t>(std::abs(steps))));
        return t->shape.duration;
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
            TACTUS_TRY(back, move_time(std::abs(stops.front() - head) + (head != stops.front() ? backlash : 0)));
            total += std::max(feed_time, back);
            for (std::size_t i = 1; i < stops.size(); ++i) {
                TACTUS_TRY(m, move_time(stops[i] - stops[i - 1] + (i == 1 ? backlash : 0)));
                total += m;
            }
            head = stops.back();
            total += static_cast<double>(end - first) * p.head.dwell_s;
            first = end;
        }
    }
    return total;
}


}  // namespace tactus::plan
