// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/print_job.hpp"

#include <utility>

#include <nlohmann/json.hpp>

#include "encode/messages.hpp"
#include "profile/controller_config.hpp"
#include "profile/profile_json.hpp"
#include "spool/printing.hpp"

namespace tactus::spool {
namespace {

// The one place a plan is paired with a controller configuration: both come
// from `profile`.
PrintJob assemble(plan::JobPlan plan, profile::PrinterProfile profile, int protocol, std::string_view device) {
    PrintJob job;
    job.config = profile::controller_config(profile);
    job.plan = std::move(plan);
    job.profile = std::move(profile);
    job.protocol = protocol;
    job.device = std::string(device);
    return job;
}

// The first place two profiles differ in anything the planner or the
// controller reads (the name is only a label), as a JSON path; empty when
// they do not.
std::string first_difference(const profile::PrinterProfile& a, const profile::PrinterProfile& b) {
    for (const auto& op : nlohmann::json::diff(profile::to_json(a), profile::to_json(b))) {
        const auto path = op.value("path", std::string{});
        if (path != "/name") return path.empty() ? "/" : path;
    }
    return {};
}

}  // namespace

Result<PrintJob> make_print_job(const layout::PagedDocument& document, const profile::PrinterProfile& profile,
                                std::string_view device, std::size_t copies) {
    auto plan = plan_copies(document, profile, copies);
    if (!plan) return std::unexpected(plan.error());
    return assemble(std::move(*plan), profile, encode::kProtocolVersion, device);
}

Result<PrintJob> make_print_job(plan::PlanFile file, std::string_view device,
                                const profile::PrinterProfile* printer_profile) {
    if (file.protocol != encode::kProtocolVersion)
        return fail("the plan was made for link protocol version " + std::to_string(file.protocol) +
                        "; this Tactus speaks version " + std::to_string(encode::kProtocolVersion) +
                        ": plan the document again (`tactus-cli plan --json`)",
                    "plan.protocol");
    if (printer_profile) {
        const auto diff = first_difference(file.profile, *printer_profile);
        if (!diff.empty())
            return fail("the plan was made with profile '" + file.profile.name + "', which differs from the "
                            "printer's profile '" + printer_profile->name + "' at " + diff +
                            ": plan the document again with the printer's profile, or emboss the plan "
                            "without --profile (the controller is then configured with the plan's own)",
                        "plan.profile");
    }
    return assemble(std::move(file.plan), std::move(file.profile), file.protocol, device);
}

plan::PlanFile to_plan_file(const PrintJob& job) {
    return plan::PlanFile{job.plan, job.profile, job.protocol};
}

Result<link::JobOutcome> send_print_job(link::Link& link, const PrintJob& job, std::size_t start_sheet,
                                        const link::ProgressFn& progress, const link::CancelToken& cancel,
                                        std::uint16_t job_id) {
    if (auto c = link.configure(job.config); !c) return std::unexpected(c.error());
    return link.send_job(job.plan, start_sheet, progress, cancel, job_id);
}

}  // namespace tactus::spool
