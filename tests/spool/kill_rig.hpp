// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The kill -9 loop shared by the kill test (tests/spool) and the soak benchmark
// (bench/spool): `tactus-cli serve` embosses over a pseudo-terminal to
// `tactus-cli sim --pty`, is SIGKILLed at a random moment, restarted, killed
// again, ... until the job completes; then the simulator's strike log is
// audited against the plan (strike_audit.hpp). No GoogleTest here, so the
// benchmark can run it too: problems come back as text.
#include <signal.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "controller/sim_controller.hpp"
#include "process.hpp"
#include "profile/profile.hpp"
#include "spool/printing.hpp"
#include "spool/snapshot.hpp"
#include "spool/spool.hpp"
#include "spool_fixtures.hpp"
#include "profile/firmware_tables.hpp"
#include "strike_audit.hpp"

namespace tactus::spool::test {

// TACTUS_KILL_SEED repeats a run; otherwise a fresh seed (always printed).
inline std::uint32_t kill_seed(std::uint32_t salt = 0) {
    if (const char* s = std::getenv("TACTUS_KILL_SEED"); s && *s)
        return static_cast<std::uint32_t>(std::strtoul(s, nullptr, 10)) + salt;
    return std::random_device{}();
}

// The simulator's strike log (one JSON object per line).
inline std::vector<controller::LoggedStrike> read_strike_log(const std::filesystem::path& file) {
    std::vector<controller::LoggedStrike> out;
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        const auto j = nlohmann::json::parse(line, nullptr, false);
        if (j.is_discarded() || !j.is_object()) continue;  // a line being written right now
        controller::LoggedStrike s;
        s.sheet = j.value("sheet", std::uint16_t{0});
        s.side = j.value("side", std::string()) == "front" ? plan::Side::front : plan::Side::back;
        s.hammer = j.value("hammer", std::string()) == "convex" ? plan::Hammer::convex : plan::Hammer::concave;
        s.carriage_step = j.value("carriage_step", std::int32_t{0});
        s.feed_step = j.value("feed_step", std::int32_t{0});
        out.push_back(s);
    }
    return out;
}

struct KillOptions {
    std::string cli;                 // tactus-cli
    std::filesystem::path dir;       // scratch folder (database, logs)
    int kills = 50;                  // SIGKILLs to deliver
    std::chrono::seconds budget{240};
    std::uint32_t seed = 1;
    int max_delay_ms = 700;          // a kill lands 0..max after serve starts
    int kills_per_job = 0;           // then the job runs to its end (0: no limit)
    std::string copies = "4";
    std::string time_scale = "1000";  // the simulator's speed-up of the machine's time
    std::string text;                // the document queued each round
    // Percent of the kills that take the controller down with `serve` (a
    // power cut of the whole bench): the simulator is SIGKILLed too and a new
    // one, which knows nothing of the sheet in its paper path, takes its place
    // on a new pseudo-terminal, appending to the same strike log.
    int controller_kill_percent = 0;
    std::function<void(const std::string&)> progress;  // one line per finished round
};

struct KillReport {
    int kills = 0;
    int rounds = 0;
    std::size_t sheets = 0;           // sheets audited
    std::size_t partial_sheets = 0;   // partial attempts (each reported as discarded)
    int controller_kills = 0;         // kills that took the simulator down too
    std::size_t lost = 0;             // sheets never completed
    std::size_t doubled = 0;          // sheets embossed more than once
    std::string problems;             // empty: exactly once everywhere
    double seconds = 0;
};

