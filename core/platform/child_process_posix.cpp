// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/child_process.hpp"
#include "platform/posix_fd.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <sstream>
#include <thread>
#include <utility>

namespace tactus::platform {

OsResult<ChildProcess> ChildProcess::spawn(const ChildOptions& o) {
    ChildProcess c;
    int input[2] = {-1, -1};
    if (o.idle_input && cloexec_pipe(input) != 0) return std::unexpected(last_error());
    c.input_[0] = input[0];
    c.input_[1] = input[1];
    std::vector<char*> argv;
    for (const auto& a : o.args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        if (chdir(o.dir.c_str()) != 0) _exit(126);
        const int out = ::open(o.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (input[0] >= 0) dup2(input[0], STDIN_FILENO);
        if (out >= 0) {
            dup2(out, STDOUT_FILENO);
            dup2(out, STDERR_FILENO);
        }
        if (o.lower_priority) (void)setpriority(PRIO_PROCESS, 0, 10);
        execvp(argv[0], argv.data());
        _exit(127);
    }
    if (pid < 0) return std::unexpected(last_error());
    c.process_ = pid;
    c.id_ = pid;
    return c;
}

ChildProcess::ChildProcess(ChildProcess&& o) noexcept
    : process_(std::exchange(o.process_, -1)),
      input_{std::exchange(o.input_[0], -1), std::exchange(o.input_[1], -1)},
      id_(o.id_) {}

bool ChildProcess::running() {
    if (process_ <= 0) return false;
    const auto pid = static_cast<pid_t>(process_);
    if (waitpid(pid, nullptr, WNOHANG) == pid) {
        process_ = -1;
        return false;
    }
    return true;
}

int ChildProcess::wait() {
    if (process_ <= 0) return -1;
    const auto pid = static_cast<pid_t>(std::exchange(process_, -1));
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void ChildProcess::stop() {
    if (process_ > 0) {
        const auto pid = static_cast<pid_t>(process_);
        process_ = -1;
        kill(pid, SIGTERM);
        bool ended = false;
        for (int i = 0; i < 50 && !ended; ++i) {
            if (waitpid(pid, nullptr, WNOHANG) == pid) ended = true;
            else std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        if (!ended) {
            kill(pid, SIGKILL);
            waitpid(pid, nullptr, 0);
        }
    }
    for (auto& fd : input_) {
        if (fd >= 0) ::close(static_cast<int>(fd));
        fd = -1;
    }
}

bool find_in_path(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/bin:/bin");
    for (std::string d; std::getline(dirs, d, ':');)
        if (!d.empty() && access((std::filesystem::path(d) / program).c_str(), X_OK) == 0) return true;
    return false;
}

}  // namespace tactus::platform
