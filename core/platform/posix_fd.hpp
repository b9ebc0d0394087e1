// The POSIX side of the platform layer keeps descriptors in the intptr_t
// handles its portable headers declare (a HANDLE on Windows).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <ctime>

// Linux creates a descriptor already closed on exec (pipe2, SOCK_CLOEXEC,
// O_CLOEXEC for posix_openpt) and waits with a nanosecond timeout (ppoll).
// macOS has none of these calls: there the flag is set just after, and the
// wait is rounded up to a millisecond. TACTUS_POSIX_PORTABLE_ONLY takes the
// macOS path on Linux, so that path is compiled and tested where macOS is not
// at hand (docs/windows.md, "macOS").
#if defined(__APPLE__) || defined(TACTUS_POSIX_PORTABLE_ONLY)
#define TACTUS_POSIX_LINUX_CALLS 0
#else
#define TACTUS_POSIX_LINUX_CALLS 1
#endif

namespace tactus::platform {

inline int fd_of(std::intptr_t h) { return static_cast<int>(h); }

// -1 (errno set) on failure; the descriptor otherwise, closed on exec.
inline int close_on_exec(int fd) {
    if (fd >= 0 && ::fcntl(fd, F_SETFD, FD_CLOEXEC) != 0) {
        ::close(fd);
        return -1;
    }
    return fd;
}

inline int cloexec_pipe(int fds[2]) {
#if TACTUS_POSIX_LINUX_CALLS
    return ::pipe2(fds, O_CLOEXEC);
#else
    if (::pipe(fds) != 0) return -1;
    if (close_on_exec(fds[0]) < 0) {
        ::close(fds[1]);
        return -1;
    }
    if (close_on_exec(fds[1]) < 0) {
        ::close(fds[0]);
        return -1;
    }
    return 0;
#endif
}

inline int cloexec_socket(int domain, int type) {
#if TACTUS_POSIX_LINUX_CALLS
    return ::socket(domain, type | SOCK_CLOEXEC, 0);
#else
    return close_on_exec(::socket(domain, type, 0));
#endif
}

// A pseudo-terminal's master side, closed on exec.
inline int cloexec_pt_master() {
#if TACTUS_POSIX_LINUX_CALLS
    return ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
#else
    return close_on_exec(::posix_openpt(O_RDWR | O_NOCTTY));
#endif
}

// poll() with a timeout in nanoseconds (ppoll on Linux; elsewhere rounded up
// to whole milliseconds, so a wait never ends before its time).
inline int poll_for(pollfd* fds, nfds_t n, std::chrono::nanoseconds timeout) {
    const auto ns = timeout.count() > 0 ? timeout.count() : 0;
#if TACTUS_POSIX_LINUX_CALLS
    const timespec ts{static_cast<time_t>(ns / 1'000'000'000), static_cast<long>(ns % 1'000'000'000)};
    return ::ppoll(fds, n, &ts, nullptr);
#else
    const auto ms = (ns + 999'999) / 1'000'000;
    return ::poll(fds, n, ms > 2'000'000'000 ? 2'000'000'000 : static_cast<int>(ms));
#endif
}

}  // namespace tactus::platform
