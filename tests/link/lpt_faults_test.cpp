// SPDX-License-Identifier: GPL-3.0-or-later
// Faults behind the parallel port, as over a serial line (link_test.cpp): a
// fault shown on nFault, paper out on PError, the cable pulled mid-job, a
// warm reset of the controller mid-pass. The C++ controller speaking protocol
// 3 with the reference firmware's tables runs in-process on virtual time
// behind the port model the firmware runs (test::SimLptBench); the host is
// the real LptPort and Link. Every job must end with each planned dot struck
// once: the strike log equals the plan, nothing twice, nothing missing.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "controller/sim_controller.hpp"
#include "link/link.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile.hpp"
#include "../common/pty_emboss.hpp"
#include "../common/sim_lpt_cable.hpp"
#include "../common/test_plans.hpp"

namespace tactus {
namespace {

struct LptRig {
    std::shared_ptr<controller::SimController> ctl;
    std::unique_ptr<test::SimLptBench> bench;
    plan::JobPlan plan;
};

LptRig make_rig(std::size_t sheets, std::size_t passes, std::size_t strikes, unsigned seed,
                controller::SimOptions sim = {}) {
    auto t = profile::load_firmware_tables(TACTUS_FIRMWARE_TABLES);
    EXPECT_TRUE(t) << t.error().to_string();
    sim.firmware = t ? *t : machine::FirmwareTables{};
    LptRig r;
    r.ctl = std::make_shared<controller::SimController>(sim);
    r.bench = std::make_unique<test::SimLptBench>(r.ctl);
    r.plan = test::make_firmware_plan(*sim.firmware, profile::strike_timing(profile::default_profile()), sheets,
                                      passes, strikes, seed);
    return r;
}

// The job over the rig's port, as tactus-cli emboss runs it.
link::JobOutcome run(LptRig& rig, std::vector<std::string>* notes = nullptr) {
    auto port = rig.bench->open_port();
    EXPECT_TRUE(port) << port.error().to_string();
    if (!port) return {};
    auto l = link::Link::over(std::move(*port));
    auto h = l.hello();
    EXPECT_TRUE(h) << h.error().to_string();
    EXPECT_EQ(l.protocol(), 3);
    EXPECT_TRUE(l.use_firmware_tables(*rig.ctl->firmware(), profile::strike_timing(profile::default_profile())));
    EXPECT_TRUE(l.configure({}));
    link::CancelToken cancel;
    auto out = l.send_job(
        rig.plan, 1, [&](const link::Progress& p) { if (notes && !p.note.empty()) notes->push_back(p.note); },
        cancel);
    EXPECT_TRUE(out) << out.error().to_string();
    return out ? *out : link::JobOutcome{};
}

TEST(LptFaults, ACleanJobStrikesThePlanAndShowsNoCondition) {
    auto rig = make_rig(2, 6, 12, 1);
    const auto out = run(rig);
    EXPECT_EQ(out.end, link::JobEnd::completed) << out.error.to_string();
    EXPECT_EQ(rig.ctl->strike_log(), controller::planned_strikes(rig.plan));
    EXPECT_EQ(rig.bench->condition_seen().fault_on_nfault, 0U);
    EXPECT_EQ(rig.bench->condition_seen().nfault_without_fault, 0U);
    EXPECT_EQ(rig.bench->condition_seen().perror_with_paper, 0U);
}

// The limit switch trips mid-pass: the fault shows on nFault (and only while
// it stands), the host re-homes and resumes the pass at the strike it stopped at.
TEST(LptFaults, AFaultShowsOnNFaultAndTheJobResumesStrikingEachDotOnce) {
    auto rig = make_rig(1, 10, 20, 6);
    rig.ctl->inject_limit_switch_at_strike(33);
    const auto out = run(rig);
    EXPECT_EQ(out.end, link::JobEnd::completed) << out.error.to_string();
    EXPECT_EQ(rig.ctl->strike_log(), controller::planned_strikes(rig.plan));
    EXPECT_GT(rig.bench->condition_seen().fault_on_nfault, 0U);
    EXPECT_EQ(rig.bench->condition_seen().nfault_without_fault, 0U);
}

// A hammer fault is not one the host can clear: the job fails at it, and
// what was struck is the plan's beginning up to the strike whose hammer
// failed (protocol 3 finds it once that strike has fired), the fault on nFault.
TEST(LptFaults, AHammerFaultOnNFaultStopsTheJobAfterTheStrikesMade) {
    auto rig = make_rig(2, 10, 20, 7);
    rig.ctl->inject_hammer_fault_at_strike(40);
    const auto out = run(rig);
    EXPECT_EQ(out.end, link::JobEnd::failed);
    EXPECT_NE(out.error.message.find("hammer"), std::string::npos) << out.error.message;
    const auto planned = controller::planned_strikes(rig.plan);
    const auto& log = rig.ctl->strike_log();
    ASSERT_EQ(log.size(), 40U);
    EXPECT_TRUE(std::equal(log.begin(), log.end(), planned.begin()));
    EXPECT_GT(rig.bench->condition_seen().fault_on_nfault, 0U);
}

// Sheet 2 finds no paper: PError shows it, the job waits, the operator loads
// paper 5 s later and the job goes on by itself.
TEST(LptFaults, PaperOutOnPErrorWaitsForPaperThenCompletes) {
    controller::SimOptions sim;
    sim.reload_paper_after_s = 5.0;
    auto rig = make_rig(3, 4, 10, 2, sim);
    rig.ctl->inject_paper_out_at_sheet(2);
    std::vector<std::string> notes;
    const auto out = run(rig, &notes);
    EXPECT_EQ(out.end, link::JobEnd::completed) << out.error.to_string();
    EXPECT_EQ(rig.ctl->strike_log(), controller::planned_strikes(rig.plan));
    EXPECT_GT(rig.bench->condition_seen().paper_out_on_perror, 0U);
    EXPECT_EQ(rig.bench->condition_seen().perror_with_paper, 0U);
    EXPECT_TRUE(std::any_of(notes.begin(), notes.end(),
                            [](const std::string& n) { return n.find("paper out") != std::string::npos; }));
}

// The cable is pulled for 4.5 s mid-job (longer than the controller's
// keep-alive): the host's port stays, its status lines float high (Busy), no
// strobe reaches the chip. The host reconnects when it is back and the job
// completes, each dot once.
TEST(LptFaults, ACablePulledMidJobReconnectsAndStrikesEachDotOnce) {
    auto rig = make_rig(2, 10, 20, 3);
    rig.bench->pull_cable_between(1.5, 6.0);
    const auto out = run(rig);
    EXPECT_EQ(out.end, link::JobEnd::completed) << out.error.to_string();
    EXPECT_EQ(rig.ctl->strike_log(), controller::planned_strikes(rig.plan));
    EXPECT_GT(rig.bench->reads_while_pulled(), 0U);
    EXPECT_GE(out.stats.reconnects, 1U);
}

// A watchdog reset of the controller in the middle of a pass (RAM kept): the
// host restarts the job stream where the controller's progress says, and the
// dots already struck are not struck again.
TEST(LptFaults, AWarmResetMidPassResumesAtTheExactStrike) {
    auto rig = make_rig(2, 10, 20, 4);
    rig.ctl->reset_at_strike(57, true);  // sheet 1, the third pass's 17th strike
    const auto out = run(rig);
    EXPECT_EQ(out.end, link::JobEnd::completed) << out.error.to_string();
    EXPECT_EQ(rig.ctl->resets(), 1U);
    EXPECT_EQ(rig.ctl->strike_log(), controller::planned_strikes(rig.plan));
    EXPECT_EQ(out.stats.restarts, 1U);
}

// A real one-page document nobody here wrote (pandoc's test/docx
// block_quotes.docx: 57 passes, 729 strikes), laid out, translated and
// planned by the pipeline, embossed through the parallel port: every dot of
// the plan struck once, in order. (The same page through the firmware's pins
// in s51: FirmwareOverLpt.AOnePageDocumentStrikesThePlanDotForDot.)
TEST(LptDocument, AOnePageDocumentIsEmbossedDotForDot) {
    auto rig = make_rig(1, 1, 1, 1);
    rig.plan = test::plan_with_firmware_tables(std::string(TACTUS_TEST_DATA) + "/import/public/pandoc-block_quotes.docx",
                                               TACTUS_FIRMWARE_TABLES);
    ASSERT_EQ(rig.plan.sheets.size(), 1U);
    const auto want = controller::planned_strikes(rig.plan);
    ASSERT_GT(want.size(), 500U);
    const auto out = run(rig);
    EXPECT_EQ(out.end, link::JobEnd::completed) << out.error.to_string();
    EXPECT_EQ(rig.ctl->strike_log(), want);
}

}  // namespace
}  // namespace tactus
