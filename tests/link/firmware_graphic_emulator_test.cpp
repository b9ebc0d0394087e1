// SPDX-License-Identifier: GPL-3.0-or-later
// A tactile graphic on the reference firmware in s51: `tactus-cli emboss
// drawing.svg` over a pty at 9600 baud (protocol 3), and the strikes read from
// the chip's port pins are the host's plan, strike for strike, and stand on
// the graphic's dots. A graphic page is more passes for the firmware, not a
// new kind of command (docs/graphics.md, "Through the pipeline"); this is
// where that is checked against the firmware itself, not the C++ controller.
// Needs sdcc, s51 and socat; one emulator at a time (RESOURCE_LOCK s51).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <utility>

#include "controller/sim_controller.hpp"
#include "graphic/graphic_page.hpp"
#include "graphic/svg_import.hpp"
#include "plan/planner.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/page_geometry.hpp"
#include "profile/profile.hpp"
#include "translate/catalogue.hpp"
#include "../common/pty_emboss.hpp"
#include "../common/strike_log.hpp"

namespace tactus {
namespace {

namespace fs = std::filesystem;

// A circle, a triangle labelled A and B, a dashed line and a textured bar:
// 70 x 56 mm, about 15 s of embossing (s51 runs at about 0.9 emulated
// seconds a second with the serial line polled often).
const std::string kDrawing = std::string(TACTUS_TEST_DATA) + "/graphics/firmware-shapes.svg";

TEST(FirmwareGraphic, StrikesReadFromThePinsAreThePlannedDotsOfTheDrawing) {
    const auto prof = profile::default_profile();
    const auto tables = profile::load_firmware_tables(TACTUS_FIRMWARE_EMU_TABLES);
    ASSERT_TRUE(tables) << tables.error().to_string();
    // The layout and plan the CLI makes for the firmware: the same library calls.
    const auto drawing = graphic::load_svg(kDrawing);
    ASSERT_TRUE(drawing) << drawing.error().to_string();
    const auto table = translate::Translator::open(translate::kDefaultTable);
    ASSERT_TRUE(table) << table.error().to_string();
    const auto laid = graphic::lay_out_drawing(*drawing, prof, profile::page_geometry(prof), *table,
                                               graphic::dot_options(prof, &*tables));
    ASSERT_TRUE(laid) << laid.error().to_string();
    ASSERT_EQ(laid->document.pages.size(), 1U);  // both labels on the drawing: no key
    std::size_t kinds[3] = {0, 0, 0};
    for (const auto& d : laid->dots.dots) ++kinds[static_cast<int>(d.kind)];
    EXPECT_GT(kinds[static_cast<int>(graphic::DotKind::line)], 100U);
    EXPECT_GT(kinds[static_cast<int>(graphic::DotKind::texture)], 0U);
    EXPECT_GT(kinds[static_cast<int>(graphic::DotKind::label)], 0U);
    plan::PlanOptions po;
    po.firmware = *tables;
    const auto job = plan::plan_job(laid->document, prof, po);
    ASSERT_TRUE(job) << job.error().to_string();
    const auto want = controller::planned_strikes(*job);
    ASSERT_EQ(want.size(), laid->dots.dots.size());

    const auto dir = fs::temp_directory_path() / ("tactus-fw-graphic-" + std::to_string(getpid()));
    fs::create_directories(dir);
    test::PtyEmboss e;
    e.sim = {TACTUS_CLI, "sim", "--firmware", TACTUS_FIRMWARE_IHX, "--pty"};
    e.emboss = {TACTUS_CLI, "emboss", kDrawing, "--firmware-tables", TACTUS_FIRMWARE_EMU_TABLES};
    e.baud = "9600";
    e.strike_log = dir / "strikes.jsonl";
    e.sim_stderr = (dir / "sim.err").string();
    const auto r = test::emboss_through_pty(e);
    fs::remove_all(dir);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("(protocol 3)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("embossed " + std::to_string(job->sheets[0].passes.size()) + " passes"),
              std::string::npos)
        << r.output;
    // Strike for strike, in order: sheet, side, hammer, carriage and feed step.
    ASSERT_EQ(r.log.size(), want.size());
    std::size_t first_diff = want.size();
    for (std::size_t i = 0; i < want.size() && first_diff == want.size(); ++i)
        if (!(r.log[i] == want[i])) first_diff = i;
    EXPECT_EQ(first_diff, want.size()) << "strike " << first_diff << ": pins at carriage " << r.log[first_diff].carriage_step
                                       << ", feed " << r.log[first_diff].feed_step << "; planned carriage "
                                       << want[first_diff].carriage_step << ", feed " << want[first_diff].feed_step;

    // Where the pins' step counts stood at each strike: the graphic's dots, one
    // for one. The carriage count includes the backlash taken up at each
    // reversal (docs/protocol.md, "Backlash"), so it may stand that many
    // steps off the dot; the feed count is exact. The back carries nothing.
    std::set<std::pair<std::int32_t, std::int32_t>> dots;
    for (const auto& d : laid->document.pages[0].graphic)
        dots.insert({static_cast<std::int32_t>(std::llround(d.y_mm * prof.feed.steps_per_mm)),
                     static_cast<std::int32_t>(std::llround(d.x_mm * prof.carriage.steps_per_mm))});
    ASSERT_EQ(dots.size(), laid->document.pages[0].graphic.size());
    const auto backlash = static_cast<std::int32_t>(std::llround(prof.carriage.backlash_mm * prof.carriage.steps_per_mm));
    std::size_t strays = 0;
    for (const auto& s : r.log) {
        EXPECT_EQ(s.side, plan::Side::front);
        bool found = false;
        for (std::int32_t off = -backlash; off <= backlash && !found; ++off)
            if (const auto it = dots.find({s.feed_step, s.carriage_step + off}); it != dots.end()) {
                dots.erase(it);
                found = true;
            }
        if (!found) ++strays;
    }
    EXPECT_EQ(strays, 0U) << "strikes on the pins that are no dot of the drawing";
    EXPECT_TRUE(dots.empty()) << dots.size() << " dots of the drawing never struck";
    std::printf("%zu strikes in %zu passes from the pins, the plan's\n", r.log.size(), job->sheets[0].passes.size());
}

}  // namespace
}  // namespace tactus
