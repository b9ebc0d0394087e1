// SPDX-License-Identifier: GPL-3.0-or-later
// End to end over a real pseudo-terminal: `tactus-cli sim --pty` in one process,
// `tactus-cli emboss --device pty:...` in another, and the simulator's strike
// log compared with the plan dot for dot, with line faults injected.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "controller/sim_controller.hpp"
#include "encode/messages.hpp"
#include "profile/profile.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/plan_file.hpp"
#include "plan/planner.hpp"
#include "profile/firmware_tables.hpp"
#include "../common/process.hpp"
#include "../common/pty_emboss.hpp"
#include "../common/strike_log.hpp"
#include "../common/test_plans.hpp"
#include "../common/firmware_tables_fixture.hpp"
#include "link/link.hpp"
#include "profile/profile_json.hpp"

namespace tactus {
namespace {

namespace fs = std::filesystem;

using test::Process;

// tactus-cli's stdout and stderr together, as a user at a terminal sees them.
Process cli_merged(const std::vector<std::string>& args) {
    return Process(args, Process::Options{{}, true, {}});
}

struct Result {
    int exit_code = -1;
    std::string output;
    std::vector<controller::LoggedStrike> log;
};

class PtyEndToEnd : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("tactus-e2e-" + std::to_string(getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
        plan_ = test::make_plan(2, 6, 14, 11);
        std::ofstream(dir_ / "plan.json")
            << plan::plan_to_json({plan_, profile::default_profile(), encode::kProtocolVersion}).dump();
    }
    void TearDown() override { fs::remove_all(dir_); }

    Result run(std::vector<std::string> sim_faults, const std::string& baud = "115200") {
        test::PtyEmboss e;
        // A saved plan is protocol 2's: the simulator speaks it on request
        // (its default is protocol 3, as the firmware built from the profile).
        e.sim = {TACTUS_CLI, "sim", "--pty", "--protocol", "2", "--baud", baud, "--time-scale", "40"};
        e.sim.insert(e.sim.end(), sim_faults.begin(), sim_faults.end());
        e.emboss = {TACTUS_CLI, "emboss", "--plan", (dir_ / "plan.json").string()};
        e.baud = baud;
        e.strike_log = dir_ / "strikes.jsonl";
        e.merge_output = false;
        const auto p = test::emboss_through_pty(e);
        return Result{p.exit_code, p.output, p.log};
    }

    fs::path dir_;
    plan::JobPlan plan_;
};

TEST_F(PtyEndToEnd, CleanLine) {
    const auto r = run({});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.log, controller::planned_strikes(plan_));
    EXPECT_NE(r.output.find("pass 12/12 executed"), std::string::npos) << r.output;
}

TEST_F(PtyEndToEnd, NoisyLine) {
    const auto r = run({"--noise", "0.001", "--seed", "3"}, "57600");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.log, controller::planned_strikes(plan_));
}

TEST_F(PtyEndToEnd, DisconnectMidJob) {
    const auto r = run({"--disconnect-at", "0.25", "--disconnect-for", "3.5"});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.log, controller::planned_strikes(plan_));
}

TEST_F(PtyEndToEnd, ControllerResetMidSheet) {
    const auto r = run({"--reset-at-strike", "23"});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.log, controller::planned_strikes(plan_));
    EXPECT_NE(r.output.find("restarted"), std::string::npos) << r.output;
}

TEST_F(PtyEndToEnd, PowerLossFailsWithResumeHint) {
    const auto r = run({"--power-loss-at-strike", "60"});
    EXPECT_EQ(r.exit_code, 1);
    ASSERT_GE(r.log.size(), 60U);
    const auto planned = controller::planned_strikes(plan_);
    EXPECT_TRUE(std::equal(r.log.begin(), r.log.begin() + 60, planned.begin()));
}

