// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "estimate/step_train.hpp"
#include "hand_pages.hpp"
#include "machine/limits.hpp"
#include "motion/steps.hpp"
#include "motion/table_move.hpp"
#include "plan/plan_file.hpp"
#include "plan/planner.hpp"
#include "profile/firmware_tables.hpp"
#include "../common/firmware_tables_fixture.hpp"

using namespace tactus;
using namespace tactus::plan;
using tactus::test::doc_of;
using tactus::test::page_of;

namespace {
std::vector<double> xs(const Pass& p) {
    std::vector<double> v;
    for (const auto& s : p.strikes) v.push_back(s.paper_x_mm);
    return v;
}
}  // namespace

// Front: line 1 "⠉⠀⠁" (dots 1+4 in cell 1, dot 1 in cell 3), line 2 "⠂" (dot 2).
// Back: line 1 "⠁". Worked by hand with the default profile (80 steps/mm,
// backlash 0.01 mm = 1 step, concave hammer 12 mm right of the convex one).
TEST(Planner, HandWorkedSheet) {
    const auto doc = doc_of({page_of({U"⠉⠀⠁", U"⠂"}), page_of({U"⠁"})});
    auto job = plan_job(doc, profile::default_profile());
    ASSERT_TRUE(job.has_value()) << job.error().to_string();
    ASSERT_EQ(job->sheets.size(), 1u);
    const auto& passes = job->sheets[0].passes;
    ASSERT_EQ(passes.size(), 3u);
    // Dot rows in paper order: front 30, back 31.25, front 42.5 mm.
    EXPECT_DOUBLE_EQ(passes[0].y_mm, 30.0);
    EXPECT_EQ(passes[0].side, Side::front);
    EXPECT_EQ(passes[0].direction, +1);
    EXPECT_EQ(xs(passes[0]), (std::vector<double>{25.0, 27.5, 37.0}));
    EXPECT_DOUBLE_EQ(passes[1].y_mm, 31.25);
    EXPECT_EQ(passes[1].side, Side::back);
    EXPECT_EQ(passes[1].direction, -1);
    EXPECT_EQ(xs(passes[1]), (std::vector<double>{186.25}));
    EXPECT_EQ(passes[1].strikes[0].hammer, Hammer::concave);
    EXPECT_DOUBLE_EQ(passes[1].strikes[0].x_mm, 25.0);  // top-left as the reader holds the back
    EXPECT_DOUBLE_EQ(passes[2].y_mm, 42.5);
    EXPECT_EQ(passes[2].direction, +1);
    // Feed positions at 40 steps/mm.
    EXPECT_EQ(passes[0].feed_step, 1200);
    EXPECT_EQ(passes[1].feed_step, 1250);
    EXPECT_EQ(passes[2].feed_step, 1700);
    EXPECT_EQ(passes[1].feed.steps, 50);
    // Carriage step counter: 25 mm = 2000 steps, ... ; the back dot needs the
    // carriage at 186.25 - 12 = 174.25 mm = 13940 steps; going back to 25 mm
    // reverses the carriage, so one step of backlash is added. Every command
    // stops the tuner's aim (3 steps on the default profile) past its dot, in
    // the direction it moves: 2003, ..., 13943, then 2000 - 3 = 1997 moving
    // -x, less the step of backlash on the counter.
    ASSERT_EQ(estimate::MoveTuner(profile::default_profile()).aim_steps(), 3);
    EXPECT_EQ(passes[0].strikes[0].carriage_step, 2003);
    EXPECT_EQ(passes[0].strikes[1].carriage_step, 2203);
    EXPECT_EQ(passes[0].strikes[2].carriage_step, 2963);
    EXPECT_EQ(passes[1].strikes[0].carriage_step, 13943);
    EXPECT_EQ(passes[2].strikes[0].carriage_step, 1996);
    EXPECT_EQ(passes[2].moves[0].steps, 1996 - 13943);
    EXPECT_EQ(job->strikes, 5u);
    // Step moves add up to the counter at every strike (no lost step).
    std::int64_t counter = 0;
    for (const auto& p : passes)
        for (std::size_t i = 0; i < p.strikes.size(); ++i) {
            counter += p.moves[i].steps;
            EXPECT_EQ(counter, p.strikes[i].carriage_step);
        }
}

