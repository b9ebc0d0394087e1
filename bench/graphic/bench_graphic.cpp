// SPDX-License-Identifier: GPL-3.0-or-later
// Time per graphic page: an SVG read, its dots placed and the page planned,
// for protocol 3 (the reference firmware's tables and grid) and protocol 2
// (every motor step addressable). Figures per drawing: dots, passes, the
// embossing time the plan takes against its lower bound (time-optimal
// jerk-limited moves with the same limits, dwell and feed), and the wall time
// of reading, placing and planning.
// Usage: bench_graphic FIRMWARE_TABLES.json DRAWING.svg...
#include <chrono>
#include <cstdio>

#include "graphic/graphic_page.hpp"
#include "graphic/svg_import.hpp"
#include "plan/planner.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/page_geometry.hpp"
#include "translate/catalogue.hpp"

using namespace tactus;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s FIRMWARE_TABLES.json DRAWING.svg...\n", argv[0]);
        return 2;
    }
    const auto prof = profile::default_profile();
    const auto tables = profile::load_firmware_tables(argv[1]);
    if (!tables) {
        std::fprintf(stderr, "%s\n", tables.error().to_string().c_str());
        return 1;
    }
    const auto table = translate::Translator::open(translate::kDefaultTable);
    if (!table) return 1;
    std::printf("%-28s %-9s %6s %6s %10s %10s %7s %9s\n", "drawing", "protocol", "dots", "passes", "plan s",
                "bound s", "ratio", "wall ms");
    for (int i = 2; i < argc; ++i) {
        for (const bool v3 : {true, false}) {
            const auto t0 = Clock::now();
            const auto drawing = graphic::load_svg(argv[i]);
            if (!drawing) {
                std::fprintf(stderr, "%s\n", drawing.error().to_string().c_str());
                return 1;
            }
            const auto laid = graphic::lay_out_drawing(*drawing, prof, profile::page_geometry(prof), *table,
                                                       graphic::dot_options(prof, v3 ? &*tables : nullptr));
            if (!laid) return 1;
            plan::PlanOptions po;
            if (v3) po.firmware = *tables;
            const auto job = plan::plan_job(laid->document, prof, po, 1);
            if (!job) {
                std::fprintf(stderr, "%s\n", job.error().to_string().c_str());
                return 1;
            }
            const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
            std::size_t passes = 0;
            for (const auto& s : job->sheets) passes += s.passes.size();
            const std::string name = std::string(argv[i]).substr(std::string(argv[i]).find_last_of('/') + 1);
            std::printf("%-28s %-9s %6zu %6zu %10.1f %10.1f %7.3f %9.1f\n", name.c_str(), v3 ? "3" : "2",
                        job->strikes, passes, job->duration_s, job->lower_bound_s, job->duration_s / job->lower_bound_s,
                        ms);
        }
    }
    return 0;
}
