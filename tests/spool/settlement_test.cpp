// SPDX-License-Identifier: GPL-3.0-or-later
// Settling an interrupted stream with the controller's count: every case of
// docs/spool.md's table, on a job of three sheets of 4, 5 and 3 passes.
#include <gtest/gtest.h>

#include "spool/settlement.hpp"

namespace tactus::spool {
namespace {

std::vector<SheetProgress> shape(std::vector<std::size_t> done = {0, 0, 0}) {
    return {{1, 4, done[0], 0}, {2, 5, done[1], 0}, {3, 3, done[2], 0}};
}

JobRecord run(std::uint16_t link_job, std::size_t start_sheet, std::size_t first_pass) {
    JobRecord j;
    j.id = 7;
    j.link_job = link_job;
    j.run_start_sheet = start_sheet;
    j.run_first_pass = first_pass;
    j.run_open = true;
    return j;
}

encode::Status status(std::uint16_t job, std::uint16_t executed, std::uint8_t flags = 0, std::uint16_t sheet = 0,
                      std::uint8_t strikes = 0) {
    encode::Status s;
    s.ack.job_id = job;
    s.job_id = job;
    s.ack.executed_passes = executed;
    s.ack.strikes_in_pass = strikes;
    s.flags = flags;
    s.sheet = sheet;
    return s;
}

TEST(Settlement, AJobTheControllerFinishedAloneIsRecordedInFull) {
    // Killed after the last pass of the last sheet: 11 of 12 recorded.
    const auto s = settle(run(0x8001, 1, 0), shape({4, 5, 2}), status(0x8001, 12, encode::flag::job_ended));
    EXPECT_TRUE(s.controller_count);
    ASSERT_EQ(s.record.size(), 1U);
    EXPECT_EQ(s.record[0], (std::pair<std::size_t, std::size_t>{3, 3}));
    EXPECT_FALSE(s.discard);
    EXPECT_NE(s.message.find("finished the job by itself"), std::string::npos) << s.message;
}

TEST(Settlement, TheSheetInTheMachineIsDiscardedWithTheControllersPassNumber) {
    // Stream from sheet 2 (first pass 4); the controller got to pass 7: sheet 2 has 3 of 5.
    const auto s = settle(run(0x8002, 2, 4), shape({4, 1, 0}), status(0x8002, 7, encode::flag::job_active, 2, 0));
    ASSERT_EQ(s.record.size(), 1U);
    EXPECT_EQ(s.record[0], (std::pair<std::size_t, std::size_t>{2, 3}));
    ASSERT_TRUE(s.discard);
    EXPECT_EQ(*s.discard, 2U);
    EXPECT_NE(s.discard_message.find("interrupted after pass 3 of 5 (the controller's count)"), std::string::npos)
        << s.discard_message;
}

TEST(Settlement, ASheetFinishedJustBeforeTheKillIsNotDiscarded) {
    // Every pass of sheet 1 executed, sheet 2 not loaded yet.
    const auto s = settle(run(0x8003, 1, 0), shape({3, 0, 0}), status(0x8003, 4, encode::flag::job_active));
    ASSERT_EQ(s.record.size(), 1U);
    EXPECT_EQ(s.record[0], (std::pair<std::size_t, std::size_t>{1, 4}));
    EXPECT_FALSE(s.discard);
}

TEST(Settlement, StrikesOfTheNextPassOrALoadedSheetMeanItWasInTheMachine) {
    const auto struck = settle(run(0x8004, 1, 0), shape({4, 0, 0}), status(0x8004, 4, encode::flag::job_active, 2, 6));
    ASSERT_TRUE(struck.discard);
    EXPECT_EQ(*struck.discard, 2U);
    EXPECT_NE(struck.discard_message.find("after pass 0 of 5 and 6 strike(s) of the next"), std::string::npos)
        << struck.discard_message;
    const auto loaded = settle(run(0x8004, 1, 0), shape({4, 0, 0}), status(0x8004, 4, encode::flag::job_active, 2, 0));
    ASSERT_TRUE(loaded.discard);
    EXPECT_NE(loaded.discard_message.find("may be blank"), std::string::npos) << loaded.discard_message;
}

TEST(Settlement, AnotherJobsCountIsNeverUsed) {
    // The stream never began (the controller still reports the previous job).
    const auto never = settle(run(0x8005, 1, 0), shape(), status(0x8004, 12, encode::flag::job_ended));
    EXPECT_FALSE(never.controller_count);
    EXPECT_TRUE(never.record.empty());
    EXPECT_FALSE(never.discard);
    // Power lost after passes were recorded: the count is gone, the record's sheet is discarded
    // and no pass number is claimed as the interruption point.
    const auto lost = settle(run(0x8005, 1, 0), shape({4, 2, 0}), status(0, 0));
    EXPECT_FALSE(lost.controller_count);
    EXPECT_TRUE(lost.record.empty());
    ASSERT_TRUE(lost.discard);
    EXPECT_EQ(*lost.discard, 2U);
    EXPECT_NE(lost.discard_message.find("count was lost: at least 2 of 5"), std::string::npos) << lost.discard_message;
    EXPECT_EQ(lost.discard_message.find("interrupted after"), std::string::npos);
}

TEST(Settlement, ALostCountDiscardsTheSheetAfterTheLastFinishedOneOfTheStream) {
    // Serve and the controller died together during sheet 3's first pass: no
    // pass of it is recorded, but the stream had finished sheets 1 and 2, so
    // the controller had gone on to sheet 3 and may have struck dots on it.
    const auto lost = settle(run(0x8005, 1, 0), shape({4, 5, 0}), status(0, 0));
    EXPECT_FALSE(lost.controller_count);
    ASSERT_TRUE(lost.discard);
    EXPECT_EQ(*lost.discard, 3U);
    EXPECT_NE(lost.discard_message.find("may be blank"), std::string::npos) << lost.discard_message;
    // The same from a stream that began at sheet 2.
    const auto later = settle(run(0x8005, 2, 4), shape({4, 5, 0}), status(0, 0));
    ASSERT_TRUE(later.discard);
    EXPECT_EQ(*later.discard, 3U);
    // The stream's first sheet with nothing recorded, on a controller that
    // still names the job before the stream: the stream's JOB_BEGIN never
    // reached it, so nothing was struck.
    const auto never = settle(run(0x8005, 2, 4), shape({4, 0, 0}), status(0x8004, 9, encode::flag::job_ended));
    EXPECT_FALSE(never.discard);
}

TEST(Settlement, AControllerThatLostItsMemoryMayHaveStruckTheStreamsFirstSheet) {
    // Serve and the controller died together during the first pass of the
    // stream's first sheet: nothing of it is recorded, and the controller
    // that answers now has run no job since its power came on (job 0). It may
    // have struck dots, so the sheet is discarded, said to be possibly blank.
    const auto first = settle(run(0x8005, 2, 4), shape({4, 0, 0}), status(0, 0));
    EXPECT_FALSE(first.controller_count);
    EXPECT_TRUE(first.record.empty());
    ASSERT_TRUE(first.discard);
    EXPECT_EQ(*first.discard, 2U);
    EXPECT_NE(first.discard_message.find("began the stream"), std::string::npos) << first.discard_message;
    EXPECT_NE(first.discard_message.find("may be blank"), std::string::npos) << first.discard_message;
}

TEST(Settlement, ACountOutsideTheStreamIsNotUsed) {
    // Same id, but the count lies before the stream's first pass (or the plan shape changed).
    const auto before = settle(run(0x8006, 2, 4), shape({4, 0, 0}), status(0x8006, 2, encode::flag::job_active));
    EXPECT_FALSE(before.controller_count);
    EXPECT_TRUE(before.record.empty());
    const auto shape_changed = settle(run(0x8006, 2, 5), shape({4, 0, 0}), status(0x8006, 6));
    EXPECT_FALSE(shape_changed.controller_count);
}

}  // namespace
}  // namespace tactus::spool
