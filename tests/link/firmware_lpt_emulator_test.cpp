// SPDX-License-Identifier: GPL-3.0-or-later
// End to end over the parallel port only: `tactus-cli emboss --device
// lpt:emu?fw=...` drives the reference firmware's pins in s51 with the host's
// own LptPort (compatibility mode out, IEEE 1284 nibble mode back), no serial
// line at all, and the strikes read back from the chip's port 1 must be the
// host's plan, dot for dot. Needs sdcc and s51; ctest label "emulator".
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "controller/sim_controller.hpp"
#include "../common/process.hpp"
#include "../common/pty_emboss.hpp"
#include "../common/strike_log.hpp"
#include "../spool/strike_audit.hpp"

namespace tactus {
namespace {

namespace fs = std::filesystem;

class FirmwareOverLpt : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("tactus-fw-lpt-" + std::to_string(getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    struct Run {
        test::RunResult r;
        std::vector<controller::LoggedStrike> log;
    };
    // The bundled note (6 passes, 50 strikes) over lpt:emu with `options`.
    Run emboss_note(const std::string& options) {
        const auto log = dir_ / "strikes.jsonl";
        const std::string device = "lpt:emu?fw=" + std::string(TACTUS_FIRMWARE_IHX) + "&log=" + log.string() + options;
        auto r = test::run_captured({TACTUS_CLI, "emboss", kNote, "--firmware-tables", TACTUS_FIRMWARE_EMU_TABLES,
                                     "--device", device});
        return {std::move(r), test::read_strike_log(log.string())};
    }
    // The strikes read from the pins against the plan: every sheet once,
    // complete, nothing out of sequence (the audit the spool's fault tests
    // run), and dot for dot the plan's.
    static void expect_the_plan_once(const std::vector<controller::LoggedStrike>& log) {
        const auto job = test::plan_with_firmware_tables(kNote, TACTUS_FIRMWARE_EMU_TABLES);
        const auto audit = spool::test::audit_strikes(job, log, {});
        EXPECT_EQ(audit.problems, "");
        EXPECT_EQ(audit.partial_attempts, 0U);
        EXPECT_EQ(log, controller::planned_strikes(job));
    }

    static inline const std::string kNote = std::string(TACTUS_RESOURCES_DIR) + "/samples/firmware-note.md";
    fs::path dir_;
};

// A short document embossed through the firmware's parallel port, starting
// with paper out: the firmware finds no paper at the sheet's start and shows
// it on PError; the job waits, the operator loads paper half a second (chip
// time) after PError showed, and the job goes on by itself: every planned
// strike once, none twice, none missing. Two letters (10 strikes with the
// page number, against 23 for "Tactus", which took 3.5 minutes), because
// every s51 console line costs milliseconds and the port takes thousands. The
// same job without paper out ran a second one, which this one holds whole
// (HELLO, protocol 3, every strike), so it was dropped.
TEST_F(FirmwareOverLpt, PaperOutOnPErrorWaitsAndTheJobResumesStrikingEachDotOnce) {
    const auto doc = dir_ / "word.md";
    std::ofstream(doc) << "ab\n";
    const auto log = dir_ / "strikes.jsonl";
    const std::string device =
        "lpt:emu?fw=" + std::string(TACTUS_FIRMWARE_IHX) + "&paper=out&reload=0.5&log=" + log.string();
    const auto r = test::run_captured({TACTUS_CLI, "emboss", doc.string(), "--firmware-tables",
                                       TACTUS_FIRMWARE_EMU_TABLES, "--device", device});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("(protocol 3)"), std::string::npos) << r.out;
    EXPECT_NE((r.out + r.err).find("paper out"), std::string::npos) << r.out << r.err;
    const auto want = controller::planned_strikes(test::plan_with_firmware_tables(doc.string(), TACTUS_FIRMWARE_EMU_TABLES));
    ASSERT_FALSE(want.empty());
    EXPECT_EQ(test::read_strike_log(log.string()), want);
}

// A real one-page document nobody here wrote (pandoc's test/docx
// block_quotes.docx: 57 passes, 729 strikes), laid out, translated and
// planned by the pipeline, embossed through the firmware's parallel port
// only: the strikes read from the chip's port 1 are the plan's, dot for dot,
// in order. About 40,000 console lines: 1.5-2 minutes on a loaded machine
// with s51 woken for each line (firmware/tools/s51_wake.c); most of an hour
// when each line waited for s51's nap.
TEST_F(FirmwareOverLpt, AOnePageDocumentStrikesThePlanDotForDot) {
    const std::string doc = std::string(TACTUS_TEST_DATA) + "/import/public/pandoc-block_quotes.docx";
    const auto want = controller::planned_strikes(test::plan_with_firmware_tables(doc, TACTUS_FIRMWARE_EMU_TABLES));
    ASSERT_GT(want.size(), 500U);
    const auto log = dir_ / "strikes.jsonl";
    const auto r = test::run_captured({TACTUS_CLI, "emboss", doc, "--firmware-tables", TACTUS_FIRMWARE_EMU_TABLES,
                                       "--device", "lpt:emu?fw=" + std::string(TACTUS_FIRMWARE_IHX) + "&log=" + log.string()});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("embossed 57 passes"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("0 frames resent"), std::string::npos) << r.out;
    EXPECT_EQ(test::read_strike_log(log.string()), want);
}

// The hammer-home sensor stays low from the 20th strike on (a hammer stuck
// down): the firmware finds it at the next strike's dwell, stops on a hammer
// fault and shows it on nFault. The host cannot clear that one: the job
// fails at once naming the sheet to resume from, and what was struck is the
// plan's beginning, nothing twice and nothing after the fault.
TEST_F(FirmwareOverLpt, AHammerFaultOnNFaultStopsTheJobAfterTheStrikesMade) {
    const auto [r, log] = emboss_note("&hammer=20");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.err.find("hammer fault at sheet 1"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("resume with --start-sheet 1"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("at the end nFault is low (a fault stands), PError low"), std::string::npos) << r.err;
    const auto planned = controller::planned_strikes(test::plan_with_firmware_tables(kNote, TACTUS_FIRMWARE_EMU_TABLES));
    ASSERT_GE(log.size(), 20U);
    ASSERT_LE(log.size(), 21U);  // the strike whose dwell found the hammer down was made
    EXPECT_TRUE(std::equal(log.begin(), log.end(), planned.begin()));
}

// The cable is out from 3 s to 7.5 s of chip time, mid-job: the chip runs on
// (its input pins float high), the host reads every status line high, loses
// the port and reopens it until the controller shows ready again: the same
// chip, its job where the cable left it. Each dot once.
TEST_F(FirmwareOverLpt, ACablePulledMidJobReconnectsAndStrikesEachDotOnce) {
    const auto [r, log] = emboss_note("&pull=3:7.5");
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.err.find("the cable is back in"), std::string::npos) << r.err;
    EXPECT_NE((r.out + r.err).find("reconnected"), std::string::npos) << r.out << r.err;
    EXPECT_EQ(r.out.find(", 0 reconnects"), std::string::npos) << r.out;
    expect_the_plan_once(log);
}

// A warm reset of the chip (s51's RST: SFRs cleared, RAM kept) just after the
// 20th strike, in the middle of a pass, while the host polls for replies in
// nibble mode: the host's transfer fails, it reopens the port, opens a new
// session and resumes the pass skipping what was struck. This needs the
// firmware to leave a negotiation the host gave up: a chip that stayed in it
// would never answer again (the job would give up after 30 s, 20 strikes made).
TEST_F(FirmwareOverLpt, AWarmResetMidPassResumesAtTheExactStrike) {
    const auto [r, log] = emboss_note("&reset=20");
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find(", 1 restarts"), std::string::npos) << r.out;
    expect_the_plan_once(log);
}

// A device string the cable cannot use is refused before anything runs, with
// what is wrong and the exit code of a usage error or a missing device.
TEST(FirmwareOverLptDevice, ABadDeviceStringIsRefusedWithTheReason) {
    const auto unknown = test::run_captured({TACTUS_CLI, "emboss", std::string(TACTUS_RESOURCES_DIR) + "/samples/firmware-note.md",
                                             "--device", "lpt:emu?fw=" + std::string(TACTUS_FIRMWARE_IHX) + "&speed=9"});
    EXPECT_NE(unknown.exit_code, 0);
    EXPECT_NE(unknown.err.find("unknown option \"speed=9\""), std::string::npos) << unknown.err;
    const auto missing = test::run_captured({TACTUS_CLI, "emboss", std::string(TACTUS_RESOURCES_DIR) + "/samples/firmware-note.md",
                                             "--device", "lpt:emu?fw=/nonexistent/tactus-fw.ihx"});
    EXPECT_NE(missing.exit_code, 0);
    EXPECT_NE(missing.err.find("no such firmware image"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace tactus
