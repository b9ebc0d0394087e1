// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One print job as the embosser gets it: the plan and the controller
// configuration, both derived from the same printer profile, for one printer
// (device string), with what identifies them (the profile and the link
// protocol version). Every road to the embosser builds one here -- a direct
// `tactus-cli emboss`, `emboss --plan`, `emboss --queue` (checked before it is
// stored), the spool's runner and the app -- and sends `config` in CONFIGURE
// before `plan`'s frames, so the controller and the planner never get
// different profiles.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "common/result.hpp"
#include "layout/page.hpp"
#include "link/link.hpp"
#include "machine/controller_config.hpp"
#include "machine/firmware_tables.hpp"
#include "plan/plan.hpp"
#include "plan/plan_file.hpp"
#include "profile/profile.hpp"

namespace tactus::spool {

struct PrintJob {
    plan::JobPlan plan;
    machine::ControllerConfig config;  // what CONFIGURE sends: profile::controller_config(profile)
    profile::PrinterProfile profile;   // what plan and config were derived from
    int protocol = 0;                  // the link protocol version the plan is for
    std::string device;                // the printer; empty for a dry run
    // For the reference firmware (protocol 3): the ramp tables it was built
    // with, which the plan's moves are made of, and its strike timing.
    std::optional<machine::FirmwareTables> firmware;
    machine::StrikeTiming timing;
};

// The one function that makes a print job from a document: plans `copies`
// copies with `profile` (plan_copies: the spool's sheet numbering, the
// 65,535-pass limit) and derives the configuration from the same profile.
Result<PrintJob> make_print_job(const layout::PagedDocument& document, const profile::PrinterProfile& profile,
                                std::string_view device, std::size_t copies = 1);

// The same for the reference firmware (protocol 3): planned with the ramp
// tables it was built with, so the plan's moves are the ones it makes.
Result<PrintJob> make_firmware_print_job(const layout::PagedDocument& document, const profile::PrinterProfile& profile,
                                         const machine::FirmwareTables& tables, std::string_view device,
                                         std::size_t copies = 1);

// A saved plan as a print job for `device`. Refused (ErrorKind::input, with
// the reason) when the plan was made for another link protocol version, or,
// when `printer_profile` is given, with a profile other than the printer's.
// The controller is configured with the plan's own profile.
Result<PrintJob> make_print_job(plan::PlanFile file, std::string_view device,
                                const profile::PrinterProfile* printer_profile = nullptr);

// The job as a plan file (`plan --json` writes the same format a sheet at a time).
plan::PlanFile to_plan_file(const PrintJob& job);

// Sends the job on an open link with a session (after hello()): CONFIGURE
// from the job's profile (for the firmware, its tables checked first), then
// the plan from `start_sheet` (1-based).
// `job_id` as in link::Link::send_job.
Result<link::JobOutcome> send_print_job(link::Link& link, const PrintJob& job, std::size_t start_sheet,
                                        const link::ProgressFn& progress, const link::CancelToken& cancel,
                                        std::uint16_t job_id = 0);

// What sending a document from `start_sheet` would put on the line: the
// figures encode_job and chunk_stream give for the whole job (`emboss
// --dry-run`), made a sheet at a time, so a book costs the memory of two
// sheets' plans, not of its whole plan and stream. Fails as encode_job does,
// and as soon as the job passes the controller's 65,535 passes.
struct StreamSize {
    std::size_t stream_bytes = 0;  // job-stream bytes (DATA payloads)
    std::size_t frames = 0;        // DATA frames of at most encode::kMaxPayload bytes
    std::size_t line_bytes = 0;    // those frames on the line, headers and CRCs included
    std::size_t sheets = 0;        // of the whole job
    std::size_t strikes = 0;
};
Result<StreamSize> measure_print_job(const layout::PagedDocument& document, const profile::PrinterProfile& profile,
                                     std::size_t start_sheet = 1);

}  // namespace tactus::spool
