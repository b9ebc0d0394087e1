// SPDX-License-Identifier: GPL-3.0-or-later
// Golden files for the back half of the pipeline: the bundled samples laid out
// with the bundled printer profile, planned, and encoded into the DATA frames a
// controller receives. They pin the plan (every move, segment, settle and
// strike) and the bytes on the line, so a refactoring that moves code between
// stages can prove it changed nothing. Regenerate after an intended change with
// TACTUS_UPDATE_GOLDEN=1 and review the diff: one frame per line, in hex.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "common/file_io.hpp"
#include "encode/frame.hpp"
#include "encode/messages.hpp"
#include "plan/plan_file.hpp"
#include "encode/stream.hpp"
#include "encode/stream_v3.hpp"
#include "profile/firmware_tables.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/planner.hpp"
#include "profile/page_geometry.hpp"
#include "profile/profile.hpp"
#include "../common/firmware_tables_fixture.hpp"

using namespace tactus;
namespace fs = std::filesystem;

namespace {

const fs::path kSamples = fs::path(TACTUS_RESOURCES_DIR) / "samples";

struct BackHalfCase {
    std::string name;   // expected files: <name>.plan.json and <name>.frames.hex
    std::string input;  // under resources/samples
    std::string tables;
};

// The profile's page geometry decides the layout, as `tactus-cli plan` does.
plan::JobPlan plan_sample(const BackHalfCase& c) {
    const auto prof = profile::default_profile();
    pipeline::PipelineOptions o;
    o.tables = c.tables;
    o.layout.geometry = profile::page_geometry(prof);
    auto doc = pipeline::lay_out_file(kSamples / c.input, o);
    EXPECT_TRUE(doc) << doc.error().to_string();
    if (!doc) return {};
    auto plan = plan::plan_job(*doc, prof);
    EXPECT_TRUE(plan) << plan.error().to_string();
    return plan ? *plan : plan::JobPlan{};
}

// The job as DATA frames, sequence numbers counting from 1 as after a HELLO
// with SEQ 0, one frame per line in hex.
std::string frames_hex(const plan::JobPlan& plan) {
    auto stream = encode::encode_job(plan, /*job_id=*/1, {});
    EXPECT_TRUE(stream) << stream.error().to_string();
    if (!stream) return {};
    std::string out;
    std::uint8_t seq = 1;
    for (const auto& [begin, end] : encode::chunk_stream(*stream, encode::kMaxPayload)) {
        const std::span<const std::uint8_t> payload(stream->bytes.data() + begin, end - begin);
        for (const auto byte : encode::encode_frame(seq++, encode::FrameType::data, payload)) {
            char hex[3];
            std::snprintf(hex, sizeof hex, "%02x", byte);
            out += hex;
        }
        out += '\n';
    }
    return out;
}

void expect_golden(const std::string& actual, const std::string& file) {
    const auto path = fs::path(TACTUS_GOLDEN_DIR) / file;
    if (std::getenv("TACTUS_UPDATE_GOLDEN")) {
        ASSERT_TRUE(write_file_atomic(path, actual));
        return;
    }
    const auto expected = read_file(path);
    ASSERT_TRUE(expected) << expected.error().to_string();
    EXPECT_TRUE(actual == *expected) << "golden mismatch for " << file
                                     << " (TACTUS_UPDATE_GOLDEN=1 regenerates; review the diff)";
}

class BackHalf : public ::testing::TestWithParam<BackHalfCase> {};

}  // namespace

TEST_P(BackHalf, PlanAndFramesMatchExpected) {
    const auto& c = GetParam();
    const auto plan = plan_sample(c);
    ASSERT_FALSE(plan.sheets.empty());
    expect_golden(plan::plan_to_json({plan, profile::default_profile(), encode::kProtocolVersion}).dump(1) + "\n", c.name + ".plan.json");
    expect_golden(frames_hex(plan), c.name + ".frames.hex");
}

INSTANTIATE_TEST_SUITE_P(Samples, BackHalf,
                         ::testing::Values(BackHalfCase{"welcome", "welcome.md", "en-ueb-g2.ctb"},
                                           BackHalfCase{"chinese-tw", "chinese-tw.txt", "zh-tw.ctb"}),
                         [](const auto& param_info) {
                             std::string n = param_info.param.name;
                             for (auto& ch : n)
                                 if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return n;
                         });

namespace {

// Protocol v3 (the reference firmware): welcome.md's first sheet planned with
// the firmware's ramp tables for the bundled profile, as the DATA frames the
// firmware receives (31 bytes of ops and the 2-byte check each, SEQ from 1).
// Pins the planner's table moves and the v3 encoder; also the protocol's bar:
// at most 2 line bytes per strike on a typical page, every frame byte counted.
TEST(BackHalfV3, WelcomeSheetOneFramesMatchExpected) {
    const auto prof = profile::default_profile();
    const auto* tables = &test::firmware_tables();
    pipeline::PipelineOptions o;
    o.tables = "en-ueb-g2.ctb";
    o.layout.geometry = profile::page_geometry(prof);
    auto doc = pipeline::lay_out_file(kSamples / "welcome.md", o);
    ASSERT_TRUE(doc) << doc.error().to_string();
    plan::PlanOptions po;
    po.firmware = *tables;
    auto planner = plan::Planner::create(prof, po);
    ASSERT_TRUE(planner) << planner.error().to_string();
    auto sheet = planner->plan_sheet(*doc, 1);
    ASSERT_TRUE(sheet) << sheet.error().to_string();
    plan::JobPlan job;
    job.strikes = planner->totals().strikes;
    job.sheets.push_back(*sheet);
    auto stream = encode::encode_job_v3(job, *tables, profile::strike_timing(prof), 1, {});
    ASSERT_TRUE(stream) << stream.error().to_string();
    std::string out;
    std::size_t line = 0;
    std::uint8_t seq = 1;
    for (const auto& [begin, end] : encode::chunk_stream_v3(*stream, 31)) {
        const auto payload =
            encode::data_payload_v3(std::span<const std::uint8_t>(stream->bytes.data() + begin, end - begin));
        const auto frame = encode::encode_frame(seq++, encode::FrameType::data, payload);
        line += frame.size();
        for (const auto byte : frame) {
            char hex[3];
            std::snprintf(hex, sizeof hex, "%02x", byte);
            out += hex;
        }
        out += '\n';
    }
    expect_golden(out, "welcome-sheet1.v3.frames.hex");
    ASSERT_GT(job.strikes, 1000U);
    const double per_strike = static_cast<double>(line) / static_cast<double>(job.strikes);
    EXPECT_LE(per_strike, 2.0) << line << " line bytes for " << job.strikes << " strikes";
}

}  // namespace