// The line goes dead mid-job and stays dead. The CLI gives
// up after --give-up-after seconds without acknowledged progress, exits with
// the device code (4) and says which sheet to resume from. (The old CLI had
// no such option and, without it, never gave up.)
TEST_F(PtyEndToEnd, AnEmbosserThatStopsAnsweringEndsWithTheDeviceCodeAndTheSheetToResume) {
    Process server({TACTUS_CLI, "sim", "--pty", "--protocol", "2", "--baud", "115200", "--time-scale", "40",
                    "--disconnect-at", "0.25",
                    "--disconnect-for", "100000", "--strike-log", (dir_ / "strikes.jsonl").string()});
    const std::string pty = server.read_line(std::chrono::seconds(30));
    ASSERT_EQ(pty.rfind("/dev/pts/", 0), 0U) << pty;
    Process client = cli_merged({TACTUS_CLI, "emboss", "--plan", (dir_ / "plan.json").string(), "--device",
                                 "pty:" + pty + "?baud=115200", "--give-up-after", "4"});
    const auto out = client.read_all();
    EXPECT_EQ(client.wait(), 4) << out;  // exit_device
    EXPECT_NE(out.find("the embosser stopped answering: nothing acknowledged for 4 s"), std::string::npos) << out;
    const auto hint = out.find("resume with --start-sheet ");
    ASSERT_NE(hint, std::string::npos) << out;
    const int sheet = std::stoi(out.substr(hint + std::string("resume with --start-sheet ").size()));
    EXPECT_GE(sheet, 1);
    EXPECT_LE(sheet, 2);
    server.signal(SIGTERM);
    server.wait();
    // What was struck is the plan's beginning, up to the sheet to resume from.
    const auto log = test::read_strike_log((dir_ / "strikes.jsonl").string());
    const auto planned = controller::planned_strikes(plan_);
    ASSERT_LE(log.size(), planned.size());
    EXPECT_TRUE(std::equal(log.begin(), log.end(), planned.begin()));
    for (const auto& s : log) EXPECT_LE(s.sheet, sheet);
}

TEST_F(PtyEndToEnd, AbsentDeviceGivesTheDocumentedError) {
    for (const std::string dev : {"pty:/dev/pts/999999", "serial:/dev/ttyTACTUS-NONE", "lpt:/dev/parport9",
                                  "hid:10c4:ea80:NOPE"}) {
        Process p = cli_merged({TACTUS_CLI, "emboss", "--plan", (dir_ / "plan.json").string(), "--device", dev});
        const auto out = p.read_all();
        EXPECT_EQ(p.wait(), 4) << dev << ": " << out;  // exit_device
        EXPECT_NE(out.find("no such device"), std::string::npos) << dev << ": " << out;
    }
}

// The error's kind picks the exit code: a device string that cannot be used is
// a usage error (2), whether the transport or the simulator finds the fault.
TEST_F(PtyEndToEnd, MalformedDeviceIsAUsageError) {
    for (const std::string dev : {"usb:/dev/x", "serial:", "serial:/dev/x?baud=12", "sim?noise=-1",
                                  "sim?colour=red", "lpt:/dev/parport0?baud=9600"}) {
        Process p = cli_merged({TACTUS_CLI, "emboss", "--plan", (dir_ / "plan.json").string(), "--device", dev});
        const auto out = p.read_all();
        EXPECT_EQ(p.wait(), 2) << dev << ": " << out;  // exit_usage
    }
}

TEST_F(PtyEndToEnd, DryRunPrintsTheByteCount) {
    Process p({TACTUS_CLI, "emboss", "--dry-run", "--plan", (dir_ / "plan.json").string()});
    const auto out = p.read_all();
    EXPECT_EQ(p.wait(), 0);
    EXPECT_NE(out.find(" bytes of job stream in "), std::string::npos) << out;
}

TEST_F(PtyEndToEnd, EmbossOnTheInProcessSimulator) {
    Process p({TACTUS_CLI, "emboss", "--plan", (dir_ / "plan.json").string(), "--device", "sim?speed=max"});
    const auto out = p.read_all();
    EXPECT_EQ(p.wait(), 0) << out;
    EXPECT_NE(out.find("embossed 12 passes"), std::string::npos) << out;
}

