// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/printing.hpp"

#include <algorithm>
#include <cmath>

#include "encode/stream.hpp"
#include "plan/planner.hpp"

namespace tactus::spool {

plan::JobPlan repeat_plan(const plan::JobPlan& one, std::size_t copies) {
    plan::JobPlan all = one;
    all.sheets.clear();
    all.sheets.reserve(one.sheets.size() * copies);
    const std::size_t per_copy = one.sheets.size();
    for (std::size_t c = 0; c < copies; ++c)
        for (const auto& sheet : one.sheets) {
            plan::SheetPlan s = sheet;
            s.index = sheet.index + c * per_copy;
            for (auto& pass : s.passes) pass.sheet = s.index;
            all.sheets.push_back(std::move(s));
        }
    const auto n = static_cast<double>(copies);
    all.duration_s = one.duration_s * n;
    all.lower_bound_s = one.lower_bound_s * n;
    all.strikes = one.strikes * copies;
    return all;
}

Result<std::size_t> sheet_of_page(const layout::PagedDocument& doc, std::size_t page) {
    if (page < 1 || page > doc.pages.size())
        return fail(ErrorKind::input,
                    "page " + std::to_string(page) + " is not in the job (it has " + std::to_string(doc.pages.size()) +
                        " braille pages)",
                    "page");
    return doc.geometry.sheet_of_page(page - 1);
}

Result<plan::JobPlan> plan_copies(const layout::PagedDocument& doc, const profile::PrinterProfile& profile,
                                  std::size_t copies, const machine::FirmwareTables* firmware) {
    copies = std::max<std::size_t>(copies, 1);
    // Refused as soon as the plan is known to be too long, before the copies
    // are made: planning all of a 100,000-page book first took gigabytes.
    plan::PlanOptions options;
    options.max_passes = encode::kMaxJobPasses / copies;
    if (firmware && copies > 1) {
        // The firmware's passes are relative moves, each copy's first from
        // where the previous one left the carriage (and its backlash): the
        // copies are planned as one document, each starting on a new sheet.
        options.firmware = *firmware;
        options.max_passes = encode::kMaxJobPasses;
        layout::PagedDocument all = doc;
        all.pages.clear();
        for (std::size_t c = 0; c < copies; ++c) {
            all.pages.insert(all.pages.end(), doc.pages.begin(), doc.pages.end());
            if (doc.geometry.interpoint && doc.pages.size() % 2 == 1) {
                layout::Page blank;  // the copy's last sheet has no back
                blank.filler = true;
                all.pages.push_back(std::move(blank));
            }
        }
        auto plan = plan::plan_job(all, profile, options);
        if (!plan && plan.error().where == plan::kTooManyPassesWhere)
            return fail(ErrorKind::input, "the job has more than 65,535 passes (" + plan.error().message + ", " +
                            std::to_string(copies) + " copies); the controller counts at most 65,535 in one job. "
                            "Queue it in parts (--pages, or fewer copies at a time)",
                        kPassesWhere);
        return plan;
    }
    if (firmware) options.firmware = *firmware;
    auto one = plan::plan_job(doc, profile, options);
    if (!one && one.error().where == plan::kTooManyPassesWhere)
        return fail(ErrorKind::input, "the job has more than 65,535 passes (" + one.error().message +
                        (copies > 1 ? " of one copy, " + std::to_string(copies) + " copies" : std::string{}) +
                        "); the controller counts at most 65,535 in one job. Queue it in parts "
                        "(--pages, or fewer copies at a time)",
                    kPassesWhere);
    if (!one) return std::unexpected(one.error());
    if (copies == 1) return std::move(*one);
    return repeat_plan(*one, copies);
}


}  // namespace tactus::spool
