// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The plan file: a JobPlan as JSON, with what it was planned for. One format
// for `tactus-cli plan --json` (which adds its analysis fields, ignored on
// reading) and `tactus-cli emboss --plan` (tests, replaying a job, a plan made
// elsewhere). It keeps every field the encoder reads, settles included, so a
// saved plan encodes to the same bytes as the plan it came from.
//
//   {"tactus_plan": 2, "protocol": 2, "profile": {...the printer profile...},
//    "duration_s": ..., "sheets": [{"index", "duration_s", "passes": [{"side",
//    "y_mm", "feed_step", "direction", "feed": MOVE, "duration_s", "strikes":
//    [{"hammer", "side", "x_mm", "y_mm", "carriage_step", "time_s", "move": MOVE}]}]}]}
//   MOVE = {"steps", "duration_s", "settle_ticks", "segments": [[interval_q16, count, add_q16], ...]}
//
// The profile is the whole printer profile the plan was made with: the
// controller is configured from it, and a plan is refused on a printer with
// another one. `protocol` is the link protocol version the plan was made for
// (the plan stage only carries it; the print job checks it against the encoder).
#include <filesystem>
#include <string_view>

#include <nlohmann/json.hpp>

#include "common/result.hpp"
#include "plan/plan.hpp"
#include "profile/profile.hpp"

namespace tactus::plan {

// The format's version (`tactus_plan`). Version 1 carried no profile, no
// protocol and no settles; it is refused with that reason.
inline constexpr int kPlanFileFormat = 2;

struct PlanFile {
    JobPlan plan;
    profile::PrinterProfile profile;  // what it was planned with
    int protocol = 0;                 // the link protocol version it was planned for
};

// The file's head without its sheets (`plan --json` writes the sheets one at a time).
nlohmann::json plan_file_head(const profile::PrinterProfile& profile, int protocol);
nlohmann::json sheet_to_json(const SheetPlan& sheet);
nlohmann::json plan_to_json(const PlanFile& file);
// Strict about every field the encoder reads; unknown fields are ignored (the
// analysis `plan --json` adds). Errors name the field ("plan.sheets[0].passes[2].side").
Result<PlanFile> plan_from_json(const nlohmann::json& j);
Result<PlanFile> load_plan(const std::filesystem::path& path);
// Written atomically: a crash leaves the old file or the new one.
Result<void> save_plan(const PlanFile& file, const std::filesystem::path& path);

}  // namespace tactus::plan
