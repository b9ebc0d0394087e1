// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/termination.hpp"

#include <signal.h>
#include <unistd.h>

namespace tactus::platform {
namespace {

int g_notice_pipe[2] = {-1, -1};

extern "C" void write_notice(int) {
    const char c = 1;
    (void)!write(g_notice_pipe[1], &c, 1);
}

}  // namespace

void on_termination(TerminationHandler handler) {
    signal(SIGTERM, handler);
    signal(SIGINT, handler);
}

void on_termination_interrupting(TerminationHandler handler) {
    struct sigaction sa {};
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGTERM, &sa, nullptr);
    sigaction(SIGINT, &sa, nullptr);
}

void default_termination() {
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
}

void ignore_broken_pipe() { signal(SIGPIPE, SIG_IGN); }

std::intptr_t termination_notice() {
    if (g_notice_pipe[0] < 0 && pipe(g_notice_pipe) != 0) return -1;
    on_termination(write_notice);
    return g_notice_pipe[0];
}

}  // namespace tactus::platform
