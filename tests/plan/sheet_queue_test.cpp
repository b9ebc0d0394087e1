// SPDX-License-Identifier: GPL-3.0-or-later
// SheetQueue plans sheets ahead on worker threads; what it hands out must be
// what the serial planner makes, byte for byte: every pass, move, strike time
// and residual, the plan file's text, the totals, and the planner's state
// after it (a serial plan_sheet may follow). Over a real document (welcome.md
// laid out, twelve times over) and random pages, on profiles that sweep both ways or one way, interpoint or
// single-sided, in the planner's own mode and for the firmware's tables.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>

#include "hand_pages.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/plan_file.hpp"
#include "plan/planner.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/page_geometry.hpp"
#include "../common/firmware_tables_fixture.hpp"

namespace tactus::plan {
namespace {

namespace fs = std::filesystem;

layout::Page random_page(std::mt19937& rng, const profile::PrinterProfile& p) {
    std::uniform_int_distribution<int> cells(0, p.geometry.cells_per_line);
    std::uniform_int_distribution<int> dots(0, 63);
    std::bernoulli_distribution blank_line(0.3), blank_cell(0.4), blank_page(0.1);
    std::vector<std::u32string> lines;
    if (blank_page(rng)) return test::page_of(lines);
    for (int l = 0; l < p.geometry.lines_per_page; ++l) {
        std::u32string line;
        if (!blank_line(rng)) {
            const int n = cells(rng);
            for (int c = 0; c < n; ++c) line += static_cast<char32_t>(0x2800 + (blank_cell(rng) ? 0 : dots(rng)));
        }
        lines.push_back(line);
    }
    return test::page_of(lines);
}

struct Planned {
    std::vector<SheetPlan> sheets;
    JobPlan totals;
    std::size_t decisions = 0;
    std::optional<Error> error;
    std::size_t error_sheet = 0;
};

// Sheets first..last on `planner`: serially (threads == 1 is plan_sheet
// itself, tested below) or through a queue.
void plan_range(Planner& planner, const layout::PagedDocument& doc, std::size_t first, std::size_t last,
                unsigned threads, Planned& out) {
    std::optional<SheetQueue> queue;
    if (threads > 1) {
        queue.emplace(planner, doc, first, threads);
        // The threads are used whenever there are enough sheets.
        if (last + 1 - first >= SheetQueue::kMinSheets) {
            EXPECT_GT(queue->threads(), 0U);
        }
    }
    for (std::size_t s = first; s <= last; ++s) {
        auto sheet = queue ? queue->next() : planner.plan_sheet(doc, s);
        if (!sheet) {
            out.error = sheet.error();
            out.error_sheet = s;
            return;
        }
        out.sheets.push_back(std::move(*sheet));
    }
}

// The whole document; with `split`, through a queue up to sheet `split`,
// then plan_sheet on the same planner (and the other way round when
// `queue_after`), as a caller that mixes the two would.
Planned plan_all(const layout::PagedDocument& doc, const profile::PrinterProfile& p, const PlanOptions& o,
                 unsigned threads, std::size_t split = 0, bool queue_after = false) {
    auto planner = Planner::create(p, o);
    EXPECT_TRUE(planner) << planner.error().to_string();
    Planned out;
    const std::size_t n = doc.sheet_count();
    if (split == 0 || split >= n) {
        plan_range(*planner, doc, 1, n, threads, out);
    } else {
        plan_range(*planner, doc, 1, split, queue_after ? 1 : threads, out);
        if (!out.error) plan_range(*planner, doc, split + 1, n, queue_after ? threads : 1, out);
    }
    out.totals = planner->totals();
    out.decisions = planner->tuner().decisions().size();
    return out;
}

void expect_same(const Planned& serial, const Planned& parallel) {
    ASSERT_EQ(serial.error.has_value(), parallel.error.has_value());
    if (serial.error) {
        EXPECT_EQ(serial.error->to_string(), parallel.error->to_string());
        EXPECT_EQ(serial.error_sheet, parallel.error_sheet);
        return;
    }
    ASSERT_EQ(serial.sheets.size(), parallel.sheets.size());
    for (std::size_t i = 0; i < serial.sheets.size(); ++i) {
        SCOPED_TRACE("sheet " + std::to_string(i + 1));
        const auto &a = serial.sheets[i], &b = parallel.sheets[i];
        EXPECT_EQ(a.index, b.index);
        ASSERT_EQ(a.passes.size(), b.passes.size());
        for (std::size_t k = 0; k < a.passes.size(); ++k) ASSERT_EQ(a.passes[k], b.passes[k]) << "pass " << k + 1;
        EXPECT_EQ(a.duration_s, b.duration_s);
        EXPECT_EQ(a.lower_bound_s, b.lower_bound_s);
        // The plan file's text: every double to the last bit.
        EXPECT_EQ(sheet_to_json(a).dump(), sheet_to_json(b).dump());
    }
    const auto &x = serial.totals, &y = parallel.totals;
    EXPECT_EQ(x.duration_s, y.duration_s);
    EXPECT_EQ(x.lower_bound_s, y.lower_bound_s);
    EXPECT_EQ(x.strikes, y.strikes);
    EXPECT_EQ(x.segments, y.segments);
    EXPECT_EQ(x.max_residual_um, y.max_residual_um);
    EXPECT_EQ(x.max_worst_residual_um, y.max_worst_residual_um);
    EXPECT_EQ(x.strikes_over_tolerance, y.strikes_over_tolerance);
    EXPECT_EQ(serial.decisions, parallel.decisions);
}

layout::PagedDocument laid_out(const fs::path& file, const char* tables, const profile::PrinterProfile& prof) {
    pipeline::PipelineOptions o;
    o.tables = tables;
    o.layout.geometry = profile::page_geometry(prof);
    auto doc = pipeline::lay_out_file(file, o);
    EXPECT_TRUE(doc) << doc.error().to_string();
    return doc ? std::move(*doc) : layout::PagedDocument{};
}

// welcome.md twelve times over: a real document of many sheets.
fs::path long_welcome() {
    const fs::path samples = fs::path(TACTUS_RESOURCES_DIR) / "samples";
    std::ifstream in(samples / "welcome.md");
    std::stringstream text;
    text << in.rdbuf();
    const auto path = fs::temp_directory_path() / ("tactus-sheet-queue-" + std::to_string(getpid()) + ".md");
    std::ofstream out(path);
    for (int i = 0; i < 12; ++i) out << text.str() << "\n\n";
    return path;
}

struct Variant {
    const char* name;
    bool interpoint, bidirectional, firmware;
};
constexpr Variant kVariants[] = {
    {"interpoint, both ways", true, true, false},
    {"interpoint, one way", true, false, false},
    {"single-sided, both ways", false, true, false},
    {"firmware tables, both ways", true, true, true},
    {"firmware tables, single-sided, one way", false, false, true},
};

profile::PrinterProfile profile_of(const Variant& v) {
    auto p = profile::default_profile();
    p.geometry.interpoint = v.interpoint;
    p.motion.bidirectional = v.bidirectional;
    return p;
}

PlanOptions options_of(const Variant& v) {
    PlanOptions o;
    if (v.firmware) o.firmware = test::firmware_tables();
    return o;
}

TEST(SheetQueue, RealDocumentsPlanAsTheSerialPlanner) {
    const auto book = long_welcome();
    for (const auto& v : kVariants) {
        SCOPED_TRACE(v.name);
        const auto prof = profile_of(v);
        const auto o = options_of(v);
        const auto doc = laid_out(book, "en-ueb-g2.ctb", prof);
        ASSERT_GE(doc.sheet_count(), 2 * SheetQueue::kMinSheets);
        const auto serial = plan_all(doc, prof, o, 1);
        ASSERT_FALSE(serial.error) << serial.error->to_string();
        for (unsigned threads : {2U, 3U}) {
            if (threads == 3 && &v != &kVariants[0]) continue;
            SCOPED_TRACE(std::to_string(threads) + " threads");
            expect_same(serial, plan_all(doc, prof, o, threads));
        }
    }
    fs::remove(book);
}

TEST(SheetQueue, RandomDocumentsPlanAsTheSerialPlanner) {
    std::mt19937 rng(20261126);
    for (const auto& v : kVariants) {
        SCOPED_TRACE(v.name);
        // Small pages: fewer move lengths to tune and encode, the same sheet-to-sheet state.
        auto prof = profile_of(v);
        prof.geometry.cells_per_line = 12;
        prof.geometry.lines_per_page = 6;
        const auto o = options_of(v);
        for (int trial = 0; trial < 2; ++trial) {
            SCOPED_TRACE("trial " + std::to_string(trial));
            std::vector<layout::Page> pages;
            const int n = 8 + static_cast<int>(rng() % 8);
            for (int i = 0; i < n; ++i) pages.push_back(random_page(rng, prof));
            const auto doc = test::doc_of(std::move(pages), prof.geometry.interpoint);
            const auto serial = plan_all(doc, prof, o, 1);
            ASSERT_FALSE(serial.error) << serial.error->to_string();
            expect_same(serial, plan_all(doc, prof, o, static_cast<unsigned>(2 + rng() % 3)));
            if (trial > 0) continue;
            // A queue for the first sheets and plan_sheet after it, and the other way round.
            const std::size_t split = 1 + rng() % doc.sheet_count();
            SCOPED_TRACE("split after sheet " + std::to_string(split));
            expect_same(serial, plan_all(doc, prof, o, 2, split, false));
            expect_same(serial, plan_all(doc, prof, o, 2, split, true));
        }
    }
}

// A sheet that cannot be planned fails as plan_sheet fails, on the same
// sheet, with the same error, whatever the workers have planned after it.
TEST(SheetQueue, AnErrorComesOnTheSheetThatHasIt) {
    std::mt19937 rng(7);
    const auto prof = profile::default_profile();
    std::vector<layout::Page> pages;
    for (int i = 0; i < 12; ++i) pages.push_back(random_page(rng, prof));
    // Page 7 (sheet 4) has a line too long for the profile.
    pages[6].lines.at(0).resize(static_cast<std::size_t>(prof.geometry.cells_per_line) + 3,
                                document::Cell::from_unicode(U'⠿'));
    const auto doc = test::doc_of(std::move(pages), true);
    const auto serial = plan_all(doc, prof, {}, 1);
    ASSERT_TRUE(serial.error);
    EXPECT_EQ(serial.error_sheet, 4U);
    expect_same(serial, plan_all(doc, prof, {}, 3));
    // plan_job goes through a queue: the same error.
    auto job = plan_job(doc, prof, {}, 2);
    ASSERT_FALSE(job);
    EXPECT_EQ(job.error().to_string(), serial.error->to_string());
}

TEST(SheetQueue, OneThreadOrAFewSheetsPlanOnTheCallingThread) {
    const auto prof = profile::default_profile();
    auto planner = Planner::create(prof);
    ASSERT_TRUE(planner);
    std::vector<layout::Page> pages(2 * SheetQueue::kMinSheets, test::page_of({U"⠁"}));
    const auto enough = test::doc_of(pages, true);
    EXPECT_EQ(SheetQueue(*planner, enough, 1, 1).threads(), 0U);
    EXPECT_EQ(SheetQueue(*planner, enough, 1, 3).threads(), 3U);
    EXPECT_EQ(SheetQueue(*planner, enough, 1, 100).threads(), SheetQueue::kMinSheets);  // no more than sheets
    EXPECT_EQ(SheetQueue(*planner, enough, 2, 100).threads(), 0U);  // from sheet 2: too few left
    pages.pop_back();
    pages.pop_back();
    EXPECT_EQ(SheetQueue(*planner, test::doc_of(pages, true), 1, 4).threads(), 0U);
}

}  // namespace
}  // namespace tactus::plan