TEST(Planner, TimesAreConsistentAndAboveTheLowerBound) {
    const auto doc = doc_of({page_of({U"⠿⠿⠿⠀⠀⠀⠿", U"", U"⠁⠂⠄⠈⠐⠠"}), page_of({U"⠿⠀⠿", U"⠛⠛"})});
    auto job = plan_job(doc, profile::default_profile());
    ASSERT_TRUE(job.has_value()) << job.error().to_string();
    double sum = 0, bound = 0, last_strike = -1;
    for (const auto& p : job->sheets[0].passes) {
        EXPECT_TRUE(std::isfinite(p.duration_s));
        EXPECT_GE(p.duration_s, p.lower_bound_s - 1e-12);
        EXPECT_GT(p.segments, 0u);
        for (const auto& s : p.strikes) {
            EXPECT_GT(s.time_s, last_strike);  // strictly in order, dwell apart at least
            if (last_strike >= 0) {
                EXPECT_GE(s.time_s - last_strike, 0.004 - 1e-12);
            }
            last_strike = s.time_s;
            EXPECT_LE(s.worst_residual_um, 50.0);
            EXPECT_LE(s.residual_um, s.worst_residual_um + 1e-9);
        }
        sum += p.duration_s;
        bound += p.lower_bound_s;
    }
    EXPECT_NEAR(job->duration_s, sum, 1e-9);
    EXPECT_NEAR(job->lower_bound_s, bound, 1e-9);
    EXPECT_GE(job->duration_s / job->lower_bound_s, 1.0);
    EXPECT_LE(job->duration_s / job->lower_bound_s, 1.10);
    EXPECT_LE(job->max_worst_residual_um, 50.0);
}

TEST(Planner, EmptyRowsCostOnlyFeed) {
    // Lines 1 and 24 only: two passes, the second fed straight down 230 mm.
    std::vector<std::u32string> lines(24);
    lines[0] = U"⠁";
    lines[23] = U"⠁";
    auto job = plan_job(doc_of({page_of(lines)}), profile::default_profile());
    ASSERT_TRUE(job.has_value());
    const auto& passes = job->sheets[0].passes;
    ASSERT_EQ(passes.size(), 2u);
    EXPECT_EQ(passes[1].feed.steps, 230 * 40);
    EXPECT_EQ(passes[1].moves[0].steps, 0);
    // The carriage does not move, so the pass is the feed plus one dwell.
    EXPECT_NEAR(passes[1].duration_s,
                motion::jerk_min_time(230.0, {150, 5000, 1e6}) + 0.004, 1e-9);
}

TEST(Planner, UnidirectionalSweepsAlwaysPlus) {
    auto p = profile::default_profile();
    p.motion.bidirectional = false;
    const auto doc = doc_of({page_of({U"⠿⠿", U"⠿⠿"})});
    auto uni = plan_job(doc, p);
    auto bi = plan_job(doc, profile::default_profile());
    ASSERT_TRUE(uni.has_value() && bi.has_value());
    for (const auto& pass : uni->sheets[0].passes) {
        EXPECT_EQ(pass.direction, +1);
        const auto v = xs(pass);
        EXPECT_TRUE(std::is_sorted(v.begin(), v.end()));
    }
    int minus = 0;
    for (const auto& pass : bi->sheets[0].passes) {
        auto v = xs(pass);
        if (pass.direction < 0) {
            ++minus;
            EXPECT_TRUE(std::is_sorted(v.rbegin(), v.rend()));
        }
    }
    EXPECT_EQ(minus, 3);  // six dot rows, alternating
    EXPECT_LT(bi->duration_s, uni->duration_s);
    auto naive = naive_duration(doc, profile::default_profile());
    ASSERT_TRUE(naive.has_value());
    EXPECT_GT(*naive, bi->duration_s);
}

