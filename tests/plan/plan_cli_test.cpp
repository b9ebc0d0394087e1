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
    const auto r = run("plan --json " + file.string());
    ASSERT_EQ(r.code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
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
