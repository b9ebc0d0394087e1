// SPDX-License-Identifier: GPL-3.0-or-later
// Link benchmarks (docs/protocol.md, "Measured (version 2, bench/link)"):
//  1. efficiency = payload bytes / raw line capacity over the pty simulator at
//     9600..115200 baud, windowed (ours) vs stop-and-wait (Marlin-like senders);
//  2. does the controller ever wait for data when the link is faster than the
//     plan needs (in-process, motion in real simulated time);
//  3. bytes sent per sheet versus the BRF size of the same sheet.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "controller/pty_server.hpp"
#include "controller/sim_controller.hpp"
#include "encode/frame.hpp"
#include "encode/stream.hpp"
#include "link/link.hpp"
#include "test_plans.hpp"
#include "controller/sim_transport.hpp"

#include "export/export.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/planner.hpp"
#include "profile/controller_config.hpp"
#include "profile/profile_json.hpp"

using namespace tactus;

namespace {

struct Efficiency {
    double efficiency = 0;
    double seconds = 0;
    std::size_t payload = 0;
    std::size_t resent = 0;
};

Efficiency over_pty(int baud, const plan::JobPlan& plan, const link::LinkOptions& opt) {
    controller::PtyServerOptions so;
    so.baud = baud;
    so.sim.instant_motion = true;  // the link is the only limit
    auto server = controller::PtyServer::open(so);
    if (!server) {
        std::fprintf(stderr, "%s\n", server.error().to_string().c_str());
        std::exit(1);
    }
    std::atomic<bool> stop{false};
    std::thread t([&] { (void)server->serve(stop, {}); });
    Efficiency e;
    auto link = link::Link::open("pty:" + server->path() + "?baud=" + std::to_string(baud), opt);
    if (link && link->hello()) {
        link::CancelToken cancel;
        auto out = link->send_job(plan, 1, {}, cancel);
        if (out && out->end == link::JobEnd::completed) {
            e.seconds = out->stats.data_seconds;
            e.payload = out->stats.payload_bytes;
            e.resent = out->stats.frames_resent;
            e.efficiency = static_cast<double>(e.payload) / (e.seconds * baud / 10.0);
        } else {
            std::fprintf(stderr, "job failed at %d baud\n", baud);
        }
    }
    stop = true;
    t.join();
    return e;
}

struct Starvation {
    double starved_s = 0;
    std::size_t waits = 0;
    double longest_wait_s = 0;
    std::size_t underruns = 0;
    double job_s = 0;
};

// Motion in simulated real time; the link at `baud`. Waiting before the first
// op and after the last is not starvation; waiting in between is.
Starvation starvation(int baud, const plan::JobPlan& plan, const machine::ControllerConfig& cfg) {
    auto ctl = std::make_shared<controller::SimController>();
    controller::SimLineOptions line;
    line.baud = baud;
    auto tr = std::make_unique<controller::SimTransport>(ctl, line);
    auto* raw = tr.get();
    auto link = link::Link::over(std::move(tr));
    (void)link.hello();
    (void)link.configure(cfg);
    link::CancelToken cancel;
    const double t0 = raw->now();
    auto out = link.send_job(plan, 1, {}, cancel);
    Starvation s;
    s.job_s = raw->now() - t0;
    s.starved_s = ctl->starved_seconds();
    s.underruns = ctl->status().underruns;
    s.waits = ctl->waits().size();
    for (const auto& w : ctl->waits()) s.longest_wait_s = std::max(s.longest_wait_s, w.seconds);
    if (!out || out->end != link::JobEnd::completed) std::fprintf(stderr, "starvation run failed at %d baud\n", baud);
    return s;
}

// The lowest line rate from which the controller never waits: rates are tried
// from 460800 baud down in steps of 4 %, and the answer is the last one before
// the first that waits (waiting is not strictly monotonic in the rate: the
// phase of ACKs against moves shifts, so a bisection could land in a gap).
int no_wait_baud(const plan::JobPlan& plan, const machine::ControllerConfig& cfg) {
    int last_clean = -1;
    for (double baud = 460800; baud >= 1200; baud *= 0.96) {
        if (starvation(static_cast<int>(baud), plan, cfg).waits > 0) break;
        last_clean = static_cast<int>(baud);
    }
    return last_clean;
}

}  // namespace

