// SPDX-License-Identifier: GPL-3.0-or-later
// The CUPS filter `tactus-layout` (filter(7)): a document in any format Tactus
// imports -> braille pages laid out for the embosser behind the queue
// (application/vnd.tactus-paged, the spool's page snapshot), which the
// `tactus` backend embosses. The page format is the embosser's profile in
// the spool on this server; `-o` options (job_options.hpp) choose the table
// and may narrow the page. Any error is one ERROR: line and exit 1: CUPS
// stops the job and shows the line, and nothing reaches the embosser.
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include "cups_options.hpp"
#include "cups_uri.hpp"
#include "job_options.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/planner.hpp"
#include "profile/profile_json.hpp"
#include "spool/snapshot.hpp"
#include "spool_binding.hpp"

namespace {

using namespace tactus;

std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? v : "";
}

int fail_job(const std::string& why) {
    std::cerr << "ERROR: " << why << std::endl;
    return 1;
}

Result<std::string> read_all(int argc, char** argv) {
    std::string data;
    if (argc == 7) {
        std::ifstream in(argv[6], std::ios::binary);
        if (!in) return fail(ErrorKind::input, "cannot read the print file", argv[6]);
        data.assign(std::istreambuf_iterator<char>(in), {});
    } else {
        std::ostringstream ss;
        ss << std::cin.rdbuf();
        data = ss.str();
    }
    if (data.size() > import::max_import_bytes) return fail(ErrorKind::input, "the document is larger than 256 MB");
    return data;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 6 || argc > 7) {
        std::cerr << "Usage: tactus-layout job-id user title copies options [file]\n";
        return 1;
    }
    const auto options = cups::parse_cups_options(argv[5]);
    const std::string content_type = env("CONTENT_TYPE");
    const auto bytes = read_all(argc, argv);
    if (!bytes) return fail_job(bytes.error().to_string());

    // The embosser's profile: the layout is the machine's, as for `emboss --queue`.
    const auto device = cups::device_from_uri(env("DEVICE_URI"));
    if (!device) return fail_job("the queue's device URI is wrong: " + device.error().to_string());
    auto s = cups::open_cups_spool();
    if (!s) return fail_job("cannot open the Tactus spool: " + s.error().to_string());
    const auto printer = cups::bind_printer(*s, *device, env("PRINTER"));
    if (!printer) return fail_job(printer.error().to_string());
    const auto machine = profile::parse_profile(printer->profile_json);
    if (!machine)
        return fail_job("the profile of embosser '" + printer->name + "' on the print server is broken (" +
                        machine.error().to_string() + "); fix it with `tactus-cli queue printer set " + printer->name +
                        " --profile FILE`");

    layout::PagedDocument doc;
    if (content_type == "application/vnd.tactus-paged") {
        // Already laid out (e.g. by the Tactus app): checked, passed on.
        auto d = spool::from_snapshot(*bytes);
        if (!d) return fail_job("the laid-out pages are damaged: " + d.error().to_string());
        doc = std::move(*d);
    } else {
        const auto format = cups::source_format(content_type);
        if (!format) return fail_job(format.error().message);
        auto layout_options = cups::pipeline_options(options, *machine);
        if (!layout_options) return fail_job(layout_options.error().to_string());
        layout_options->import.format = *format;
        layout_options->translation_workers = 1;  // one job, one process: cupsd runs several at once
        const auto name_it = options.find("document-name-supplied");
        const std::string name = name_it != options.end() ? name_it->second : argv[3];
        auto document = import::import_bytes(*bytes, name, layout_options->import);
        if (!document) return fail_job(document.error().to_string());
        auto laid = pipeline::lay_out(*document, *layout_options);
        if (!laid) return fail_job(laid.error().to_string());
        doc = std::move(*laid);
    }
    if (doc.pages.empty()) return fail_job("the document has no text to emboss");
    // Planned once here so a page the machine cannot emboss fails the job now,
    // naming page and line, instead of at the embosser.
    if (auto plan = plan::plan_job(doc, *machine); !plan)
        return fail_job("embosser '" + printer->name + "' cannot emboss this layout: " + plan.error().to_string());
    for (std::size_t i = 0; i < doc.warnings.size() && i < 5; ++i) std::cerr << "WARNING: " << doc.warnings[i] << '\n';
    std::cerr << "INFO: " << doc.pages.size() << " braille page(s) on " << doc.sheet_count() << " sheet(s)"
              << std::endl;
    std::cout << spool::to_snapshot(doc);
    std::cout.flush();
    return std::cout ? 0 : 1;
}