TEST(Planner, LayoutThatDoesNotFitIsRefused) {
    auto r = plan_job(doc_of({page_of({std::u32string(28, U'⠁')})}), profile::default_profile());
    ASSERT_FALSE(r.has_value());
    EXPECT_EQ(r.error().where, "page 1 line 1");
    r = plan_job(doc_of({page_of({U"⡁"})}), profile::default_profile());  // dot 7 on six-dot
    ASSERT_FALSE(r.has_value());
    EXPECT_NE(r.error().message.find("dot 7 or 8"), std::string::npos);
    r = plan_job(doc_of({page_of({U"⠁"})}, false), profile::default_profile());
    ASSERT_FALSE(r.has_value());
    EXPECT_EQ(r.error().where, "field geometry.interpoint");
}

TEST(Planner, BadProfileGivesAnErrorNeverANaN) {
    const auto doc = doc_of({page_of({U"⠿⠿"})});
    auto p = profile::default_profile();
    p.dynamics.head_mass_kg = -0.25;
    auto r = plan_job(doc, p);
    ASSERT_FALSE(r.has_value());
    EXPECT_EQ(r.error().where, "field dynamics.head_mass_kg");
    p = profile::default_profile();
    p.carriage.v_max_mm_s = std::nan("");
    r = plan_job(doc, p);
    ASSERT_FALSE(r.has_value());
    EXPECT_EQ(r.error().where, "field carriage.v_max_mm_s");
}

TEST(Planner, ToleranceUnreachableWhenTheHeadCannotFollow) {
    // A head so heavy on so soft a belt that it barely moves during any move:
    // the residual is the whole distance at every speed the tuner may try.
    auto p = profile::default_profile();
    p.dynamics.head_mass_kg = 500;
    p.dynamics.belt_stiffness_n_m = 10;
    p.dynamics.rotor_inertia_kg_m2 = 0;
    auto r = plan_job(doc_of({page_of({U"⠉"})}), p);
    ASSERT_FALSE(r.has_value());
    EXPECT_EQ(r.error().where, "field vibration.tolerance_um");
    EXPECT_NE(r.error().message.find("unreachable at any speed"), std::string::npos);
}

// Protocol v3: the plan is the firmware's timer schedule (docs/protocol.md,
// "Timing"), and the head model runs on the table moves' real step trains.
TEST(Planner, FirmwareModeTimesTheFirmwaresScheduleAndEstimatesItsStepTrains) {
    const auto* tables = &test::firmware_tables();
    ASSERT_GT(tables->start_gap_ticks, 0u);
    const auto prof = profile::default_profile();
    const auto timing = profile::strike_timing(prof);
    PlanOptions o;
    o.firmware = *tables;
    const auto doc = doc_of({page_of({U"⠉⠀⠁⠿", U"⠂⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠁"}), page_of({U"⠁⠃"})});
    auto job = plan_job(doc, prof, o);
    ASSERT_TRUE(job) << job.error().to_string();
    estimate::MoveTuner tuner(prof);
    const auto tick = [](double s) { return std::llround(s * machine::kTickHz); };
    const auto gap = static_cast<long long>(tables->start_gap_ticks);
    const auto ticks = [](std::uint64_t n) { return static_cast<long long>(n); };
    long long clock = 0;  // the last timer event before the pass: the previous hammer going up
    std::size_t moved = 0;
    std::map<std::uint32_t, std::pair<double, double>> expected;  // steps -> nominal, worst residual
    for (const auto& pass : job->sheets[0].passes) {
        ASSERT_TRUE(motion::is_table_move(tables->feed, pass.feed));
        if (pass.feed.steps != 0)
            clock += gap + ticks(tables->feed.move_ticks(static_cast<std::uint32_t>(std::abs(pass.feed.steps))));
        for (std::size_t k = 0; k < pass.strikes.size(); ++k) {
            const auto& m = pass.moves[k];
            const auto n = static_cast<std::uint32_t>(std::abs(m.steps));
            ASSERT_TRUE(motion::is_table_move(tables->carriage, m));
            // Each move starts the start gap after the event before it; the
            // hammer comes down the settle after its last step and goes up
            // the hammer pulse later: the strike time to the machine cycle.
            if (n != 0) clock += gap + ticks(tables->carriage.move_ticks(n));
            clock += timing.settle_ticks;
            EXPECT_EQ(tick(pass.strikes[k].time_s), clock) << "strike " << k;
            clock += timing.hammer_ticks;
            // The residual is the head model's on this move's step train.
            const auto& s = pass.strikes[k];
            if (n == 0) {
                EXPECT_EQ(s.residual_um, 0.0);
                continue;
            }
            ++moved;
            // Once per move length (the same length is the same table move),
            // one piecewise simulation for both figures: simulating a step
            // train a piece per step is slow in the sanitizer build.
            auto e = expected.find(n);
            if (e == expected.end()) {
                const auto train = estimate::step_train_shape(m.segments, prof.carriage.steps_per_mm, m.duration_s);
                const auto& ringing = tuner.ringing();
                const auto res = ringing.from_rest(*ringing.prepare(train));
                e = expected.emplace(n, std::pair{res.nominal_um, res.worst_um}).first;
            }
            // (The plan simulates the train by runs of equal intervals: the same to rounding.)
            EXPECT_NEAR(s.residual_um, e->second.first, 1e-6);
            EXPECT_NEAR(s.worst_residual_um, e->second.second, 1e-6);
            EXPECT_GT(s.worst_residual_um, 0.0);
        }
    }
    EXPECT_GT(moved, 5u);
    EXPECT_EQ(tick(job->duration_s), clock);
    EXPECT_GT(job->max_residual_um, 0.0);
}

