// SPDX-License-Identifier: GPL-3.0-or-later
// A saved plan encodes to the same bytes as the plan it came from:
// encode(plan) == encode(load(save(plan))), byte for byte, over random plans
// (random settles, both hammers, both sweep directions) and real ones
// (welcome.md and a Chinese sample with the bundled profile). A plan file
// that dropped settle_ticks would lose all 1,584 non-zero settles of
// welcome.md, and the stream would differ.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "encode/messages.hpp"
#include "encode/stream.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/plan_file.hpp"
#include "plan/planner.hpp"
#include "profile/page_geometry.hpp"
#include "profile/profile.hpp"
#include "../common/test_plans.hpp"

namespace tactus::plan {
namespace {

namespace fs = std::filesystem;

std::vector<std::uint8_t> encoded(const JobPlan& plan) {
    auto s = encode::encode_job(plan, 7, {});
    EXPECT_TRUE(s) << s.error().to_string();
    return s ? s->bytes : std::vector<std::uint8_t>{};
}

// Through a real file, as `plan --json > f; emboss --plan f` does.
JobPlan saved_and_loaded(const JobPlan& plan, const std::string& name) {
    const auto path = fs::temp_directory_path() / ("tactus-plan-roundtrip-" + std::to_string(getpid()) + "-" + name);
    const PlanFile file{plan, profile::default_profile(), encode::kProtocolVersion};
    auto saved = save_plan(file, path);
    EXPECT_TRUE(saved) << saved.error().to_string();
    auto back = load_plan(path);
    fs::remove(path);
    EXPECT_TRUE(back) << back.error().to_string();
    if (!back) return {};
    EXPECT_EQ(back->protocol, encode::kProtocolVersion);
    EXPECT_EQ(back->profile.name, file.profile.name);
    return back->plan;
}

std::size_t nonzero_settles(const JobPlan& plan) {
    std::size_t n = 0;
    for (const auto& sheet : plan.sheets)
        for (const auto& pass : sheet.passes)
            for (const auto& m : pass.moves) n += m.settle_ticks != 0;
    return n;
}

TEST(PlanFileRoundTrip, RandomPlansEncodeToTheSameBytes) {
    std::mt19937 rng(20261123);
    for (int trial = 0; trial < 40; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        auto plan = test::make_plan(1 + rng() % 3, 1 + rng() % 8, 1 + rng() % 20, static_cast<unsigned>(rng()));
        // Settles anywhere in what a STRIKE op carries, and none at all.
        std::uniform_int_distribution<std::uint32_t> settle(0, encode::kMaxStrikeWaitTicks);
        for (auto& sheet : plan.sheets)
            for (auto& pass : sheet.passes) {
                pass.feed.settle_ticks = rng() % 2 ? settle(rng) : 0;
                for (auto& m : pass.moves) m.settle_ticks = rng() % 4 ? settle(rng) : 0;
            }
        ASSERT_GT(nonzero_settles(plan), 0U);
        const auto back = saved_and_loaded(plan, std::to_string(trial));
        ASSERT_EQ(back.sheets.size(), plan.sheets.size());
        EXPECT_EQ(back.strikes, plan.strikes);
        for (std::size_t s = 0; s < plan.sheets.size(); ++s) EXPECT_EQ(back.sheets[s].passes, plan.sheets[s].passes);
        EXPECT_EQ(encoded(back), encoded(plan));
    }
}

TEST(PlanFileRoundTrip, RealPlansEncodeToTheSameBytes) {
    const fs::path samples = fs::path(TACTUS_RESOURCES_DIR) / "samples";
    const auto prof = profile::default_profile();
    for (const auto& [file, tables] : {std::pair{"welcome.md", "en-ueb-g2.ctb"}, std::pair{"chinese-tw.txt", "zh-tw.ctb"}}) {
        SCOPED_TRACE(file);
        pipeline::PipelineOptions o;
        o.tables = tables;
        o.layout.geometry = profile::page_geometry(prof);
        auto doc = pipeline::lay_out_file(samples / file, o);
        ASSERT_TRUE(doc) << doc.error().to_string();
        auto plan = plan_job(*doc, prof);
        ASSERT_TRUE(plan) << plan.error().to_string();
        // The auto-tuner settles before most strikes: what the old format lost.
        EXPECT_GT(nonzero_settles(*plan), 100U);
        const auto back = saved_and_loaded(*plan, file);
        EXPECT_EQ(encoded(back), encoded(*plan));
    }
}

// Every field the encoder reads is refused with its path when it has the
// wrong type, settles included (never silently read as 0).
TEST(PlanFileRoundTrip, ASettleOfTheWrongTypeIsAnError) {
    auto plan = test::make_plan(1, 2, 3);
    plan.sheets[0].passes[1].moves[0].settle_ticks = 9000;
    auto j = plan_to_json({plan, profile::default_profile(), encode::kProtocolVersion});
    j["sheets"][0]["passes"][1]["strikes"][0]["move"]["settle_ticks"] = "9000";
    auto bad = plan_from_json(j);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().where, "plan.sheets[0].passes[1].strikes[0].move.settle_ticks");
    j["sheets"][0]["passes"][1]["strikes"][0]["move"]["settle_ticks"] = -1;
    bad = plan_from_json(j);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().message, "out of range");
}

// A plan file of format 1 (no profile, no protocol, no settles) is refused
// with the reason, not embossed with the controller's defaults.
TEST(PlanFileRoundTrip, FormatOneIsRefusedWithTheReason) {
    auto j = plan_to_json({test::make_plan(1, 1, 1), profile::default_profile(), encode::kProtocolVersion});
    j["tactus_plan"] = 1;
    const auto old = plan_from_json(j);
    ASSERT_FALSE(old);
    EXPECT_EQ(old.error().where, "plan.tactus_plan");
    EXPECT_NE(old.error().message.find("profile"), std::string::npos) << old.error().message;
    j["tactus_plan"] = 2;
    j.erase("profile");
    const auto no_profile = plan_from_json(j);
    ASSERT_FALSE(no_profile);
    EXPECT_EQ(no_profile.error().where, "plan.profile");
}

}  // namespace
}  // namespace tactus::plan
