// SPDX-License-Identifier: GPL-3.0-or-later
// Line bytes per strike of protocol v3 (the reference firmware's), every byte
// of every DATA frame counted (header, CRC, the 2-byte DATA check), against
// protocol v2 on the same sheet; and the plan's sheet time with the
// firmware's table moves. The bar: at most 2 bytes per strike, so a 2400-baud
// line keeps up with the hammer.
//
//   bench_v3_stream [FILE...]      (default: resources/samples/welcome.md)
//   bench_v3_stream --tables firmware/build/ramp.json FILE...
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "encode/frame.hpp"
#include "encode/stream.hpp"
#include "encode/stream_v3.hpp"
#include "machine/reference_firmware.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/planner.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/page_geometry.hpp"
#include "profile/profile.hpp"

using namespace tactus;

namespace {

namespace fw = machine::reference_firmware;  // its DATA payload: kMaxOps of ops and the check

std::size_t v3_line_bytes(const plan::JobPlan& job, const machine::FirmwareTables& t, const machine::StrikeTiming& st) {
    auto s = encode::encode_job_v3(job, t, st, 1, {});
    if (!s) {
        std::fprintf(stderr, "v3: %s\n", s.error().to_string().c_str());
        std::exit(1);
    }
    std::size_t n = 0;
    for (const auto& [b, e] : encode::chunk_stream_v3(*s, fw::kMaxOps)) n += e - b + fw::kDataCheckBytes + encode::kFrameOverhead;
    return n;
}

std::size_t v2_line_bytes(const plan::JobPlan& job) {
    auto s = encode::encode_job(job, 1, {});
    if (!s) {
        std::fprintf(stderr, "v2: %s\n", s.error().to_string().c_str());
        std::exit(1);
    }
    std::size_t n = 0;
    for (const auto& [b, e] : encode::chunk_stream(*s, encode::kMaxPayload)) n += e - b + encode::kFrameOverhead;
    return n;
}

}  // namespace

int main(int argc, char** argv) {
    std::string tables_path = TACTUS_FIRMWARE_TABLES;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--tables") == 0 && i + 1 < argc)
            tables_path = argv[++i];
        else
            files.emplace_back(argv[i]);
    }
    if (files.empty()) files.emplace_back(TACTUS_SAMPLE);
    const auto prof = profile::default_profile();
    auto tables = profile::load_firmware_tables(tables_path);
    if (!tables) {
        std::fprintf(stderr, "%s\n", tables.error().to_string().c_str());
        return 1;
    }
    const auto timing = profile::strike_timing(prof);
    std::printf("%-34s %7s %9s %9s %7s %10s %11s\n", "document, sheet 1", "strikes", "v3 bytes",
                "v3 B/dot", "v2 B/dot", "v2 / v3", "sheet time");
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
        auto v3p = plan::Planner::create(prof, po);
        auto v2p = plan::Planner::create(prof);
        if (!v3p || !v2p) return 1;
        auto s3 = v3p->plan_sheet(*doc, 1);
        auto s2 = v2p->plan_sheet(*doc, 1);
        if (!s3 || !s2) {
            std::fprintf(stderr, "plan failed\n");
            return 1;
        }
        plan::JobPlan j3, j2;
        j3.sheets.push_back(*s3);
        j2.sheets.push_back(*s2);
        const auto strikes = v3p->totals().strikes;
        const auto b3 = v3_line_bytes(j3, *tables, timing);
        const auto b2 = v2_line_bytes(j2);
        const auto name = f.substr(f.find_last_of('/') + 1);
        std::printf("%-34s %7zu %9zu %9.2f %7.2f %10.1f %9.1f s\n", name.c_str(), strikes, b3,
                    static_cast<double>(b3) / static_cast<double>(strikes),
                    static_cast<double>(b2) / static_cast<double>(strikes), static_cast<double>(b2) / static_cast<double>(b3),
                    s3->duration_s);
    }
    return 0;
}
