// SPDX-License-Identifier: GPL-3.0-or-later
// End to end against the real firmware: `tactus-cli sim --firmware` runs the
// reference firmware (firmware/, the emulator build) in s51 behind a pty,
// `tactus-cli emboss --device pty:...?baud=9600` embosses a document through
// it (protocol 3, found from HELLO_REPLY), and the strikes read back from the
// chip's port pins must be the host's plan, dot for dot. Needs sdcc, s51 and
// socat (tools/install-deps.sh); ctest label "emulator". One emulator at a
// time (RESOURCE_LOCK s51): s51 takes a whole core.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/file_io.hpp"
#include "controller/firmware_trace.hpp"
#include "controller/sim_controller.hpp"
#include "machine/firmware_tables.hpp"
#include "machine/limits.hpp"
#include "motion/steps.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/planner.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile.hpp"
#include "../common/process.hpp"
#include "../common/pty_emboss.hpp"
#include "../common/strike_log.hpp"

namespace tactus {
namespace {

namespace fs = std::filesystem;
using test::Process;

// The bundled short sample the README's main job embosses on the firmware.
const std::string kNote = std::string(TACTUS_RESOURCES_DIR) + "/samples/firmware-note.md";

using Kind = controller::PinEdge::Kind;

// A step or hammer edge the plan implies, in machine cycles (timer ticks).
struct PlannedEdge {
    Kind kind;
    long long tick;
};

// Every carriage and feed step and every hammer going down and up, at the
// plan's times: a carriage move's steps are its table intervals, ending its
// settle before the strike; the hammer goes up its pulse after the strike; a
// pass's feed starts the firmware's start gap after the event before the pass
// (docs/protocol.md, "Timing").
std::vector<PlannedEdge> planned_edges(const plan::JobPlan& job, const machine::FirmwareTables& t,
                                       const machine::StrikeTiming& timing) {
    const auto tick = [](double s) { return std::llround(s * machine::kTickHz); };
    std::vector<PlannedEdge> out;
    double clock = 0;  // the planner's clock at the start of each pass
    for (const auto& sheet : job.sheets)
        for (const auto& pass : sheet.passes) {
            const long long start = tick(clock);
            if (pass.feed.steps != 0)
                for (const auto s : motion::expand_steps(pass.feed.segments))
                    out.push_back({Kind::feed_step, start + static_cast<long long>(t.start_gap_ticks) + s});
            for (std::size_t k = 0; k < pass.strikes.size(); ++k) {
                const auto& m = pass.moves[k];
                const long long strike = tick(pass.strikes[k].time_s);
                const auto steps = motion::expand_steps(m.segments);
                const long long last = strike - static_cast<long long>(m.settle_ticks);
                for (const auto s : steps) out.push_back({Kind::carriage_step, last - steps.back() + s});
                out.push_back({Kind::hammer_down, strike});
                out.push_back({Kind::hammer_up, strike + timing.hammer_ticks});
            }
            clock += pass.duration_s;
        }
    return out;
}

struct EmulatorRun {
    int exit_code = -1;
    std::string output;
    std::vector<controller::LoggedStrike> log;
    std::vector<double> times;
};

class FirmwareEndToEnd : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("tactus-fw-e2e-" + std::to_string(getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // The plan the CLI makes for the firmware: the same library calls.
    plan::JobPlan planned() { return test::plan_with_firmware_tables(kNote, TACTUS_FIRMWARE_EMU_TABLES); }

    EmulatorRun emboss(const std::string& tables, std::vector<std::string> sim_extra = {}) {
        test::PtyEmboss e;
        e.sim = {TACTUS_CLI, "sim", "--firmware", TACTUS_FIRMWARE_IHX, "--pty"};
        e.sim.insert(e.sim.end(), sim_extra.begin(), sim_extra.end());
        e.emboss = {TACTUS_CLI, "emboss", kNote, "--firmware-tables", tables};
        e.strike_log = dir_ / "strikes.jsonl";
        e.sim_stderr = (dir_ / "sim.err").string();
        const auto p = test::emboss_through_pty(e);
        EmulatorRun r{p.exit_code, p.output, p.log, {}};
        for (const auto& k : r.log) r.times.push_back(k.time_s);
        return r;
    }

    fs::path dir_;
};

// A plan saved by `plan --json` (protocol 3, the build's tables in the file)
// strikes on the firmware exactly what its document's plan says: the file
// carries every field the encoder reads, and the tables its moves are made of.
TEST_F(FirmwareEndToEnd, ASavedPlanStrikesWhatItsDocumentPlans) {
    const auto saved = test::run_captured(
        {TACTUS_CLI, "plan", "--json", "--firmware-tables", TACTUS_FIRMWARE_EMU_TABLES, kNote});
    ASSERT_EQ(saved.exit_code, 0) << saved.err;
    std::ofstream(dir_ / "note.plan.json") << saved.out;
    test::PtyEmboss e;
    e.sim = {TACTUS_CLI, "sim", "--firmware", TACTUS_FIRMWARE_IHX, "--pty"};
    e.emboss = {TACTUS_CLI, "emboss", "--plan", (dir_ / "note.plan.json").string()};
    e.strike_log = dir_ / "strikes.jsonl";
    e.sim_stderr = (dir_ / "sim.err").string();
    const auto r = test::emboss_through_pty(e);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("(protocol 3)"), std::string::npos) << r.output;
    const auto want = controller::planned_strikes(planned());
    ASSERT_FALSE(want.empty());
    EXPECT_EQ(r.log, want);
}

// The strikes the pins show are the plan's, and every step and hammer edge
// (down and up) comes at the plan's time, to the machine cycle: the step
// interrupt compensates its own latency, so each edge comes
// machine::kPinEdgeTicks after its timer event (FirmwareTrace takes that off)
// and the emulated edges minus the planned ones are one constant (the plan's
// time origin on the emulator's clock). The first to last strike is the
// plan's to the cycle. Before the compensation (firmware/src/step.asm) edges
// were off by 0-5 cycles (the instruction the interrupt waited for), and this
// failed; on the firmware that started each phase when its main loop got
// there, edges drifted by thousands of cycles from phase to phase.
TEST_F(FirmwareEndToEnd, StrikesAndStepEdgesReadFromThePinsAreThePlan) {
    const auto job = planned();
    const auto want = controller::planned_strikes(job);
    ASSERT_FALSE(want.empty());
    const auto vcd = dir_ / "pins.vcd";
    const auto r = emboss(TACTUS_FIRMWARE_EMU_TABLES, {"--pin-trace", vcd.string()});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("embossed " + std::to_string(job.sheets[0].passes.size()) + " passes"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.log, want);
    // The emulator's clock is the chip's: the host is never late here (the
    // firmware's schedule starts each phase from its timer, and the job's
    // data is in before it is needed at 9600 baud).
    if (r.log.size() == want.size() && want.size() > 1) {
        const double emulated = r.times.back() - r.times.front();
        const double plan_span = want.back().time_s - want.front().time_s;
        std::printf("first to last strike: emulated %.6f s, planned %.6f s (%+.4f %%)\n", emulated, plan_span,
                    100 * (emulated / plan_span - 1));
        EXPECT_LE(std::abs(emulated / plan_span - 1), 0.005);
        EXPECT_EQ(std::llround(emulated * machine::kTickHz), std::llround(plan_span * machine::kTickHz))
            << "first to last strike, machine cycles";
    }
    // The step and hammer edges against the plan's times.
    const auto tables = profile::load_firmware_tables(TACTUS_FIRMWARE_EMU_TABLES);
    ASSERT_TRUE(tables) << tables.error().to_string();
    const auto plan_edges = planned_edges(job, *tables, profile::strike_timing(profile::default_profile()));
    controller::FirmwareTrace trace(80, 40);
    trace.keep_edges(true);
    std::vector<controller::LoggedStrike> ignored;
    const auto text = read_file(vcd, std::size_t{1} << 30);
    ASSERT_TRUE(text) << text.error().to_string();
    ASSERT_TRUE(trace.push(*text, ignored));
    const auto& got = trace.edges();
    ASSERT_EQ(got.size(), plan_edges.size());
    std::map<long long, std::size_t> offsets;  // emulated minus planned, cycles -> edges
    std::size_t kinds_differ = 0, hammers = 0;
    std::string first_off;  // where the emulated edges first leave the plan's
    const long long first_offset = std::llround(got[0].time_s * machine::kTickHz) - plan_edges[0].tick;
    for (std::size_t i = 0; i < got.size(); ++i) {
        if (got[i].kind != plan_edges[i].kind) ++kinds_differ;
        const long long d = std::llround(got[i].time_s * machine::kTickHz) - plan_edges[i].tick;
        ++offsets[d];
        if (first_off.empty() && d != first_offset)
            first_off = "edge " + std::to_string(i) + " (after strike " + std::to_string(hammers) + ") is " +
                        std::to_string(d - first_offset) + " cycles off";
        if (plan_edges[i].kind == Kind::hammer_down) ++hammers;
    }
    EXPECT_EQ(kinds_differ, 0U);
    const long long spread = offsets.rbegin()->first - offsets.begin()->first;
    std::printf("%zu step and hammer edges, emulated minus planned (cycles: edges):", got.size());
    for (const auto& [d, n] : offsets) std::printf(" %lld: %zu", d - offsets.begin()->first, n);
    std::printf("\n");
    EXPECT_EQ(spread, 0) << "step and hammer edges off the plan's times by up to " << spread << " cycles; "
                         << first_off;
    const auto sent = r.output.find(" bytes sent");
    if (sent != std::string::npos) {
        const auto start = r.output.rfind(' ', sent - 1) + 1;
        const double bytes = std::stod(r.output.substr(start, sent - start));
        std::printf("line bytes (host to controller) per strike: %.2f (%zu strikes)\n",
                    bytes / static_cast<double>(want.size()), want.size());
    }
}

// The host's pin-edge delay is the one the firmware was assembled with: the
// EDGE_TICKS symbol of step.asm, from the assembler's symbol table next to
// the image (sdas cuts names to 8 characters: "EDGE_TIC", hexadecimal).
TEST(FirmwareEdgeDelay, ThePinEdgeDelayIsTheFirmwares) {
    const auto sym = fs::path(TACTUS_FIRMWARE_IHX).parent_path() / "step.sym";
    const auto text = read_file(sym, std::size_t{1} << 20);
    ASSERT_TRUE(text) << text.error().to_string();
    const auto at = text->find("EDGE_TIC");
    ASSERT_NE(at, std::string::npos) << sym;
    const auto eq = text->find('=', at);
    ASSERT_NE(eq, std::string::npos);
    const auto edge = std::stoul(text->substr(eq + 1, 16), nullptr, 16);
    EXPECT_EQ(edge, machine::kPinEdgeTicks);
}

TEST_F(FirmwareEndToEnd, TablesOfAnotherBuildAreRefusedWithTheReason) {
    // The same tables under another id: what a firmware built from another profile reports.
    auto j = nlohmann::json::parse(std::ifstream(TACTUS_FIRMWARE_EMU_TABLES));
    j["table_id"] = "1c0ffee5";
    std::ofstream(dir_ / "other.json") << j.dump();
    const auto r = emboss((dir_ / "other.json").string());
    EXPECT_EQ(r.exit_code, 4) << r.output;  // exit_device
    EXPECT_NE(r.output.find("the firmware was built for ramp table"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("1c0ffee5"), std::string::npos) << r.output;
    EXPECT_TRUE(r.log.empty());
}

// Paper out, from the firmware's paper sensor (P3.6 held low): SHEET_BEGIN
// faults, the host reports it and waits for paper; cancelled, nothing struck.
TEST_F(FirmwareEndToEnd, PaperOutIsReportedAndNothingIsStruck) {
    Process server({TACTUS_CLI, "sim", "--firmware", TACTUS_FIRMWARE_IHX, "--pty", "--paper-out-at", "1",
                    "--strike-log", (dir_ / "strikes.jsonl").string()});
    const std::string pty = server.read_line(std::chrono::seconds(30));
    ASSERT_EQ(pty.rfind("/dev/pts/", 0), 0U) << pty;
    Process client({TACTUS_CLI, "emboss", kNote, "--device", "pty:" + pty + "?baud=9600", "--firmware-tables",
                    TACTUS_FIRMWARE_EMU_TABLES},
                   Process::Options{{}, true, {}});
    std::string seen;
    for (int i = 0; i < 20 && seen.find("paper out") == std::string::npos; ++i) {
        // The first line comes after the plan: with the firmware's tables the
        // planner estimates each table move on its step train, which under
        // ASan took longer than the 15 s this waited before.
        const auto line = client.read_line(std::chrono::seconds(120));
        if (line.empty()) break;
        seen += line + "\n";
    }
    EXPECT_NE(seen.find("paper out at sheet 1"), std::string::npos) << seen;
    client.signal(SIGINT);
    const auto rest = client.read_all();
    EXPECT_EQ(client.wait(), 1) << seen << rest;
    EXPECT_NE(rest.find("cancelled after 0 passes"), std::string::npos) << rest;
    server.signal(SIGTERM);
    server.wait();
    EXPECT_TRUE(test::read_strike_log((dir_ / "strikes.jsonl").string()).empty()) << "struck with no paper";
}

// A reset in the middle of a pass: s51 stops the chip at a breakpoint just
// after its Nth strike and resets it (RST: the SFRs cleared, RAM kept), a
// warm restart. The firmware keeps its place (executed passes, strikes in the
// pass, the pass still active); the host opens a new session, homes, seeks
// and sends the pass again skipping what was struck. The strikes read from
// the pins are the plan: none twice, none missing. (Before the firmware kept
// the pass active over a warm reset, the host restarted the pass from its
// first strike and the first dots were struck twice.)
TEST_F(FirmwareEndToEnd, AResetInTheMiddleOfAPassResumesAtTheExactStrike) {
    const auto job = planned();
    const auto want = controller::planned_strikes(job);
    // The third strike of the second pass with at least five: mid-pass.
    std::size_t before = 0, n = 0;
    int seen = 0;
    for (const auto& pass : job.sheets.at(0).passes) {
        if (pass.strikes.size() >= 5 && ++seen == 2) {
            n = before + 3;
            break;
        }
        before += pass.strikes.size();
    }
    ASSERT_GT(n, 0U) << "the note has no two passes of five strikes";
    const auto r = emboss(TACTUS_FIRMWARE_EMU_TABLES, {"--reset-at-strike", std::to_string(n)});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("restarted: resuming at sheet 1"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("after strike 3"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(", 1 restarts"), std::string::npos) << r.output;
    EXPECT_EQ(r.log.size(), want.size());
    EXPECT_EQ(r.log, want);
}

// A chip that stops by itself crashed, and `sim --firmware` says so and
// fails: s51 stops on a stack overflow (SP past the top of internal RAM), and
// under line noise the firmware's deepest call chain with both interrupts
// nested on it once did (firmware/README.md, "Stack"). The run then
// ended like a finished one: exit 0, the reason only in a log. Here a
// three-instruction image overflows at once (mov SP,#0xF0; push ACC;
// sjmp back to the push), beside a map naming the one symbol sim reads.
TEST_F(FirmwareEndToEnd, AChipThatOverflowsItsStackFailsTheRunLoudly) {
    const auto ihx = dir_ / "overflow.ihx";
    std::ofstream(ihx) << ":070000007581F0C0E080FCF7\n:00000001FF\n";
    std::ofstream(dir_ / "overflow.map") << "     00000030  _fw_sheet\n";
    Process sim({TACTUS_CLI, "sim", "--firmware", ihx.string(), "--pty"}, Process::Options{{}, true, {}});
    const auto out = sim.read_all();  // sim ends when s51 does
    EXPECT_EQ(sim.wait(), 1) << out;  // exit_failure
    EXPECT_NE(out.find("the emulated chip stopped by itself after 0 strikes: Stack overflow, PC=0x3"),
              std::string::npos)
        << out;
}

// A noisy line between the host and the chip (bytes dropped, flipped and
// duplicated, each at the rate, both ways): every strike still exactly the plan.
TEST_F(FirmwareEndToEnd, NoisyLineStrikesExactly) {
    const auto want = controller::planned_strikes(planned());
    for (const auto& [rate, seed] : {std::pair{"0.001", "7"}, std::pair{"0.01", "3"}}) {
        const auto r = emboss(TACTUS_FIRMWARE_EMU_TABLES, {"--noise", rate, "--seed", seed});
        EXPECT_EQ(r.exit_code, 0) << rate << ": " << r.output;
        EXPECT_EQ(r.log, want) << rate;
        std::ifstream err(dir_ / "sim.err");
        std::string text, last;
        while (std::getline(err, text)) last = text;  // this run's summary (the file is appended to)
        std::printf("noise %s: %s\n", rate, last.c_str());
        std::printf("host: %s", r.output.substr(r.output.rfind("embossed")).c_str());
    }
}

}  // namespace
}  // namespace tactus
