// SPDX-License-Identifier: GPL-3.0-or-later
#include "emboss_queue.hpp"

#include <pwd.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "command.hpp"
#include "pipeline/pipeline.hpp"
#include "profile/profile_json.hpp"
#include "spool/snapshot.hpp"
#include "spool_args.hpp"

namespace tactus::cli {
namespace {

std::string user_name() {
    if (const char* u = std::getenv("USER"); u && *u) return u;
    if (const passwd* pw = getpwuid(getuid())) return pw->pw_name;
    return "uid " + std::to_string(getuid());
}

std::pair<std::size_t, std::size_t> parse_range(const std::string& r) {
    if (r.empty()) return {0, 0};
    std::size_t first = 0, last = 0;
    const auto dash = r.find('-');
    try {
        first = std::stoul(r.substr(0, dash));
        last = dash == std::string::npos ? first : (dash + 1 == r.size() ? 0 : std::stoul(r.substr(dash + 1)));
    } catch (const std::exception&) {
        throw CLI::ValidationError("--pages", "expected FIRST-LAST, FIRST- or N, e.g. 3-10");
    }
    if (first == 0) throw CLI::ValidationError("--pages", "pages count from 1");
    return {first, last};
}

}  // namespace

void add_emboss_queue_options(CLI::App& cmd, EmbossQueueArgs& a) {
    cmd.add_flag("--queue", a.enabled,
                 "Store the job in the print queue and return (`tactus-cli serve` embosses it)");
    add_db_option(cmd, a.db);
    cmd.add_option("--printer", a.printer, "With --queue: the queue's printer (default: the only one set up)");
    cmd.add_option("--copies", a.copies, "With --queue: copies")->capture_default_str()->check(CLI::Range(1, 10000));
    cmd.add_option("--pages", a.pages, "With --queue: braille page range, e.g. 3-10, 5- or 7 (default: all)");
    cmd.add_option("--priority", a.priority, "With --queue: higher runs first")->capture_default_str();
    cmd.add_option("--title", a.title, "With --queue: job title (default: the file name)");
}

void enqueue_emboss(const LayoutArgs& layout, const EmbossQueueArgs& a) {
    // The printer first: an unknown printer should not cost a layout.
    spool::Spool s = open_spool(a.db, false);
    std::string printer = a.printer;
    if (printer.empty()) {
        const auto all = require(s.printers());
        if (all.size() != 1)
            fail_with(exit_usage, Error{all.empty() ? "no printers are set up; add one with `tactus-cli queue printer add`"
                                                    : "several printers are set up; choose one with --printer",
                                        "--printer"});
        printer = all.front().name;
    }
    const auto record = require(s.printer(printer));
    const auto [first, last] = parse_range(a.pages);
    // The page format is the queue printer's unless the command line overrides
    // it, as for direct embossing.
    const auto profile = profile::parse_profile(record.profile_json);
    if (!profile) fail_with(exit_bad_input, located(profile.error(), "printer " + record.name));
    const auto options = layout.pipeline_options(*profile);
    const auto doc = lay_out_for_cli(layout, options);
    const auto part = require(spool::select_pages(doc, first, last));
    spool::JobSubmission job;
    job.printer = printer;
    job.title = a.title.empty() ? std::filesystem::path(layout.file).filename().string() : a.title;
    job.document = spool::to_snapshot(part);
    job.sheets_per_copy = part.sheet_count();
    job.copies = a.copies;
    job.first_page = first;
    job.last_page = first ? (last ? last : doc.pages.size()) : 0;
    job.priority = a.priority;
    job.user = user_name();
    const auto id = require(s.submit(job), exit_failure);
    std::cout << "queued job " << id << ": " << job.title << ", " << job.sheets_per_copy << " sheet(s) x "
              << job.copies << " on " << printer << '\n';
}

}  // namespace tactus::cli
