// SPDX-License-Identifier: GPL-3.0-or-later
#include "backend_job.hpp"

#include <chrono>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <thread>

#include "backend_status.hpp"
#include "cups_uri.hpp"
#include "import/import.hpp"
#include "link/link.hpp"
#include "spool/runner.hpp"
#include "spool/snapshot.hpp"
#include "spool/spool.hpp"
#include "spool_binding.hpp"

namespace tactus::cups {
namespace {

using spool::JobState;
using std::chrono::milliseconds;

bool contains(const std::string& s, const char* what) { return s.find(what) != std::string::npos; }

// Faults a person must clear at the machine: CUPS stops the queue with the
// reason, and `cupsenable` (after clearing it) runs the job on from where it stopped.
bool needs_person(const spool::JobRecord& j) {
    return j.state == JobState::paused && j.runner.empty() && !contains(j.reason, "paper out") &&
           j.reason != "paused by the operator";
}

Result<std::string> read_input(const std::optional<std::string>& file) {
    std::string data;
    if (file) {
        std::ifstream in(*file, std::ios::binary);
        if (!in) return fail(ErrorKind::input, "cannot read the print file", *file);
        data.assign(std::istreambuf_iterator<char>(in), {});
    } else {
        std::ostringstream ss;
        ss << std::cin.rdbuf();
        data = ss.str();
    }
    if (data.size() > import::max_import_bytes) return fail(ErrorKind::input, "the print data is larger than 256 MB");
    return data;
}

JobView view_of(spool::Spool& s, const spool::JobRecord& j) {
    JobView v;
    v.state = j.state;
    v.reason = j.reason;
    v.total_sheets = j.total_sheets();
    if (auto p = s.progress(j.id)) v.progress = *p;
    if (auto ev = s.events(j.id, 20))
        for (auto it = ev->rbegin(); it != ev->rend(); ++it)
            if (it->kind == "printer") {
                v.last_note = it->message;
                break;
            }
    if (j.state == JobState::queued)
        if (auto all = s.jobs(false, j.printer))
            for (const auto& other : *all) {
                if (other.id == j.id) break;
                ++v.jobs_ahead;
            }
    return v;
}

// The spool job for this CUPS job: the one an earlier run submitted (set
// going again if it stopped), or a new one.
Result<spool::JobRecord> submit_once(spool::Spool& s, const BackendJob& job, const spool::PrinterRecord& printer,
                                     const layout::PagedDocument& doc, const std::function<void(const std::string&)>& say) {
    const auto key = origin_key(job);
    auto existing = s.job_by_origin(key);
    if (!existing) return std::unexpected(existing.error());
    if (*existing) {
        auto j = **existing;
        say("INFO: CUPS runs this job again: continuing Tactus job " + std::to_string(j.id) + " (" +
            to_string(j.state) + ")");
        std::optional<spool::Action> again;
        if (j.state == JobState::cancelled || j.state == JobState::failed) again = spool::Action::retry;
        if (j.state == JobState::paused && j.runner.empty()) again = spool::Action::resume;
        if (again) {
            auto r = s.act(j.id, *again);
            if (!r) return std::unexpected(r.error());
            return *r;
        }
        return j;
    }
    spool::JobSubmission sub;
    sub.printer = printer.name;
    sub.title = job.title;
    sub.document = spool::to_snapshot(doc);
    sub.sheets_per_copy = doc.sheet_count();
    sub.copies = job.copies;
    sub.user = job.user;
    sub.origin = key;
    auto id = s.submit(sub);
    if (!id) return std::unexpected(id.error());
    return s.job(*id);
}

}  // namespace

std::string origin_key(const BackendJob& job) {
    if (const auto it = job.options.find("job-uuid"); it != job.options.end() && !it->second.empty())
        return "cups:" + it->second;
    return "cups:" + job.queue + ":" + job.cups_job_id;
}

int run_backend_job(const BackendJob& job, const BackendTuning& tuning,
                    const std::function<void(const std::string&)>& say, const std::atomic<bool>& terminate) {
    // --- what to emboss: the filter's laid-out pages, checked before anything is queued
    const auto device = device_from_uri(job.device_uri);
    if (!device) {
        say("ERROR: the queue's device URI is wrong: " + device.error().to_string());
        return backend_stop;
    }
    const auto input = read_input(job.file);
    if (!input) {
        say("ERROR: " + input.error().to_string());
        return backend_cancel;
    }
    if (input->empty()) {
        say("ERROR: nothing to emboss: the document could not be laid out (the filter's error says why)");
        return backend_cancel;
    }
    const auto doc = spool::from_snapshot(*input);
    if (!doc) {
        say("ERROR: the print data is not a Tactus page layout (was the queue added with the Tactus PPD?): " +
            doc.error().to_string());
        return backend_cancel;
    }
    if (doc->pages.empty()) {
        say("ERROR: nothing to emboss: the document has no pages");
        return backend_cancel;
    }

    // --- into the spool, once
    const auto db = cups_spool_path();
    auto opened = open_cups_spool();
    if (!opened) {
        say("ERROR: cannot open the Tactus spool: " + opened.error().to_string());
        return backend_stop;
    }
    spool::Spool& s = *opened;
    const auto printer = bind_printer(s, *device, job.queue);
    if (!printer) {
        say("ERROR: " + printer.error().to_string());
        return backend_stop;
    }
    const auto submitted = submit_once(s, job, *printer, *doc, say);
    if (!submitted) {
        say("ERROR: cannot queue the job in the Tactus spool: " + submitted.error().to_string());
        return backend_stop;
    }
    const spool::JobId id = submitted->id;
    const int retries_at_start = submitted->retries;
    say("INFO: Tactus job " + std::to_string(id) + " on " + printer->name + " (" + printer->device + ")");

    // --- report while the spool embosses it
    std::atomic<bool> finished{false};
    std::atomic<bool> stop_runner{false};
    std::thread observer([&] {
        auto os = spool::Spool::open(db, {.create = false});
        if (!os) return;
        StatusReporter reporter(os->progress(id).value_or(std::vector<spool::SheetProgress>{}));
        bool cancel_sent = false;
        for (;;) {
            const bool last = finished.load();
            if (auto j = os->job(id)) {
                if (terminate.load() && !cancel_sent && !is_terminal(j->state)) {
                    // Cancelled in CUPS (or cupsd stopping): cancel on the
                    // controller. If CUPS runs the job again, it resumes at
                    // the first sheet not embossed.
                    cancel_sent = true;
                    if (os->act(id, spool::Action::cancel)) say("INFO: cancelling on the embosser");
                }
                // Our job is over but the runner is busy with another job:
                // a backend that is going away must not hold the cable.
                if (terminate.load() && is_terminal(j->state)) stop_runner = true;
                for (const auto& line : reporter.update(view_of(*os, *j))) say(line);
            }
            if (last) break;
            std::this_thread::sleep_for(milliseconds(tuning.poll_ms));
        }
        for (const auto& line : reporter.clear()) say(line);
    });

    spool::RunnerOptions options;
    options.poll = milliseconds(tuning.poll_ms);
    options.link.reconnect_deadline = milliseconds(tuning.reconnect_ms);
    options.link.fault_wait = milliseconds(tuning.fault_wait_ms);
    const auto link_options = options.link;
    spool::Runner runner(db, printer->name,
                         [link_options](const spool::PrinterRecord& p) { return spool::open_printer(p, link_options); },
                         options);
    bool runner_held = false;
    bool told_waiting = false;
    int code = backend_ok;
    std::optional<spool::JobRecord> last;
    for (;;) {
        auto j = s.job(id);
        if (!j) {
            say("ERROR: the Tactus spool lost the job: " + j.error().to_string());
            code = backend_stop;
            break;
        }
        last = *j;
        if (is_terminal(j->state)) break;
        if (terminate.load() && !runner_held) {
            // Another runner holds the embosser: the cancel request reaches it
            // through the spool; give it a moment to carry it out.
            for (int i = 0; i < 50 && !is_terminal(j->state); ++i) {
                std::this_thread::sleep_for(milliseconds(tuning.poll_ms));
                if (auto again = s.job(id)) *j = *again;
            }
            last = *j;
            break;
        }
        if (j->state == JobState::paused && j->runner.empty() && contains(j->reason, "paper out")) {
            // Paper out for longer than the link waits: keep waiting, as a
            // printer does; the job goes on when paper is in.
            (void)s.act(id, spool::Action::resume);
            continue;
        }
        if (needs_person(*j)) {
            say("ERROR: " + j->reason);
            code = backend_stop;
            break;
        }
        if (j->state == JobState::queued && j->retries > retries_at_start &&
            j->not_before > spool::now_seconds()) {
            say("ERROR: the embosser is not reachable (" + j->reason + "); CUPS tries again later");
            code = backend_retry;
            break;
        }
        if (!runner_held) {
            if (runner.start()) {
                runner_held = true;
            } else if (!told_waiting) {
                told_waiting = true;
                say("INFO: another Tactus print server drives this embosser; following the job there");
            }
        }
        if (runner_held) {
            auto end = runner.run_next(stop_runner);
            if (!end) {
                say("ERROR: the Tactus spool cannot record progress: " + end.error().to_string());
                code = backend_stop;
                break;
            }
            if (*end) continue;
        }
        std::this_thread::sleep_for(milliseconds(tuning.poll_ms));
    }
    if (runner_held) runner.finish();
    finished = true;
    observer.join();

    if (code != backend_ok || !last) return code;
    switch (last->state) {
    case JobState::completed: return backend_ok;
    case JobState::cancelled:
        if (terminate.load()) return backend_ok;  // CUPS asked for it
        say("ERROR: the job was cancelled on the embosser's computer (" + last->reason + ")");
        return backend_cancel;
    case JobState::failed: say("ERROR: " + last->reason); return backend_cancel;
    default:
        // Terminated while another runner still had it: CUPS is going away.
        return backend_ok;
    }
}

}  // namespace tactus::cups
