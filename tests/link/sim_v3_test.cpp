// SPDX-License-Identifier: GPL-3.0-or-later
// The C++ simulated controller speaking protocol 3 (SimOptions::firmware),
// driven by the host's link in virtual time: the strikes it fires are the
// plan's, at the plan's times (the firmware's timer schedule), and the fault
// and restart cases the firmware has end exactly too: a warm reset in the
// middle of a pass resumes at the exact strike, paper out waits for paper, a
// limit switch restarts from the reported progress, power loss and a hammer
// fault fail with the sheet to resume from.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "controller/sim_controller.hpp"
#include "controller/sim_transport.hpp"
#include "encode/frame.hpp"
#include "encode/stream_v3.hpp"
#include "link/link.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/planner.hpp"
#include "profile/controller_config.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/page_geometry.hpp"
#include "profile/profile.hpp"
#include "../common/test_plans.hpp"
#include "../common/firmware_tables_fixture.hpp"

namespace tactus {
namespace {

const machine::FirmwareTables& tables() { return test::firmware_tables(); }
machine::StrikeTiming timing() { return profile::strike_timing(profile::default_profile()); }

struct Run {
    std::shared_ptr<controller::SimController> ctl;
    controller::SimTransport* line = nullptr;
    std::optional<link::Link> link;
};

Run open(double baud = 57600) {
    Run r;
    controller::SimOptions o;
    o.firmware = tables();
    r.ctl = std::make_shared<controller::SimController>(o);
    controller::SimLineOptions line;
    line.baud = baud;
    auto t = std::make_unique<controller::SimTransport>(r.ctl, line);
    r.line = t.get();
    r.link.emplace(link::Link::over(std::move(t)));
    auto h = r.link->hello();
    EXPECT_TRUE(h) << h.error().to_string();
    EXPECT_EQ(r.link->protocol(), encode::kProtocolV3);
    EXPECT_EQ(h->table_id, tables().table_id);
    EXPECT_TRUE(r.link->use_firmware_tables(tables(), timing()));
    EXPECT_TRUE(r.link->configure(profile::controller_config(profile::default_profile())));
    return r;
}

link::JobOutcome send(Run& r, const plan::JobPlan& plan) {
    link::CancelToken cancel;
    auto out = r.link->send_job(plan, 1, {}, cancel);
    EXPECT_TRUE(out) << out.error().to_string();
    return out ? *out : link::JobOutcome{};
}

plan::JobPlan hand_plan(unsigned seed = 3) { return test::make_firmware_plan(tables(), timing(), 2, 4, 12, seed); }

TEST(SimV3, OnlyProtocol3IsSpoken) {
    controller::SimOptions o;
    o.firmware = tables();
    controller::SimController c(o);
    EXPECT_EQ(c.protocol(), 3);
    // HELLO for protocol 2: refused, as the firmware refuses it.
    std::vector<std::uint8_t> f;
    encode::append_frame(f, 0, encode::FrameType::hello, encode::encode_hello({0x1111, 2}));
    c.receive(f, 0);
    encode::FrameDecoder d;
    std::vector<encode::Frame> frames;
    d.push(c.take_output(), frames);
    ASSERT_EQ(frames.size(), 1U);
    EXPECT_EQ(frames[0].type, 0x83);
    EXPECT_EQ(frames[0].payload[0], static_cast<std::uint8_t>(encode::NakReason::bad_payload));
}

// A planned document: the strikes are the plan's, and each comes at the
// plan's time plus one constant (the plan counts from its own start), to
// well under a timer tick.
TEST(SimV3, APlannedDocumentStrikesThePlanAtThePlansTimes) {
    const auto prof = profile::default_profile();
    pipeline::PipelineOptions o;
    o.layout.geometry = profile::page_geometry(prof);
    auto doc = pipeline::lay_out_file(std::string(TACTUS_RESOURCES_DIR) + "/samples/firmware-note.md", o);
    ASSERT_TRUE(doc) << doc.error().to_string();
    plan::PlanOptions po;
    po.firmware = tables();
    auto job = plan::plan_job(*doc, prof, po);
    ASSERT_TRUE(job) << job.error().to_string();
    auto r = open(115200);
    const auto out = send(r, *job);
    EXPECT_EQ(out.end, link::JobEnd::completed) << out.error.message;
    const auto want = controller::planned_strikes(*job);
    const auto& got = r.ctl->strike_log();
    ASSERT_EQ(got, want);
    ASSERT_FALSE(got.empty());
    EXPECT_EQ(r.ctl->starved_seconds(), 0.0);
    const double offset = got[0].time_s - want[0].time_s;
    double worst = 0;
    for (std::size_t i = 0; i < got.size(); ++i) worst = std::max(worst, std::abs(got[i].time_s - want[i].time_s - offset));
    EXPECT_LT(worst * machine::kTickHz, 0.5) << "strike times off the plan's by up to " << worst * 1e6 << " us";
    if (std::getenv("TACTUS_V3_TIMES"))
        for (std::size_t i = 0; i < got.size(); ++i)
            std::printf("%zu pass %u: %+.6f\n", i, got[i].pass_index, got[i].time_s - want[i].time_s - offset);
}

// A page whose last line stands far below the one before (a short page and
// its number at the foot): every gap from one line to 23 is fed exactly. A
// feed of 64..127 grid units went 20 units backwards (a 71-sheet job from
// the app struck its last page number 50 mm too high).
TEST(SimV3, EveryGapBetweenTwoLinesIsFedExactly) {
    const auto prof = profile::default_profile();
    layout::PagedDocument doc;
    doc.geometry = profile::page_geometry(prof);
    const auto rows = static_cast<std::size_t>(doc.geometry.lines_per_page);
    for (std::size_t last = 1; last < rows; ++last) {
        layout::Page page;
        page.lines.resize(last + 1);
        page.lines.front() = document::BrailleLine(4, document::Cell{0x3F});
        page.lines.back() = document::BrailleLine(4, document::Cell{0x3F});
        doc.pages.push_back(std::move(page));
    }
    plan::PlanOptions po;
    po.firmware = tables();
    auto job = plan::plan_job(doc, prof, po);
    ASSERT_TRUE(job) << job.error().to_string();
    auto r = open(115200);
    const auto out = send(r, *job);
    EXPECT_EQ(out.end, link::JobEnd::completed) << out.error.message;
    EXPECT_EQ(r.ctl->strike_log(), controller::planned_strikes(*job));
}

TEST(SimV3, AHandPlanStrikesExactly) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const auto plan = hand_plan(seed);
        auto r = open();
        const auto out = send(r, plan);
        EXPECT_EQ(out.end, link::JobEnd::completed) << out.error.message;
        EXPECT_EQ(r.ctl->strike_log(), controller::planned_strikes(plan)) << "seed " << seed;
    }
}

