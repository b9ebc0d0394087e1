// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli emboss: lay out, plan, encode and send a document to the embosser.
// Exit 0 only when the controller has confirmed executing every pass.
#include <unistd.h>

#include <csignal>
#include <iostream>

#include "command.hpp"
#include "conflict_warnings.hpp"
#include "emboss_queue.hpp"
#include "emboss_remote.hpp"
#include "ipp/queue_uri.hpp"
#include "profile/controller_config.hpp"
#include "encode/frame.hpp"
#include "plan/plan_file.hpp"
#include "encode/stream.hpp"
#include "layout_args.hpp"
#include "link/link.hpp"

#include "plan/planner.hpp"
#include "encode/stream_v3.hpp"
#include "profile/firmware_tables.hpp"
#include "profile_arg.hpp"

namespace tactus::cli {
namespace {

// The reference firmware's DATA payload: 31 bytes of ops and the check
// (firmware/PROTOCOL-v3.md); the dry run's frame count assumes it.
constexpr std::size_t kFirmwareMaxOps = 31;

link::CancelToken* g_cancel = nullptr;
extern "C" void on_interrupt(int) {
    if (g_cancel) g_cancel->cancel();
}

struct EmbossArgs {
    LayoutArgs layout;
    std::string profile;
    std::string device;
    bool dry_run = false;
    bool plan_file = false;
    std::size_t start_sheet = 1;
    std::string firmware_tables;  // the reference firmware's build/ramp.json (protocol v3)
    EmbossQueueArgs queue;
};

struct Prepared {
    plan::JobPlan plan;
    machine::ControllerConfig config;
    std::optional<machine::FirmwareTables> tables;
    machine::StrikeTiming timing;
};

// Plans for the controller: with the firmware's ramp tables when it is the
// reference firmware (protocol v3), so the plan's moves are the ones it makes.
Prepared prepare(const EmbossArgs& a, bool for_firmware) {
    Prepared out;
    if (a.plan_file && !for_firmware) {
        out.plan = require(plan::load_plan(a.layout.file));
        return out;
    }
    const auto profile = load_profile_arg(a.profile);
    if (for_firmware) {
        if (a.firmware_tables.empty())
            throw CommandFailed(exit_usage,
                                "emboss: the controller is the reference firmware (protocol 3): give the ramp "
                                "tables it was built with, --firmware-tables firmware/build/ramp.json");
        out.tables = require(profile::load_firmware_tables(a.firmware_tables));
        out.timing = profile::strike_timing(profile);
        out.config = profile::controller_config(profile);
    }
    if (a.plan_file) {
        out.plan = require(plan::load_plan(a.layout.file));
        return out;
    }
    const auto options = a.layout.pipeline_options(profile);
    const auto doc = lay_out_for_cli(a.layout, options);
    warn_about_conflicts(doc, profile);
    plan::PlanOptions po;
    po.firmware = out.tables;
    out.plan = require(plan::plan_job(doc, profile, po));
    out.config = profile::controller_config(profile);
    return out;
}

void print_bar(std::size_t done, std::size_t total, const link::PassExecuted& e) {
    const int width = 30;
    const auto filled = total ? static_cast<int>(width * done / total) : width;
    std::cerr << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
              << std::string(static_cast<std::size_t>(width - filled), ' ') << "] "
              << (total ? 100 * done / total : 100) << "%  sheet " << e.sheet << "  pass "
              << done << '/' << total << std::flush;
}

void run_emboss(const EmbossArgs& a, const CLI::App& cmd) {
    if (ipp::is_queue_uri(a.device))
        return emboss_remote(a.layout, a.device, cmd, a.queue.copies, a.queue.title);
    if (a.queue.enabled) {
        EmbossQueueArgs q = a.queue;
        q.device = a.device;  // --device with --queue: the queue printer on that device
        return enqueue_emboss(a.layout, q);
    }
    if (a.dry_run) {
        // With --firmware-tables: the v3 stream for the reference firmware
        // (its payload: 31 bytes of ops and the 2-byte check).
        const bool v3 = !a.firmware_tables.empty();
        const auto prepared = prepare(a, v3);
        const auto& plan = prepared.plan;
        std::size_t first = 0;
        for (const auto& s : plan.sheets) {
            if (s.index >= a.start_sheet) break;
            first += s.passes.size();
        }
        const auto stream = v3 ? require(encode::encode_job_v3(plan, *prepared.tables, prepared.timing, 1,
                                                               {first, 0, false}))
                               : require(encode::encode_job(plan, 1, {first, 0, false}));
        const auto chunks = v3 ? encode::chunk_stream_v3(stream, kFirmwareMaxOps)
                               : encode::chunk_stream(stream, encode::kMaxPayload);
        std::size_t line = 0;
        for (const auto& [b, e] : chunks) line += e - b + encode::kFrameOverhead + (v3 ? 2 : 0);
        std::cout << stream.bytes.size() << " bytes of job stream in " << chunks.size()
                  << " frames (" << line << " bytes on the line) for " << plan.sheets.size()
                  << " sheets, " << plan.strikes << " strikes\n";
        return;
    }
    if (a.device.empty()) throw CommandFailed(exit_usage, "emboss: --device is required (try --device sim)");
    // The error's kind tells a malformed device string (usage) from a device
    // that is not there (device).
    auto link = require(link::Link::open(a.device));
    // HELLO_REPLY says which controller answered: the reference firmware
    // (protocol 3) is planned for with its own tables.
    require(link.hello());
    const bool firmware = link.protocol() == encode::kProtocolV3;
    const auto prepared = prepare(a, firmware);
    const auto& plan = prepared.plan;
    if (firmware) require(link.use_firmware_tables(*prepared.tables, prepared.timing));
    require(link.configure(prepared.config));

    const bool tty = isatty(STDERR_FILENO) != 0;
    link::CancelToken cancel;
    g_cancel = &cancel;
    std::signal(SIGINT, on_interrupt);
    std::signal(SIGTERM, on_interrupt);
    bool bar_drawn = false;
    auto out = link.send_job(
        plan, a.start_sheet,
        [&](const link::Progress& p) {
            if (p.executed) {
                if (tty) {
                    print_bar(p.executed->passes_done, p.executed->passes_total, *p.executed);
                    bar_drawn = true;
                } else {
                    std::cout << "pass " << p.executed->passes_done << '/' << p.executed->passes_total
                              << " executed (sheet " << p.executed->sheet << ")" << std::endl;
                }
                return;
            }
            if (tty && bar_drawn) std::cerr << '\n';
            bar_drawn = false;
            // Flushed: a program reading the pipe (a test, a front end) sees
            // "paper out" while the job waits for paper, not after it.
            (tty ? std::cerr : std::cout) << "emboss: " << p.note << std::endl;
        },
        cancel);
    g_cancel = nullptr;
    if (bar_drawn) std::cerr << '\n';
    if (!out) fail_with(out.error());
    const auto& s = out->stats;
    switch (out->end) {
        case link::JobEnd::completed:
            std::cout << "embossed " << out->passes_done << " passes on " << a.device << ": "
                      << s.bytes_written << " bytes sent, " << s.frames_resent
                      << " frames resent, " << s.reconnects << " reconnects, " << s.restarts
                      << " restarts\n";
            return;
        case link::JobEnd::cancelled:
            throw CommandFailed(exit_failure, "cancelled after " + std::to_string(out->passes_done) +
                                                  " passes; resume with --start-sheet " +
                                                  std::to_string(out->resume_sheet));
        case link::JobEnd::failed:
            throw CommandFailed(exit_failure, out->error.to_string() + "; resume with --start-sheet " +
                                                  std::to_string(out->resume_sheet));
    }
}

}  // namespace

void add_emboss_command(CLI::App& app) {
    auto args = std::make_shared<EmbossArgs>();
    auto* cmd = app.add_subcommand("emboss", "Emboss a document (or a saved plan) on a device");
    args->layout.add_to(*cmd, /*with_interpoint=*/false);
    cmd->add_option("--profile,-p", args->profile, "Printer profile (JSON); default: the source embosser");
    cmd->add_option("--device,-d", args->device,
                    "serial:/dev/ttyUSB0?baud=57600, pty:/dev/pts/N, hid:VID:PID, lpt:/dev/parport0, sim, or a "
                    "CUPS queue ipp://host[:port]/printers/NAME (the server lays the document out with its "
                    "embosser's profile; --table, --cells, --lines, --page-numbers, --no-print-pages, "
                    "--eight-dot, --encoding, --copies and --title go with the job; the command follows "
                    "the job until it ends, Ctrl-C cancels it)");
    cmd->add_flag("--dry-run", args->dry_run, "Stop after encoding and print the byte count");
    cmd->add_flag("--plan", args->plan_file, "FILE is a saved plan (JSON), not a document");
    cmd->add_option("--firmware-tables", args->firmware_tables,
                    "The reference firmware's ramp tables (its build/ramp.json): a controller speaking protocol 3 "
                    "is planned for with them, and refused when it was built with others")
        ->check(CLI::ExistingFile);
    cmd->add_option("--start-sheet", args->start_sheet, "Resume from this sheet (1-based)")
        ->check(CLI::PositiveNumber);
    add_emboss_queue_options(*cmd, args->queue);
    cmd->callback([args, cmd] { run_emboss(*args, *cmd); });
}

}  // namespace tactus::cli
