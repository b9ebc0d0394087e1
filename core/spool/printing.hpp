// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// From a stored job to what the link sends: the profile parsed, the document
// planned once per copy, copies joined into one plan whose sheets are numbered
// 1..copies*sheets (the spool's sheet numbers), and the controller
// configuration taken from the same profile.
#include <cstddef>
#include <string_view>

#include "common/result.hpp"
#include "profile/controller_config.hpp"
#include "encode/messages.hpp"
#include "layout/page.hpp"
#include "machine/firmware_tables.hpp"
#include "plan/plan.hpp"
#include "profile/profile.hpp"

namespace tactus::spool {

// Plans `copies` copies of `doc`. Fails, naming page and line, when the
// document does not fit the profile (e.g. the profile now has fewer cells per
// line), and with `where` == kPassesWhere when all copies together have more
// passes than the controller counts in one job (encode::kMaxJobPasses).
// `firmware`: planned for the reference firmware (protocol 3) built with
// these ramp tables (plan::PlanOptions::firmware).
inline constexpr const char* kPassesWhere = "passes";
Result<plan::JobPlan> plan_copies(const layout::PagedDocument& doc, const profile::PrinterProfile& profile,
                                  std::size_t copies, const machine::FirmwareTables* firmware = nullptr);

// The sheet carrying braille page `page` (1-based) of a stored job's first
// copy (`queue resume --from-page`, the app's Resume from page). A page
// beyond the document is an error naming both.
Result<std::size_t> sheet_of_page(const layout::PagedDocument& doc, std::size_t page);

// Copies of an already planned copy, renumbered (exposed for tests).
plan::JobPlan repeat_plan(const plan::JobPlan& one, std::size_t copies);


}  // namespace tactus::spool
