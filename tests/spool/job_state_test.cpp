// SPDX-License-Identifier: GPL-3.0-or-later
// The operator's actions against every job state: the whole table, so a new
// state or action cannot slip in without a decision.
#include <gtest/gtest.h>

#include "spool/job_state.hpp"

namespace tactus::spool {
namespace {

constexpr JobState kAll[] = {JobState::queued,    JobState::running,   JobState::paused,
                             JobState::completed, JobState::cancelled, JobState::failed};

TEST(JobState, NamesRoundTrip) {
    for (JobState s : kAll) {
        auto parsed = parse_job_state(to_string(s));
        ASSERT_TRUE(parsed);
        EXPECT_EQ(*parsed, s);
    }
    EXPECT_FALSE(parse_job_state("printing"));
    for (Control c : {Control::none, Control::pause, Control::resume, Control::cancel})
        EXPECT_EQ(*parse_control(to_string(c)), c);
}

TEST(JobState, PauseOfAQueuedJobHoldsItInTheQueue) {
    auto t = apply(JobState::queued, false, Action::pause);
    ASSERT_TRUE(t);
    EXPECT_EQ(t->state, JobState::paused);
    EXPECT_EQ(t->control, Control::none);
}

TEST(JobState, PauseOfARunningJobIsLeftToItsRunner) {
    auto t = apply(JobState::running, true, Action::pause);
    ASSERT_TRUE(t);
    EXPECT_EQ(t->state, JobState::running);  // paused only once the printer has stopped
    EXPECT_EQ(t->control, Control::pause);
}

TEST(JobState, ResumeContinuesInPlaceWhenHeldOtherwiseRequeues) {
    auto held = apply(JobState::paused, true, Action::resume);
    ASSERT_TRUE(held);
    EXPECT_EQ(held->control, Control::resume);
    EXPECT_EQ(held->state, JobState::paused);
    auto released = apply(JobState::paused, false, Action::resume);
    ASSERT_TRUE(released);
    EXPECT_EQ(released->state, JobState::queued);
    EXPECT_EQ(released->control, Control::none);
}

TEST(JobState, CancelAbortsThroughTheRunnerOnlyWhileHeld) {
    EXPECT_EQ(apply(JobState::running, true, Action::cancel)->control, Control::cancel);
    EXPECT_EQ(apply(JobState::paused, true, Action::cancel)->control, Control::cancel);
    for (JobState s : {JobState::queued, JobState::paused, JobState::failed}) {
        auto t = apply(s, false, Action::cancel);
        ASSERT_TRUE(t) << to_string(s);
        EXPECT_EQ(t->state, JobState::cancelled);
        EXPECT_EQ(t->control, Control::none);
    }
}

TEST(JobState, RetryOnlyFromFailedOrCancelled) {
    for (JobState s : kAll) {
        auto t = apply(s, false, Action::retry);
        const bool allowed = s == JobState::failed || s == JobState::cancelled;
        EXPECT_EQ(t.has_value(), allowed) << to_string(s);
        if (t) {
            EXPECT_EQ(t->state, JobState::queued);
        }
    }
}

TEST(JobState, FinishedJobsRefuseEverythingButRetryWithAReason) {
    for (Action a : {Action::pause, Action::resume, Action::cancel}) {
        auto t = apply(JobState::completed, false, a);
        ASSERT_FALSE(t);
        EXPECT_NE(t.error().message.find("job is completed"), std::string::npos) << t.error().message;
    }
    EXPECT_FALSE(apply(JobState::cancelled, false, Action::cancel));
    EXPECT_FALSE(apply(JobState::paused, false, Action::pause));
    EXPECT_FALSE(apply(JobState::queued, false, Action::resume));
}

TEST(JobState, TerminalStates) {
    int terminal = 0;
    for (JobState s : kAll) terminal += is_terminal(s);
    EXPECT_EQ(terminal, 3);
    EXPECT_FALSE(is_terminal(JobState::paused));
}

}  // namespace
}  // namespace tactus::spool
