// SPDX-License-Identifier: GPL-3.0-or-later
// The pass-completion edge, in process and in virtual time (deterministic):
// the controller executes a pass and its acknowledgement never reaches the
// runner, because the line dies at that instant (the simulator holds its
// replies from that pass on, and the host's side of the cable is cut as soon
// as the controller has gone quiet). The controller runs on by itself; the
// runner gives up on the device and, when the printer is back, must settle
// with the controller's own count before it sends anything. The information
// the runner has is exactly what a runner restarted after kill -9 at that
// instant has (the kill tests do that with real processes).
#include <gtest/gtest.h>

#include "profile/profile.hpp"
#include "profile/profile_json.hpp"
#include "spool/printing.hpp"
#include "spool/runner.hpp"
#include "spool/snapshot.hpp"
#include "sim_rig.hpp"
#include "spool_fixtures.hpp"
#include "strike_audit.hpp"

namespace tactus::spool {
namespace {

using test::TempDir;

// Whether the line is cut; it is cut once, the first time the controller is
// seen quiet, and stays whole after the test restores it.
struct Cut {
    bool cut = false;
    bool happened = false;
};

struct Edge {
    TempDir dir;
    std::filesystem::path db = dir / "spool.db";
    Spool spool = *Spool::open(db);
    std::shared_ptr<controller::SimController> controller = std::make_shared<controller::SimController>();
    std::shared_ptr<controller::SimTransport> line =
        std::make_shared<controller::SimTransport>(controller, controller::SimLineOptions{});
    std::shared_ptr<Cut> cut = std::make_shared<Cut>();
    std::atomic<bool> stop{false};

    Edge() { EXPECT_TRUE(spool.add_printer("lab", "sim", profile::to_json(profile::default_profile()).dump())); }