// Protocol 3 end to end through the CLI, against the C++ controller speaking
// it (`sim --pty --firmware-tables`): `emboss --firmware-tables` finds the
// version from HELLO_REPLY, plans with the tables, and the strikes are the
// plan's, on a clean line, across a warm reset in the middle of a pass, and
// on a noisy line. The same commands the firmware in s51 is driven with
// (firmware_emulator_e2e_test.cpp).
class PtyEndToEndV3 : public PtyEndToEnd {
protected:
    static std::string note() { return std::string(TACTUS_RESOURCES_DIR) + "/samples/firmware-note.md"; }
    plan::JobPlan planned() { return test::plan_with_firmware_tables(note(), TACTUS_FIRMWARE_TABLES); }
    Result emboss(std::vector<std::string> sim_extra) {
        test::PtyEmboss e;
        e.sim = {TACTUS_CLI, "sim", "--pty", "--baud", "9600", "--time-scale", "40",
                 "--firmware-tables", TACTUS_FIRMWARE_TABLES};
        e.sim.insert(e.sim.end(), sim_extra.begin(), sim_extra.end());
        e.emboss = {TACTUS_CLI, "emboss", note(), "--firmware-tables", TACTUS_FIRMWARE_TABLES};
        e.strike_log = dir_ / "strikes.jsonl";
        const auto p = test::emboss_through_pty(e);
        return Result{p.exit_code, p.output, p.log};
    }
};

TEST_F(PtyEndToEndV3, StrikesThePlan) {
    const auto want = controller::planned_strikes(planned());
    ASSERT_FALSE(want.empty());
    const auto r = emboss({});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.log, want);
}

TEST_F(PtyEndToEndV3, AWarmResetInTheMiddleOfAPassResumesAtTheExactStrike) {
    const auto want = controller::planned_strikes(planned());
    ASSERT_GT(want.size(), 20U);
    const auto r = emboss({"--reset-at-strike", "17"});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("restarted"), std::string::npos) << r.output;
    EXPECT_EQ(r.log, want);
}

TEST_F(PtyEndToEndV3, ANoisyLineStrikesExactly) {
    const auto want = controller::planned_strikes(planned());
    for (const char* seed : {"1", "2"}) {
        const auto r = emboss({"--noise", "0.01", "--seed", seed});
        EXPECT_EQ(r.exit_code, 0) << r.output;
        EXPECT_EQ(r.log, want) << "seed " << seed;
    }
}

// The simulators speak protocol 3 by default, with the tables the profile
// makes (profile::make_firmware_tables, the firmware build's rule): `sim
// --pty` and `emboss` are given no tables, and the host plans with the ones
// its profile makes, which HELLO_REPLY's table id must match.
TEST_F(PtyEndToEndV3, TheDefaultSimulatorSpeaksProtocol3WithTheProfilesTables) {
    const auto want = controller::planned_strikes(planned());  // the firmware build's tables
    test::PtyEmboss e;
    e.sim = {TACTUS_CLI, "sim", "--pty", "--baud", "9600", "--time-scale", "40"};
    e.emboss = {TACTUS_CLI, "emboss", note()};
    e.strike_log = dir_ / "strikes.jsonl";
    const auto r = test::emboss_through_pty(e);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("(protocol 3)"), std::string::npos) << r.output;
    EXPECT_EQ(r.log, want);
}

TEST(SimDefaultProtocol, HelloReplyIsVersion3WithTheProfilesTableId) {
    const auto tables = profile::make_firmware_tables(profile::default_profile());
    ASSERT_TRUE(tables.has_value());
    link::LinkOptions o;
    o.sim_firmware = *tables;
    auto l = link::Link::open("sim?speed=max", o);
    ASSERT_TRUE(l.has_value()) << l.error().to_string();
    const auto h = l->hello();
    ASSERT_TRUE(h.has_value()) << h.error().to_string();
    EXPECT_EQ(h->protocol, 3);
    EXPECT_EQ(h->table_id, tables->table_id);
    EXPECT_EQ(h->table_id, test::firmware_tables().table_id);  // the firmware build's, from the same profile
    // sim?protocol=2: the older protocol, on request.
    auto old = link::Link::open("sim?speed=max&protocol=2", o);
    ASSERT_TRUE(old.has_value());
    const auto h2 = old->hello();
    ASSERT_TRUE(h2.has_value()) << h2.error().to_string();
    EXPECT_EQ(h2->protocol, 2);
    // protocol=3 without tables is refused; nothing else is a protocol.
    EXPECT_FALSE(link::Link::open("sim?protocol=3").has_value());
    const auto bad = link::Link::open("sim?protocol=4");
    ASSERT_FALSE(bad.has_value());
    EXPECT_EQ(bad.error().kind, ErrorKind::usage);
}

