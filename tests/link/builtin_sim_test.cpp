// SPDX-License-Identifier: GPL-3.0-or-later
// The app's built-in simulator (controller::BuiltInSimulator) through the link:
// one controller for many connections, so its job count survives a dropped
// connection as on the real machine; every logged strike names the controller
// job it belongs to; and the technician's faults reach the line and the
// controller while a job streams from another thread.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <thread>

#include "../common/test_plans.hpp"
#include "controller/builtin_sim.hpp"
#include "link/link.hpp"
#include "profile/controller_config.hpp"
#include "profile/firmware_tables.hpp"

namespace tactus {
namespace {

struct Sent {
    link::JobOutcome outcome;
    std::vector<std::string> notes;
};

Sent send(link::Link& l, const plan::JobPlan& plan, std::uint16_t job_id,
          const std::function<void(std::size_t)>& on_pass = {}) {
    Sent out;
    link::CancelToken cancel;
    std::size_t passes = 0;
    auto r = l.send_job(plan, 1, [&](const link::Progress& p) {
        if (p.executed && on_pass) on_pass(++passes);
        if (!p.note.empty()) out.notes.push_back(p.note);
    }, cancel, job_id);
    EXPECT_TRUE(r) << r.error().to_string();
    if (r) out.outcome = *r;
    return out;
}

// As `sim?speed=max` connects (the plan's own speed is the printer panel's test).
link::Link connect(controller::BuiltInSimulator& sim) {
    transport::SimSettings fastest;
    fastest.speed = 0;
    auto l = link::Link::over(sim.connect(fastest));
    EXPECT_TRUE(l.hello());
    EXPECT_TRUE(l.configure({}));
    return l;
}

bool noted(const Sent& s, const std::string& what) {
    for (const auto& n : s.notes)
        if (n.find(what) != std::string::npos) return true;
    return false;
}

TEST(BuiltInSimulator, TheControllerOutlivesAConnectionAndEveryStrikeNamesItsJob) {
    controller::BuiltInSimulator sim;
    const auto plan = test::make_plan(2, 3, 4);
    {
        auto first = connect(sim);
        EXPECT_EQ(send(first, plan, 0x8001).outcome.end, link::JobEnd::completed);
    }
    const auto planned = controller::planned_strikes(plan);
    auto strikes = sim.strikes();
    ASSERT_EQ(strikes.size(), planned.size());
    for (const auto& s : strikes) EXPECT_EQ(s.job_id, 0x8001);
    EXPECT_EQ(strikes, planned);
    // A new connection meets the same controller: it still reports the last job.
    auto second = connect(sim);
    auto st = second.status();
    ASSERT_TRUE(st);
    EXPECT_EQ(st->ack.job_id, 0x8001);
    EXPECT_EQ(send(second, plan, 0x8002).outcome.end, link::JobEnd::completed);
    strikes = sim.strikes();
    ASSERT_EQ(strikes.size(), 2 * planned.size());
    for (std::size_t i = planned.size(); i < strikes.size(); ++i) EXPECT_EQ(strikes[i].job_id, 0x8002);
}

// Each fault is injected from another thread while the job streams, as the
// printer panel's buttons do while the app's runner embosses (joined before
// the stream goes on, so where it lands is the same on every run).
TEST(BuiltInSimulator, FaultsFromAnotherThreadReachTheRunningJob) {
    controller::BuiltInSimulator sim;
    const auto plan = test::make_plan(6, 4, 6);
    struct Case {
        const char* name;
        std::function<void()> inject;
        const char* note;  // what the link says about it (empty: only its statistics)
    };
    const std::vector<Case> cases{
        {"paper out", [&] { sim.paper_out(); }, "paper out"},
        {"controller reset", [&] { sim.reset_controller(); }, "controller restarted"},
        {"pulled cable", [&] { sim.pull_cable(5); }, "reconnected"},
        {"noise", [&] { sim.noise(60, 0.02); }, ""},
    };
    std::uint16_t id = 0x8100;
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        auto l = connect(sim);
        const auto before = sim.strikes().size();
        bool injected = false;
        const auto sent = send(l, plan, ++id, [&](std::size_t passes) {
            if (passes != 3 || injected) return;
            // From another thread, finished before the stream goes on: the
            // fault lands at the line's next moment, wherever the job is then.
            std::thread technician(c.inject);
            technician.join();
            injected = true;
        });
        EXPECT_TRUE(injected);
        EXPECT_EQ(sent.outcome.end, link::JobEnd::completed) << sent.outcome.error.to_string();
        if (*c.note) EXPECT_TRUE(noted(sent, c.note));
        else EXPECT_GT(sent.outcome.stats.frames_resent + sent.outcome.stats.crc_errors + sent.outcome.stats.naks, 0u);
        // Ridden through: every planned dot struck once, under this job's id.
        const auto all = sim.strikes();
        std::vector<controller::LoggedStrike> got(all.begin() + static_cast<std::ptrdiff_t>(before), all.end());
        for (const auto& s : got) EXPECT_EQ(s.job_id, id);
        EXPECT_EQ(got, controller::planned_strikes(plan));
    }
}

// The app makes its simulator with the tables of its profile, and a printer
// connects it with its own profile's (printer_panel.cpp): protocol 3, as the
// firmware built from that profile speaks it, with that table id; protocol 2
// only on request (sim?protocol=2), which reflashes it.
TEST(BuiltInSimulator, SpeaksProtocol3WithThePrintersTablesAndProtocol2OnlyOnRequest) {
    const auto tables = profile::make_firmware_tables(profile::default_profile());
    ASSERT_TRUE(tables.has_value());
    auto options = controller::BuiltInSimulator::default_options();
    options.firmware = *tables;
    controller::BuiltInSimulator sim(options);
    EXPECT_EQ(sim.protocol(), 3);
    transport::SimSettings fastest;
    fastest.speed = 0;
    {
        auto stream = sim.connect(fastest, *tables);
        ASSERT_TRUE(stream.has_value()) << stream.error().to_string();
        auto l = link::Link::over(std::move(*stream));
        const auto h = l.hello();
        ASSERT_TRUE(h.has_value()) << h.error().to_string();
        EXPECT_EQ(h->protocol, 3);
        EXPECT_EQ(h->table_id, tables->table_id);
    }
    auto v2 = fastest;
    v2.protocol = 2;
    {
        auto stream = sim.connect(v2, *tables);
        ASSERT_TRUE(stream.has_value());
        auto l = link::Link::over(std::move(*stream));
        const auto h = l.hello();
        ASSERT_TRUE(h.has_value()) << h.error().to_string();
        EXPECT_EQ(h->protocol, 2);
        EXPECT_EQ(sim.protocol(), 2);
    }
    // Protocol 3 without tables (a profile the firmware cannot run): refused.
    auto v3 = fastest;
    v3.protocol = 3;
    const auto refused = sim.connect(v3, std::nullopt);
    ASSERT_FALSE(refused.has_value());
    EXPECT_EQ(refused.error().kind, ErrorKind::usage);
    EXPECT_EQ(refused.error().where, "sim option protocol");
}

// The app's simulator speaking protocol 3 under its noise injection (the
// printer panel's Noise button, and a noisy `sim?noise=` line): every job
// either completes with exactly the planned strikes, or fails cleanly, having
// struck a prefix of them and nothing else. Never a wrong or a missing dot in
// a completed job.
TEST(BuiltInSimulator, UnderNoiseAProtocol3JobCompletesExactlyOrFailsCleanly) {
    const auto prof = profile::default_profile();
    const auto tables = profile::make_firmware_tables(prof);
    ASSERT_TRUE(tables.has_value());
    const auto timing = profile::strike_timing(prof);
    auto options = controller::BuiltInSimulator::default_options();
    options.firmware = *tables;
    controller::BuiltInSimulator sim(options);
    std::size_t completed = 0, failed = 0;
    std::uint16_t id = 0x9000;
    for (unsigned seed = 1; seed <= 12; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        transport::SimSettings noisy;
        noisy.speed = 0;
        noisy.baud = 57600;
        noisy.noise = 2e-2;  // per byte: lost, flipped and doubled, each
        noisy.seed = seed;
        auto stream = sim.connect(noisy, *tables);
        ASSERT_TRUE(stream.has_value());
        link::LinkOptions lo;
        lo.give_up_after = std::chrono::seconds(20);
        auto l = link::Link::over(std::move(*stream), lo);
        if (!l.hello() || !l.use_firmware_tables(*tables, timing) ||
            !l.configure(profile::controller_config(prof))) {
            ++failed;  // not even a session: nothing sent, nothing struck
            continue;
        }
        const auto plan = test::make_firmware_plan(*tables, timing, 2, 4, 8, seed);
        const auto planned = controller::planned_strikes(plan);
        const auto before = sim.strikes().size();
        bool injected = false;
        link::CancelToken cancel;
        auto out = l.send_job(plan, 1, [&](const link::Progress& p) {
            // A burst on top, from the technician's thread, as the Noise button.
            if (p.executed && p.executed->passes_done == 2 && !injected) {
                std::thread technician([&] { sim.noise(1, 5e-2); });
                technician.join();
                injected = true;
            }
        }, cancel, ++id);
        ASSERT_TRUE(out.has_value()) << out.error().to_string();
        const auto all = sim.strikes();
        std::vector<controller::LoggedStrike> got(all.begin() + static_cast<std::ptrdiff_t>(before), all.end());
        for (const auto& s : got) EXPECT_EQ(s.job_id, id);
        if (out->end == link::JobEnd::completed) {
            ++completed;
            EXPECT_EQ(got, planned);
        } else {
            ++failed;
            EXPECT_FALSE(out->error.message.empty());
            ASSERT_LE(got.size(), planned.size());
            EXPECT_TRUE(std::equal(got.begin(), got.end(), planned.begin())) << "a wrong strike in a failed job";
        }
    }
    std::printf("built-in simulator, protocol 3, 2e-2 noise: %zu completed, %zu failed cleanly\n", completed, failed);
    EXPECT_GT(completed, 0U);
}

}  // namespace
}  // namespace tactus
