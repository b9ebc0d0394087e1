// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the spool database holds, as plain values (docs/spool.md has the schema).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "spool/job_state.hpp"

namespace tactus::spool {

using JobId = std::int64_t;
using PrinterId = std::int64_t;

struct PrinterRecord {
    PrinterId id = 0;
    std::string name;
    std::string device;        // link device string, e.g. "serial:/dev/ttyUSB0", "pty:/dev/pts/3"
    std::string profile_json;  // the printer's current profile (profile/profile_json.hpp)
    std::string runner;        // "host:pid" of the `serve` running it, empty when none
};

// What a client hands in to queue a job.
struct JobSubmission {
    std::string printer;        // printer name
    std::string title;
    std::string document;       // snapshot (snapshot.hpp) of the laid-out pages to emboss
    std::size_t sheets_per_copy = 0;
    std::size_t copies = 1;
    std::size_t first_page = 0;  // the range the snapshot was cut from (for display; 0 = all)
    std::size_t last_page = 0;
    int priority = 0;           // higher first; equal priorities in submission order
    std::string user;
    // Where the job comes from when another system sent it (e.g.
    // "cups:urn:uuid:..."); empty for local jobs. Submitting a job with an
    // origin the spool already has returns that job instead of a new one.
    std::string origin;
};

struct JobRecord {
    JobId id = 0;
    PrinterId printer_id = 0;
    std::string printer;
    std::string title;
    std::size_t sheets_per_copy = 0;
    std::size_t copies = 1;
    std::size_t first_page = 0, last_page = 0;
    int priority = 0;
    JobState state = JobState::queued;
    std::string reason;          // why it is paused or failed, or what it waits for
    Control control = Control::none;
    std::optional<std::size_t> resume_sheet;  // operator's choice for the next start
    int retries = 0;             // transient failures so far (retry policy)
    double not_before = 0;       // retry back-off: not started before this time
    std::string runner;          // who holds it on its printer
    std::string user;
    double submitted_at = 0, updated_at = 0;
    std::optional<double> started_at, finished_at;
    // Write-ahead record of the stream in flight (see docs/spool.md, crash safety).
    std::optional<std::uint16_t> link_job;
    std::size_t run_start_sheet = 0;
    std::size_t run_first_pass = 0;  // job-wide index of run_start_sheet's first pass
    bool run_open = false;

    [[nodiscard]] std::size_t total_sheets() const { return sheets_per_copy * copies; }
};

struct SheetProgress {
    std::size_t sheet = 0;         // 1-based over all copies
    std::size_t passes_total = 0;  // 0 until the job has been planned
    std::size_t passes_done = 0;   // passes the controller reported EXECUTED
    std::size_t spoiled = 0;       // partial sheets of this number ejected after an interruption
    [[nodiscard]] bool done() const { return passes_total > 0 && passes_done == passes_total; }
};

struct EventRecord {
    std::int64_t id = 0;
    std::optional<JobId> job;
    double at = 0;
    std::string kind;     // submitted, started, progress, fault, paused, resumed, ...
    std::string message;
};

}  // namespace tactus::spool
