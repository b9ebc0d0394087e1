// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli emboss: lay out, plan, encode and send a document to the embosser.
// Exit 0 only when the controller has confirmed executing every pass.
#include <chrono>
#include <iostream>
#include <optional>

#include "command.hpp"
#include "conflict_warnings.hpp"
#include "emboss_queue.hpp"
#include "emboss_remote.hpp"
#include "encode/frame.hpp"
#include "encode/stream.hpp"
#include "encode/stream_v3.hpp"
#include "ipp/queue_uri.hpp"
#include "layout_args.hpp"
#include "link/link.hpp"
#include "machine/reference_firmware.hpp"
#include "plan/plan_file.hpp"
#include "platform/console.hpp"
#include "platform/termination.hpp"
#include "profile/firmware_tables.hpp"
#include "profile_arg.hpp"
#include "protocol_choice.hpp"
#include "spool/print_job.hpp"
#include "transport/device.hpp"

namespace tactus::cli {
namespace {

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
    double give_up_after_s = 30;  // LinkOptions::give_up_after
    std::string firmware_tables;  // the reference firmware's build/ramp.json (protocol v3)
    EmbossQueueArgs queue;
};

// The tables a protocol-3 controller runs: the firmware build's ramp.json
// when given, else the ones the profile makes (the rule the firmware build
// and the simulator use); HELLO_REPLY's table id must match either way.
// `known`: the ones already made for the simulator.
machine::FirmwareTables firmware_tables(const EmbossArgs& a, const profile::PrinterProfile& p,
                                        const std::optional<machine::FirmwareTables>& known) {
    if (known) return *known;
    if (!a.firmware_tables.empty()) return require(profile::load_firmware_tables(a.firmware_tables));
    auto t = profile::make_firmware_tables(p);
    if (!t)
        throw CommandFailed(exit_bad_input,
                            "emboss: the controller speaks protocol 3, but the reference firmware cannot run this "
                            "profile: " + t.error().to_string());
    return *t;
}

// A saved plan (`--plan`), read once: its protocol decides the simulator's
// and is checked against the embosser's.
std::optional<plan::PlanFile> saved_plan(const EmbossArgs& a) {
    if (!a.plan_file) return std::nullopt;
    return require(plan::load_plan(a.layout.file));
}

// The tables the built-in simulator (`--device sim...`) runs: the profile's,
// so it speaks protocol 3 as the firmware built from the profile does; a
// saved plan's own (none for a legacy protocol-2 plan); none (protocol 2) for
// `sim?protocol=2`, and, with a one-line notice, for a profile the firmware
// cannot run. With a saved plan it speaks the plan's protocol (a legacy plan:
// 2), unless `protocol=` says otherwise.
std::optional<machine::FirmwareTables> sim_tables(const EmbossArgs& a, const std::optional<plan::PlanFile>& saved) {
    auto spec = transport::parse_device(a.device);
    if (!spec || spec->scheme != "sim") return std::nullopt;
    auto settings = transport::sim_settings(*spec);
    if (!settings || settings->protocol == 2) return std::nullopt;
    // The simulator follows a saved plan's protocol unless told one.
    if (saved && settings->protocol == 3 && !saved->firmware)
        throw CommandFailed(exit_bad_input, "emboss: the plan was made for protocol 2 (legacy), but the embosser speaks "
                                            "protocol 3: plan the document again without --protocol 2");
    if (saved) return saved->firmware;
    if (!a.firmware_tables.empty()) return require(profile::load_firmware_tables(a.firmware_tables));
    auto t = profile::make_firmware_tables(load_profile_arg(a.profile));
    if (t) return *t;
    if (settings->protocol == 3)
        throw CommandFailed(exit_bad_input, "emboss: sim?protocol=3: the reference firmware cannot run this profile: " +
                                                t.error().to_string());
    std::cerr << "emboss: the simulator speaks protocol 2, since the reference firmware cannot run this profile ("
              << t.error().to_string() << ")" << std::endl;
    return std::nullopt;
}

// A saved plan as the job for an embosser speaking `protocol`: the plan's
// own protocol must be the embosser's (a plan is not converted: its moves are
// the protocol's own), and with --firmware-tables, its tables those.
spool::PrintJob saved_plan_job(const EmbossArgs& a, plan::PlanFile file, int protocol) {
    if (file.protocol != protocol)
        throw CommandFailed(
            exit_bad_input,
            "emboss: the plan was made for protocol " + std::to_string(file.protocol) +
                (file.protocol == encode::kProtocolVersion ? " (legacy)" : "") + ", but the embosser speaks protocol " +
                std::to_string(protocol) + ": plan the document again" +
                (protocol == encode::kProtocolVersion ? " with --protocol 2" : " without --protocol 2"));
    if (file.firmware && !a.firmware_tables.empty()) {
        const auto given = require(profile::load_firmware_tables(a.firmware_tables));
        if (given.table_id != file.firmware->table_id)
            throw CommandFailed(exit_bad_input, "emboss: the plan was made with other ramp tables than --firmware-tables "
                                                "gives: plan the document again with --firmware-tables");
    }
    std::optional<profile::PrinterProfile> printer;
    if (!a.profile.empty()) printer = load_profile_arg(a.profile);
    return require(spool::make_print_job(std::move(file), a.device, printer ? &*printer : nullptr));
}

// The print job from the document; the controller is configured from the
// same profile. `for_firmware`: planned with the reference firmware's tables
// (protocol 3), `known_tables` when already made.
spool::PrintJob prepare(const EmbossArgs& a, bool for_firmware = false,
                        const std::optional<machine::FirmwareTables>& known_tables = std::nullopt) {
    const auto profile = load_profile_arg(a.profile);
    const auto options = a.layout.pipeline_options(profile);
    std::optional<machine::FirmwareTables> tables;
    if (for_firmware) tables = firmware_tables(a, profile, known_tables);
    const auto doc = lay_out_for_cli(a.layout, options, &profile, tables, !for_firmware);
    warn_about_conflicts(doc, profile);
    if (tables) return require(spool::make_firmware_print_job(doc, profile, *tables, a.device));
    return require(spool::make_print_job(doc, profile, a.device));
}

// What the job would put on the line. A protocol-2 document is measured a
// sheet at a time (a book in constant memory); a protocol-3 job and a saved
// plan are measured whole.
spool::StreamSize dry_run(const EmbossArgs& a, std::optional<plan::PlanFile> saved,
                          const std::optional<machine::FirmwareTables>& tables) {
    const int saved_protocol = saved ? saved->protocol : 0;
    const auto job = saved ? saved_plan_job(a, std::move(*saved), saved_protocol)
                           : (tables ? prepare(a, true, tables) : spool::PrintJob{});
    if (!saved && !tables) {
        const auto profile = load_profile_arg(a.profile);
        const auto options = a.layout.pipeline_options(profile);
        const auto doc = lay_out_for_cli(a.layout, options, &profile, std::nullopt, true);
        warn_about_conflicts(doc, profile);
        return require(spool::measure_print_job(doc, profile, a.start_sheet));
    }
    std::size_t first = 0;
    for (const auto& s : job.plan.sheets) {
        if (s.index >= a.start_sheet) break;
        first += s.passes.size();
    }
    spool::StreamSize m{.sheets = job.plan.sheets.size(), .strikes = job.plan.strikes};
    if (job.firmware) {
        // The v3 stream for the reference firmware (its payload: the ops and the check).
        const auto stream = require(encode::encode_job_v3(job.plan, *job.firmware, job.timing, 1, {first, 0, false}));
        m.stream_bytes = stream.bytes.size();
        for (const auto& [b, e] : encode::chunk_stream_v3(stream, machine::reference_firmware::kMaxOps)) {
            ++m.frames;
            m.line_bytes += e - b + encode::kFrameOverhead + machine::reference_firmware::kDataCheckBytes;
        }
        return m;
    }
    const auto stream = require(encode::encode_job(job.plan, 1, {first, 0, false}));
    m.stream_bytes = stream.bytes.size();
    for (const auto& [b, e] : encode::chunk_stream(stream, encode::kMaxPayload)) {
        ++m.frames;
        m.line_bytes += e - b + encode::kFrameOverhead;
    }
    return m;
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
    if (ipp::is_queue_uri(a.device)) {
#if TACTUS_HAVE_IPP
        return emboss_remote(a.layout, a.device, cmd, a.queue.copies, a.queue.title);
#else
        // The address is refused as such: sending needs libcups.
        (void)cmd;
        const auto refused = ipp::parse_queue_uri(a.device);
        throw CommandFailed(exit_usage, "emboss: " + refused.error().to_string());
#endif
    }
    if (a.queue.enabled) {
        if (a.plan_file)
            throw CommandFailed(exit_usage, "emboss: --queue stores the document, laid out again with the queue "
                                            "printer's profile; a saved plan cannot be queued (leave out --plan)");
        EmbossQueueArgs q = a.queue;
        q.device = a.device;  // --device with --queue: the queue printer on that device
        return enqueue_emboss(a.layout, q);
    }
    auto saved = saved_plan(a);
    if (a.dry_run) {
        // What `emboss` would put on the line: a saved plan's own protocol;
        // for a document, protocol 3 (the simulator's tables, --firmware-tables
        // or the profile's) unless the device is `sim?protocol=2`.
        std::optional<machine::FirmwareTables> tables = sim_tables(a, saved);
        const auto spec = transport::parse_device(a.device);
        const bool legacy_sim = spec && spec->scheme == "sim" && !tables;
        if (!saved && !tables && !legacy_sim)
            tables = protocol_tables("emboss", {0, a.firmware_tables}, load_profile_arg(a.profile));
        const int protocol = saved ? saved->protocol : (tables ? 3 : 2);
        const auto m = dry_run(a, std::move(saved), tables);
        std::cout << m.stream_bytes << " bytes of job stream in " << m.frames << " frames (" << m.line_bytes
                  << " bytes on the line) for " << m.sheets << " sheets, " << m.strikes << " strikes (protocol "
                  << protocol << ")\n";
        return;
    }
    if (a.device.empty()) throw CommandFailed(exit_usage, "emboss: --device is required (try --device sim)");
    // The error's kind tells a malformed device string (usage) from a device
    // that is not there (device).
    link::LinkOptions options;
    options.give_up_after = std::chrono::milliseconds(static_cast<std::int64_t>(a.give_up_after_s * 1000));
    options.sim_firmware = sim_tables(a, saved);
    auto link = require(link::Link::open(a.device, options));
    // HELLO_REPLY says which controller answered: the reference firmware
    // (protocol 3) is planned for with its own tables.
    require(link.hello());
    const auto job = saved ? saved_plan_job(a, std::move(*saved), link.protocol())
                           : prepare(a, link.protocol() == encode::kProtocolV3, options.sim_firmware);

    const bool tty = platform::stderr_is_terminal();
    link::CancelToken cancel;
    g_cancel = &cancel;
    platform::on_termination(on_interrupt);
    bool bar_drawn = false;
    auto out = spool::send_print_job(
        link, job, a.start_sheet,
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
                      << " restarts (protocol " << int{link.protocol()} << ")\n";
            return;
        case link::JobEnd::cancelled:
            throw CommandFailed(exit_failure, "cancelled after " + std::to_string(out->passes_done) +
                                                  " passes; resume with --start-sheet " +
                                                  std::to_string(out->resume_sheet));
        case link::JobEnd::failed:
            throw CommandFailed(exit_failure, out->error.to_string() + "; resume with --start-sheet " +
                                                  std::to_string(out->resume_sheet));
        case link::JobEnd::not_answering:
            // The embosser is gone, not the job at fault: the device exit code.
            throw CommandFailed(exit_code(out->error.kind), out->error.to_string() + "; resume with --start-sheet " +
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
                    "serial:/dev/ttyUSB0?baud=57600, pty:/dev/pts/N, hid:VID:PID, lpt:/dev/parport0, lpt:emu?fw=FILE.ihx (the reference firmware in s51, docs/transports.md), sim, or a "
                    "CUPS queue ipp://host[:port]/printers/NAME (the server lays the document out with its "
                    "embosser's profile; --table, --cells, --lines, --page-numbers, --no-print-pages, "
                    "--eight-dot, --encoding, --copies and --title go with the job; the command follows "
                    "the job until it ends, Ctrl-C cancels it)");
    cmd->add_flag("--dry-run", args->dry_run,
                  "Stop after encoding and print the byte count of what emboss would send: protocol 3 (the "
                  "reference firmware's), a saved plan's own protocol, or protocol 2 for --device "
                  "'sim?protocol=2'");
    cmd->add_flag("--plan", args->plan_file, "FILE is a saved plan (JSON), not a document");
    cmd->add_option("--firmware-tables", args->firmware_tables,
                    "The reference firmware's ramp tables (its build/ramp.json): a controller speaking protocol 3 "
                    "is planned for with them, and refused when it was built with others (default: the tables "
                    "the profile makes, as make -C firmware PROFILE=... builds them)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--start-sheet", args->start_sheet, "Resume from this sheet (1-based)")
        ->check(whole_number_from_one());
    cmd->add_option("--give-up-after", args->give_up_after_s,
                    "Seconds without any acknowledged progress before the job stops with 'the embosser stopped "
                    "answering' (exit 4) and the sheet to resume from (default 30)")
        ->check(CLI::PositiveNumber);
    add_emboss_queue_options(*cmd, args->queue);
    cmd->callback([args, cmd] { run_emboss(*args, *cmd); });
}

}  // namespace tactus::cli
