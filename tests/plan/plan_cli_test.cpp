// SPDX-License-Identifier: GPL-3.0-or-later
// End-to-end: the built tactus-cli's plan, profile and vibration commands.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../common/process.hpp"
#include "common/file_io.hpp"

namespace {

struct Run {
    int code = -1;
    std::string out;  // stdout and stderr, as a terminal shows them
};

// tactus-cli with the words of `args` (no word here contains a space).
Run run(const std::string& args) {
    std::vector<std::string> argv{TACTUS_CLI};
    std::istringstream words(args);
    for (std::string w; words >> w;) argv.push_back(w);
    tactus::test::Process p(argv, tactus::test::Process::Options{{}, true, {}});
    Run r;
    r.out = p.read_all();
    r.code = p.wait();
    return r;
}

std::filesystem::path temp(const std::string& name) {
    return std::filesystem::temp_directory_path() / ("tactus-plan-cli-" + name);
}

}  // namespace

TEST(PlanCli, ProfileDefaultHasTheGeometryObject) {
    const auto r = run("profile default");
    ASSERT_EQ(r.code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    const auto& g = j.at("geometry");
    EXPECT_EQ(g.at("dot_pitch_mm"), 2.5);
    EXPECT_EQ(g.at("cell_pitch_mm"), 6.0);
    EXPECT_EQ(g.at("line_pitch_mm"), 10.0);
    EXPECT_TRUE(g.contains("back_offset_x_mm"));
    EXPECT_TRUE(g.contains("back_offset_y_mm"));
}

TEST(PlanCli, PlanJsonForASmallDocument) {
    const auto file = temp("doc.txt");
    ASSERT_TRUE(tactus::write_file_atomic(file, "abc\n").has_value());
    // The legacy protocol's plan: its moves are tuned step schedules.
    const auto r = run("plan --json --protocol 2 " + file.string());
    ASSERT_EQ(r.code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("protocol"), 2);
    ASSERT_EQ(j.at("sheets").size(), 1u);
    EXPECT_EQ(j["sheets"][0]["index"], 1);
    const auto& passes = j["sheets"][0]["passes"];
    ASSERT_FALSE(passes.empty());
    std::size_t strikes = 0;
    double sum = 0;
    for (const auto& p : passes) {
        EXPECT_TRUE(p["side"] == "front" || p["side"] == "back");
        EXPECT_TRUE(p["direction"] == 1 || p["direction"] == -1);
        strikes += p["strikes_mm"].size();
        sum += p["duration_s"].get<double>();
    }
    const auto& t = j.at("totals");
    EXPECT_EQ(t["strikes"].get<std::size_t>(), strikes);
    EXPECT_NEAR(t["duration_s"].get<double>(), sum, 1e-9);
    EXPECT_GE(t["duration_s"].get<double>(), t["lower_bound_s"].get<double>());
    EXPECT_LE(t["max_worst_residual_um"].get<double>(), 50.0);
    EXPECT_FALSE(j.at("tuning").empty());
    std::filesystem::remove(file);
}

TEST(PlanCli, BadProfileExitsThreeNamingTheField) {
    const auto doc = temp("doc2.txt");
    const auto prof = temp("bad.json");
    ASSERT_TRUE(tactus::write_file_atomic(doc, "abc\n").has_value());
    auto j = nlohmann::json::parse(run("profile default").out);
    j["carriage"]["steps_per_mm"] = 0;
    ASSERT_TRUE(tactus::write_file_atomic(prof, j.dump()).has_value());
    auto r = run("plan --profile " + prof.string() + " " + doc.string());
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.out.find("field carriage.steps_per_mm"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("nan"), std::string::npos);
    r = run("vibration --profile " + prof.string());
    EXPECT_EQ(r.code, 3);
    std::filesystem::remove(doc);
    std::filesystem::remove(prof);
}

TEST(PlanCli, VibrationReportsTargetsAndResponse) {
    const auto r = run("vibration --json --points 5");
    ASSERT_EQ(r.code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["pass"]["all"], true);
    EXPECT_EQ(j["frequency_response"].size(), 5u);
    EXPECT_EQ(j["natural_frequencies_hz"].size(), 2u);
    EXPECT_LT(j["step_response"]["overshoot_pct"].get<double>(), 2.0);
    const auto text = run("vibration");
    EXPECT_NE(text.out.find("pass"), std::string::npos);
}

// The CLI warns about front/back dots that crush each other, with the rule the
// preview uses (plan::find_conflicts), and stays quiet when there are none.
TEST(PlanCli, WarnsAboutFrontAndBackDotsThatCrushEachOther) {
    const std::string sample = std::string(TACTUS_RESOURCES_DIR) + "/samples/welcome.md";
    const auto quiet = run("plan " + sample);
    ASSERT_EQ(quiet.code, 0) << quiet.out;
    EXPECT_EQ(quiet.out.find("front and back dots closer than"), std::string::npos) << quiet.out;

    auto prof = nlohmann::json::parse(run("profile default").out);
    prof["geometry"]["back_offset_x_mm"] = 0.0;
    prof["geometry"]["back_offset_y_mm"] = 0.0;
    prof["geometry"]["back_mirror"] = "none";
    const auto path = temp("no-offset.json");
    ASSERT_TRUE(tactus::write_file_atomic(path, prof.dump()));
    const auto loud = run("plan --profile " + path.string() + " " + sample);
    EXPECT_EQ(loud.code, 0) << loud.out;
    EXPECT_NE(loud.out.find("warning: sheet 1: "), std::string::npos) << loud.out;
    EXPECT_NE(loud.out.find("front and back dots closer than 1.25 mm"), std::string::npos) << loud.out;
    std::filesystem::remove(path);
}

// `plan --firmware-tables`: the plan emboss --firmware-tables sends (the
// firmware's table moves and timing), as JSON and in words.
TEST(PlanCli, FirmwareTablesPlanTheFirmwaresMoves) {
    const auto file = temp("fw-doc.txt");
    ASSERT_TRUE(tactus::write_file_atomic(file, "abc def\nghi\n").has_value());
    const auto v2 = run("plan --json --protocol 2 " + file.string());
    const auto v3 = run("plan --json --firmware-tables " + std::string(TACTUS_FIRMWARE_TABLES) + " " + file.string());
    ASSERT_EQ(v2.code, 0) << v2.out;
    ASSERT_EQ(v3.code, 0) << v3.out;
    // Protocol 3 is the default: the tables the profile makes are the build's.
    EXPECT_EQ(run("plan --json " + file.string()).out, v3.out);
    const auto j2 = nlohmann::json::parse(v2.out), j3 = nlohmann::json::parse(v3.out);
    EXPECT_EQ(j3.at("protocol"), 3);
    EXPECT_EQ(j3["totals"]["strikes"], j2["totals"]["strikes"]);
    EXPECT_NE(j3["totals"]["duration_s"], j2["totals"]["duration_s"]);
    EXPECT_GT(j3["totals"]["max_worst_residual_um"].get<double>(), 0.0);  // on the table moves' step trains
    // Every carriage move is the table move of its length (a table move's
    // intervals are the table's: its first step is T[0] after its start).
    const auto tables = nlohmann::json::parse(tactus::read_file(TACTUS_FIRMWARE_TABLES, 1 << 20).value());
    const auto t0 = tables["carriage"]["intervals"][0].get<std::uint64_t>();
    std::size_t moves = 0;
    for (const auto& pass : j3["sheets"][0]["passes"])
        for (const auto& strike : pass["strikes"])
            if (const auto& m = strike["move"]; m["steps"] != 0) {
                ++moves;
                EXPECT_EQ(m["segments"][0][0].get<std::uint64_t>() >> 16, t0) << m.dump();
            }
    EXPECT_GT(moves, 3u);
    const auto words = run("plan --firmware-tables " + std::string(TACTUS_FIRMWARE_TABLES) + " " + file.string());
    ASSERT_EQ(words.code, 0) << words.out;
    EXPECT_NE(words.out.find("firmware tables:  " + tables["table_id"].get<std::string>()), std::string::npos)
        << words.out;
    // Tables that are not a ramp.json: refused, naming the field.
    const auto bad = temp("bad-ramp.json");
    ASSERT_TRUE(tactus::write_file_atomic(bad, "{\"table_id\": \"474cac88\"}").has_value());
    const auto r = run("plan --firmware-tables " + bad.string() + " " + file.string());
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.out.find("carriage"), std::string::npos) << r.out;
}