int main() {
    std::printf("Tactus link benchmark (frame payload <= %zu B, ring %zu B, window %zu frames)\n\n",
                encode::kMaxPayload, machine::ram::kRingBytes, machine::ram::kWindowFrames);

    std::printf("1. Link efficiency over the pty simulator (payload / raw line capacity, 8N1)\n");
    std::printf("   %-8s %-10s %-10s %-10s %-12s %s\n", "baud", "windowed", "stop-wait", "ratio", "payload B", "seconds");
    for (const int baud : {9600, 19200, 57600, 115200}) {
        // About three seconds of line time per run.
        const auto passes = static_cast<std::size_t>(std::max(4, baud / 10 * 3 / 260));
        const auto plan = test::make_plan(1, passes, 24, 5);
        const auto ours = over_pty(baud, plan, {});
        link::LinkOptions marlin;
        marlin.max_window_frames = 1;  // one line in flight, wait for "ok"
        marlin.max_payload = 32;       // a G-code line's worth
        const auto sw = over_pty(baud, plan, marlin);
        std::printf("   %-8d %-10.3f %-10.3f %-10.2f %-12zu %.2f\n", baud, ours.efficiency, sw.efficiency,
                    sw.efficiency > 0 ? ours.efficiency / sw.efficiency : 0.0, ours.payload, ours.seconds);
    }

    plan::JobPlan sheet_plan = test::make_plan(1, 144, 54, 8);  // 24 lines x 3 rows x 2 sides
    machine::ControllerConfig cfg;
    std::size_t brf_bytes = 2 * 24 * (27 + 2) + 2;  // two full pages, CR LF per line, form feeds
    const char* source = "synthetic full sheet (144 dot rows, up to 54 dots each)";
    double step_tolerance = 0;
    {
        auto profile = profile::default_profile();
        if (const char* f = std::getenv("TACTUS_STEP_TOLERANCE")) profile.motion.step_tolerance = std::atof(f);
        pipeline::PipelineOptions po;
        po.layout.geometry.interpoint = true;
        auto doc = pipeline::lay_out_file(TACTUS_SAMPLE, po);
        if (doc) {
            auto p = plan::plan_job(*doc, profile);
            if (p && !p->sheets.empty()) {
                sheet_plan = *p;
                step_tolerance = profile.motion.step_tolerance;
                sheet_plan.sheets.resize(1);
                source = "welcome.md sheet 1, planned with the default profile";
                cfg = profile::controller_config(profile);
                double d = 0;
                for (const auto& pass : sheet_plan.sheets[0].passes) d += pass.duration_s;
                sheet_plan.duration_s = d;
                if (auto brf = exporter::to_brf(*doc)) brf_bytes = brf->size() / std::max<std::size_t>(1, doc->sheet_count());
            }
        }
    }
    const auto stream = encode::encode_job(sheet_plan, 1, {});
    double average_baud = 0;
    if (stream && sheet_plan.duration_s > 0) {
        const auto chunks = encode::chunk_stream(*stream, encode::kMaxPayload);
        const std::size_t line = stream->bytes.size() + chunks.size() * encode::kFrameOverhead;
        average_baud = static_cast<double>(line) * 10.0 / sheet_plan.duration_s;
    }
    const int needed = no_wait_baud(sheet_plan, cfg);
    std::printf("\n2. Does the controller wait for data? (%s; plan %.1f s)\n", source, sheet_plan.duration_s);
    std::size_t moves = 0, segments = 0;
    for (const auto& pass : sheet_plan.sheets[0].passes)
        for (const auto& m : pass.moves)
            if (m.steps != 0) ++moves, segments += m.segments.size();
    std::printf("   step timing tolerance %.2f of a step interval: %.1f segments per carriage move\n",
                step_tolerance, moves ? static_cast<double>(segments) / static_cast<double>(moves) : 0.0);
    std::printf("   the plan's average line rate %.0f baud; lowest rate from which the controller never waits\n"
                "   (160-byte ring, whole moves buffered before they start): %d baud\n",
                average_baud, needed);
    std::printf("   %-8s %-10s %-8s %-12s %-10s %-8s %s\n", "baud", "starved s", "waits", "longest ms", "underruns",
                "job s", "link faster than needed?");
    bool goal = true;
    for (const int baud : {9600, 19200, 38400, 57600, 115200}) {
        const auto s = starvation(baud, sheet_plan, cfg);
        const bool faster = needed > 0 && baud >= needed;
        if (faster && s.waits > 0) goal = false;
        std::printf("   %-8d %-10.4f %-8zu %-12.1f %-10zu %-8.1f %s\n", baud, s.starved_s, s.waits,
                    s.longest_wait_s * 1000, s.underruns, s.job_s, faster ? "yes" : "no");
    }
    std::printf("   goal (never waits while the link is faster than the plan needs): %s\n", goal ? "met" : "NOT met");

    std::size_t strikes = 0;
    for (const auto& p : sheet_plan.sheets[0].passes) strikes += p.strikes.size();
    if (stream) {
        const auto chunks = encode::chunk_stream(*stream, encode::kMaxPayload);
        const std::size_t line = stream->bytes.size() + chunks.size() * encode::kFrameOverhead;
        std::printf("\n3. Bytes per sheet (%s, %zu strikes)\n", source, strikes);
        std::printf("   job stream %zu B, on the line %zu B (%zu frames), BRF of the same sheet %zu B: %.1fx\n",
                    stream->bytes.size(), line, chunks.size(), brf_bytes,
                    static_cast<double>(line) / static_cast<double>(brf_bytes));
        std::printf("   %.1f line bytes per strike\n", static_cast<double>(line) / static_cast<double>(strikes));
    }
    return 0;
}
