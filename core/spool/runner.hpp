// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One runner per printer: takes the printer's jobs from the spool in queue
// order and streams them through the link, recording each pass only once the
// controller reports it EXECUTED. It survives faults (job paused with the
// reason), unplugged cables (retry with back-off), operator requests (pause,
// resume, cancel, read from the database so any client can send them) and its
// own death (the next runner reconciles with the controller before sending).
// docs/spool.md describes the exactly-once argument.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "common/result.hpp"
#include "link/link.hpp"
#include "spool/disk_reserve.hpp"
#include "spool/records.hpp"
#include "spool/spool.hpp"

namespace tactus::spool {

struct RunnerOptions {
    // Transient failures (device gone, link errors) before the job is paused
    // for the operator instead of retried.
    // (A printer that cannot be reached at all is not a job failure: its
    // jobs wait in the queue, however long, with the same back-off.)
    int max_retries = 5;
    std::chrono::milliseconds retry_backoff{2000};  // doubles per retry
    std::chrono::milliseconds max_backoff{60000};
    // How often an idle runner looks for work and a busy one for operator requests.
    std::chrono::milliseconds poll{100};
    // How long a refused write of a job's progress (disk full, failing disk) is
    // tried again before the job is stopped and paused with that reason: long
    // enough to ride out a moment's shortage, short enough that nobody waits
    // on a silent printer.
    std::chrono::milliseconds write_retry{10000};
    link::LinkOptions link;
};

// Opens the printer's device (open_printer in serve; the in-process simulator in tests).
using ConnectFn = std::function<Result<link::Link>(const PrinterRecord&)>;

// The ramp tables the reference firmware built from the printer's profile
// runs (profile::make_firmware_tables); nullopt when the profile is invalid
// or the firmware cannot run it.
std::optional<machine::FirmwareTables> printer_firmware_tables(const PrinterRecord& p);

// Link::open for a printer. A `sim` device simulates the reference firmware
// built from the printer's profile: protocol 3 with its tables
// (controller::open_device), protocol 2 for `sim?protocol=2` or a profile the
// firmware cannot run.
Result<link::Link> open_printer(const PrinterRecord& p, link::LinkOptions options);

// What one job run came to (for tests and serve's log).
enum class RunEnd { completed, cancelled, paused, requeued, failed, stopped };
[[nodiscard]] const char* to_string(RunEnd e);

class Runner {
public:
    Runner(std::filesystem::path db, std::string printer, ConnectFn connect,
           RunnerOptions options = {});
    ~Runner();
    Runner(const Runner&) = delete;
    Runner& operator=(const Runner&) = delete;

    // Opens the spool and takes the printer (refused while another live runner has it).
    Result<void> start();
    // Runs jobs until `stop` is set. Returns an error only when the spool itself
    // becomes unusable (the database cannot be written: the job under way is
    // stopped and paused with that reason): then nothing more can be recorded,
    // so nothing more may be embossed.
    Result<void> run(const std::atomic<bool>& stop);
    // Runs the next ready job, if any, to its end, pause or requeue.
    Result<std::optional<RunEnd>> run_next(const std::atomic<bool>& stop);
    // Lets go of the printer (jobs it held go back to the queue, progress kept).
    void finish();

    [[nodiscard]] const std::string& token() const { return token_; }

private:
    struct Run;
    Result<RunEnd> run_job(JobRecord job, const std::atomic<bool>& stop);
    // Opens the device, hello, configure, then settles every open run record
    // of the printer with the controller's own count before anything is sent.
    Result<void> connect();
    Result<void> settle_open_runs();
    Result<RunEnd> transient_failure(const JobRecord& job, const std::string& why);
    // The printer cannot be reached (not there, busy, switched off): the job
    // waits in the queue as it would for a busy printer, however long that
    // takes, trying again with back-off; it is not a fault of the job.
    Result<RunEnd> wait_for_printer(const JobRecord& job, const std::string& why);
    // The spool refused a write of the job's run: the job is paused with the
    // reason (in the room the reserve gives back) and the error passed up.
    Error cannot_record(JobId id, const Error& why);

    std::filesystem::path db_path_;
    std::string printer_name_;
    ConnectFn connect_;
    RunnerOptions options_;
    std::string token_;
    std::optional<Spool> spool_;
    PrinterRecord printer_;
    std::optional<link::Link> link_;
    std::uint16_t controller_job_ = 0;  // the job id the controller last reported
    int unreachable_ = 0;               // connection attempts failed in a row
    DiskReserve reserve_;               // room for the last write when the disk fills
};

}  // namespace tactus::spool
