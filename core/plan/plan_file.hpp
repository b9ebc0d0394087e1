// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A JobPlan as JSON: `tactus-cli emboss --plan` sends a saved plan as it is
// (tests, replaying a job, a plan made elsewhere), and the simulator's strike
// log is written in the same units.
#include <filesystem>
#include <string_view>

#include <nlohmann/json.hpp>

#include "common/result.hpp"
#include "plan/plan.hpp"

namespace tactus::plan {

nlohmann::json plan_to_json(const plan::JobPlan& plan);
Result<plan::JobPlan> plan_from_json(const nlohmann::json& j);
Result<plan::JobPlan> load_plan(const std::filesystem::path& path);

}  // namespace tactus::plan
