// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The plan file: a JobPlan as JSON, with what it was planned for. One format
// for `tactus-cli plan --json` (which adds its analysis fields, ignored on
// reading) and `tactus-cli emboss --plan` (tests, replaying a job, a plan made
// elsewhere). It keeps every field the encoder reads, settles included, so a
// saved plan encodes to the same bytes as the plan it came from.
//
//   {"tactus_plan": 2, "protocol": 3, "profile": {...the printer profile...},
//    "firmware_tables": {...ramp.json...}, "duration_s": ..., "sheets": [{"index", "duration_s", "passes": [{"side",
//    "y_mm", "feed_step", "direction", "feed": MOVE, "duration_s", "strikes":
//    [{"hammer", "side", "x_mm", "y_mm", "carriage_step", "time_s", "move": MOVE}]}]}]}
//   MOVE = {"steps", "duration_s", "settle_ticks", "segments": [[interval_q16, count, add_q16], ...]}
//
// The profile is the whole printer profile the plan was made with: the
// controller is configured from it, and a plan is refused on a printer with
// another one. `protocol` is the link protocol version the plan was made for
// (the plan stage only carries it; the print job checks it against the encoder).
// A protocol-3 plan's moves are table moves of the reference firmware's ramp
// tables, so the file carries those tables (ramp.json's fields), and a reader
// checks them against the profile: the plan embosses exactly as the document
// it came from, on any machine. Protocol 2 (legacy) carries none.
#include <filesystem>
#include <string_view>

#include <nlohmann/json.hpp>

#include "common/result.hpp"
#include <optional>

#include "machine/firmware_tables.hpp"
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
    // Protocol 3: the ramp tables its moves are made of; none for protocol 2.
    std::optional<machine::FirmwareTables> firmware = std::nullopt;
};

// The file's head without its sheets (`plan --json` writes the sheets one at a
// time): protocol 3 when `firmware` is given, else 2.
nlohmann::json plan_file_head(const profile::PrinterProfile& profile,
                              const std::optional<machine::FirmwareTables>& firmware);
nlohmann::json sheet_to_json(const SheetPlan& sheet);
nlohmann::json plan_to_json(const PlanFile& file);
// Strict about every field the encoder reads; unknown fields are ignored (the
// analysis `plan --json` adds). Errors name the field ("plan.sheets[0].passes[2].side").
// The sheets are at least one, numbered from 1 upwards without repeats
// (their index is what --start-sheet and the controller's sheet count use).
Result<PlanFile> plan_from_json(const nlohmann::json& j);
Result<PlanFile> load_plan(const std::filesystem::path& path);
// Written atomically: a crash leaves the old file or the new one.
Result<void> save_plan(const PlanFile& file, const std::filesystem::path& path);

}  // namespace tactus::plan
