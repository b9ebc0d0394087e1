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
#include "encode/stream_v3.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/plan_file.hpp"
#include "plan/planner.hpp"
#include "profile/page_geometry.hpp"
#include "profile/profile.hpp"
#include "../common/firmware_tables_fixture.hpp"
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

// A protocol-3 plan (the reference firmware's table moves) carries the ramp
// tables it was made with, and encodes to the same v3 stream after a round
// trip through a file; a file whose tables are not its profile's is refused.
TEST(PlanFileRoundTrip, AProtocol3PlanCarriesItsTablesAndEncodesToTheSameBytes) {
    const auto prof = profile::default_profile();
    const auto& tables = test::firmware_tables();
    pipeline::PipelineOptions o;
    o.layout.geometry = profile::page_geometry(prof);
    auto doc = pipeline::lay_out_file(fs::path(TACTUS_RESOURCES_DIR) / "samples" / "firmware-note.md", o);
    ASSERT_TRUE(doc) << doc.error().to_string();
    PlanOptions po;
    po.firmware = tables;
    auto plan = plan_job(*doc, prof, po);
    ASSERT_TRUE(plan) << plan.error().to_string();
    const PlanFile file{*plan, prof, encode::kProtocolV3, tables};
    const auto j = plan_to_json(file);
    EXPECT_EQ(j["protocol"], 3);
    auto back = plan_from_json(nlohmann::json::parse(j.dump()));
    ASSERT_TRUE(back) << back.error().to_string();
    EXPECT_EQ(back->protocol, encode::kProtocolV3);
    ASSERT_TRUE(back->firmware.has_value());
    EXPECT_EQ(*back->firmware, tables);
    const auto timing = profile::strike_timing(prof);
    const auto a = encode::encode_job_v3(*plan, tables, timing, 7, {});
    const auto b = encode::encode_job_v3(back->plan, *back->firmware, timing, 7, {});
    ASSERT_TRUE(a && b);
    EXPECT_EQ(b->bytes, a->bytes);

    auto no_tables = j;
    no_tables.erase("firmware_tables");
    auto bad = plan_from_json(no_tables);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().where, "plan.firmware_tables");
    auto other_profile = j;
    other_profile["profile"]["carriage"]["v_max_mm_s"] = 40.0;
    bad = plan_from_json(other_profile);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().where.rfind("plan.firmware_tables", 0), 0U) << bad.error().to_string();
}

// The sheets of a plan file are its job: at least one, numbered from 1 in
// order, each once. (An empty list or a sheet 0 used to fail later with
// "start_sheet: sheet 1 is not in the plan", and two sheets of one number
// were embossed.)
TEST(PlanFileRoundTrip, SheetsAreAtLeastOneAndNumberedInOrderEachOnce) {
    const auto j = plan_to_json({test::make_plan(2, 1, 2), profile::default_profile(), encode::kProtocolVersion});
    ASSERT_TRUE(plan_from_json(j));
    auto empty = j;
    empty["sheets"] = nlohmann::json::array();
    auto bad = plan_from_json(empty);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().where, "plan.sheets");
    auto zero = j;
    zero["sheets"][0]["index"] = 0;
    bad = plan_from_json(zero);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().where, "plan.sheets[0].index");
    EXPECT_EQ(bad.error().message, "sheets are numbered from 1");
    auto twice = j;
    twice["sheets"][1]["index"] = twice["sheets"][0]["index"];
    bad = plan_from_json(twice);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().where, "plan.sheets[1].index");
}

}  // namespace
}  // namespace tactus::plan
