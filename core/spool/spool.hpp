// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The durable print queue: one SQLite database (WAL) shared by every client
// (`tactus-cli queue`, `emboss --queue`, the GUI) and the runners of `serve`.
// Each process opens its own Spool; SQLite's locking and BEGIN IMMEDIATE make
// their changes serialise. Every change is one transaction that also appends to
// the event log, so the log never disagrees with the state.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "spool/records.hpp"
#include "spool/settlement.hpp"
#include "spool/sqlite.hpp"

namespace tactus::spool {

struct OpenOptions {
    bool create = true;          // create the file (and its folder) when missing
    bool read_only_ok = false;   // list/show/history work on a read-only database
    int busy_timeout_ms = 10000; // wait this long for another client's transaction
};

// Seconds since the Unix epoch (wall clock: timestamps are for people).
double now_seconds();

class Spool {
public:
    // Opens or creates the database, checks it is a Tactus spool of a version we
    // know, and switches it to WAL. A damaged, locked or foreign file is an
    // error naming the file; it is never replaced (see set_aside()).
    static Result<Spool> open(const std::filesystem::path& path, OpenOptions options = {});

    [[nodiscard]] const std::filesystem::path& path() const { return db_.path(); }
    [[nodiscard]] bool read_only() const { return read_only_; }
    // Full consistency check (PRAGMA quick_check); serve runs it at start.
    Result<void> check();

    // --- printers
    Result<PrinterRecord> add_printer(std::string_view name, std::string_view device,
                                      std::string_view profile_json);
    // Changes device and/or profile; jobs keep their own profile snapshot.
    Result<PrinterRecord> update_printer(std::string_view name, std::optional<std::string> device,
                                         std::optional<std::string> profile_json);
    Result<PrinterRecord> printer(std::string_view name);
    Result<PrinterRecord> printer(PrinterId id);
    Result<std::vector<PrinterRecord>> printers();

    // --- clients
    // The profile snapshot is the printer's profile at this moment.
    // Idempotent on `job.origin` (records.hpp): a known origin returns its job.
    Result<JobId> submit(const JobSubmission& job);
    // The job submitted with this origin, if any.
    Result<std::optional<JobRecord>> job_by_origin(std::string_view origin);
    Result<JobRecord> job(JobId id);
    Result<std::string> document_snapshot(JobId id);
    Result<std::string> profile_snapshot(JobId id);
    // Unfinished jobs first in queue order, then (with `finished`) the rest newest first.
    Result<std::vector<JobRecord>> jobs(bool finished, std::optional<std::string> printer = {});
    Result<std::vector<SheetProgress>> progress(JobId id);
    // `limit` newest events of one job or of the whole spool, oldest first.
    Result<std::vector<EventRecord>> events(std::optional<JobId> job, std::size_t limit = 200);

    // Applies an operator action (job_state.hpp rules) in one transaction.
    // `resume_sheet` (resume or retry) overrides where the job starts again.
    Result<JobRecord> act(JobId id, Action action, std::optional<std::size_t> resume_sheet = {});

    // --- runners (one per printer, see runner.hpp)
    // Takes the printer for `token` ("host:pid"). Refused while another live
    // runner holds it; a dead holder's jobs are released: running jobs go back
    // to the queue (their progress kept), held paused jobs stay paused.
    Result<void> claim_printer(PrinterId printer, std::string_view token);
    Result<void> release_printer(PrinterId printer, std::string_view token);
    // The next job to run (highest priority, oldest, not in back-off), marked
    // running and held by `token`; nullopt when none is ready.
    Result<std::optional<JobRecord>> claim_next(PrinterId printer, std::string_view token,
                                                double now);
    // Creates the per-sheet progress rows once the job is planned (kept if present).
    Result<void> set_sheet_passes(JobId id, const std::vector<std::size_t>& passes_per_sheet);
    // The controller executed passes [0, passes_done) of `sheet`. Never lowers.
    Result<void> record_passes(JobId id, std::size_t sheet, std::size_t passes_done);
    // A partly embossed sheet was ejected: its progress restarts, spoiled++.
    Result<void> spoil_sheet(JobId id, std::size_t sheet, std::string_view message);
    // Sheets embossed before that the operator asked to emboss again: their
    // progress restarts (not counted as spoiled: they were finished).
    Result<void> restart_sheet(JobId id, std::size_t sheet, std::string_view message);
    // Write-ahead, before the first DATA frame of a stream: in one transaction,
    // hands out the printer's next controller job id (never `avoid`, the id the
    // controller reports now) and records it with the start sheet and the
    // stream's first pass (job-wide). Returns the id the stream must carry.
    Result<std::uint16_t> begin_run(JobId id, std::size_t start_sheet, std::size_t first_pass,
                                    std::uint16_t avoid);
    Result<void> end_run(JobId id);
    // Jobs of `printer` with a run record still open (at most one in practice).
    Result<std::vector<JobRecord>> open_runs(PrinterId printer);
    // Applies a settlement (settlement.hpp) and closes the run record, all in
    // one transaction: a crash half-way settles it again from scratch.
    Result<void> settle_run(JobId id, const RunSettlement& settlement);
    // Runner-side state change with its event (`kind`) and reason. `held`:
    // the runner keeps the job on its printer (running, or paused inside a
    // stream it can resume); otherwise the job is let go.
    Result<void> set_state(JobId id, JobState state, std::string_view reason,
                           std::string_view kind, std::string_view message, bool held = false);
    // Back to the queue after a transient failure, not before `not_before`.
    Result<void> requeue(JobId id, std::string_view reason, double not_before, bool count_retry);
    // Reads and clears the operator's request for the runner.
    Result<Control> take_control(JobId id);
    Result<void> clear_resume_sheet(JobId id);
    Result<void> log(std::optional<JobId> job, std::optional<PrinterId> printer,
                     std::string_view kind, std::string_view message);
    // Cheap "did anyone commit since I last looked" (PRAGMA data_version).
    Result<std::int64_t> data_version();

private:
    explicit Spool(sql::Database db, bool read_only) : db_(std::move(db)), read_only_(read_only) {}
    Result<void> insert_event(std::optional<JobId> job, std::optional<PrinterId> printer,
                              std::string_view kind, std::string_view message);
    Result<JobRecord> job_locked(JobId id);

    sql::Database db_;
    bool read_only_ = false;
};

// What `queue recover` finds at a spool path. Only `damaged` (SQLite cannot
// read it, or its integrity check fails) may be moved aside: a read-only
// spool, one from a newer Tactus, another program's file or one in use is
// healthy or not ours, and is left where it is.
enum class SpoolHealth { missing, healthy, read_only, newer, foreign, in_use, damaged };
struct Diagnosis {
    SpoolHealth health = SpoolHealth::missing;
    Error detail;  // what was found, naming the file
};
Diagnosis diagnose(const std::filesystem::path& path);

// Moves a damaged database (and its -wal/-shm files) aside to
// "<name>.broken-<UTC time>" so a new one can be created; returns the new name.
Result<std::filesystem::path> set_aside(const std::filesystem::path& path);

}  // namespace tactus::spool