    ConnectFn connect() {
        return [this](const PrinterRecord&) -> Result<link::Link> {
            if (cut->cut) return fail(ErrorKind::device, "no such device: sim (unplugged)", "sim");
            // The in-process line, cut from the moment the controller has
            // gone quiet until the test restores it.
            return link::Link::over(std::make_unique<test::SharedLine>(line, [l = line, c = cut] {
                if (!c->happened && l->controller().muted()) c->cut = c->happened = true;
                return c->cut;
            }));
        };
    }
    static RunnerOptions options() {
        RunnerOptions o;
        o.retry_backoff = std::chrono::milliseconds(0);
        o.poll = std::chrono::milliseconds(5);
        o.link.reconnect_deadline = std::chrono::milliseconds(3000);  // virtual time
        return o;
    }
    plan::JobPlan plan_of(JobId id) {
        auto doc = from_snapshot(*spool.document_snapshot(id));
        return *plan_copies(*doc, profile::default_profile(), spool.job(id)->copies);
    }
    std::size_t recorded(JobId id) {
        std::size_t n = 0;
        const auto progress = *spool.progress(id);
        for (const auto& p : progress) n += p.passes_done;
        return n;
    }
};

std::vector<std::size_t> sheet_ends(const plan::JobPlan& plan) {
    std::vector<std::size_t> ends;
    std::size_t n = 0;
    for (const auto& s : plan.sheets) ends.push_back(n += s.passes.size());
    return ends;
}

// Every sheet's last pass, the job's last pass among them.
class PassEdge : public ::testing::TestWithParam<int> {};

TEST_P(PassEdge, TheControllersCountIsRecordedBeforeAnythingIsSentAgain) {
    Edge e;
    const auto id = *e.spool.submit(test::submission("lab", 5, 2));  // 3 sheets x 2 copies
    const auto ends = sheet_ends(e.plan_of(id));
    ASSERT_EQ(ends.size(), 6U);
    const std::size_t sheet = static_cast<std::size_t>(GetParam());
    const std::size_t at = ends[sheet - 1];
    SCOPED_TRACE("the ACK of pass " + std::to_string(at) + " (the last of sheet " + std::to_string(sheet) + ") is lost");
    e.controller->mute_after_pass(static_cast<std::uint16_t>(at));

    Runner r(e.db, "lab", e.connect(), Edge::options());
    ASSERT_TRUE(r.start());
    auto first = r.run_next(e.stop);
    ASSERT_TRUE(first) << first.error().to_string();
    EXPECT_EQ(*first, RunEnd::requeued);
    ASSERT_LT(e.recorded(id), at) << "the window was not hit";
    const auto st = e.controller->status();
    EXPECT_GE(st.ack.executed_passes, at);
    if (sheet == ends.size()) {
        // The controller ended the job by itself while the host was away.
        EXPECT_EQ(st.flags & encode::flag::job_active, 0);
        EXPECT_NE(st.flags & encode::flag::job_ended, 0);
    }

    e.cut->cut = false;  // the printer is back
    auto second = r.run_next(e.stop);
    ASSERT_TRUE(second) << second.error().to_string();
    EXPECT_EQ(*second, RunEnd::completed);
    const auto audit = test::audit_strikes(e.plan_of(id), e.controller->strike_log(), *e.spool.progress(id));
    std::string history;
    const auto events = *e.spool.events(id, 1000);
    for (const auto& ev : events) history += ev.kind + ": " + ev.message + "\n";
    EXPECT_EQ(audit.problems, "") << history;
    // Nothing claims the sheet was cut short one pass before its end (the
    // record's count, which the controller had already passed).
    const std::size_t in_sheet = at - (sheet > 1 ? ends[sheet - 2] : 0);
    EXPECT_EQ(history.find(" after pass " + std::to_string(in_sheet - 1) + " of " + std::to_string(in_sheet)),
              std::string::npos)
        << history;
}

INSTANTIATE_TEST_SUITE_P(LastPassOfEachSheet, PassEdge, ::testing::Range(1, 7));

// The id the spool records for a stream is the one JOB_BEGIN carries, written
// before the first DATA frame: an ACK of the previous job still on the line
// when the stream starts must not be taken for the new one's.
TEST(RunnerEdge, TheRunRecordNamesTheStreamBeforeItsFirstDataFrame) {
    Edge e;
    const auto a = *e.spool.submit(test::submission("lab", 3, 1));
    const auto b = *e.spool.submit(test::submission("lab", 3, 1));
    Runner r(e.db, "lab", e.connect(), Edge::options());
    ASSERT_TRUE(r.start());
    auto end_a = r.run_next(e.stop);
    ASSERT_TRUE(end_a);
    EXPECT_EQ(*end_a, RunEnd::completed);
    const auto previous = e.controller->status().ack.job_id;
    // Job b's stream loses its line after the first pass.
    e.controller->mute_after_pass(static_cast<std::uint16_t>(1));
    auto end_b = r.run_next(e.stop);
    ASSERT_TRUE(end_b);
    const auto jb = *e.spool.job(b);
    ASSERT_TRUE(jb.link_job.has_value());
    EXPECT_NE(*jb.link_job, previous);
    EXPECT_EQ(*jb.link_job, e.controller->status().ack.job_id);
    EXPECT_TRUE(jb.run_open);
    e.cut->cut = false;
    auto again = r.run_next(e.stop);
    ASSERT_TRUE(again);
    std::string history;
    const auto events = *e.spool.events(b, 1000);
    for (const auto& ev : events) history += ev.kind + ": " + ev.message + "\n";
    EXPECT_EQ(*again, RunEnd::completed) << history;
    EXPECT_EQ(test::audit_strikes(e.plan_of(b), [&] {
                  // Only job b's strikes: a and b are different documents of the same shape.
                  std::vector<controller::LoggedStrike> log = e.controller->strike_log();
                  const auto na = controller::planned_strikes(e.plan_of(a)).size();
                  log.erase(log.begin(), log.begin() + static_cast<std::ptrdiff_t>(na));
                  return log;
              }(),
                                    *e.spool.progress(b))
                  .problems,
              "");
}

}  // namespace
}  // namespace tactus::spool