// A warm reset just after a strike in the middle of a pass (RAM kept): the
// host homes, seeks and skips exactly the strikes made; none twice, none lost.
TEST(SimV3, AWarmResetInTheMiddleOfAPassResumesAtTheExactStrike) {
    const auto plan = hand_plan(5);
    const auto want = controller::planned_strikes(plan);
    for (std::size_t nth : {std::size_t{1}, std::size_t{4}, want.size() / 2, want.size() - 1}) {
        auto r = open();
        r.ctl->reset_at_strike(nth, true);
        const auto out = send(r, plan);
        EXPECT_EQ(out.end, link::JobEnd::completed) << out.error.message;
        EXPECT_EQ(r.ctl->resets(), 1U);
        EXPECT_EQ(r.ctl->strike_log(), want) << "reset after strike " << nth;
        EXPECT_GE(out.stats.restarts, 1U);
    }
}

// The operator's pause stops the firmware at rest between two strikes (not at
// the end of the pass, as protocol 2 does); resumed, the pass goes on with the
// next strike. For every place in the job a pause can be asked for, the job
// strikes exactly the plan.
TEST(SimV3, PauseAndResumeByTheOperatorStrikesExactly) {
    const auto plan = hand_plan(5);
    for (std::size_t at = 1; at < 8; ++at) {
        auto r = open();
        link::CancelToken cancel;
        bool paused = false;
        auto out = r.link->send_job(
            plan, 1,
            [&](const link::Progress& p) {
                if (p.executed && p.executed->passes_done == at) r.link->request_pause();
                if (p.status.ack.state == encode::ControllerState::paused && !paused) {
                    paused = true;
                    r.link->request_resume();
                }
            },
            cancel);
        ASSERT_TRUE(out) << out.error().to_string();
        EXPECT_EQ(out->end, link::JobEnd::completed);
        EXPECT_TRUE(paused) << "pause after pass " << at;
        EXPECT_EQ(r.ctl->strike_log(), controller::planned_strikes(plan)) << "pause after pass " << at;
    }
}

// The host dies with the ACK of a pass on the wire (mute_after_pass: every
// reply is lost until a new session): a new host's HELLO opens a session, as
// on protocol 2, and the job's progress is read back.
TEST(SimV3, AHostThatDiedMidJobIsFollowedByANewSession) {
    const auto plan = hand_plan(7);
    auto r = open();
    r.ctl->mute_after_pass(3);
    link::CancelToken cancel;
    auto out = r.link->send_job(plan, 1, {}, cancel);
    EXPECT_TRUE(!out || out->end != link::JobEnd::completed);
    EXPECT_TRUE(r.ctl->muted());
    // A new host on the same controller.
    auto line = std::make_unique<controller::SimTransport>(r.ctl, controller::SimLineOptions{});
    line->sleep(std::chrono::seconds(5));
    auto next = link::Link::over(std::move(line));
    auto h = next.hello();
    ASSERT_TRUE(h) << h.error().to_string();
    EXPECT_EQ(next.protocol(), encode::kProtocolV3);
    EXPECT_FALSE(r.ctl->muted());
}

