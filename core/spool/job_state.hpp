// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The life of a print job and what an operator may do to it. Pure functions, so
// the rules are tested on their own and the store only applies them.
//
//   queued --claim--> running --all sheets--> completed
//     ^  \             |  |  \--cancel--> cancelled
//     |   pause        |  |   \--bad document / retries used up--> failed
//     |    v           |  fault or operator pause
//     +--resume-- paused <-+
//   failed|cancelled --retry--> queued
#include <optional>
#include <string>
#include <string_view>

#include "common/result.hpp"

namespace tactus::spool {

enum class JobState { queued, running, paused, completed, cancelled, failed };

[[nodiscard]] const char* to_string(JobState s);
Result<JobState> parse_job_state(std::string_view s);
[[nodiscard]] bool is_terminal(JobState s);  // completed, cancelled, failed: the runner never picks it

// What the operator asks (tactus-cli queue pause|resume|cancel|retry).
enum class Action { pause, resume, cancel, retry };
[[nodiscard]] const char* to_string(Action a);

// A request for the runner that holds the job on its printer; it acts on it at
// the next pass boundary (pause), at once (cancel: controller abort), or by
// continuing (resume).
enum class Control { none, pause, resume, cancel };
[[nodiscard]] const char* to_string(Control c);
Result<Control> parse_control(std::string_view s);

struct Transition {
    JobState state;              // the state written now
    Control control = Control::none;  // the request left for the runner (none: nothing to do)
    std::string reason;          // shown in `queue list`; empty keeps nothing
};

// What `action` does to a job in `state`. `held` says a runner holds the job on
// its printer (state running, or paused with the session still open): then the
// runner must carry the request out, so the state stays and a control is left.
// Errors say why the action makes no sense ("job is completed: nothing to cancel").
Result<Transition> apply(JobState state, bool held, Action action);

}  // namespace tactus::spool