namespace {
// Every sheet of `doc` planned in firmware mode, as the plan file writes it
// (byte for byte), and the sheets themselves (strike for strike).
struct FirmwarePlan {
    std::string json;
    std::vector<SheetPlan> sheets;
};
FirmwarePlan firmware_plan(const layout::PagedDocument& doc, const profile::PrinterProfile& prof,
                           const machine::FirmwareTables& tables, bool shared) {
    PlanOptions o;
    o.firmware = tables;
    o.share_table_estimates = shared;
    auto job = plan_job(doc, prof, o);
    EXPECT_TRUE(job) << job.error().to_string();
    FirmwarePlan out;
    if (!job) return out;
    for (const auto& sheet : job->sheets) out.json += sheet_to_json(sheet).dump() + "\n";
    out.sheets = std::move(job->sheets);
    return out;
}
// Every strike's nominal and worst residual, in plan order.
std::vector<double> residuals(const FirmwarePlan& plan) {
    std::vector<double> out;
    for (const auto& sheet : plan.sheets)
        for (const auto& pass : sheet.passes)
            for (const auto& s : pass.strikes) {
                out.push_back(s.residual_um);
                out.push_back(s.worst_residual_um);
            }
    return out;
}
}  // namespace

// Firmware mode shares table-move estimates across plans (TableEstimates):
// a plan made from the shared cache, cold or warm, is the plan made without
// it, byte for byte and strike for strike.
TEST(Planner, FirmwareModeSharedEstimatesGiveTheSamePlan) {
    const auto* tables = &test::firmware_tables();
    const auto prof = profile::default_profile();
    const auto doc = doc_of({page_of({U"⠉⠀⠁⠿⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠇", U"⠂⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠀⠁"}),
                             page_of({U"⠁⠃⠀⠀⠀⠀⠀⠀⠀⠀⠿"})});
    TableEstimates::clear();
    const auto own = firmware_plan(doc, prof, *tables, false);
    EXPECT_EQ(TableEstimates::keys(), 0u) << "a planner that does not share adds nothing";
    const auto cold = firmware_plan(doc, prof, *tables, true);
    EXPECT_EQ(TableEstimates::keys(), 1u);
    const auto moves = TableEstimates::moves();
    EXPECT_GT(moves, 5u);
    const auto warm = firmware_plan(doc, prof, *tables, true);
    EXPECT_EQ(TableEstimates::moves(), moves) << "the second plan finds every move in the cache";
    ASSERT_FALSE(own.json.empty());
    EXPECT_TRUE(cold.json == own.json) << "the plan file differs (cold cache)";
    EXPECT_TRUE(warm.json == own.json) << "the plan file differs (warm cache)";
    ASSERT_EQ(warm.sheets.size(), own.sheets.size());
    std::size_t strikes = 0;
    for (std::size_t s = 0; s < own.sheets.size(); ++s) {
        ASSERT_EQ(warm.sheets[s].passes.size(), own.sheets[s].passes.size());
        for (std::size_t p = 0; p < own.sheets[s].passes.size(); ++p) {
            EXPECT_EQ(warm.sheets[s].passes[p], own.sheets[s].passes[p]) << "sheet " << s << " pass " << p;
            EXPECT_EQ(cold.sheets[s].passes[p], own.sheets[s].passes[p]) << "sheet " << s << " pass " << p;
            strikes += own.sheets[s].passes[p].strikes.size();
        }
    }
    EXPECT_GT(strikes, 10u);
}