TEST(SimV3, PowerLossFailsWithTheSheetToResumeFrom) {
    const auto plan = hand_plan(6);
    const auto want = controller::planned_strikes(plan);
    auto r = open();
    r.ctl->reset_at_strike(want.size() - 2, false);
    const auto out = send(r, plan);
    EXPECT_EQ(out.end, link::JobEnd::failed);
    EXPECT_NE(out.error.message.find("lost power"), std::string::npos) << out.error.message;
    EXPECT_EQ(out.resume_sheet, want[want.size() - 3].sheet);
}

TEST(SimV3, PaperOutWaitsForPaperAndStrikesExactly) {
    const auto plan = hand_plan(7);
    auto r = open();
    r.ctl->inject_paper_out_at_sheet(2);
    r.ctl->set_paper_reload(5.0);
    const auto out = send(r, plan);
    EXPECT_EQ(out.end, link::JobEnd::completed) << out.error.message;
    EXPECT_EQ(r.ctl->strike_log(), controller::planned_strikes(plan));
}

TEST(SimV3, ALimitSwitchRestartsFromTheReportedProgress) {
    const auto plan = hand_plan(8);
    auto r = open();
    r.ctl->inject_limit_switch_at_strike(9);
    const auto out = send(r, plan);
    EXPECT_EQ(out.end, link::JobEnd::completed) << out.error.message;
    EXPECT_EQ(r.ctl->strike_log(), controller::planned_strikes(plan));
}

TEST(SimV3, AHammerFaultFailsTheJob) {
    const auto plan = hand_plan(9);
    auto r = open();
    r.ctl->inject_hammer_fault_at_strike(3);
    const auto out = send(r, plan);
    EXPECT_EQ(out.end, link::JobEnd::failed);
    EXPECT_NE(out.error.message.find("hammer fault"), std::string::npos) << out.error.message;
    // The firmware finds the hammer stuck after it fired: the third strike was made.
    const auto want = controller::planned_strikes(plan);
    ASSERT_EQ(r.ctl->strike_log().size(), 3U);
    EXPECT_TRUE(std::equal(r.ctl->strike_log().begin(), r.ctl->strike_log().end(), want.begin()));
}

// Garbage that passes both checks: random frames of every type, with good
// CRCs and DATA checks and random ops, near the expected sequence number,
// with time running between them. The controller never takes more than its
// ring, never executes past what it checked, and keeps answering.
TEST(SimV3, RandomValidFramesNeverBreakTheController) {
    std::mt19937 rng(12);
    for (int run = 0; run < 40; ++run) {
        controller::SimOptions o;
        o.firmware = tables();
        controller::SimController c(o);
        double now = 0;
        std::uint8_t seq = 0;
        std::size_t replies = 0;
        encode::FrameDecoder d;
        for (int i = 0; i < 400; ++i) {
            std::vector<std::uint8_t> payload;
            auto type = static_cast<std::uint8_t>(1 + rng() % 9);
            if (i == 0) type = 1;
            if (type == 1) {
                payload = encode::encode_hello({static_cast<std::uint16_t>(rng() % 3), 3});
            } else if (type == 2) {
                machine::ControllerConfig cfg;
                cfg.carriage_travel_steps = static_cast<std::int32_t>(rng() % 4000);
                payload = encode::encode_config_v3(cfg, static_cast<std::uint16_t>(rng() % 4000));
            } else if (type == 3) {
                // Ops from the v3 alphabet and random bytes.
                static constexpr std::uint8_t kOps[] = {0x10, 0x11, 0x12, 0x13, 0x14, 0x40, 0x42, 0x43};
                std::vector<std::uint8_t> ops(1 + rng() % controller::v3::kMaxOps);
                for (auto& b : ops) b = rng() % 2 ? kOps[rng() % 8] : static_cast<std::uint8_t>(rng());
                payload = encode::data_payload_v3(ops);
            }
            std::vector<std::uint8_t> f;
            const auto s = rng() % 4 == 0 ? static_cast<std::uint8_t>(rng()) : seq;
            encode::append_frame(f, s, static_cast<encode::FrameType>(type), payload);
            c.receive(f, now);
            now += static_cast<double>(rng() % 200) / 1000.0;
            c.advance(now);
            ASSERT_LE(c.ring_used(), controller::v3::kRingBytes);
            std::vector<encode::Frame> frames;
            d.push(c.take_output(), frames);
            replies += frames.size();
            for (const auto& fr : frames) seq = fr.seq;  // the next it expects
        }
        EXPECT_GT(replies, 100U);
        // Still a controller: a new session is answered with its table id.
        std::vector<std::uint8_t> f;
        encode::append_frame(f, 7, encode::FrameType::hello, encode::encode_hello({0x7777, 3}));
        c.receive(f, now + 1);
        std::vector<encode::Frame> frames;
        d.push(c.take_output(), frames);
        ASSERT_FALSE(frames.empty());
        EXPECT_EQ(frames.back().type, 0x81);
    }
}

}  // namespace
}  // namespace tactus
