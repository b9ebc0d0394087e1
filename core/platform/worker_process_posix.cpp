// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/worker_process.hpp"
#include "platform/posix_fd.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <utility>

namespace tactus::platform {

bool WorkerOutput::write_all(const void* data, std::size_t n) {
    const auto* p = static_cast<const char*>(data);
    while (n > 0) {
        const auto w = ::write(fd_of(handle_), p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return false;
        p += w;
        n -= static_cast<std::size_t>(w);
    }
    return true;
}

bool WorkerProcess::supported() { return true; }

WorkerStart WorkerProcess::how() { return WorkerStart::copy; }

// A POSIX worker is a copy (fork): the program is never started again as one.
OsResult<WorkerProcess> WorkerProcess::start_program() {
    return os_fail("a worker here is a copy of this process (fork), not the program started again",
                   OsErrorKind::unsupported);
}

OsResult<void> WorkerProcess::send_input(std::string_view) {
    return os_fail("a copied worker has no input pipe", OsErrorKind::unsupported);
}

std::optional<OsResult<WorkerSide>> WorkerProcess::worker_side(int, char**) { return std::nullopt; }

OsResult<WorkerProcess> WorkerProcess::start(const std::function<int(WorkerOutput&)>& body,
                                             std::span<const WorkerProcess> siblings) {
    int fds[2];
    if (cloexec_pipe(fds) != 0) return os_fail("cannot create a pipe: " + last_error().what);
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
        for (const auto& s : siblings)
            if (s.read_end_ >= 0) ::close(fd_of(s.read_end_));
        WorkerOutput out(fds[1]);
        ::_exit(body(out));
    }
    ::close(fds[1]);
    if (pid < 0) {
        const auto e = last_error();
        ::close(fds[0]);
        return std::unexpected(e);
    }
    return WorkerProcess(pid, fds[0]);
}

int WorkerProcess::read_all(void* data, std::size_t n) {
    auto* p = static_cast<char*>(data);
    std::size_t done = 0;
    while (done < n) {
        const auto r = ::read(fd_of(read_end_), p + done, n - done);
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) return -1;
        if (r == 0) return done == 0 ? 0 : -1;
        done += static_cast<std::size_t>(r);
    }
    return 1;
}

std::string WorkerProcess::wait_for_end() {
    int status = 0;
    ::waitpid(static_cast<pid_t>(pid_), &status, 0);
    pid_ = -1;
    return WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status))
                               : "exit status " + std::to_string(WEXITSTATUS(status));
}

void WorkerProcess::stop() {
    if (read_end_ >= 0) ::close(fd_of(read_end_));
    read_end_ = -1;
    if (pid_ > 0) {
        const auto pid = static_cast<pid_t>(pid_);
        ::kill(pid, SIGTERM);
        while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
        }
    }
    pid_ = -1;
}

}  // namespace tactus::platform
