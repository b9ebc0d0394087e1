// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One CUPS job in the tactus backend: the laid-out document from the
// tactus-layout filter goes into the Tactus spool (once, however often CUPS
// runs the job), the spool's runner for that embosser embosses it (this
// process becomes the runner unless a `tactus-cli serve` or another backend
// already is), and what the spool records is reported to cupsd. docs/cups.md
// explains the exit codes and why exactly-once holds through cupsd restarts.
#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "job_options.hpp"

namespace tactus::cups {

// backend(7) exit codes.
enum BackendExit : int {
    backend_ok = 0,
    backend_failed = 1,
    backend_stop = 4,           // the printer is stopped; the last ERROR: line says why
    backend_cancel = 5,         // the job is cancelled (it can never be embossed as it is)
    backend_retry = 6,          // retry the job later
};

struct BackendJob {
    std::string cups_job_id;   // argv[1]
    std::string user;          // argv[2]
    std::string title;         // argv[3]
    std::size_t copies = 1;    // argv[4]
    CupsOptions options;       // argv[5], parsed
    std::optional<std::string> file;  // argv[6]; stdin without it
    std::string device_uri;    // $DEVICE_URI
    std::string queue;         // $PRINTER
};

struct BackendTuning {
    int poll_ms = 100;          // how often the spool is read for progress
    int reconnect_ms = 30000;   // the link rides out a pulled cable this long, then RETRY
    int fault_wait_ms = 120000; // paper out: the link waits this long, then the job is resumed
};

// Runs the job; `say` writes one backend(7) line to cupsd; `terminate` is set
// by SIGTERM (the job was cancelled in CUPS, or cupsd is stopping).
int run_backend_job(const BackendJob& job, const BackendTuning& tuning,
                    const std::function<void(const std::string&)>& say, const std::atomic<bool>& terminate);

// The key that makes a CUPS job one spool job, however often CUPS runs it:
// its job-uuid, else queue and job number.
std::string origin_key(const BackendJob& job);

}  // namespace tactus::cups
