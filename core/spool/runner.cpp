// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/runner.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <thread>

#include "encode/messages.hpp"
#include "link/fault_words.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile_json.hpp"
#include "spool/print_job.hpp"
#include "spool/printing.hpp"
#include "spool/runner_token.hpp"
#include "spool/settlement.hpp"
#include "spool/snapshot.hpp"
#include "common/try.hpp"
#include "transport/device.hpp"

namespace tactus::spool {
namespace {

using std::chrono::milliseconds;
namespace fault = encode::fault;

// Faults only a person can clear: the job waits for them instead of retrying.
constexpr std::uint8_t kOperatorFaults =
    fault::paper_out | fault::limit_switch | fault::hammer | fault::power_on_reset;


void sleep_unless(const std::atomic<bool>& stop, milliseconds d) {
    const auto until = std::chrono::steady_clock::now() + d;
    while (!stop.load() && std::chrono::steady_clock::now() < until)
        std::this_thread::sleep_for(std::min(d, milliseconds(20)));
}

// The sheet a stream stopped on (1-based; 0: none) goes out of the machine
// unfinished: report it, and emboss it again in full next time.
Result<void> spoil_interrupted(Spool& s, JobId id, std::size_t sheet, const std::string& why) {
    if (sheet == 0) return {};
    TACTUS_TRY(progress, s.progress(id));
    if (sheet > progress.size() || progress[sheet - 1].done()) return {};
    return s.spoil_sheet(id, sheet,
                         sheet_word(sheet) + " was in the printer when " + why +
                             ": discard it (it may be blank); it is embossed again in full");
}

// The wait before the nth attempt (1-based): --retry-ms, doubling, capped.
double backoff_ms(const RunnerOptions& o, int attempt) {
    return std::min<double>(static_cast<double>(o.max_backoff.count()),
                            static_cast<double>(o.retry_backoff.count()) * std::pow(2.0, std::min(attempt, 40) - 1));
}

}  // namespace

const char* to_string(RunEnd e) {
    switch (e) {
    case RunEnd::completed: return "completed";
    case RunEnd::cancelled: return "cancelled";
    case RunEnd::paused: return "paused";
    case RunEnd::requeued: return "requeued";
    case RunEnd::failed: return "failed";
    case RunEnd::stopped: return "stopped";
    }
    return "?";
}

std::optional<machine::FirmwareTables> printer_firmware_tables(const PrinterRecord& p) {
    auto prof = profile::parse_profile(p.profile_json);
    if (!prof) return std::nullopt;
    auto t = profile::make_firmware_tables(*prof);
    if (!t) return std::nullopt;
    return std::move(*t);
}

Result<link::Link> open_printer(const PrinterRecord& p, link::LinkOptions options) {
    // A simulated printer runs the firmware its profile makes (protocol 3),
    // unless its device string says protocol=2 (sim_firmware_for).
    const auto spec = transport::parse_device(p.device);
    if (spec && spec->scheme == "sim") options.sim_firmware = printer_firmware_tables(p);
    return link::Link::open(p.device, options);
}

Runner::Runner(std::filesystem::path db, std::string printer, ConnectFn connect, RunnerOptions options)
    : db_path_(std::move(db)),
      printer_name_(std::move(printer)),
      connect_(std::move(connect)),
      options_(options),
      token_(this_runner_token()) {}

Runner::~Runner() { finish(); }

Result<void> Runner::start() {
    TACTUS_TRY(s, Spool::open(db_path_, {.create = false}));
    spool_.emplace(std::move(s));
    TACTUS_TRY(p, spool_->printer(printer_name_));
    printer_ = p;
    if (auto r = spool_->claim_printer(printer_.id, token_); !r) return r;
    reserve_ = DiskReserve(db_path_.string() + ".reserve-" + std::to_string(printer_.id));
    if (!reserve_.hold())
        (void)spool_->log({}, printer_.id, "disk",
                          "no room for the spool's reserve beside " + db_path_.string() +
                              ": a disk that fills mid-job may leave the job shown as running");
    return {};
}

void Runner::finish() {
    link_.reset();
    reserve_.release();
    if (spool_) (void)spool_->release_printer(printer_.id, token_);
    spool_.reset();
}

Result<void> Runner::run(const std::atomic<bool>& stop) {
    while (!stop.load()) {
        TACTUS_TRY(end, run_next(stop));
        if (!end) sleep_unless(stop, options_.poll);
    }
    return {};
}

Result<std::optional<RunEnd>> Runner::run_next(const std::atomic<bool>& stop) {
    TACTUS_TRY(job, spool_->claim_next(printer_.id, token_, now_seconds()));
    if (!job) return std::optional<RunEnd>{};
    const JobId id = job->id;
    auto end = run_job(std::move(*job), stop);
    // The spool refused a write mid-job (a full or failing disk): the job
    // must not stay "running" with nobody running it.
    if (!end && end.error().kind == ErrorKind::io) return std::unexpected(cannot_record(id, end.error()));
    if (!end) return std::unexpected(end.error());
    return std::optional<RunEnd>{*end};
}

Result<void> Runner::connect() {
    TACTUS_TRY(p, spool_->printer(printer_.id));  // the device may have been changed
    printer_ = p;
    TACTUS_TRY(link, connect_(printer_));
    TACTUS_TRY_VOID(link.hello());
    // No CONFIGURE here: each job sends its own, from the profile it was
    // planned with (run_job), after the open runs are settled.
    link_.emplace(std::move(link));
    (void)spool_->log({}, printer_.id, "connected", "connected to " + printer_.device);
    if (auto r = settle_open_runs(); !r) {
        link_.reset();
        return r;
    }
    return {};
}

// After a crash or a lost link the controller may have executed passes whose
// acknowledgement never reached the database, up to finishing the job by
// itself. The controller keeps the id and count of the job it last ran (a new
// session pauses a running job, the count intact), so before anything else is
// planned or sent the count is read and every open run record of this printer
// is settled with it (settlement.hpp, in one transaction each); then a job the
// controller still holds is aborted so it can never run on.
Result<void> Runner::settle_open_runs() {
    TACTUS_TRY(st, link_->status());
    controller_job_ = st.ack.job_id;
    TACTUS_TRY(open, spool_->open_runs(printer_.id));
    for (const auto& job : open) {
        TACTUS_TRY(progress, spool_->progress(job.id));
        TACTUS_TRY_VOID(spool_->settle_run(job.id, settle(job, progress, st)));
    }
    if ((st.flags & encode::flag::job_active) != 0) {
        if (auto a = link_->abort(); !a) return a;
        TACTUS_TRY_VOID(spool_->log({}, printer_.id, "aborted",
                              "the interrupted stream left on the controller (job " + std::to_string(st.ack.job_id) +
                                  ") was aborted"));
    }
    return {};
}

Result<RunEnd> Runner::transient_failure(const JobRecord& job, const std::string& why) {
    link_.reset();  // reopen from scratch next time
    const int attempt = job.retries + 1;
    if (attempt > options_.max_retries) {
        TACTUS_TRY_VOID(spool_->set_state(job.id, JobState::paused,
                                    why + " (gave up after " + std::to_string(options_.max_retries) +
                                        " retries; resume when the printer is back)",
                                    "fault", why));
        return RunEnd::paused;
    }
    const auto backoff = backoff_ms(options_, attempt);
    TACTUS_TRY_VOID(spool_->requeue(job.id,
                              "retry " + std::to_string(attempt) + " of " +
                                  std::to_string(options_.max_retries) + " in " +
                                  std::to_string(static_cast<int>(backoff / 1000)) + " s: " + why,
                              now_seconds() + backoff / 1000.0, true));
    return RunEnd::requeued;
}

Error Runner::cannot_record(JobId id, const Error& why) {
    const std::string reason = "the spool cannot be written (" + why.message +
                               "): make room on its disk, then resume the job (it starts again at its "
                               "first unfinished sheet)";
    reserve_.release();
    const auto paused = spool_->set_state(id, JobState::paused, reason, "disk", reason);
    reserve_.hold();  // taken again if the disk has room by now, else at the next start
    const auto job = std::to_string(id);
    return Error{"cannot record progress in the spool (" + why.message + "); " +
                     (paused ? "job " + job + " is paused: make room on the disk, then `tactus-cli queue resume " +
                                   job + "` and start serve again"
                             : "the job could not be paused either and resumes at the next start") +
                     " (the controller's count is kept for it)",
                 why.where, ErrorKind::io};
}

Result<RunEnd> Runner::wait_for_printer(const JobRecord& job, const std::string& why) {
    link_.reset();
    const auto backoff = backoff_ms(options_, ++unreachable_);
    TACTUS_TRY_VOID(spool_->requeue(job.id,
                              "waiting for printer '" + printer_.name + "': " + why + " (trying again in " +
                                  std::to_string(static_cast<int>(backoff / 1000)) + " s)",
                              now_seconds() + backoff / 1000.0, false));
    return RunEnd::requeued;
}

Result<RunEnd> Runner::run_job(JobRecord job, const std::atomic<bool>& stop) {
    Spool& s = *spool_;
    // --- what to emboss: the stored document, planned with the printer's profile now
    TACTUS_TRY(snapshot, s.document_snapshot(job.id));
    auto doc = from_snapshot(snapshot);
    if (!doc) {
        const auto why = "the stored document is unreadable: " + doc.error().to_string();
        TACTUS_TRY_VOID(s.set_state(job.id, JobState::failed, why, "failed", why));
        return RunEnd::failed;
    }
    TACTUS_TRY(printer, s.printer(job.printer_id));
    printer_ = printer;
    auto profile = profile::parse_profile(printer.profile_json);
    if (!profile) {
        const auto why = "printer '" + printer.name + "' has an invalid profile (" +
                         profile.error().to_string() + "); fix it, then retry the job";
        TACTUS_TRY_VOID(s.set_state(job.id, JobState::failed, why, "failed", why));
        return RunEnd::failed;
    }
    // --- the printer first: connecting settles whatever an earlier run left
    // behind with the controller's count, and says which protocol it speaks,
    // so the job is planned once, for that protocol.
    if (!link_) {
        if (auto c = connect(); !c) return wait_for_printer(job, c.error().to_string());
        unreachable_ = 0;
    }
    // The reference firmware (protocol 3, as the simulators speak it too) runs
    // table moves: the job is planned with the tables the profile makes, the
    // rule the firmware was built with; HELLO_REPLY's table id must be theirs
    // (use_firmware_tables), or the firmware was built for another profile.
    const auto firmware_refuses = [&](const Error& e) -> Result<RunEnd> {
        const auto why = "printer '" + printer.name + "' runs the reference firmware (protocol 3), which "
                         "cannot emboss with its current profile: " + e.to_string();
        TACTUS_TRY_VOID(s.set_state(job.id, JobState::failed, why, "failed", why));
        return RunEnd::failed;
    };
    std::optional<machine::FirmwareTables> tables;
    if (link_->protocol() == encode::kProtocolV3) {
        auto t = profile::make_firmware_tables(*profile);
        if (!t) return firmware_refuses(t.error());
        tables = std::move(*t);
    }
    auto print = tables ? make_firmware_print_job(*doc, *profile, *tables, printer.device, job.copies)
                        : make_print_job(*doc, *profile, printer.device, job.copies);
    auto* plan = print ? &print->plan : nullptr;
    if (!print && print.error().where == kPassesWhere) {
        TACTUS_TRY_VOID(s.set_state(job.id, JobState::failed, print.error().message, "failed", print.error().message));
        return RunEnd::failed;
    }
    if (!plan || plan->sheets.size() != job.total_sheets()) {
        const auto why = "the document no longer lays out with printer '" + printer.name +
                         "''s current profile: " +
                         (plan ? "it plans to " + std::to_string(plan->sheets.size()) +
                                     " sheets, the job has " + std::to_string(job.total_sheets())
                               : print.error().to_string()) +
                         "; the job is kept (restore the profile or lay the document out again)";
        TACTUS_TRY_VOID(s.set_state(job.id, JobState::failed, why, "failed", why));
        return RunEnd::failed;
    }
    if (tables)
        if (auto checked = link_->use_firmware_tables(*print->firmware, print->timing); !checked)
            return firmware_refuses(checked.error());
    TACTUS_TRY(submitted_profile, s.profile_snapshot(job.id));
    if (submitted_profile != printer.profile_json)
        TACTUS_TRY_VOID(s.log(job.id, printer.id, "profile",
                        "the printer's profile changed since submission; planned with the current one"));
    std::vector<std::size_t> passes;
    for (const auto& sheet : plan->sheets) passes.push_back(sheet.passes.size());
    // The controller gets the configuration of the profile this job was just
    // planned with (the printer's profile may have changed since the link opened).
    if (auto c = link_->configure(print->config); !c) return transient_failure(job, c.error().to_string());
    TACTUS_TRY_VOID(s.set_sheet_passes(job.id, passes));

    // --- where to start: the first unfinished sheet, or the operator's choice
    TACTUS_TRY(progress, s.progress(job.id));
    std::size_t first_unfinished = 0;
    for (const auto& p : progress)
        if (!p.done()) {
            first_unfinished = p.sheet;
            break;
        }
    std::size_t start = first_unfinished;
    if (job.resume_sheet) {
        start = *job.resume_sheet;
        TACTUS_TRY_VOID(s.clear_resume_sheet(job.id));
        TACTUS_TRY_VOID(s.log(job.id, printer.id, "resume-point",
                        "starting at " + sheet_word(start) + " as the operator chose (first unfinished: " +
                            (first_unfinished ? sheet_word(first_unfinished) : "none") + ")"));
    }
    if (start == 0) {
        TACTUS_TRY_VOID(s.set_state(job.id, JobState::completed, "", "completed",
                              "every sheet had already been embossed"));
        return RunEnd::completed;
    }
    // A sheet cannot be fed twice: a partly embossed one is ejected and
    // discarded, and the sheet is embossed again in full on fresh paper.
    for (std::size_t k = start; k <= progress.size(); ++k) {
        const auto& p = progress[k - 1];
        if (p.done())
            TACTUS_TRY_VOID(s.restart_sheet(job.id, k, sheet_word(k) + " is embossed again at the operator's request"));
        else if (p.passes_done > 0)
            // Settled runs leave no partial sheet; this is a record from
            // before that rule (or an operator's restart point inside one).
            TACTUS_TRY_VOID(s.spoil_sheet(job.id, k,
                                    sheet_word(k) + " was left unfinished (" + std::to_string(p.passes_done) +
                                        " of " + std::to_string(p.passes_total) +
                                        " passes recorded): that partial sheet is discarded and the sheet "
                                        "embossed again in full"));
    }

    // --- stream it, named first: the controller job id, the start sheet and
    // the first pass are committed before the first DATA frame
    const auto first = first_passes(progress);
    TACTUS_TRY(link_job, s.begin_run(job.id, start, first[start - 1], controller_job_));
    controller_job_ = link_job;
    TACTUS_TRY_VOID(s.log(job.id, printer.id, "sending",
                    "sending " + sheet_word(start) + " to " + std::to_string(job.total_sheets()) + " to " +
                        printer.device));
    link::CancelToken cancel;
    std::atomic<bool> watching{true};
    std::atomic<bool> operator_cancel{false};
    std::mutex state_mutex;  // the watcher and the progress callback both change the state
    bool fault_paused = false;
    std::optional<Error> db_error;
    std::uint8_t last_faults = 0;

    link::Link& link = *link_;
    // Operator requests arrive through the database from any client; the watcher
    // has its own connection (a SQLite connection belongs to one thread).
    std::thread watcher([&] {
        auto ws = Spool::open(db_path_, {.create = false});
        if (!ws) return;
        while (watching.load()) {
            if (stop.load()) cancel.cancel();
            auto control = ws->take_control(job.id);
            if (control && *control != Control::none) {
                std::lock_guard lock(state_mutex);
                switch (*control) {
                case Control::pause:
                    link.request_pause();
                    (void)ws->set_state(job.id, JobState::paused, "paused by the operator", "paused",
                                        "pause sent: the printer stops at the end of the current pass",
                                        true);
                    break;
                case Control::resume:
                    link.request_resume();
                    fault_paused = false;
                    (void)ws->set_state(job.id, JobState::running, "", "resumed", "resume sent to the printer", true);
                    break;
                case Control::cancel:
                    operator_cancel = true;
                    cancel.cancel();
                    break;
                case Control::none: break;
                }
            }
            std::this_thread::sleep_for(options_.poll);
        }
    });

    auto on_progress = [&](const link::Progress& p) {
        last_faults = p.status.ack.faults;
        if (p.executed) {
            // Recorded before the link goes on. If the disk refuses, try again
            // for a while (the link stalls meanwhile); then stop the job on the
            // controller as a stopping server does: the run stays open, so the
            // next start settles it with the controller's count.
            const auto refused_since = std::chrono::steady_clock::now();
            for (;;) {
                auto r = s.record_passes(job.id, p.executed->sheet, p.executed->pass_in_sheet + 1);
                if (r) break;
                db_error = r.error();
                if (stop.load() || cancel.cancelled()) return;
                if (std::chrono::steady_clock::now() - refused_since >= options_.write_retry) {
                    cancel.cancel();
                    return;
                }
                std::this_thread::sleep_for(options_.poll);
            }
            db_error.reset();
            std::lock_guard lock(state_mutex);
            if (fault_paused) {
                fault_paused = false;
                (void)s.set_state(job.id, JobState::running, "", "resumed", "the printer is running again", true);
            }
            return;
        }
        if (p.note.empty()) return;
        (void)s.log(job.id, printer_.id, "printer", p.note);
        if ((p.status.ack.faults & kOperatorFaults) != 0) {
            std::lock_guard lock(state_mutex);
            if (!fault_paused) {
                fault_paused = true;
                // The reason in words with what to do ("Paper out: put paper in
                // the feeder..."): the link's first note is only "controller fault".
                auto why = link::explain_faults(p.status.ack.faults & kOperatorFaults);
                if (why.empty()) why = p.note;
                (void)s.set_state(job.id, JobState::paused, why, "fault", why, true);
            }
        }
    };

    auto outcome = link.send_job(print->plan, start, on_progress, cancel, link_job);
    watching = false;
    watcher.join();
    if (db_error) {
        link_.reset();  // the next start settles the open run with the controller's count
        return std::unexpected(*db_error);  // run_next pauses the job with it
    }
    if (!outcome) {
        // Nothing was sent: the plan is one the protocol cannot carry. Retrying
        // cannot change that.
        TACTUS_TRY_VOID(s.end_run(job.id));
        const auto why = "the printer cannot be sent this job: " + outcome.error().to_string();
        TACTUS_TRY_VOID(s.set_state(job.id, JobState::failed, why, "failed", why));
        return RunEnd::failed;
    }

    switch (outcome->end) {
    case link::JobEnd::completed:
        TACTUS_TRY_VOID(s.end_run(job.id));
        TACTUS_TRY_VOID(s.set_state(job.id, JobState::completed, "", "completed",
                              "all " + std::to_string(job.total_sheets()) + " sheets embossed"));
        return RunEnd::completed;
    case link::JobEnd::cancelled: {
        if (operator_cancel) {
            // The link aborted the controller's job; the sheet it was on is ejected unfinished.
            TACTUS_TRY_VOID(s.end_run(job.id));
            TACTUS_TRY_VOID(spoil_interrupted(s, job.id, outcome->resume_sheet, "the job was cancelled"));
            TACTUS_TRY_VOID(s.set_state(job.id, JobState::cancelled, "cancelled by the operator", "cancelled",
                                  "aborted on the controller at " + sheet_word(outcome->resume_sheet)));
            return RunEnd::cancelled;
        }
        // The server is stopping. A pass may have finished between the last
        // report and the abort, so the run stays open: the next start settles
        // it with the controller's count, as after a crash.
        link_.reset();
        TACTUS_TRY_VOID(s.requeue(job.id, "the print server stopped; resumes at the first unfinished sheet",
                            0, false));
        return RunEnd::stopped;
    }
    case link::JobEnd::not_answering:
        // The printer stopped answering (the link's bounded give-up): the job
        // is not at fault. It waits in the queue for the printer, as a job
        // for a printer that cannot be reached does; the run stays open, so
        // the next connection settles it with the controller's own count.
        return wait_for_printer(job, outcome->error.to_string());
    case link::JobEnd::failed: break;
    }
    const std::string why = outcome->error.to_string();
    // The link names the fault in its error; the last status says it too
    // unless the failure came before any report.
    const bool needs_operator = (last_faults & kOperatorFaults) != 0 ||
                                why.find("lost power") != std::string::npos ||
                                why.find("hammer fault") != std::string::npos ||
                                why.find("paper out") != std::string::npos;
    if (needs_operator) {
        // The run stays open: the next start reads the controller's count.
        // After a power loss there is no count left to read: the sheet in the
        // machine is reported now.
        link_.reset();
        if (why.find("lost power") != std::string::npos)
            TACTUS_TRY_VOID(spoil_interrupted(s, job.id, outcome->resume_sheet, "the controller lost power"));
        TACTUS_TRY_VOID(s.set_state(job.id, JobState::paused, why, "fault", why));
        return RunEnd::paused;
    }
    return transient_failure(job, why);
}

}  // namespace tactus::spool
