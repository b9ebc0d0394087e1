// SPDX-License-Identifier: GPL-3.0-or-later
// End-to-end: the built tactus-cli's plan, profile and vibration commands.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "common/file_io.hpp"

namespace {

struct Run {
    int code = -1;
    std::string out;
};

Run run(const std::string& args) {
    Run r;
    const std::string cmd = std::string(TACTUS_CLI) + " " + args + " 2>&1";
    FILE* f = ::popen(cmd.c_str(), "r");
    if (!f) return r;
    char buf[4096];
    std::size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) r.out.append(buf, n);
    const int status = ::pclose(f);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
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
        EXPECT_TRUE(p["direction"] == "+" || p["direction"] == "-");
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
