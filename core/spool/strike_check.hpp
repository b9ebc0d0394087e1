// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A finished job's strikes, as a simulated controller logged them, against
// its plan: the job's document planned again with its printer's profile, as
// the runner planned it. The desktop app says the result after each job on
// its built-in simulator ("all 1453 strikes checked against the plan").
#include <cstddef>
#include <span>
#include <string_view>

#include "common/result.hpp"
#include "controller/sim_controller.hpp"
#include "machine/firmware_tables.hpp"
#include "spool/records.hpp"

namespace tactus::spool {

struct StrikeCheck {
    std::size_t embossed = 0;     // strikes the controller logged for the job
    std::size_t planned = 0;      // strikes the plan has from first_sheet on
    std::size_t first_sheet = 1;  // the run started here (a resumed job)
    std::size_t last_sheet = 0;
    bool agrees = false;          // the same strikes, in the same order
};

// `document_snapshot` and `profile_json`: the job's stored document and its
// printer's profile. `logged`: every strike the controller logged (other
// jobs' strikes are left out by the job's link number). `firmware`: the
// tables the controller ran the job with (protocol 3), or null.
// Fails when the snapshot or the profile cannot be read, or the job never
// reached the controller (no link number).
Result<StrikeCheck> check_strikes(const JobRecord& job, std::string_view document_snapshot,
                                  std::string_view profile_json, std::span<const controller::LoggedStrike> logged,
                                  const machine::FirmwareTables* firmware);

}  // namespace tactus::spool