TEST(SimDefaultProtocol, EmbossOnTheSimulatorSpeaksProtocol3AndProtocol2OnRequest) {
    const std::string note = std::string(TACTUS_RESOURCES_DIR) + "/samples/firmware-note.md";
    auto r = test::run_captured({TACTUS_CLI, "emboss", "--device", "sim?speed=max", note});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("(protocol 3)"), std::string::npos) << r.out;
    EXPECT_EQ(r.err.find("protocol 2"), std::string::npos) << r.err;
    r = test::run_captured({TACTUS_CLI, "emboss", "--device", "sim?speed=max&protocol=2", note});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("(protocol 2)"), std::string::npos) << r.out;
    // A profile the firmware cannot run (a carriage cruising below 3,600
    // steps/s): protocol 2, with a one-line notice naming the field.
    const auto dir = fs::temp_directory_path() / ("tactus-slow-" + std::to_string(getpid()));
    fs::create_directories(dir);
    auto j = profile::to_json(profile::default_profile());
    j["carriage"]["v_max_mm_s"] = 40.0;
    std::ofstream(dir / "slow.json") << j.dump();
    r = test::run_captured({TACTUS_CLI, "emboss", "--device", "sim?speed=max", "--profile", (dir / "slow.json").string(),
                            note});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("(protocol 2)"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("emboss: the simulator speaks protocol 2"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("carriage.v_max_mm_s"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    // ... and refused when protocol 3 is insisted on.
    r = test::run_captured({TACTUS_CLI, "emboss", "--device", "sim?speed=max&protocol=3", "--profile",
                            (dir / "slow.json").string(), note});
    EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
    fs::remove_all(dir);
}

// `emboss --dry-run` measures the stream `emboss` would send to the same
// device: the firmware's protocol 3 on the simulator (it measured protocol
// 2's whatever the device), protocol 2 on request.
TEST(SimDefaultProtocol, DryRunMeasuresTheProtocolTheDeviceSpeaks) {
    const std::string note = std::string(TACTUS_RESOURCES_DIR) + "/samples/firmware-note.md";
    const auto line_bytes = [](const std::string& out) {
        const auto open = out.find(" frames (");
        return open == std::string::npos ? 0UL : std::stoul(out.substr(open + 9));
    };
    auto v3 = test::run_captured({TACTUS_CLI, "emboss", "--dry-run", "--device", "sim?speed=max", note});
    EXPECT_EQ(v3.exit_code, 0) << v3.err;
    EXPECT_NE(v3.out.find("(protocol 3)"), std::string::npos) << v3.out;
    auto v2 = test::run_captured({TACTUS_CLI, "emboss", "--dry-run", "--device", "sim?protocol=2", note});
    EXPECT_EQ(v2.exit_code, 0) << v2.err;
    EXPECT_NE(v2.out.find("(protocol 2)"), std::string::npos) << v2.out;
    EXPECT_LT(line_bytes(v3.out), line_bytes(v2.out) / 4) << v3.out << v2.out;
}

// The "N passes on DEVICE: B bytes sent, R frames resent" line without the
// device (a pty's name differs from run to run).
std::string embossed_line(const std::string& out) {
    const auto at = out.find("embossed ");
    if (at == std::string::npos) return {};
    const auto end = out.find('\n', at);
    std::string line = out.substr(at, end - at);
    const auto on = line.find(" on "), colon = line.find(": ", on);
    if (on != std::string::npos && colon != std::string::npos) line.erase(on, colon - on);
    return line;
}

// A saved plan embosses exactly as its document: `plan --json` plans for
// protocol 3 by default and the file carries the profile's ramp tables, so
// `emboss --plan` sends the same bytes and strikes the same dots as `emboss
// DOC`, on the simulator over a pty and in process. (A protocol-2 plan file
// sent 36 times the bytes, and a protocol-3 one was refused.)
TEST(SavedPlan, EmbossesExactlyLikeItsDocumentOnTheSimulator) {
    const std::string note = std::string(TACTUS_RESOURCES_DIR) + "/samples/firmware-note.md";
    const auto dir = fs::temp_directory_path() / ("tactus-saved-plan-" + std::to_string(getpid()));
    fs::create_directories(dir);
    const auto plan_path = (dir / "note.plan.json").string();
    const auto planned = test::run_captured({TACTUS_CLI, "plan", "--json", note});
    ASSERT_EQ(planned.exit_code, 0) << planned.err;
    std::ofstream(plan_path) << planned.out;
    const auto j = nlohmann::json::parse(planned.out);
    EXPECT_EQ(j["protocol"], 3);
    EXPECT_EQ(j["firmware_tables"]["table_id"], [] {
        char id[16];
        std::snprintf(id, sizeof id, "%08x", test::firmware_tables().table_id);
        return std::string(id);
    }());

    test::PtyEmboss e;
    e.sim = {TACTUS_CLI, "sim", "--pty", "--baud", "115200", "--time-scale", "40"};
    e.baud = "115200";
    e.merge_output = false;
    e.emboss = {TACTUS_CLI, "emboss", note};
    e.strike_log = dir / "document.jsonl";
    const auto from_document = test::emboss_through_pty(e);
    e.emboss = {TACTUS_CLI, "emboss", "--plan", plan_path};
    e.strike_log = dir / "plan.jsonl";
    const auto from_plan = test::emboss_through_pty(e);
    EXPECT_EQ(from_document.exit_code, 0) << from_document.output;
    EXPECT_EQ(from_plan.exit_code, 0) << from_plan.output;
    EXPECT_NE(from_plan.output.find("(protocol 3)"), std::string::npos) << from_plan.output;
    EXPECT_EQ(embossed_line(from_plan.output), embossed_line(from_document.output));
    EXPECT_FALSE(from_document.log.empty());
    EXPECT_EQ(from_plan.log, from_document.log);

    // In process, and measured by the dry run: the same figures.
    for (const auto* extra : {"", "--dry-run"}) {
        std::vector<std::string> doc_cmd{TACTUS_CLI, "emboss", "--device", "sim?speed=max", note};
        std::vector<std::string> plan_cmd{TACTUS_CLI, "emboss", "--device", "sim?speed=max", "--plan", plan_path};
        if (*extra) doc_cmd.push_back(extra), plan_cmd.push_back(extra);
        const auto a = test::run_captured(doc_cmd);
        const auto b = test::run_captured(plan_cmd);
        EXPECT_EQ(a.exit_code, 0) << a.err;
        EXPECT_EQ(b.exit_code, 0) << b.err;
        EXPECT_NE(a.out.find("(protocol 3)"), std::string::npos) << a.out;
        EXPECT_EQ(b.out, a.out) << extra;
    }
    fs::remove_all(dir);
}

// Protocol 2 is legacy, planned only on request, and a plan is never sent to
// an embosser speaking the other protocol: the refusal says how to plan again.
// (The built-in simulator, which can speak both, speaks the plan's.)
TEST(SavedPlan, ALegacyPlanIsMadeOnRequestAndRefusedByAProtocol3Embosser) {
    const std::string note = std::string(TACTUS_RESOURCES_DIR) + "/samples/firmware-note.md";
    const auto dir = fs::temp_directory_path() / ("tactus-legacy-plan-" + std::to_string(getpid()));
    fs::create_directories(dir);
    const auto v2 = test::run_captured({TACTUS_CLI, "plan", "--json", "--protocol", "2", note});
    ASSERT_EQ(v2.exit_code, 0) << v2.err;
    EXPECT_EQ(nlohmann::json::parse(v2.out)["protocol"], 2);
    std::ofstream(dir / "v2.json") << v2.out;
    auto r = test::run_captured(
        {TACTUS_CLI, "emboss", "--device", "sim?speed=max&protocol=3", "--plan", (dir / "v2.json").string()});
    EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
    EXPECT_NE(r.err.find("the plan was made for protocol 2 (legacy), but the embosser speaks protocol 3"),
              std::string::npos)
        << r.err;
    // The built-in simulator follows the saved plan's protocol when not told one.
    for (const char* device : {"sim?speed=max", "sim?speed=max&protocol=2"}) {
        r = test::run_captured({TACTUS_CLI, "emboss", "--device", device, "--plan", (dir / "v2.json").string()});
        EXPECT_EQ(r.exit_code, 0) << device << r.out << r.err;
        EXPECT_NE(r.out.find("(protocol 2)"), std::string::npos) << device << r.out;
    }
    // A protocol-3 plan on a protocol-2 embosser: refused the other way round.
    const auto v3 = test::run_captured({TACTUS_CLI, "plan", "--json", note});
    std::ofstream(dir / "v3.json") << v3.out;
    r = test::run_captured(
        {TACTUS_CLI, "emboss", "--device", "sim?speed=max&protocol=2", "--plan", (dir / "v3.json").string()});
    EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
    EXPECT_NE(r.err.find("plan the document again with --protocol 2"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace tactus
