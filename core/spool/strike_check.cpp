// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/strike_check.hpp"

#include <algorithm>
#include <vector>

#include "profile/profile_json.hpp"
#include "spool/printing.hpp"
#include "spool/snapshot.hpp"

namespace tactus::spool {

Result<StrikeCheck> check_strikes(const JobRecord& job, std::string_view document_snapshot,
                                  std::string_view profile_json, std::span<const controller::LoggedStrike> logged,
                                  const machine::FirmwareTables* firmware) {
    const std::string where = "job " + std::to_string(job.id);
    if (!job.link_job) return fail(ErrorKind::internal, "the job never reached the controller", where);
    auto doc = from_snapshot(document_snapshot);
    if (!doc) return std::unexpected(located(doc.error(), where + " document"));
    auto profile = profile::parse_profile(profile_json);
    if (!profile) return std::unexpected(located(profile.error(), where + " profile"));
    auto plan = plan_copies(*doc, *profile, job.copies, firmware);
    if (!plan) return std::unexpected(located(plan.error(), where));
    StrikeCheck check;
    check.first_sheet = std::max<std::size_t>(job.run_start_sheet, 1);
    check.last_sheet = job.total_sheets();
    std::vector<controller::LoggedStrike> expected;
    for (const auto& s : controller::planned_strikes(*plan))
        if (s.sheet >= check.first_sheet) expected.push_back(s);
    std::vector<controller::LoggedStrike> got;
    for (const auto& s : logged)
        if (s.job_id == *job.link_job) got.push_back(s);
    check.embossed = got.size();
    check.planned = expected.size();
    check.agrees = got == expected;
    return check;
}

}  // namespace tactus::spool
