// SPDX-License-Identifier: GPL-3.0-or-later
// Plans and estimates a whole book (the KJV from Debian's bible-kjv) on the
// default profile, in the same run as its layout, and one page alone.
// Figures: pages per second; planning time / layout time (goal <= 1), the
// plan made on one thread and through a SheetQueue (the same plan, checked); the
// embossing-time ratio plan / lower bound (goal <= 1.10); the speed-up over a
// naive plan (one direction, a stop at every dot column).
// Usage: bench_plan BOOK.txt [TABLE]
#include <sys/resource.h>

#include <bit>
#include <chrono>
#include <cstdlib>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <thread>

#include "pipeline/pipeline.hpp"
#include "plan/planner.hpp"
#include "profile/page_geometry.hpp"

using namespace tactus;
using Clock = std::chrono::steady_clock;

namespace {
double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}
// CPU seconds of this process and of its children that have ended (the
// layout translates in forked worker processes, reaped when it returns).
double cpu_seconds() {
    const auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6; };
    double total = 0;
    for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
        rusage u{};
        ::getrusage(who, &u);
        total += s(u.ru_utime) + s(u.ru_stime);
    }
    return total;
}
}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s BOOK.txt [TABLE]\n", argv[0]);
        return 2;
    }
    // The 1-minute load average before and after: on a shared machine the
    // wall times mean little without it (CPU times are steadier).
    double load_before[1] = {-1};
    if (::getloadavg(load_before, 1) < 1) load_before[0] = -1;
    const auto prof = profile::default_profile();
    pipeline::PipelineOptions options;
    if (argc > 2) options.tables = argv[2];
    options.layout.geometry = profile::page_geometry(prof);

    // Layout and plan alternate, three rounds each, and the best of each is
    // compared: on a shared machine a single run of either can be slowed by
    // other work, and alternating exposes both to the same conditions. The
    // plan is made twice per round: one sheet at a time on this thread
    // (Planner::plan_sheet), and through a SheetQueue (sheets planned ahead on
    // the machine's cores, as the CLI and the spool plan); the two must agree
    // to the bit (a digest of every strike's time, step and residual).
    constexpr int rounds = 3;
    double layout_s = 1e300, layout_cpu = 1e300;
    double plan_s[2] = {1e300, 1e300}, plan_cpu[2] = {1e300, 1e300};  // [serial, queue]
    std::uint64_t digest[2] = {0, 0};
    unsigned threads = 0;
    std::optional<layout::PagedDocument> doc;
    std::optional<plan::Planner> planner;
    std::size_t passes = 0, max_pass_bytes = 0;
    for (int round = 0; round < rounds; ++round) {
        doc.reset();  // one book in memory at a time
        planner.reset();
        auto t0 = Clock::now();
        double c0 = cpu_seconds();
        auto laid = pipeline::lay_out_file(argv[1], options);
        if (!laid) {
            std::fprintf(stderr, "%s\n", laid.error().to_string().c_str());
            return 1;
        }
        layout_s = std::min(layout_s, seconds_since(t0));
        layout_cpu = std::min(layout_cpu, cpu_seconds() - c0);
        doc.emplace(std::move(*laid));

        for (int queued = 0; queued < 2; ++queued) {
            // The whole book, one sheet at a time (the plan of a sheet freed before the next).
            planner.reset();
            t0 = Clock::now();
            c0 = cpu_seconds();
            auto made = plan::Planner::create(prof);
            if (!made) return 1;
            std::optional<plan::SheetQueue> queue;
            if (queued) queue.emplace(*made, *doc);
            passes = 0, max_pass_bytes = 0;
            std::uint64_t h = 1469598103934665603ULL;
            const auto mix = [&h](std::uint64_t v) { h = (h ^ v) * 1099511628211ULL; };
            for (std::size_t s = 1; s <= doc->sheet_count(); ++s) {
                auto sheet = queue ? queue->next() : made->plan_sheet(*doc, s);
                if (!sheet) {
                    std::fprintf(stderr, "%s\n", sheet.error().to_string().c_str());
                    return 1;
                }
                passes += sheet->passes.size();
                for (const auto& p : sheet->passes) {
                    max_pass_bytes = std::max(max_pass_bytes, p.segments * 6);
                    for (std::size_t k = 0; k < p.strikes.size(); ++k) {
                        mix(std::bit_cast<std::uint64_t>(p.strikes[k].time_s));
                        mix(static_cast<std::uint64_t>(p.strikes[k].carriage_step));
                        mix(std::bit_cast<std::uint64_t>(p.strikes[k].worst_residual_um));
                        mix(p.moves[k].settle_ticks);
                        mix(p.moves[k].segments.size());
                    }
                }
            }
            if (queue) threads = queue->threads();
            queue.reset();
            plan_s[queued] = std::min(plan_s[queued], seconds_since(t0));
            plan_cpu[queued] = std::min(plan_cpu[queued], cpu_seconds() - c0);
            mix(std::bit_cast<std::uint64_t>(made->totals().duration_s));
            digest[queued] = h;
            planner.emplace(std::move(*made));
        }
    }
    const plan::JobPlan t = planner->totals();  // a copy: the warm single-page runs below add to the totals

    auto t0 = Clock::now();
    auto naive = plan::naive_duration(*doc, prof);
    const double naive_s = seconds_since(t0);
    if (!naive) return 1;

    // One page alone, repeated for a stable figure (each run a fresh planner:
    // this includes tuning its moves from cold).
    layout::PagedDocument one;
    one.geometry = doc->geometry;
    one.pages.push_back(doc->pages.at(doc->pages.size() / 2));
    const int reps = 20;
    double page_emboss = 0;
    t0 = Clock::now();
    for (int i = 0; i < reps; ++i) {
        auto j = plan::plan_job(one, prof);
        if (!j) return 1;
        page_emboss = j->duration_s;
    }
    const double page_s = seconds_since(t0) / reps;
    // The same page on a planner that has tuned its moves already (as within a book).
    t0 = Clock::now();
    for (int i = 0; i < reps; ++i)
        if (!planner->plan_sheet(one, 1)) return 1;
    const double page_warm_s = seconds_since(t0) / reps;

    rusage self{};
    ::getrusage(RUSAGE_SELF, &self);
    double load_after[1] = {-1};
    if (::getloadavg(load_after, 1) < 1) load_after[0] = -1;
    std::printf("load:                 %.2f before, %.2f after (1-minute load average; %u cores)\n", load_before[0],
                load_after[0], std::thread::hardware_concurrency());
    std::printf("book:                 %s: %zu pages on %zu sheets, %zu passes, %zu strikes\n", argv[1],
                doc->pages.size(), doc->sheet_count(), passes, t.strikes);
    std::printf("layout:               %.3f s (best of %d, alternating with the plan)\n", layout_s, rounds);
    std::printf("plan + estimate:      %.3f s = %.0f pages/s, one thread (best of %d)\n", plan_s[0],
                static_cast<double>(doc->pages.size()) / plan_s[0], rounds);
    std::printf("plan + estimate:      %.3f s = %.0f pages/s, SheetQueue on %u threads (best of %d)\n", plan_s[1],
                static_cast<double>(doc->pages.size()) / plan_s[1], threads, rounds);
    std::printf("same plan:            %s (digest %016llx, %016llx)\n", digest[0] == digest[1] ? "yes" : "NO",
                static_cast<unsigned long long>(digest[0]), static_cast<unsigned long long>(digest[1]));
    std::printf("ratio plan/layout:    %.3f with the queue, %.3f on one thread (goal <= 1.0)\n", plan_s[1] / layout_s,
                plan_s[0] / layout_s);
    // CPU time is steadier on a shared machine; the layout's includes its
    // translation workers (processes, run in parallel: its wall time is less).
    std::printf("cpu layout, plan:     %.3f s; %.3f s with the queue, %.3f s on one thread (best of %d)\n",
                layout_cpu, plan_cpu[1], plan_cpu[0], rounds);
    std::printf("cpu plan/layout:      %.3f with the queue, %.3f on one thread\n", plan_cpu[1] / layout_cpu,
                plan_cpu[0] / layout_cpu);
    std::printf("one page (cold):      %.2f ms = %.0f pages/s; embosses in %.1f s\n", page_s * 1e3,
                1.0 / page_s, page_emboss);
    std::printf("one page (warm):      %.3f ms = %.0f pages/s\n", page_warm_s * 1e3, 1.0 / page_warm_s);
    std::printf("embossing time:       %.0f s = %.1f h (%.1f s per sheet)\n", t.duration_s,
                t.duration_s / 3600, t.duration_s / static_cast<double>(doc->sheet_count()));
    std::printf("lower bound:          %.0f s = %.1f h\n", t.lower_bound_s, t.lower_bound_s / 3600);
    std::printf("ratio plan/bound:     %.3f (goal <= 1.10)\n", t.duration_s / t.lower_bound_s);
    std::printf("naive plan:           %.0f s = %.1f h (computed in %.2f s)\n", *naive, *naive / 3600, naive_s);
    std::printf("speed-up vs naive:    %.2fx\n", *naive / t.duration_s);
    std::printf("residual at strikes:  %.2f um nominal, %.2f um worst case (tolerance %.0f um)\n",
                t.max_residual_um, t.max_worst_residual_um, prof.vibration.tolerance_um);
    std::printf("step schedule:        %zu segments = %.1f MB; largest pass %zu bytes\n", t.segments,
                static_cast<double>(t.segments) * 6 / 1048576.0, max_pass_bytes);
    std::printf("distinct moves tuned: %zu\n", planner->tuner().decisions().size());
    std::printf("peak memory:          %.1f MB\n", static_cast<double>(self.ru_maxrss) / 1024.0);
    return 0;
}
