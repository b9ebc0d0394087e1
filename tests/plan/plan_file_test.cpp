// SPDX-License-Identifier: GPL-3.0-or-later
// Plan files with a wrong JSON type: an error naming the field, never an
// abort (a side given as a number once ended the process with SIGABRT,
// exit 134).
#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include <nlohmann/json.hpp>

#include "plan/plan_file.hpp"
#include "profile/profile_json.hpp"

namespace tactus::plan {
namespace {

using nlohmann::json;

json one_strike_plan() {
    const json move = {{"steps", 8}, {"segments", json::array({json::array({65536 * 300, 8, 0})})}, {"duration_s", 0.01}};
    return {{"tactus_plan", 2},
            {"protocol", 2},
            {"profile", profile::to_json(profile::default_profile())},
            {"duration_s", 1.0},
            {"sheets",
             json::array({{{"index", 1},
                           {"passes",
                            json::array({{{"side", "front"},
                                          {"y_mm", 10.0},
                                          {"feed_step", 400},
                                          {"direction", 1},
                                          {"feed", move},
                                          {"strikes", json::array({{{"hammer", "convex"},
                                                                    {"side", "front"},
                                                                    {"carriage_step", 8},
                                                                    {"move", move}}})}}})}}})}};
}

TEST(PlanFile, AWrongJsonTypeIsAnErrorNamingTheField) {
    ASSERT_TRUE(plan_from_json(one_strike_plan())) << plan_from_json(one_strike_plan()).error().to_string();
    struct Case {
        const char* what;
        std::function<void(json&)> edit;
        const char* where;
    };
    const std::vector<Case> cases = {
        {"pass side as a number", [](json& j) { j["sheets"][0]["passes"][0]["side"] = 1; },
         "plan.sheets[0].passes[0].side"},
        {"strike hammer as a number", [](json& j) { j["sheets"][0]["passes"][0]["strikes"][0]["hammer"] = 2; },
         "plan.sheets[0].passes[0].strikes[0].hammer"},
        {"strike side as an array", [](json& j) { j["sheets"][0]["passes"][0]["strikes"][0]["side"] = json::array(); },
         "plan.sheets[0].passes[0].strikes[0].side"},
        {"direction as text", [](json& j) { j["sheets"][0]["passes"][0]["direction"] = "left"; },
         "plan.sheets[0].passes[0].direction"},
        {"side an unknown word", [](json& j) { j["sheets"][0]["passes"][0]["side"] = "top"; },
         "plan.sheets[0].passes[0].side"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.what);
        json j = one_strike_plan();
        c.edit(j);
        const auto p = plan_from_json(j);
        ASSERT_FALSE(p);
        EXPECT_EQ(p.error().where, c.where) << p.error().to_string();
    }
}

}  // namespace
}  // namespace tactus::plan
