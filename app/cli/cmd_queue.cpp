// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli queue: look at and steer the print queue. Every subcommand is one
// transaction on the spool database, so it works whether or not `serve` runs;
// requests for a job on a printer reach its runner through the database.
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "command.hpp"
#include "common/file_io.hpp"
#include "profile/profile.hpp"
#include "profile/profile_json.hpp"
#include "spool/db_path.hpp"
#include "spool/snapshot.hpp"
#include "spool_args.hpp"

namespace tactus::cli {
namespace {

using spool::JobRecord;
using spool::Spool;

struct QueueArgs {
    std::string db;
    bool all = false;
    std::string printer;
    std::int64_t job = 0;
    std::size_t from_sheet = 0;
    std::size_t from_page = 0;
    std::size_t limit = 50;
    // printer add/set
    std::string name, device, profile;
};

struct Totals {
    std::size_t done = 0, spoiled = 0;
};

Totals totals(Spool& s, spool::JobId id) {
    Totals t;
    for (const auto& p : require(s.progress(id))) {
        t.done += p.done();
        t.spoiled += p.spoiled;
    }
    return t;
}

std::string fit(std::string s, std::size_t width) {
    if (s.size() > width) s = s.substr(0, width - 1) + "~";
    return s;
}

void list(const QueueArgs& a) {
    Spool s = open_spool(a.db, false, true);
    std::optional<std::string> printer;
    if (!a.printer.empty()) printer = require(s.printer(a.printer)).name;
    const auto jobs = require(s.jobs(a.all, printer));
    if (jobs.empty()) {
        std::cout << (a.all ? "no jobs\n" : "no jobs waiting (use --all for finished ones)\n");
        return;
    }
    std::cout << std::left << std::setw(6) << "ID" << std::setw(10) << "STATE" << std::setw(5) << "PRI"
              << std::setw(12) << "PRINTER" << std::setw(10) << "SHEETS" << std::setw(10) << "USER"
              << std::setw(24) << "TITLE" << "NOTE\n";
    for (const auto& j : jobs) {
        const auto t = totals(s, j.id);
        std::ostringstream sheets;
        sheets << t.done << "/" << j.total_sheets();
        std::string note = j.reason;
        if (j.control != spool::Control::none) note = std::string(to_string(j.control)) + " requested";
        std::cout << std::setw(6) << j.id << std::setw(10) << to_string(j.state) << std::setw(5)
                  << j.priority << std::setw(12) << fit(j.printer, 11) << std::setw(10) << sheets.str()
                  << std::setw(10) << fit(j.user, 9) << std::setw(24) << fit(j.title, 23) << note
                  << '\n';
    }
}

void show(const QueueArgs& a) {
    Spool s = open_spool(a.db, false, true);
    const JobRecord j = require(s.job(a.job));
    const auto progress = require(s.progress(j.id));
    const auto t = totals(s, j.id);
    std::cout << "job:        " << j.id << "  " << j.title << '\n'
              << "state:      " << to_string(j.state) << (j.reason.empty() ? "" : " (" + j.reason + ")")
              << '\n'
              << "printer:    " << j.printer << '\n'
              << "submitted:  " << local_time(j.submitted_at) << " by " << j.user << '\n';
    if (j.started_at) std::cout << "started:    " << local_time(*j.started_at) << '\n';
    if (j.finished_at) std::cout << "finished:   " << local_time(*j.finished_at) << '\n';
    std::cout << "copies:     " << j.copies << " x " << j.sheets_per_copy << " sheets";
    if (j.first_page) std::cout << " (pages " << j.first_page << "-" << j.last_page << ")";
    std::cout << "\npriority:   " << j.priority << "\nsheets:     " << t.done << " of "
              << j.total_sheets() << " embossed";
    if (t.spoiled) std::cout << ", " << t.spoiled << " partial sheet(s) discarded";
    std::cout << '\n';
    if (j.retries) std::cout << "retries:    " << j.retries << '\n';
    if (j.resume_sheet) std::cout << "restart at: sheet " << *j.resume_sheet << '\n';
    if (j.control != spool::Control::none)
        std::cout << "requested:  " << to_string(j.control) << " (waiting for the runner)\n";
    for (const auto& p : progress)
        if (!p.done() && p.passes_done > 0)
            std::cout << "in progress: sheet " << p.sheet << ", pass " << p.passes_done << " of "
                      << p.passes_total << '\n';
    std::cout << "recent events:\n";
    for (const auto& e : require(s.events(j.id, 10)))
        std::cout << "  " << local_time(e.at) << "  " << std::setw(12) << std::left << e.kind << e.message
                  << '\n';
}

void act(const QueueArgs& a, spool::Action action) {
    Spool s = open_spool(a.db, false);
    std::optional<std::size_t> sheet;
    if (a.from_sheet && a.from_page) throw CLI::ValidationError("--from-sheet", "give --from-sheet or --from-page, not both");
    if (a.from_sheet) sheet = a.from_sheet;
    if (a.from_page) {
        // Page -> sheet within the first copy, from the job's stored geometry.
        const JobRecord j = require(s.job(a.job));
        const auto doc = require(spool::from_snapshot(require(s.document_snapshot(j.id))));
        const std::size_t pages = doc.pages.size();
        if (a.from_page > pages)
            fail_with(Error{"page " + std::to_string(a.from_page) + " is beyond the job's " +
                                std::to_string(pages) + " pages",
                            "--from-page", ErrorKind::input});
        sheet = a.from_page < 1 ? 0 : doc.geometry.sheet_of_page(a.from_page - 1);
    }
    const JobRecord j = require(s.act(a.job, action, sheet));
    std::cout << "job " << j.id << ": " << to_string(j.state);
    if (j.control != spool::Control::none)
        std::cout << " (" << to_string(j.control) << " passed to the runner on " << j.printer << ")";
    if (j.resume_sheet) std::cout << ", restarts at sheet " << *j.resume_sheet;
    std::cout << '\n';
}

void history(const QueueArgs& a) {
    Spool s = open_spool(a.db, false, true);
    std::optional<spool::JobId> job;
    if (a.job) job = require(s.job(a.job)).id;
    for (const auto& e : require(s.events(job, a.limit))) {
        std::cout << local_time(e.at) << "  ";
        std::cout << std::left << std::setw(6) << (e.job ? "#" + std::to_string(*e.job) : "-")
                  << std::setw(13) << e.kind << e.message << '\n';
    }
}

std::string read_profile(const std::string& file) {
    if (file.empty()) return profile::to_json(profile::default_profile()).dump(2);
    const auto text = require(read_file(file));
    const auto parsed = profile::parse_profile(text);
    if (!parsed) fail_with(exit_bad_input, located(parsed.error(), file));
    return profile::to_json(*parsed).dump(2);
}

void printer_add(const QueueArgs& a) {
    Spool s = open_spool(a.db, true);
    const auto p = require(s.add_printer(a.name, a.device, read_profile(a.profile)));
    std::cout << "printer " << p.name << " on " << p.device << '\n';
}

void printer_set(const QueueArgs& a) {
    Spool s = open_spool(a.db, false);
    std::optional<std::string> device, prof;
    if (!a.device.empty()) device = a.device;
    if (!a.profile.empty()) prof = read_profile(a.profile);
    const auto p = require(s.update_printer(a.name, device, prof));
    std::cout << "printer " << p.name << " on " << p.device << '\n';
}

void printer_list(const QueueArgs& a) {
    Spool s = open_spool(a.db, false, true);
    for (const auto& p : require(s.printers())) {
        std::cout << p.name << "  " << p.device;
        if (!p.runner.empty()) std::cout << "  (served by " << p.runner << ")";
        std::cout << '\n';
    }
}

void recover(const QueueArgs& a) {
    const auto path = require(spool::spool_path(a.db), exit_usage);
    // Only a damaged file is moved aside; anything else keeps its queue.
    const auto d = spool::diagnose(path);
    switch (d.health) {
    case spool::SpoolHealth::missing:
        std::cout << path.string() << ": no spool database here; nothing to recover\n";
        return;
    case spool::SpoolHealth::healthy:
        std::cout << path.string() << ": the spool database is fine; nothing to do\n";
        return;
    case spool::SpoolHealth::read_only:
        std::cout << path.string() << ": the spool database is fine but read-only (make the file and its "
                                      "folder writable to queue again); nothing moved\n";
        return;
    case spool::SpoolHealth::newer:
    case spool::SpoolHealth::foreign:
    case spool::SpoolHealth::in_use:
        fail_with(Error{d.detail.message + " (not damaged, so `queue recover` leaves it where it is)",
                        d.detail.where, ErrorKind::input});
    case spool::SpoolHealth::damaged: break;
    }
    const auto aside = require(spool::set_aside(path), exit_failure);
    std::cout << "moved the damaged spool to " << aside.string()
              << " (kept for inspection); a new, empty spool is created on next use\n";
}

}  // namespace

void add_queue_command(CLI::App& app) {
    auto a = std::make_shared<QueueArgs>();
    auto* q = app.add_subcommand("queue", "Show and steer the print queue (the spool database)");
    q->require_subcommand(1);
    // `--db` may come anywhere: subcommands pass options they do not know up.
    q->fallthrough();
    add_db_option(*q, a->db);

    auto* l = q->add_subcommand("list", "Jobs waiting or printing, in queue order");
    l->add_flag("--all,-a", a->all, "Also finished, cancelled and failed jobs (newest first)");
    l->add_option("--printer,-p", a->printer, "Only this printer's jobs");
    l->callback([a] { list(*a); });

    auto* sh = q->add_subcommand("show", "One job: state, progress, recent events");
    sh->add_option("job", a->job, "Job number")->required()->check(whole_number_from_one());
    sh->callback([a] { show(*a); });

    struct Act {
        const char* name;
        const char* help;
        spool::Action action;
    };
    for (const Act& x : {Act{"pause", "Hold a waiting job, or stop a printing one at the end of a pass", spool::Action::pause},
                         Act{"resume", "Continue a paused job (after clearing the fault)", spool::Action::resume},
                         Act{"cancel", "Cancel a job (a printing one is aborted on the controller)", spool::Action::cancel},
                         Act{"retry", "Queue a failed or cancelled job again from its first unfinished sheet", spool::Action::retry}}) {
        auto* c = q->add_subcommand(x.name, x.help);
        c->add_option("job", a->job, "Job number")->required()->check(whole_number_from_one());
        if (x.action == spool::Action::resume || x.action == spool::Action::retry) {
            c->add_option("--from-sheet", a->from_sheet,
                          "Start again at this sheet (1-based over all copies) instead of the first unfinished one")
                ->check(whole_number_from_one());
            c->add_option("--from-page", a->from_page, "Start again at the sheet carrying this braille page (first copy)")
                ->check(whole_number_from_one());
        }
        const auto action = x.action;
        c->callback([a, action] { act(*a, action); });
    }

    auto* h = q->add_subcommand("history", "The event log of one job, or of the whole spool");
    h->add_option("job", a->job, "Job number (default: all jobs)")->check(whole_number_from_one());
    h->add_option("--limit,-n", a->limit, "Newest events to show")->capture_default_str();
    h->callback([a] { history(*a); });

    auto* p = q->add_subcommand("printer", "Printers the queue knows");
    p->require_subcommand(1);
    auto* pa = p->add_subcommand("add", "Add a printer");
    pa->add_option("name", a->name, "Printer name")->required();
    pa->add_option("--device,-d", a->device, "Device string, e.g. serial:/dev/ttyUSB0 or pty:/dev/pts/3")->required();
    pa->add_option("--profile", a->profile, "Printer profile (JSON); default: the source embosser's A4 profile");
    pa->callback([a] { printer_add(*a); });
    auto* ps = p->add_subcommand("set", "Change a printer's device or profile");
    ps->add_option("name", a->name, "Printer name")->required();
    ps->add_option("--device,-d", a->device, "New device string");
    ps->add_option("--profile", a->profile, "New printer profile (JSON)");
    ps->callback([a] { printer_set(*a); });
    auto* pl = p->add_subcommand("list", "List printers");
    pl->callback([a] { printer_list(*a); });

    auto* r = q->add_subcommand("recover", "Move a damaged spool database aside (it is kept) so a new one can be made");
    r->callback([a] { recover(*a); });
}

}  // namespace tactus::cli
