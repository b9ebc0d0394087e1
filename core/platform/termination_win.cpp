// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/termination.hpp"

#include <windows.h>

#include <atomic>
#include <csignal>

namespace tactus::platform {
namespace {

std::atomic<TerminationHandler> g_handler{nullptr};

// Ctrl-C and Ctrl-Break come on a thread of their own: the handler sets its
// flag and the process stops in its own time. When the console window closes,
// Windows ends the process once the handler returns (or after 5 s).
BOOL WINAPI on_console_event(DWORD event) {
    const auto handler = g_handler.load();
    if (!handler) return FALSE;
    handler(event == CTRL_C_EVENT ? SIGINT : SIGTERM);
    return TRUE;
}

}  // namespace

void on_termination(TerminationHandler handler) {
    g_handler.store(handler);
    SetConsoleCtrlHandler(on_console_event, TRUE);
    std::signal(SIGTERM, handler);
}

void on_termination_interrupting(TerminationHandler handler) { on_termination(handler); }

void default_termination() {
    g_handler.store(nullptr);
    SetConsoleCtrlHandler(on_console_event, FALSE);
    std::signal(SIGTERM, SIG_DFL);
}

void ignore_broken_pipe() {}

std::intptr_t termination_notice() { return -1; }

}  // namespace tactus::platform
