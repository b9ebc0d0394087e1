// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// End-to-end rig: `tactus-cli sim --pty` (the simulated 89C52 behind a real
// pseudo-terminal, its strike log in a file), a spool database, and
// `tactus-cli serve` / `queue` / `emboss --queue` run as separate processes.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <thread>

#include <nlohmann/json.hpp>

#include "controller/sim_controller.hpp"
#include "process.hpp"
#include "profile/profile.hpp"
#include "spool/printing.hpp"
#include "spool/snapshot.hpp"
#include "spool/spool.hpp"
#include "profile/firmware_tables.hpp"
#include "spool_fixtures.hpp"
#include "strike_audit.hpp"

namespace tactus::spool::test {

inline const std::string kCli = TACTUS_CLI;

class PtySim {
public:
    PtySim(const std::filesystem::path& dir, const std::string& name, std::vector<std::string> extra = {},
           double time_scale = 1000)
        : log_(dir / (name + ".strikes")) {
        // The simulator's default: protocol 3, the firmware the default
        // profile makes; the strike audit replays that firmware's plan.
        std::vector<std::string> args{kCli, "sim", "--pty", "--time-scale", std::to_string(time_scale),
                                      "--baud", "230400",
                                      "--strike-log", log_.string()};
        args.insert(args.end(), extra.begin(), extra.end());
        sim_ = std::make_unique<Process>(args, (dir / (name + ".sim.log")).string());
        path_ = sim_->read_line(std::chrono::milliseconds(10000));
    }
    [[nodiscard]] const std::string& path() const { return path_; }
    [[nodiscard]] std::string device() const { return "pty:" + path_ + "?baud=230400"; }
    // The simulator's next line on stdout (empty on timeout), e.g. what
    // --mute-after-pass says.
    std::string next_line(std::chrono::milliseconds timeout) { return sim_->read_line(timeout); }

    [[nodiscard]] std::vector<controller::LoggedStrike> strikes() const {
        std::vector<controller::LoggedStrike> out;
        std::ifstream in(log_);
        std::string line;
        while (std::getline(in, line)) {
            const auto j = nlohmann::json::parse(line, nullptr, false);
            if (j.is_discarded()) continue;  // a line being written right now
            controller::LoggedStrike s;
            s.sheet = j.at("sheet").get<std::uint16_t>();
            s.side = j.at("side") == "front" ? plan::Side::front : plan::Side::back;
            s.hammer = j.at("hammer") == "convex" ? plan::Hammer::convex : plan::Hammer::concave;
            s.carriage_step = j.at("carriage_step").get<std::int32_t>();
            s.feed_step = j.at("feed_step").get<std::int32_t>();
            out.push_back(s);
        }
        return out;
    }

private:
    std::filesystem::path log_;
    std::unique_ptr<Process> sim_;
    std::string path_;
};

struct E2E {
    TempDir dir;
    std::filesystem::path db = dir / "spool.db";

    std::pair<int, std::string> cli(std::vector<std::string> args) {
        args.insert(args.begin() + 1, {"--db", db.string()});
        args.insert(args.begin(), kCli);
        return run(args);
    }
    std::unique_ptr<Process> serve(std::vector<std::string> extra = {}) {
        std::vector<std::string> args{kCli, "serve", "--db", db.string(), "--poll-ms", "20", "--retry-ms", "200",
                                      "--reconnect-ms", "3000"};
        args.insert(args.end(), extra.begin(), extra.end());
        return std::make_unique<Process>(args, (dir / "serve.log").string());
    }
    Spool spool() { return *Spool::open(db, {.create = false}); }

    // A short text laid out by the real pipeline (liblouis), queued by the CLI.
    JobId queue_text(const std::string& text, std::vector<std::string> extra = {}) {
        const auto file = dir / "doc.txt";
        std::ofstream(file) << text;
        std::vector<std::string> args{"emboss", "--queue", file.string()};
        args.insert(args.end(), extra.begin(), extra.end());
        const auto [code, out] = cli(args);
        EXPECT_EQ(code, 0) << out;
        const auto pos = out.find("queued job ");
        EXPECT_NE(pos, std::string::npos) << out;
        return pos == std::string::npos ? 0 : std::stoll(out.substr(pos + 11));
    }

    bool wait_for(const std::function<bool(const JobRecord&)>& pred, JobId id,
                  std::chrono::seconds timeout = std::chrono::seconds(60)) {
        const auto end = std::chrono::steady_clock::now() + timeout;
        while (std::chrono::steady_clock::now() < end) {
            if (auto s = Spool::open(db, {.create = false}); s)
                if (auto j = s->job(id); j && pred(*j)) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        return false;
    }
    bool wait_state(JobId id, JobState state, std::chrono::seconds timeout = std::chrono::seconds(60)) {
        // A different final state ends the wait at once.
        bool other_end = false;
        const bool ok = wait_for(
            [&](const JobRecord& j) {
                other_end = is_terminal(j.state) && j.state != state;
                return j.state == state || other_end;
            },
            id, timeout);
        return ok && !other_end;
    }

    plan::JobPlan plan_of(JobId id) {
        auto s = spool();
        auto doc = from_snapshot(*s.document_snapshot(id));
        const auto tables = profile::make_firmware_tables(profile::default_profile());
        EXPECT_TRUE(tables);
        auto plan = plan_copies(*doc, profile::default_profile(), s.job(id)->copies, &*tables);
        EXPECT_TRUE(plan);
        return *plan;
    }
    AuditResult audit(JobId id, const PtySim& sim, bool require_all = true) {
        return audit_strikes(plan_of(id), sim.strikes(), *spool().progress(id), require_all);
    }
    std::string history(JobId id) { return cli({"queue", "history", std::to_string(id), "--limit", "1000"}).second; }
};

inline const std::string kText =
    "The spool keeps every page.\n\nA teacher queues a book and walks away; the technician clears a jam.\n";

}  // namespace tactus::spool::test
