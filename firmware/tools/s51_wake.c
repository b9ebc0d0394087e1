// SPDX-License-Identifier: GPL-3.0-or-later
// Preloaded into s51 (LD_PRELOAD) by the parallel-port bridge (`lpt:emu`,
// app/cli/lpt_emulator.cpp): s51's command loop, with the chip stopped, polls
// its consoles with select() and a zero timeout and, finding no command,
// sleeps 100 ms with nanosleep(). A lockstep host sends its next line right
// after the prompt, so nearly every line waited for that nap
// (bench/firmware/lpt-bridge.md). Here the nap becomes a wait on the same
// consoles for at most as long: s51 wakes when a line arrives and sleeps as
// before otherwise. Nothing else s51 does changes.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <sys/select.h>
#include <time.h>

static fd_set polled;  // what s51 last polled without waiting
static int polled_n;

typedef int select_fn(int, fd_set*, fd_set*, fd_set*, struct timeval*);
typedef int nanosleep_fn(const struct timespec*, struct timespec*);

static select_fn* real_select(void) {
    static select_fn* f;
    if (!f) f = (select_fn*)dlsym(RTLD_NEXT, "select");
    return f;
}

int select(int n, fd_set* rd, fd_set* wr, fd_set* ex, struct timeval* timeout) {
    if (rd && !wr && !ex && timeout && timeout->tv_sec == 0 && timeout->tv_usec == 0) {
        polled = *rd;
        polled_n = n;
    }
    return real_select()(n, rd, wr, ex, timeout);
}

int nanosleep(const struct timespec* req, struct timespec* rem) {
    static nanosleep_fn* real_nanosleep;
    if (!real_nanosleep) real_nanosleep = (nanosleep_fn*)dlsym(RTLD_NEXT, "nanosleep");
    if (polled_n > 0 && req) {
        fd_set rd = polled;
        struct timeval t = {req->tv_sec, req->tv_nsec / 1000};
        // A console closed since the poll (EBADF): sleep as s51 asked.
        if (real_select()(polled_n, &rd, 0, 0, &t) >= 0) return 0;
    }
    return real_nanosleep(req, rem);
}
