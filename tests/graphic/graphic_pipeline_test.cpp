// SPDX-License-Identifier: GPL-3.0-or-later
// A graphic page through the whole pipeline: planned (protocol 3, the
// reference firmware's tables), sent to the simulated controller, and the
// dots it strikes are the planned dots, which are the graphic's dots. The
// back of a graphic's sheet carries nothing. And the CLI's layout, plan and
// emboss take an SVG.
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "../common/firmware_tables_fixture.hpp"
#include "../common/process.hpp"
#include "controller/sim_controller.hpp"
#include "controller/sim_transport.hpp"
#include "graphic/graphic_page.hpp"
#include "graphic/svg_import.hpp"
#include "import/import.hpp"
#include "spool/snapshot.hpp"
#include "link/link.hpp"
#include "plan/planner.hpp"
#include "profile/controller_config.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/page_geometry.hpp"
#include "profile/profile_json.hpp"
#include "common/file_io.hpp"
#include "profile/profile.hpp"
#include "translate/catalogue.hpp"

namespace tactus {
namespace {

const std::string kShapes = std::string(TACTUS_TEST_DATA) + "/graphics/shapes.svg";

// Laid out for the reference firmware (protocol 3, the default plan): its grid.
graphic::GraphicLayout shapes_layout(const profile::PrinterProfile& prof) {
    auto d = graphic::load_svg(kShapes);
    EXPECT_TRUE(d) << d.error().to_string();
    const auto t = translate::Translator::open(translate::kDefaultTable);
    EXPECT_TRUE(t);
    auto g = graphic::lay_out_drawing(*d, prof, profile::page_geometry(prof), *t,
                                      graphic::dot_options(prof, &test::firmware_tables()));
    EXPECT_TRUE(g) << g.error().to_string();
    return std::move(*g);
}

TEST(GraphicPipeline, TheSimulatorStrikesThePlannedDotsWhichAreTheGraphics) {
    const auto prof = profile::default_profile();
    ASSERT_TRUE(prof.geometry.interpoint);
    const auto g = shapes_layout(prof);
    const auto& doc = g.document;
    ASSERT_EQ(doc.pages.size(), 1U);  // every label found room: no key
    EXPECT_EQ(doc.pages[0].graphic.size(), g.dots.dots.size());
    EXPECT_GT(g.dots.dots.size(), 300U);
    plan::PlanOptions po;
    po.firmware = test::firmware_tables();
    const auto job = plan::plan_job(doc, prof, po);
    ASSERT_TRUE(job) << job.error().to_string();
    ASSERT_EQ(job->sheets.size(), 1U);
    EXPECT_EQ(job->strikes, doc.pages[0].graphic.size());

    // The planned strikes are the graphic's dots, in the machine's steps.
    std::set<std::pair<std::int32_t, std::int32_t>> want, planned;
    for (const auto& d : doc.pages[0].graphic)
        want.insert({static_cast<std::int32_t>(std::llround(d.y_mm * prof.feed.steps_per_mm)),
                     static_cast<std::int32_t>(std::llround(d.x_mm * prof.carriage.steps_per_mm))});
    ASSERT_EQ(want.size(), doc.pages[0].graphic.size());  // no two dots on one spot
    for (const auto& p : job->sheets[0].passes)
        for (const auto& s : p.strikes) {
            // Interpoint paper: the back of a graphic carries nothing.
            EXPECT_EQ(s.side, plan::Side::front);
            EXPECT_EQ(s.hammer, plan::Hammer::convex);
            planned.insert({p.feed_step, static_cast<std::int32_t>(std::llround(s.paper_x_mm * prof.carriage.steps_per_mm))});
        }
    EXPECT_EQ(planned, want);

    // The simulated controller, speaking protocol 3 as the firmware does.
    controller::SimOptions so;
    so.firmware = test::firmware_tables();
    auto ctl = std::make_shared<controller::SimController>(so);
    controller::SimLineOptions line;
    line.baud = 115200;
    auto link = link::Link::over(std::make_unique<controller::SimTransport>(ctl, line));
    ASSERT_TRUE(link.hello());
    ASSERT_TRUE(link.use_firmware_tables(test::firmware_tables(), profile::strike_timing(prof)));
    ASSERT_TRUE(link.configure(profile::controller_config(prof)));
    link::CancelToken cancel;
    const auto out = link.send_job(*job, 1, {}, cancel);
    ASSERT_TRUE(out) << out.error().to_string();
    EXPECT_EQ(out->end, link::JobEnd::completed) << out->error.message;
    const auto& log = ctl->strike_log();
    ASSERT_EQ(log, controller::planned_strikes(*job));
    // Where the controller's step counters stood at each strike: the graphic's
    // dots, one for one. The carriage counter counts the backlash taken up at
    // each reversal too (docs/protocol.md, "Backlash"), so it may stand that
    // many steps off the dot; the feed counter is exact.
    const auto backlash = static_cast<std::int32_t>(std::llround(prof.carriage.backlash_mm * prof.carriage.steps_per_mm));
    auto left = want;
    for (const auto& s : log) {
        bool found = false;
        for (std::int32_t off = -backlash; off <= backlash && !found; ++off) {
            const auto it = left.find({s.feed_step, s.carriage_step + off});
            if (it == left.end()) continue;
            left.erase(it);
            found = true;
        }
        EXPECT_TRUE(found) << "a strike at feed " << s.feed_step << ", carriage " << s.carriage_step
                           << " that is no dot of the graphic";
    }
    EXPECT_TRUE(left.empty()) << left.size() << " dots of the graphic never struck";
}

// A label sent to the key: its sheet's back stays blank (a filler page), the key on the next sheet.
TEST(GraphicPipeline, TheKeyGoesOnASheetOfItsOwnAndTheBackStaysBlank) {
    const auto prof = profile::default_profile();
    // Lines 4 mm apart all over: no place for a label 5 mm clear of them.
    std::string lines;
    for (int y = 0; y <= 100; y += 4) lines += "M0 " + std::to_string(y) + "H100";
    auto d = graphic::read_svg(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"100mm\" viewBox=\"0 0 100 100\">"
        "<path d=\"" + lines + "\" stroke=\"black\"/><text x=\"40\" y=\"8\">crowded</text></svg>");
    ASSERT_TRUE(d) << d.error().to_string();
    const auto t = translate::Translator::open(translate::kDefaultTable);
    const auto g = graphic::lay_out_drawing(*d, prof, profile::page_geometry(prof), *t, graphic::dot_options(prof));
    ASSERT_TRUE(g) << g.error().to_string();
    ASSERT_EQ(g->document.pages.size(), 3U);
    EXPECT_TRUE(g->document.pages[1].filler);
    EXPECT_TRUE(g->document.pages[1].lines.empty());
    EXPECT_TRUE(g->document.pages[1].graphic.empty());
    EXPECT_FALSE(g->document.pages[2].lines.empty());
    const auto job = plan::plan_job(g->document, prof);
    ASSERT_TRUE(job) << job.error().to_string();
    ASSERT_EQ(job->sheets.size(), 2U);
    for (const auto& p : job->sheets[0].passes) EXPECT_EQ(p.side, plan::Side::front);
}

TEST(GraphicPipeline, ADotOffThePaperIsRefusedByThePlanner) {
    const auto prof = profile::default_profile();
    layout::PagedDocument doc;
    doc.geometry = profile::page_geometry(prof);
    layout::Page page;
    page.graphic.push_back({10, 10});
    page.graphic.push_back({prof.paper.width_mm + 1, 10});
    doc.pages.push_back(page);
    const auto job = plan::plan_job(doc, prof);
    ASSERT_FALSE(job);
    EXPECT_NE(job.error().message.find("graphic dot 2"), std::string::npos) << job.error().message;
}

// tactus-cli with these arguments, its messages merged into its output.
test::RunResult cli(const std::vector<std::string>& args) { return test::run_merged(test::cli(args)); }

TEST(GraphicPipeline, TheCliLaysOutPlansAndEmbossesAnSvg) {
    const auto layout = cli({"layout", kShapes, "--summary"});
    ASSERT_EQ(layout.exit_code, 0) << layout.out;
    EXPECT_NE(layout.out.find("graphic:"), std::string::npos) << layout.out;
    const auto plan = cli({"plan", kShapes});
    ASSERT_EQ(plan.exit_code, 0) << plan.out;
    const auto g = shapes_layout(profile::default_profile());
    EXPECT_NE(plan.out.find(std::to_string(g.document.pages[0].graphic.size())), std::string::npos) << plan.out;
    const auto emboss = cli({"emboss", "--device", "sim?speed=max", kShapes});
    ASSERT_EQ(emboss.exit_code, 0) << emboss.out;
    EXPECT_NE(emboss.out.find("embossed"), std::string::npos) << emboss.out;
    const auto bad = cli({"plan", std::string(TACTUS_TEST_DATA) + "/graphics/broken.svg"});
    EXPECT_EQ(bad.exit_code, 3) << bad.out;
    EXPECT_NE(bad.out.find("broken.svg:line 4: attribute d"), std::string::npos) << bad.out;
}


// A queued job keeps the graphic: the spool's snapshot of the pages holds its dots.
TEST(GraphicPipeline, TheSpoolSnapshotKeepsTheGraphicsDots) {
    const auto g = shapes_layout(profile::default_profile());
    const auto text = spool::to_snapshot(g.document);
    const auto back = spool::from_snapshot(text);
    ASSERT_TRUE(back) << back.error().to_string();
    ASSERT_EQ(back->pages.size(), g.document.pages.size());
    EXPECT_EQ(back->pages[0].graphic, g.document.pages[0].graphic);
    // A text page's snapshot has no graphic field at all (snapshots of text are as before).
    layout::PagedDocument plain;
    plain.pages.emplace_back();
    EXPECT_EQ(spool::to_snapshot(plain).find("graphic"), std::string::npos);
    const auto bad = spool::from_snapshot(R"({"format":"tactus-paged-1","geometry":{"cells_per_line":27,)"
                                          R"("lines_per_page":24,"interpoint":true,"eight_dot":false},)"
                                          R"("pages":[{"number":1,"print_page":"","lines":[],"graphic":[[1]]}]})");
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().where, "page 1");
}

// Where a document's text is imported (the app, a queued file), an SVG is
// refused with the reason, not read as text.
// The profile's graphic spacings reach the dots: a solid line's dots at the
// profile's spacing, a dotted line's at its own, a texture's rows at its
// pitch; and the CLI plans with them from a --profile file.
TEST(GraphicPipeline, TheProfilesSpacingsPlaceTheDots) {
    const std::string svg =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"150mm\" height=\"100mm\" viewBox=\"0 0 150 100\">"
        "<path d=\"M10 10 H130\" stroke=\"black\"/>"
        "<path d=\"M10 30 H130\" stroke=\"black\" stroke-dasharray=\"0.5 2\"/>"
        "<rect x=\"10\" y=\"45\" width=\"120\" height=\"50\" fill=\"black\"/></svg>";
    const auto d = graphic::read_svg(svg);
    ASSERT_TRUE(d) << d.error().to_string();
    const auto t = translate::Translator::open(translate::kDefaultTable);
    ASSERT_TRUE(t);
    // Counted per kind and row, on one motor step of grid (protocol 2) so no grid rounding hides a spacing.
    struct Counts {
        std::size_t solid = 0, dotted = 0, texture_rows = 0;
    };
    const auto count = [&](const profile::PrinterProfile& prof) {
        const auto g = graphic::lay_out_drawing(*d, prof, profile::page_geometry(prof), *t, graphic::dot_options(prof));
        EXPECT_TRUE(g) << g.error().to_string();
        Counts c;
        std::set<long long> rows;
        const double top = prof.paper.margin_top_mm;
        for (const auto& dot : g->dots.dots) {
            if (dot.kind == graphic::DotKind::texture) rows.insert(std::llround(dot.at.y * 100));
            if (dot.kind != graphic::DotKind::line) continue;
            if (std::abs(dot.at.y - (top + 10)) < 0.1) ++c.solid;
            if (std::abs(dot.at.y - (top + 30)) < 0.1) ++c.dotted;
        }
        c.texture_rows = rows.size();
        return c;
    };
    const auto by_default = count(profile::default_profile());
    EXPECT_EQ(by_default.solid, 81U);   // 120 mm at 1.5 mm: 80 intervals
    EXPECT_EQ(by_default.dotted, 41U);  // at 3 mm: 40
    auto prof = profile::default_profile();
    prof.graphic.line_dot_spacing_mm = 2.0;
    prof.graphic.dotted_dot_spacing_mm = 4.0;
    prof.graphic.texture_pitch_mm = 7.5;
    ASSERT_TRUE(profile::validate(prof));
    const auto changed = count(prof);
    EXPECT_EQ(changed.solid, 61U);
    EXPECT_EQ(changed.dotted, 31U);
    EXPECT_LT(changed.texture_rows, by_default.texture_rows);
    EXPECT_GT(changed.texture_rows, 0U);

    // The CLI reads the spacings from the profile it plans for.
    const auto dir = std::filesystem::temp_directory_path() / ("tactus-graphic-profile-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    ASSERT_TRUE(write_file_atomic(dir / "line.svg", svg));
    ASSERT_TRUE(write_file_atomic(dir / "machine.json", profile::to_json(prof).dump(2)));
    const auto with_default = cli({"plan", "--protocol", "2", (dir / "line.svg").string()});
    const auto with_profile = cli({"plan", "--protocol", "2", "--profile", (dir / "machine.json").string(), (dir / "line.svg").string()});
    std::filesystem::remove_all(dir);
    ASSERT_EQ(with_default.exit_code, 0) << with_default.out;
    ASSERT_EQ(with_profile.exit_code, 0) << with_profile.out;
    const auto strikes = [](const std::string& out) {
        const auto at = out.find(" strikes");
        const auto from = out.rfind(' ', at - 1);
        return out.substr(from + 1, at - from - 1);
    };
    EXPECT_NE(strikes(with_default.out), strikes(with_profile.out)) << with_default.out << with_profile.out;
    const auto g = graphic::lay_out_drawing(*d, prof, profile::page_geometry(prof), *t, graphic::dot_options(prof));
    ASSERT_TRUE(g);
    EXPECT_EQ(strikes(with_profile.out), std::to_string(g->dots.dots.size())) << with_profile.out;
}

TEST(GraphicPipeline, TheTextImporterRefusesAnSvg) {
    const auto r = import::import_file(kShapes, {});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().kind, ErrorKind::input);
    EXPECT_NE(r.error().message.find("SVG drawing"), std::string::npos) << r.error().message;
    const auto by_content = import::import_bytes("<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"/>",
                                                 "drawing.xml", {});
    EXPECT_FALSE(by_content);
}
}  // namespace
}  // namespace tactus
