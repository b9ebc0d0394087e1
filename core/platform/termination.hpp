// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Requests from outside to end this process (Ctrl-C; SIGTERM from a session
// ending, `kill` or a service manager; Ctrl-Break on Windows), and the broken
// pipe a closed reader leaves. A handler only sets a flag or writes a byte.
#include <cstdint>

namespace tactus::platform {

using TerminationHandler = void (*)(int);

// Calls `handler` on a request to end; blocking calls carry on after it.
void on_termination(TerminationHandler handler);
// The same, but a blocking call the request lands in returns early (POSIX:
// sigaction without SA_RESTART), so a loop waiting on a device sees the flag.
void on_termination_interrupting(TerminationHandler handler);
// Back to the system's default: a request ends the process.
void default_termination();
// A write to a reader that is gone fails (EPIPE) instead of ending the
// process. Windows has no such signal: nothing to do there.
void ignore_broken_pipe();

// For an event loop: a handle that becomes readable when a request to end
// comes (a pipe written by the handler); -1 where the system tells the event
// loop itself (Windows sends the window WM_CLOSE / WM_ENDSESSION).
std::intptr_t termination_notice();

}  // namespace tactus::platform
