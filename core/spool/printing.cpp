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
                                  std::size_t copies) {
    copies = std::max<std::size_t>(copies, 1);
    // Refused as soon as the plan is known to be too long, before the copies
    // are made: planning all of a 100,000-page book first took gigabytes.
    plan::PlanOptions options;
    options.max_passes = encode::kMaxJobPasses / copies;
    auto one = plan::plan_job(doc, profile, options);
    if (!one && one.error().where == plan::kTooManyPassesWhere)
        return fail("the job has more than 65,535 passes (" + one.error().message +
                        (copies > 1 ? " of one copy, " + std::to_string(copies) + " copies" : std::string{}) +
                        "); the controller counts at most 65,535 in one job. Queue it in parts "
                        "(--pages, or fewer copies at a time)",
                    kPassesWhere);
    if (!one) return std::unexpected(one.error());
    if (copies == 1) return std::move(*one);
    return repeat_plan(*one, copies);
}


}  // namespace tactus::spool
