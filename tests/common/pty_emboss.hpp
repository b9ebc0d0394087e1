// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// End to end through tactus-cli over a real pseudo-terminal: a `sim` process
// (the C++ controller, `sim --pty`, or the firmware in s51, `sim --firmware
// --pty`) prints its /dev/pts/N, `tactus-cli emboss --device pty:...`
// embosses through it, and the strike log the sim wrote is read back. One
// helper for tests/link/emboss_pty_e2e_test.cpp and
// firmware_emulator_e2e_test.cpp, and the plan
// the CLI makes for a document with the firmware's tables.
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "controller/sim_controller.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/planner.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/page_geometry.hpp"
#include "profile/profile.hpp"
#include "process.hpp"
#include "strike_log.hpp"

namespace tactus::test {

// The plan tactus-cli makes for `document` with the firmware tables at
// `tables_json` (a firmware build's ramp.json): the same library calls.
inline plan::JobPlan plan_with_firmware_tables(const std::string& document, const std::string& tables_json) {
    const auto prof = profile::default_profile();
    pipeline::PipelineOptions o;
    o.layout.geometry = profile::page_geometry(prof);
    auto doc = pipeline::lay_out_file(document, o);
    EXPECT_TRUE(doc) << doc.error().to_string();
    if (!doc) return {};
    plan::PlanOptions po;
    auto tables = profile::load_firmware_tables(tables_json);
    EXPECT_TRUE(tables) << tables.error().to_string();
    if (!tables) return {};
    po.firmware = *tables;
    auto job = plan::plan_job(*doc, prof, po);
    EXPECT_TRUE(job) << job.error().to_string();
    return job ? *job : plan::JobPlan{};
}

struct PtyRun {
    int exit_code = -1;
    std::string output;  // the emboss command's
    std::vector<controller::LoggedStrike> log;
};

struct PtyEmboss {
    std::vector<std::string> sim;     // the sim command, without --strike-log
    std::vector<std::string> emboss;  // the emboss command, without --device
    std::string baud = "9600";
    std::filesystem::path strike_log;
    std::string sim_stderr;       // a file for the sim's stderr (empty: inherited)
    bool merge_output = true;     // the emboss command's stderr with its stdout
};

// Starts the sim, embosses through the pty it prints, stops the sim (SIGTERM)
// and reads what it logged.
inline PtyRun emboss_through_pty(const PtyEmboss& e) {
    auto sim = e.sim;
    // The sim appends to its log: each run reads only its own strikes.
    std::filesystem::remove(e.strike_log);
    sim.insert(sim.end(), {"--strike-log", e.strike_log.string()});
    Process server(sim, e.sim_stderr);
    const std::string pty = server.read_line(std::chrono::seconds(30));
    EXPECT_EQ(pty.rfind("/dev/pts/", 0), 0U) << pty;
    auto emboss = e.emboss;
    emboss.insert(emboss.end(), {"--device", "pty:" + pty + "?baud=" + e.baud});
    Process client(emboss, Process::Options{{}, e.merge_output, {}});
    PtyRun r;
    r.output = client.read_all();
    r.exit_code = client.wait();
    server.signal(SIGTERM);
    server.wait();
    r.log = read_strike_log(e.strike_log.string());
    return r;
}

}  // namespace tactus::test
