// SPDX-License-Identifier: GPL-3.0-or-later
// Link speed against the firmware's own link code: the host's
// real link sending a planned sheet to the reference firmware's C compiled
// natively (tests/firmware/native_firmware.hpp), on a clean line at several
// baud rates, in virtual time. Per rate: the job's time against the plan's,
// and every time the executor waited for data after the first strike (the
// bar: never at 2400 baud on a typical page); and the link's efficiency with
// motion taking no time (what the firmware's ring and window let through of
// the line: DATA payload bytes over the line's capacity while DATA flowed).
//
//   bench_link_native [--max-payload N] [FILE...]   (default: resources/samples/welcome.md, sheet 1)
//
// --max-payload N: DATA payloads of at most N bytes (the firmware's is 33),
// so that two frames fit the ring and the host need not wait for each ACK.
#include <cstdio>
#include <string>
#include <vector>

#include "native_firmware.hpp"
#include "controller/sim_transport.hpp"
#include "link/link.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/planner.hpp"
#include "profile/controller_config.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/page_geometry.hpp"
#include "profile/profile.hpp"

using namespace tactus;

namespace {

struct Run {
    bool completed = false;
    double seconds = 0;
    std::vector<controller::SimController::Wait> waits;
    link::LinkStats stats;
    std::size_t strikes = 0;
    double first_to_last = 0;  // first to last strike
    std::size_t line_bytes = 0;  // host to controller, every byte
};

std::size_t g_max_payload = 0;

Run run(const plan::JobPlan& job, const machine::FirmwareTables& t, const machine::StrikeTiming& timing, double baud,
        bool instant) {
    test::NativeFirmwareOptions o;
    o.tables = t;
    o.baud = baud;
    o.instant_motion = instant;
    auto fw = std::make_shared<test::NativeFirmware>(o);
    controller::SimLineOptions line;
    line.baud = baud;
    auto tr = std::make_unique<controller::SimTransport>(fw, line);
    auto* raw = tr.get();
    link::LinkOptions lo;
    lo.max_payload = g_max_payload;
    auto l = link::Link::over(std::move(tr), lo);
    Run r;
    if (!l.hello() || !l.use_firmware_tables(t, timing) ||
        !l.configure(profile::controller_config(profile::default_profile())))
        return r;
    const double start = raw->now();
    link::CancelToken cancel;
    auto out = l.send_job(job, 1, {}, cancel);
    r.seconds = raw->now() - start;
    r.completed = out && out->end == link::JobEnd::completed && fw->strike_log() == controller::planned_strikes(job);
    if (out) r.stats = out->stats;
    r.strikes = fw->strike_log().size();
    r.line_bytes = raw->line_bytes_to_controller();
    if (r.strikes > 1) r.first_to_last = fw->strike_log().back().time_s - fw->strike_log().front().time_s;
    const double first = fw->strike_log().empty() ? 0 : fw->strike_log().front().time_s;
    for (const auto& w : fw->waits())
        if (w.at_s > first) r.waits.push_back(w);
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--max-payload" && i + 1 < argc)
            g_max_payload = std::stoul(argv[++i]);
        else
            files.emplace_back(argv[i]);
    }
    if (files.empty()) files.emplace_back(TACTUS_SAMPLE);
    const auto prof = profile::default_profile();
    auto tables = profile::load_firmware_tables(TACTUS_FIRMWARE_TABLES);
    if (!tables) {
        std::fprintf(stderr, "%s\n", tables.error().to_string().c_str());
        return 1;
    }
    const auto timing = profile::strike_timing(prof);
    for (const auto& f : files) {
        pipeline::PipelineOptions o;
        o.layout.geometry = profile::page_geometry(prof);
        auto doc = pipeline::lay_out_file(f, o);
        if (!doc) {
            std::fprintf(stderr, "%s\n", doc.error().to_string().c_str());
            return 1;
        }
        plan::PlanOptions po;
        po.firmware = *tables;
        auto planner = plan::Planner::create(prof, po);
        if (!planner) return 1;
        auto sheet = planner->plan_sheet(*doc, 1);
        if (!sheet) {
            std::fprintf(stderr, "%s\n", sheet.error().to_string().c_str());
            return 1;
        }
        plan::JobPlan job;
        job.sheets.push_back(*sheet);
        double plan_s = 0;
        for (const auto& p : sheet->passes) plan_s += p.duration_s;
        const auto want = controller::planned_strikes(job);
        const auto clean = run(job, *tables, timing, 57600, false);
        std::printf("%s, sheet 1: %zu strikes, plan %.3f s; first to last strike %.6f s planned, %.6f s by the firmware's C\n",
                    f.substr(f.find_last_of('/') + 1).c_str(), want.size(), plan_s,
                    want.size() > 1 ? want.back().time_s - want.front().time_s : 0.0, clean.first_to_last);
        std::printf("| Baud | Exact | Job time | vs 57,600 baud | Waits after the first strike | Waited | Link efficiency (motion in no time) |\n");
        std::printf("|---|---|---|---|---|---|---|\n");
        const double fast = clean.seconds;
        std::printf("line bytes to the controller: %zu, %.2f a strike (the session's frames included)\n",
                    clean.line_bytes, static_cast<double>(clean.line_bytes) / static_cast<double>(want.size()));
        for (const double baud : {600.0, 1200.0, 2400.0, 4800.0, 9600.0, 57600.0}) {
            const auto r = run(job, *tables, timing, baud, false);
            const auto e = run(job, *tables, timing, baud, true);
            double waited = 0;
            for (const auto& w : r.waits) waited += w.seconds;
            const double eff = e.stats.data_seconds > 0
                                   ? static_cast<double>(e.stats.payload_bytes) / (baud / 10.0 * e.stats.data_seconds)
                                   : 0;
            std::printf("| %.0f | %s | %.3f s | %+.2f %% | %zu | %.3f s | %.2f |\n", baud, r.completed ? "yes" : "NO",
                        r.seconds, 100 * (r.seconds / fast - 1), r.waits.size(), waited, eff);
        }
    }
    return 0;
}
