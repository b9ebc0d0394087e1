// SPDX-License-Identifier: GPL-3.0-or-later
// One PrintJob: the plan and the controller configuration
// come from the same profile on every road -- a document, a saved plan, the
// runner -- and `plan --json` is the file `emboss --plan` reads. A plan from
// another profile or protocol version is refused with the reason (exit 3),
// and the simulator's CONFIGURE is checked, not assumed.
#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "common/file_io.hpp"
#include "controller/sim_controller.hpp"
#include "encode/frame.hpp"
#include "encode/messages.hpp"
#include "encode/stream.hpp"
#include "plan/plan_file.hpp"
#include "plan/planner.hpp"
#include "profile/controller_config.hpp"
#include "profile/profile.hpp"
#include "profile/profile_json.hpp"
#include "spool/print_job.hpp"
#include "spool/printing.hpp"
#include "spool/runner.hpp"
#include "spool/snapshot.hpp"
#include "process.hpp"
#include "sim_rig.hpp"
#include "spool_fixtures.hpp"

namespace tactus::spool {
namespace {

namespace fs = std::filesystem;
using tactus::test::cli;
using tactus::test::Process;
using tactus::test::run_captured;
using test::TempDir;

// A printer that is not the bundled one in what the controller is told: a
// finer carriage lead screw and a longer hammer pulse.
profile::PrinterProfile other_profile() {
    auto p = profile::default_profile();
    p.name = "Lab embosser, fine lead screw";
    p.carriage.steps_per_mm = 100;
    p.head.dwell_s = 0.003;
    return p;
}

nlohmann::json config_json(const machine::ControllerConfig& c) {
    return {{"carriage_steps_per_m", c.carriage_steps_per_m}, {"feed_steps_per_m", c.feed_steps_per_m},
            {"carriage_travel_steps", c.carriage_travel_steps}, {"home_interval_ticks", c.home_interval_ticks},
            {"hammer_ticks", c.hammer_ticks},                   {"keepalive_ms", c.keepalive_ms}};
}

TEST(PrintJob, PlanAndConfigurationComeFromTheSameProfile) {
    const auto doc = test::make_document(3, true);
    const auto prof = other_profile();
    ASSERT_NE(profile::controller_config(prof), profile::controller_config(profile::default_profile()));
    auto job = make_print_job(doc, prof, "sim", 2);
    ASSERT_TRUE(job) << job.error().to_string();
    EXPECT_EQ(job->config, profile::controller_config(prof));
    EXPECT_EQ(job->protocol, encode::kProtocolVersion);
    EXPECT_EQ(job->device, "sim");
    EXPECT_EQ(profile::to_json(job->profile), profile::to_json(prof));
    const auto expected = plan_copies(doc, prof, 2);
    ASSERT_TRUE(expected);
    ASSERT_EQ(job->plan.sheets.size(), expected->sheets.size());
    for (std::size_t s = 0; s < expected->sheets.size(); ++s)
        EXPECT_EQ(job->plan.sheets[s].passes, expected->sheets[s].passes);
}

TEST(PrintJob, ASavedPlanConfiguresWithItsOwnProfileAndRefusesAnother) {
    const auto doc = test::make_document(2, true);
    const auto prof = other_profile();
    auto made = make_print_job(doc, prof, "sim");
    ASSERT_TRUE(made);
    auto loaded = plan::plan_from_json(plan::plan_to_json(to_plan_file(*made)));
    ASSERT_TRUE(loaded) << loaded.error().to_string();

    auto own = make_print_job(*loaded, "sim");
    ASSERT_TRUE(own) << own.error().to_string();
    EXPECT_EQ(own->config, profile::controller_config(prof));
    EXPECT_EQ(own->plan.strikes, made->plan.strikes);

    auto same = prof;
    same.name = "the same machine, renamed";  // a label, not a difference
    EXPECT_TRUE(make_print_job(*loaded, "sim", &same));

    const auto bundled = profile::default_profile();
    auto other = make_print_job(*loaded, "sim", &bundled);
    ASSERT_FALSE(other);
    EXPECT_EQ(other.error().kind, ErrorKind::input);
    EXPECT_EQ(other.error().where, "plan.profile");
    EXPECT_NE(other.error().message.find("/carriage/steps_per_mm"), std::string::npos) << other.error().message;

    auto old_protocol = *loaded;
    old_protocol.protocol = encode::kProtocolVersion - 1;
    auto refused = make_print_job(old_protocol, "sim");
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().kind, ErrorKind::input);
    EXPECT_EQ(refused.error().where, "plan.protocol");
    EXPECT_NE(refused.error().message.find("protocol version " + std::to_string(encode::kProtocolVersion - 1)),
              std::string::npos)
        << refused.error().message;
}

// A job the controller cannot count (over 65,535 passes) is refused as soon as
// that is known, not after the whole book is planned (planning first, a
// dry run of 100,000 pages took gigabytes before failing).
TEST(PrintJob, AJobTooLongForTheControllerIsRefusedBeforeItIsAllPlanned) {
    const auto doc = test::make_document(40, true);
    ASSERT_EQ(doc.sheet_count(), 20U);
    // 10,000 copies: the first sheet alone is over the limit per copy.
    auto job = make_print_job(doc, profile::default_profile(), "sim", 10000);
    ASSERT_FALSE(job);
    EXPECT_EQ(job.error().where, kPassesWhere);
    EXPECT_NE(job.error().message.find("65,535"), std::string::npos) << job.error().message;
    EXPECT_NE(job.error().message.find("in the first 1 of 20 sheets"), std::string::npos) << job.error().message;
}

// `emboss --dry-run` measures the job a sheet at a time; its figures are the
// whole job's, encoded and cut into frames at once, from every start sheet.
TEST(PrintJob, MeasuringASheetAtATimeGivesTheWholeJobsFigures) {
    for (const std::size_t pages : {1U, 2U, 7U, 12U}) {
        const auto doc = test::make_document(pages, true);
        const auto prof = profile::default_profile();
        auto whole = plan::plan_job(doc, prof);
        ASSERT_TRUE(whole) << whole.error().to_string();
        for (std::size_t start = 1; start <= doc.sheet_count() + 1; ++start) {
            SCOPED_TRACE(std::to_string(pages) + " pages from sheet " + std::to_string(start));
            std::size_t first = 0;
            for (const auto& sh : whole->sheets)
                if (sh.index < start) first += sh.passes.size();
            const auto stream = encode::encode_job(*whole, 1, {first, 0, false});
            ASSERT_TRUE(stream);
            const auto chunks = encode::chunk_stream(*stream, encode::kMaxPayload);
            std::size_t line = 0;
            for (const auto& [b, e] : chunks) line += e - b + encode::kFrameOverhead;
            const auto m = measure_print_job(doc, prof, start);
            ASSERT_TRUE(m) << m.error().to_string();
            EXPECT_EQ(m->stream_bytes, stream->bytes.size());
            EXPECT_EQ(m->frames, chunks.size());
            EXPECT_EQ(m->line_bytes, line);
            EXPECT_EQ(m->sheets, whole->sheets.size());
            EXPECT_EQ(m->strikes, whole->strikes);
        }
    }
}

// The runner keeps its link open between jobs. When the printer's profile is
// changed in between, the next job is planned with the new profile, and the
// controller must be configured with it too (it used to keep the CONFIGURE of
// the profile it connected with).
TEST(PrintJobRunner, AProfileChangedBetweenJobsReconfiguresTheController) {
    TempDir dir;
    const auto db = dir / "spool.db";
    auto spool = Spool::open(db);
    ASSERT_TRUE(spool);
    ASSERT_TRUE(spool->add_printer("lab", "sim", profile::to_json(profile::default_profile()).dump()));
    test::SimPrinter printer;
    RunnerOptions o;
    o.poll = std::chrono::milliseconds(5);
    Runner r(db, "lab", printer.connect(), o);
    ASSERT_TRUE(r.start());
    std::atomic<bool> stop{false};

    ASSERT_TRUE(spool->submit(test::submission("lab", 2)));
    auto end = r.run_next(stop);
    ASSERT_TRUE(end && *end == RunEnd::completed);
    EXPECT_EQ(printer.controller->config(), profile::controller_config(profile::default_profile()));

    const auto prof = other_profile();
    ASSERT_TRUE(spool->update_printer("lab", std::nullopt, profile::to_json(prof).dump()));
    const auto second = spool->submit(test::submission("lab", 2));
    ASSERT_TRUE(second);
    end = r.run_next(stop);
    ASSERT_TRUE(end && *end == RunEnd::completed) << (end ? to_string(**end) : end.error().to_string());
    EXPECT_EQ(printer.controller->config(), profile::controller_config(prof));
    EXPECT_EQ(printer.connects, 1);  // the same link: only a new CONFIGURE could have changed it
    r.finish();
}

// --- the command line, end to end

struct Files {
    TempDir dir;
    fs::path doc = dir / "letter.txt";
    fs::path profile = dir / "lab.json";
    fs::path plan = dir / "plan.json";
    Files() {
        EXPECT_TRUE(write_file_atomic(doc, "Dear reader,\nthis letter is embossed from a saved plan.\n"));
        EXPECT_TRUE(profile::save_profile(other_profile(), profile));
    }
    // `tactus-cli plan --json` into plan.json.
    void make_plan() {
        const auto r = run_captured(cli({"plan", "--json", "--profile", profile.string(), doc.string()}));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        ASSERT_TRUE(write_file_atomic(plan, r.out));
    }
};

TEST(PrintJobCli, PlanJsonIsEmbossedWithThePlansProfileAndStrikesThePlan) {
    Files f;
    f.make_plan();
    // This profile's plan is protocol 2's (the reference firmware cannot run
    // it; `plan` says so on stderr): the simulator speaks 2 on request.
    Process server(cli({"sim", "--pty", "--protocol", "2", "--time-scale", "40", "--strike-log",
                        (f.dir / "strikes.jsonl").string()}),
                   Process::Options{{}, true, {}});
    const std::string pty = server.read_line(std::chrono::seconds(30));
    ASSERT_EQ(pty.rfind("/dev/pts/", 0), 0U) << pty;
    const auto r = run_captured(cli({"emboss", "--plan", f.plan.string(), "--device", "pty:" + pty}));
    server.signal(SIGTERM);
    const std::string sim_said = server.read_all();
    server.wait();
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;

    // The controller was configured with the profile the plan was made with.
    const auto at = sim_said.find("sim: configured ");
    ASSERT_NE(at, std::string::npos) << sim_said;
    const auto line = sim_said.substr(at + 16, sim_said.find('\n', at) - at - 16);
    EXPECT_EQ(nlohmann::json::parse(line), config_json(profile::controller_config(other_profile()))) << line;

    // It struck what the plan says, once.
    const auto file = plan::load_plan(f.plan);
    ASSERT_TRUE(file) << file.error().to_string();
    const auto planned = controller::planned_strikes(file->plan);
    std::vector<controller::LoggedStrike> struck;
    std::ifstream in(f.dir / "strikes.jsonl");
    for (std::string l; std::getline(in, l);) {
        const auto j = nlohmann::json::parse(l);
        controller::LoggedStrike s;
        s.sheet = j["sheet"].get<std::uint16_t>();
        s.side = j["side"] == "front" ? plan::Side::front : plan::Side::back;
        s.hammer = j["hammer"] == "convex" ? plan::Hammer::convex : plan::Hammer::concave;
        s.carriage_step = j["carriage_step"].get<std::int32_t>();
        s.feed_step = j["feed_step"].get<std::int32_t>();
        struck.push_back(s);
    }
    ASSERT_FALSE(planned.empty());
    EXPECT_TRUE(struck == planned) << struck.size() << " struck, " << planned.size() << " planned";
}

TEST(PrintJobCli, APlanFromAnotherProfileOrProtocolIsRefusedWithExitThree) {
    Files f;
    f.make_plan();
    // With the profile it was made with: accepted (dry run: no device needed).
    auto r = run_captured(cli({"emboss", "--plan", f.plan.string(), "--profile", f.profile.string(), "--dry-run"}));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    // With the bundled profile: refused, naming the difference.
    const auto bundled = f.dir / "bundled.json";
    ASSERT_TRUE(profile::save_profile(profile::default_profile(), bundled));
    r = run_captured(cli({"emboss", "--plan", f.plan.string(), "--profile", bundled.string(), "--device", "sim"}));
    EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
    EXPECT_NE(r.err.find("plan.profile"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("/carriage/steps_per_mm"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("embossed"), std::string::npos) << r.out;

    // Made for a protocol version this Tactus does not speak: refused, naming
    // it; a protocol-3 plan without the ramp tables its moves are made of: the same.
    auto j = nlohmann::json::parse(*read_file(f.plan));
    j["protocol"] = 4;
    const auto other = f.dir / "other-protocol.json";
    ASSERT_TRUE(write_file_atomic(other, j.dump()));
    r = run_captured(cli({"emboss", "--plan", other.string(), "--device", "sim"}));
    EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
    EXPECT_NE(r.err.find("link protocol 4 is not one this Tactus speaks"), std::string::npos) << r.err;
    j["protocol"] = encode::kProtocolV3;
    j.erase("firmware_tables");
    ASSERT_TRUE(write_file_atomic(other, j.dump()));
    r = run_captured(cli({"emboss", "--plan", other.string(), "--device", "sim"}));
    EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
    EXPECT_NE(r.err.find("plan.firmware_tables"), std::string::npos) << r.err;

    // A job the printer could not be sent is refused when it is queued, not
    // when it runs (the queue makes the same PrintJob first).
    r = run_captured(cli({"emboss", "--queue", "--copies", "10000", "--db", (f.dir / "q.db").string(), "--device",
                          "sim", f.doc.string()}));
    EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
    EXPECT_NE(r.err.find("65,535"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("queued job"), std::string::npos) << r.out;
    fs::remove(f.dir / "q.db");

    // A saved plan cannot be queued: the queue lays the document out again.
    r = run_captured(cli({"emboss", "--plan", f.plan.string(), "--queue", "--db", (f.dir / "q.db").string(),
                          "--device", "sim"}));
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_FALSE(fs::exists(f.dir / "q.db"));
}

}  // namespace
}  // namespace tactus::spool
