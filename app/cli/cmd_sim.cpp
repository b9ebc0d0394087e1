// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli sim --pty: the simulated 89C52 behind a pseudo-terminal. Prints the
// pty path on the first line of stdout and serves until killed.
#include <algorithm>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "command.hpp"
#include "controller/pty_server.hpp"
#include "firmware_emulator.hpp"
#include "platform/termination.hpp"
#include "profile/firmware_tables.hpp"
#include "profile_arg.hpp"
#include "protocol_choice.hpp"
#include "transport/device.hpp"

namespace tactus::cli {
namespace {

std::atomic<bool> g_sim_stop{false};
extern "C" void on_signal(int) { g_sim_stop.store(true); }

// What the options default to, to tell which were given.
struct PtyServerOptionsDefaults : controller::PtyServerOptions {};

struct SimArgs {
    bool pty = false;
    controller::PtyServerOptions server;
    std::string strike_log;
    int paper_out_at = 0;
    int reset_at_strike = 0;
    int paper_reload_reads = 0;  // --firmware: paper loaded at the Nth read of the sensor
    int power_loss_at_strike = 0;
    int limit_at_strike = 0;
    int mute_after_pass = 0;
    std::string firmware;  // an .ihx: the reference firmware in s51 instead of the C++ model
    std::string profile;   // the ramp tables of protocol 3; --firmware: steps/mm for the log's millimetres
    std::string pin_trace; // --firmware: keep the pin trace (VCD) here
    ProtocolArgs protocol;  // the C++ model's protocol and tables
};

void log_strike(std::ofstream& log, const controller::LoggedStrike& s) { write_strike_json(log, s); }

std::ofstream open_log(const std::string& path) {
    std::ofstream log;
    if (path.empty()) return log;
    log.open(path, std::ios::app);
    if (!log) fail_with(Error{"cannot write the strike log", path, ErrorKind::io});
    return log;
}

// The firmware runs as it is: faults the C++ model injects have no switch on
// the emulated chip (only the paper sensor: out from the start, loaded at its
// Nth read).
void run_firmware_sim(const SimArgs& a) {
    if (!a.pty) throw CommandFailed(exit_usage, "sim: --pty is required");
    const PtyServerOptionsDefaults d;
    if (a.power_loss_at_strike > 0 || a.limit_at_strike > 0 ||
        a.mute_after_pass > 0 || a.server.sim.instant_motion || a.server.disconnect_at_s >= 0 ||
        a.server.time_scale != d.time_scale || (a.paper_out_at > 1) ||
        a.server.sim.reload_paper_after_s >= 0 ||
        (a.paper_reload_reads > 0 && a.paper_out_at != 1))
        throw CommandFailed(exit_usage,
                            "sim --firmware: the emulated chip runs in real time; of the fault options it takes "
                            "--noise, --seed, --reset-at-strike N (a warm reset just after the Nth strike), "
                            "--paper-out-at 1 (no paper from the start) and, with it, --paper-reload-reads N "
                            "(paper loaded at the firmware's Nth read of its sensor)");
    const auto profile = load_profile_arg(a.profile);
    FirmwareEmulatorOptions o;
    o.ihx = a.firmware;
    o.paper_out = a.paper_out_at == 1;
    o.carriage_steps_per_mm = profile.carriage.steps_per_mm;
    o.feed_steps_per_mm = profile.feed.steps_per_mm;
    o.noise = a.server.noise;
    o.seed = a.server.seed;
    o.pin_trace = a.pin_trace;
    o.reset_at_strike = static_cast<std::size_t>(std::max(0, a.reset_at_strike));
    o.paper_reload_reads = static_cast<std::size_t>(std::max(0, a.paper_reload_reads));
    auto log = open_log(a.strike_log);
    platform::on_termination(on_signal);
    platform::ignore_broken_pipe();
    run_firmware_emulator(o, g_sim_stop, [&](const controller::LoggedStrike& s) { log_strike(log, s); });
}

// With --mute-after-pass: one line when the controller goes quiet, one when it
// has come to rest by itself (job ended, paused by its keep-alive watchdog, or
// on protocol 3 starved at rest),
// so a test can kill the host exactly in between.
struct MuteWatch {
    bool said_muted = false;
    bool said_rest = false;
    void operator()(const controller::SimController& ctl) {
        if (!ctl.muted()) return;
        const auto st = ctl.status();
        if (!said_muted) {
            said_muted = true;
            std::cout << "muted after pass " << st.ack.executed_passes << std::endl;
        }
        const auto state = st.ack.state;
        // Protocol 3's firmware does not enforce the keep-alive (firmware/README.md,
        // "Not done"): with the host gone it runs out its ring and waits at rest
        // for the next entry, which is where it stays.
        const bool starved = ctl.protocol() == encode::kProtocolV3 && state == encode::ControllerState::waiting;
        if (!said_rest && (state == encode::ControllerState::idle || state == encode::ControllerState::paused ||
                           state == encode::ControllerState::fault || starved)) {
            said_rest = true;
            std::cout << "at rest: " << encode::state_name(state) << ", job " << st.ack.job_id << ", "
                      << st.ack.executed_passes << " passes executed"
                      << ((st.flags & encode::flag::job_ended) ? ", job ended" : "") << std::endl;
        }
    }
};

void run_sim(const SimArgs& a) {
    if (!a.firmware.empty()) return run_firmware_sim(a);
    if (!a.pty) throw CommandFailed(exit_usage, "sim: --pty is required (the in-process simulator is the device \"sim\")");
    if (a.paper_reload_reads > 0)
        throw CommandFailed(exit_usage, "sim: --paper-reload-reads is for --firmware; the C++ controller takes "
                                        "--paper-reload SECONDS");
    auto options = a.server;
    // Protocol 3 by default, as the reference firmware built from the profile
    // speaks it (the same tables: profile::make_firmware_tables).
    options.sim.firmware = protocol_tables("sim", a.protocol, load_profile_arg(a.profile));
    auto server = controller::PtyServer::open(options);
    if (!server) fail_with(server.error());
    auto& ctl = server->controller();
    if (a.paper_out_at > 0) ctl.inject_paper_out_at_sheet(static_cast<std::uint16_t>(a.paper_out_at));
    if (a.reset_at_strike > 0) ctl.reset_at_strike(static_cast<std::size_t>(a.reset_at_strike), true);
    if (a.power_loss_at_strike > 0)
        ctl.reset_at_strike(static_cast<std::size_t>(a.power_loss_at_strike), false);
    if (a.limit_at_strike > 0) ctl.inject_limit_switch_at_strike(static_cast<std::size_t>(a.limit_at_strike));
    if (a.mute_after_pass > 0) ctl.mute_after_pass(static_cast<std::uint16_t>(a.mute_after_pass));
    MuteWatch watch;
    auto log = open_log(a.strike_log);
    platform::on_termination(on_signal);
    platform::ignore_broken_pipe();
    std::cout << server->path() << std::endl;
    auto r = server->serve(g_sim_stop, [&](const controller::LoggedStrike& s) { log_strike(log, s); },
                           [&](const controller::SimController& c) {
        if (a.mute_after_pass > 0) watch(c);
    });
    if (!r) fail_with(r.error());
    // What the host configured, so a test (or a technician) can check the
    // controller got the profile the job was planned with.
    if (ctl.configured()) {
        const auto& c = ctl.config();
        std::cerr << "sim: configured " << nlohmann::json{{"carriage_steps_per_m", c.carriage_steps_per_m},
                                                          {"feed_steps_per_m", c.feed_steps_per_m},
                                                          {"carriage_travel_steps", c.carriage_travel_steps},
                                                          {"home_interval_ticks", c.home_interval_ticks},
                                                          {"hammer_ticks", c.hammer_ticks},
                                                          {"keepalive_ms", c.keepalive_ms}}
                                                .dump()
                  << '\n';
    } else {
        std::cerr << "sim: never configured\n";
    }
    std::cerr << "sim: " << ctl.strike_log().size() << " strikes, " << ctl.frames_accepted()
              << " frames accepted, " << ctl.duplicates() << " duplicates ignored, "
              << ctl.crc_errors() << " corrupt frames dropped\n";
}

}  // namespace

void add_sim_command(CLI::App& app) {
    auto args = std::make_shared<SimArgs>();
    auto* cmd = app.add_subcommand("sim", "Run the simulated embosser controller behind a pseudo-terminal");
    cmd->add_flag("--pty", args->pty, "Serve on a new pseudo-terminal; its path is printed first");
    cmd->add_option("--baud", args->server.baud, "Line rate the simulated UART paces bytes at")
        ->capture_default_str()->check(CLI::Range(300.0, 1e6));
    cmd->add_option("--time-scale", args->server.time_scale,
                    "Run motion this many times faster than real time")
        ->capture_default_str()->check(CLI::Range(0.01, 1e6));
    cmd->add_option("--noise", args->server.noise,
                    "Per-byte rate of dropped, flipped and duplicated bytes (each)")
        ->check(CLI::Range(0.0, transport::kMaxSimNoise));
    cmd->add_option("--seed", args->server.seed, "Noise seed");
    cmd->add_option("--disconnect-at", args->server.disconnect_at_s,
                    "Kill the line this many seconds after the host's first byte ...");
    cmd->add_option("--disconnect-for", args->server.disconnect_for_s, "... for this many seconds");
    cmd->add_option("--paper-out-at", args->paper_out_at, "Sheet N finds no paper")->check(whole_number_from_one(kMaxInt));
    cmd->add_option("--paper-reload", args->server.sim.reload_paper_after_s,
                    "Seconds (simulated) until the operator loads paper after a paper-out");
    cmd->add_option("--paper-reload-reads", args->paper_reload_reads,
                    "With --firmware and --paper-out-at 1: the operator loads paper at the firmware's Nth read of "
                    "its paper sensor (an s51 breakpoint; it reads it once per main-loop pass while paper is out)")
        ->check(whole_number_from_one(kMaxInt));
    cmd->add_option("--reset-at-strike", args->reset_at_strike,
                    "Watchdog reset right after strike N (with --firmware: an s51 breakpoint resets the emulated "
                    "chip, RAM kept)")->check(whole_number_from_one(kMaxInt));
    cmd->add_option("--power-loss-at-strike", args->power_loss_at_strike,
                    "Power loss right after strike N")->check(whole_number_from_one(kMaxInt));
    cmd->add_option("--limit-at-strike", args->limit_at_strike,
                    "Limit switch trips before strike N")->check(whole_number_from_one(kMaxInt));
    cmd->add_option("--mute-after-pass", args->mute_after_pass,
                    "Stop replying once N passes of the job are executed, until the host opens a new session "
                    "(the ACK is lost with the host); says \"muted\" and then \"at rest\" on stdout")
        ->check(CLI::Range(1, 65535));
    cmd->add_flag("--instant", args->server.sim.instant_motion,
                  "Execute motion in no time (link benchmarks)");
    cmd->add_option("--strike-log", args->strike_log, "Append each strike to FILE as a JSON line");
    cmd->add_option("--firmware", args->firmware,
                    "Run the reference firmware (make -C firmware emu: firmware/build-emu/tactus-fw.ihx) in the s51 "
                    "emulator instead of the C++ model; strikes are read from its pins")
        ->check(CLI::ExistingFile);
    add_protocol_options(*cmd, args->protocol, "; HELLO_REPLY reports their id");
    cmd->add_option("--profile,-p", args->profile,
                    "The printer profile whose ramp tables protocol 3 runs (default: the bundled one); with "
                    "--firmware: whose steps/mm the log's mm use");
    cmd->add_option("--pin-trace", args->pin_trace,
                    "With --firmware: keep the emulator's trace of port 1 (steps, directions, hammers) in FILE "
                    "(VCD, the emulator's clock)");
    cmd->callback([args] { run_sim(*args); });
}

}  // namespace tactus::cli
