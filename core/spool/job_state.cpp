// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/job_state.hpp"

#include <array>
#include <utility>

namespace tactus::spool {
namespace {

constexpr std::array kStates{std::pair{JobState::queued, "queued"},
                             std::pair{JobState::running, "running"},
                             std::pair{JobState::paused, "paused"},
                             std::pair{JobState::completed, "completed"},
                             std::pair{JobState::cancelled, "cancelled"},
                             std::pair{JobState::failed, "failed"}};

constexpr std::array kControls{std::pair{Control::none, ""}, std::pair{Control::pause, "pause"},
                               std::pair{Control::resume, "resume"},
                               std::pair{Control::cancel, "cancel"}};

std::unexpected<Error> refuse(JobState s, const char* what) {
    return fail(ErrorKind::input, std::string("job is ") + to_string(s) + ": " + what);
}

}  // namespace

const char* to_string(JobState s) {
    for (const auto& [state, name] : kStates)
        if (state == s) return name;
    return "?";
}

Result<JobState> parse_job_state(std::string_view s) {
    for (const auto& [state, name] : kStates)
        if (s == name) return state;
    return fail(ErrorKind::input, "unknown job state '" + std::string(s) + "'", "jobs.state");
}

bool is_terminal(JobState s) {
    return s == JobState::completed || s == JobState::cancelled || s == JobState::failed;
}

const char* to_string(Action a) {
    switch (a) {
    case Action::pause: return "pause";
    case Action::resume: return "resume";
    case Action::cancel: return "cancel";
    case Action::retry: return "retry";
    }
    return "?";
}

const char* to_string(Control c) {
    for (const auto& [control, name] : kControls)
        if (control == c) return name;
    return "?";
}

Result<Control> parse_control(std::string_view s) {
    for (const auto& [control, name] : kControls)
        if (s == name) return control;
    return fail(ErrorKind::input, "unknown runner request '" + std::string(s) + "'", "jobs.control");
}

Result<Transition> apply(JobState state, bool held, Action action) {
    switch (action) {
    case Action::pause:
        if (state == JobState::queued) return Transition{JobState::paused, Control::none, "paused by the operator"};
        if (state == JobState::running) return Transition{JobState::running, Control::pause, ""};
        if (state == JobState::paused) return refuse(state, "already paused");
        return refuse(state, "nothing to pause");
    case Action::resume:
        if (state == JobState::paused)
            // A runner still holding the session continues in place; otherwise
            // the job goes back in the queue and restarts at its first
            // unfinished sheet.
            return held ? Transition{JobState::paused, Control::resume, ""}
                        : Transition{JobState::queued, Control::none, ""};
        if (state == JobState::running && held)
            return refuse(state, "not paused (a pause may still be on its way to the printer)");
        return refuse(state, "not paused; nothing to resume (use retry for failed or cancelled jobs)");
    case Action::cancel:
        if (held && (state == JobState::running || state == JobState::paused))
            return Transition{state, Control::cancel, ""};
        if (state == JobState::queued || state == JobState::paused || state == JobState::failed)
            return Transition{JobState::cancelled, Control::none, "cancelled by the operator"};
        return refuse(state, "nothing to cancel");
    case Action::retry:
        if (state == JobState::failed || state == JobState::cancelled)
            return Transition{JobState::queued, Control::none, ""};
        return refuse(state, "only failed or cancelled jobs can be retried");
    }
    return fail(ErrorKind::internal, "unknown action");
}

}  // namespace tactus::spool
