// SPDX-License-Identifier: GPL-3.0-or-later
#include "emboss_queue.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "command.hpp"
#include "pipeline/page_range.hpp"
#include "pipeline/pipeline.hpp"
#include "profile/profile.hpp"
#include "profile/profile_json.hpp"
#include "spool/print_job.hpp"
#include "spool/printer_setup.hpp"
#include "spool/runner_token.hpp"
#include "spool/snapshot.hpp"
#include "spool_args.hpp"

namespace tactus::cli {
namespace {

}  // namespace

void add_emboss_queue_options(CLI::App& cmd, EmbossQueueArgs& a) {
    cmd.add_flag("--queue", a.enabled,
                 "Store the job in the print queue and return (`tactus-cli serve` embosses it)");
    add_db_option(cmd, a.db);
    cmd.add_option("--printer", a.printer,
                   "With --queue: the queue's printer (default: the one on --device, set up on first use; "
                   "else the only one set up)");
    cmd.add_option("--copies", a.copies, "With --queue or an ipp:// device: copies")->capture_default_str()->check(CLI::Range(1, 10000));
    cmd.add_option("--pages", a.pages, "With --queue: braille pages as numbered on them, e.g. 3-10, 5- or 7; in a book (--volumes) also "
                   "t1 (title page) and p1-p2 (contents) (default: all)");
    cmd.add_option("--priority", a.priority, "With --queue: higher runs first")->capture_default_str();
    cmd.add_option("--title", a.title, "With --queue or an ipp:// device: job title (default: the file name)");
}

namespace {

// The queue printer for this job: --printer; else the one on --device (set up
// on first use, so `emboss --queue --device X` works on a fresh machine);
// else the only one there is.
std::string choose_printer(spool::Spool& s, const EmbossQueueArgs& a) {
    const auto all = require(s.printers());
    if (!a.printer.empty()) {
        if (!a.device.empty() && !s.printer(a.printer)) {
            require(s.add_printer(a.printer, a.device, profile::to_json(profile::default_profile()).dump()));
            std::cerr << "set up queue printer '" << a.printer << "' on " << a.device << '\n';
        }
        return a.printer;
    }
    if (!a.device.empty()) {
        bool created = false;
        const auto printer = require(
            spool::printer_for_device(s, a.device, profile::to_json(profile::default_profile()).dump(), &created));
        const auto& name = printer.name;
        if (!created) return name;
        std::cerr << "set up queue printer '" << name << "' on " << a.device
                  << " with the default profile (change it with `tactus-cli queue printer set " << name
                  << " --profile FILE`)\n";
        return name;
    }
    if (all.size() == 1) return all.front().name;
    if (all.empty())
        fail_with(exit_usage, Error{"no printers are set up: give the embosser's device (--device serial:/dev/ttyUSB0, "
                                    "--device sim, ...) and a queue printer is set up for it, or add one with "
                                    "`tactus-cli queue printer add NAME --device DEVICE`",
                                    "--printer", ErrorKind::usage});
    std::string names;
    for (const auto& p : all) names += (names.empty() ? "" : ", ") + p.name + " (" + p.device + ")";
    fail_with(exit_usage, Error{"several printers are set up: " + names + "; choose one with --printer", "--printer",
                                ErrorKind::usage});
}

}  // namespace

void enqueue_emboss(const LayoutArgs& layout, const EmbossQueueArgs& a) {
    // The printer first: an unknown printer should not cost a layout. With a
    // device the spool is created on first use.
    spool::Spool s = open_spool(a.db, !a.device.empty());
    const std::string printer = choose_printer(s, a);
    const auto record = require(s.printer(printer));
    // The range as the pages show their numbers (core's one rule, the app's too).
    std::optional<pipeline::PageRange> range;
    if (!a.pages.empty()) range = require(pipeline::parse_page_range(a.pages), exit_usage);
    // The page format is the queue printer's unless the command line overrides
    // it, as for direct embossing.
    const auto profile = profile::parse_profile(record.profile_json);
    if (!profile) fail_with(exit_bad_input, located(profile.error(), "printer " + record.name));
    const auto options = layout.pipeline_options(*profile);
    std::vector<std::string> labels;
    const auto doc = lay_out_for_cli(layout, options, &*profile, std::nullopt, false, &labels);
    std::size_t first = 0, last = 0;
    if (range) std::tie(first, last) = require(pipeline::find_page_range(labels, *range));
    const auto part = require(spool::select_pages(doc, first, last));
    // The print job the runner will make, made once now: a job the printer
    // cannot be sent (more passes than the controller counts, a page the
    // profile cannot plan) is refused here, not when it runs.
    (void)require(spool::make_print_job(part, *profile, record.device, a.copies));
    spool::JobSubmission job;
    job.printer = printer;
    job.title = a.title.empty() ? std::filesystem::path(layout.file).filename().string() : a.title;
    job.document = spool::to_snapshot(part);
    job.sheets_per_copy = part.sheet_count();
    job.copies = a.copies;
    job.first_page = first;
    job.last_page = last;
    job.priority = a.priority;
    job.user = spool::this_user_name();
    const auto id = require(s.submit(job));
    std::cout << "queued job " << id << ": " << job.title << ", " << job.sheets_per_copy << " sheet(s) x "
              << job.copies << " on " << printer << '\n';
}

}  // namespace tactus::cli
