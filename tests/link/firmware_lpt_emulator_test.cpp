// SPDX-License-Identifier: GPL-3.0-or-later
// End to end over the parallel port only: `tactus-cli emboss --device
// lpt:emu?fw=...` drives the reference firmware's pins in s51 with the host's
// own LptPort (compatibility mode out, IEEE 1284 nibble mode back), no serial
// line at all, and the strikes read back from the chip's port 1 must be the
// host's plan, dot for dot. Needs sdcc and s51; ctest label "emulator".
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "controller/sim_controller.hpp"
#include "../common/process.hpp"
#include "../common/pty_emboss.hpp"
#include "../common/strike_log.hpp"

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