// Runs jobs under random SIGKILLs until `kills` have been delivered or the
// budget is spent. A fresh simulator per job, so each strike log holds one job.
inline KillReport kill_loop(const KillOptions& o) {
    using Clock = std::chrono::steady_clock;
    KillReport r;
    const auto start = Clock::now();
    std::mt19937 rng(o.seed);
    const auto db = o.dir / "spool.db";
    auto cli = [&](std::vector<std::string> args) {
        args.insert(args.begin() + 1, {"--db", db.string()});
        args.insert(args.begin(), o.cli);
        return run(args);
    };
    auto problem = [&](const std::string& p) { r.problems += "round " + std::to_string(r.rounds) + ": " + p + "\n"; };
    const auto doc = o.dir / "doc.txt";
    std::ofstream(doc) << o.text;
    bool printer_added = false;
    while (r.kills < o.kills && Clock::now() - start < o.budget && r.problems.empty()) {
        ++r.rounds;
        const auto log = o.dir / ("round" + std::to_string(r.rounds) + ".strikes");
        // Protocol 3 (the simulator's default): the firmware the default profile makes.
        std::optional<Process> sim;
        auto start_sim = [&]() -> bool {
            sim.reset();
            sim.emplace(std::vector<std::string>{o.cli, "sim", "--pty", "--time-scale", o.time_scale, "--baud", "230400",
                                                 "--strike-log", log.string()},
                        (o.dir / "sim.log").string());
            const auto pty = sim->read_line(std::chrono::seconds(10));
            if (pty.empty()) {
                problem("the simulator did not start");
                return false;
            }
            const auto device = "pty:" + pty + "?baud=230400";
            if (const auto [code, out] =
                    cli({"queue", "printer", printer_added ? "set" : "add", "lab", "--device", device});
                code != 0) {
                problem("printer: " + out);
                return false;
            }
            printer_added = true;
            return true;
        };
        if (!start_sim()) break;
        const auto [code, out] = cli({"emboss", "--queue", doc.string(), "--copies", o.copies});
        const auto pos = out.find("queued job ");
        if (code != 0 || pos == std::string::npos) {
            problem("emboss --queue: " + out);
            break;
        }
        const JobId id = std::stoll(out.substr(pos + 11));
        auto state = [&]() -> std::optional<JobState> {
            auto s = Spool::open(db, {.create = false});
            if (!s) return std::nullopt;
            auto j = s->job(id);
            return j ? std::optional<JobState>(j->state) : std::nullopt;
        };
        bool completed = false;
        bool controller_killed = false;
        int job_kills = 0;
        for (;;) {
            Process serve({o.cli, "serve", "--db", db.string(), "--poll-ms", "20", "--retry-ms", "200", "--reconnect-ms",
                           "3000"},
                          (o.dir / "serve.log").string());
            // Anywhere from "still starting" to "several sheets in".
            std::this_thread::sleep_for(
                std::chrono::milliseconds(std::uniform_int_distribution<int>(0, o.max_delay_ms)(rng)));
            if (state() == JobState::completed || r.kills >= o.kills || Clock::now() - start >= o.budget ||
                (o.kills_per_job > 0 && job_kills >= o.kills_per_job)) {
                const auto until = Clock::now() + std::chrono::seconds(120);
                while (Clock::now() < until) {
                    const auto st = state();
                    if (st && (*st == JobState::completed || is_terminal(*st) || *st == JobState::paused)) break;
                    std::this_thread::sleep_for(std::chrono::milliseconds(20));
                }
                completed = state() == JobState::completed;
                serve.signal(SIGTERM);
                if (serve.wait() != 0) problem("serve did not stop cleanly on SIGTERM");
                break;
            }
            const bool with_controller =
                std::uniform_int_distribution<int>(0, 99)(rng) < o.controller_kill_percent;
            serve.signal(SIGKILL);
            if (with_controller) sim->signal(SIGKILL);
            serve.wait();
            ++r.kills;
            ++job_kills;
            if (with_controller) {
                sim->wait();
                ++r.controller_kills;
                controller_killed = true;
                if (!start_sim()) break;
            }
        }
        if (!r.problems.empty()) break;
        auto s = Spool::open(db, {.create = false});
        if (!s) {
            problem("spool: " + s.error().to_string());
            break;
        }
        if (!completed) {
            problem("job " + std::to_string(id) + " did not complete (" + std::string(to_string(s->job(id)->state)) +
                    ": " + s->job(id)->reason + ")");
            break;
        }
        auto snapshot = s->document_snapshot(id);
        auto paged = snapshot ? from_snapshot(*snapshot) : std::unexpected(snapshot.error());
        const auto tables = profile::make_firmware_tables(profile::default_profile());
        auto plan = !paged    ? Result<plan::JobPlan>(std::unexpected(paged.error()))
                    : !tables ? Result<plan::JobPlan>(std::unexpected(tables.error()))
                              : plan_copies(*paged, profile::default_profile(), s->job(id)->copies, &*tables);
        if (!plan) {
            problem("plan: " + plan.error().to_string());
            break;
        }
        sim->signal(SIGTERM);
        sim->wait();
        const auto audit = audit_strikes(*plan, read_strike_log(log), *s->progress(id), true, controller_killed);
        r.sheets += audit.sheets_checked;
        r.partial_sheets += audit.partial_attempts;
        std::istringstream lines(audit.problems);
        for (std::string l; std::getline(lines, l);) {
            if (l.find("never completed") != std::string::npos) ++r.lost;
            if (l.find("embossed") != std::string::npos || l.find("struck again") != std::string::npos) ++r.doubled;
        }
        if (!audit.problems.empty()) problem("job " + std::to_string(id) + ":\n" + audit.problems);
        if (o.progress)
            o.progress("round " + std::to_string(r.rounds) + ": " + std::to_string(r.kills) + " kills so far, " +
                       std::to_string(audit.sheets_checked) + " sheets audited, " +
                       std::to_string(audit.partial_attempts) + " partial (reported)");
    }
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return r;
}

}  // namespace tactus::spool::test