// An entry is only ever used for the profile and table it was made with: a
// profile whose head model, band or strike timing differs gets its own
// entry, and its plan is the plan made without the cache.
TEST(Planner, FirmwareModeSharedEstimatesFollowTheProfile) {
    const auto* tables = &test::firmware_tables();
    const auto doc = doc_of({page_of({U"⠉⠀⠁⠿⠀⠀⠀⠀⠀⠀⠇", U"⠂⠀⠀⠁"})});
    const auto base = profile::default_profile();
    TableEstimates::clear();
    const auto first = firmware_plan(doc, base, *tables, true);
    ASSERT_EQ(TableEstimates::keys(), 1u);

    auto damped = base;
    damped.dynamics.damping_ratio *= 0.5;  // a livelier head: other residuals
    auto band = base;
    band.vibration.damping_band = 0.3;  // another band
    auto frequency = base;
    frequency.vibration.frequency_band = 0.1;  // and another (its key only: planning is slow in the sanitizer build)
    std::size_t keys = 1;
    for (const auto* changed : {&damped, &band}) {
        const auto own = firmware_plan(doc, *changed, *tables, false);
        const auto shared = firmware_plan(doc, *changed, *tables, true);
        EXPECT_EQ(TableEstimates::keys(), ++keys) << "a new key for a changed profile";
        ASSERT_FALSE(own.json.empty());
        EXPECT_TRUE(shared.json == own.json) << "the plan file differs";
        EXPECT_TRUE(residuals(shared) == residuals(own));
        EXPECT_TRUE(residuals(shared) != residuals(first)) << "the changed profile changes the residuals (" << keys << ")";
    }
    // The first profile's entry is still there, and still right.
    const auto again = firmware_plan(doc, base, *tables, true);
    EXPECT_EQ(TableEstimates::keys(), keys);
    EXPECT_TRUE(again.json == first.json);
    EXPECT_TRUE(residuals(again) == residuals(first));
    // The key covers every field the estimate reads.
    const auto k = TableEstimates::key_for(base, *tables);
    EXPECT_NE(TableEstimates::key_for(damped, *tables), k);
    EXPECT_NE(TableEstimates::key_for(band, *tables), k);
    EXPECT_NE(TableEstimates::key_for(frequency, *tables), k);
    auto dwell = base;
    dwell.head.dwell_s *= 1.5;  // the dwell samples of the residual (and the hammer pulse)
    EXPECT_NE(TableEstimates::key_for(dwell, *tables), k);
    auto tol = base;
    tol.vibration.tolerance_um = 40;
    EXPECT_NE(TableEstimates::key_for(tol, *tables), k);
    auto other_table = *tables;
    other_table.carriage.intervals.back() += 1;
    EXPECT_NE(TableEstimates::key_for(base, other_table), k);
    auto feed_only = *tables;
    feed_only.feed.intervals.back() += 1;
    EXPECT_EQ(TableEstimates::key_for(base, feed_only), k) << "the feed has no head model";
    // At most kMaxKeys keys are kept.
    for (int i = 0; i < 12; ++i) {
        auto p = base;
        p.dynamics.damping_ratio = 0.5 + 0.01 * i;
        (void)TableEstimates::entry(TableEstimates::key_for(p, *tables));
    }
    EXPECT_EQ(TableEstimates::keys(), TableEstimates::kMaxKeys);
    TableEstimates::clear();
    EXPECT_EQ(TableEstimates::keys(), 0u);
}
