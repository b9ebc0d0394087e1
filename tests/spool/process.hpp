// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Child processes for end-to-end tests: tactus-cli run for real (serve, sim,
// queue), with their stdout readable and killable with any signal.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace tactus::spool::test {

class Process {
public:
    // Starts `args` (args[0] is the program); stdout goes to a pipe, stderr to
    // `stderr_file` (or is inherited when empty).
    explicit Process(const std::vector<std::string>& args, const std::string& stderr_file = {}) {
        int out[2];
        if (pipe(out) != 0) return;
        pid_ = fork();
        if (pid_ == 0) {
            dup2(out[1], STDOUT_FILENO);
            close(out[0]);
            close(out[1]);
            if (!stderr_file.empty()) {
                const int fd = open(stderr_file.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
                if (fd >= 0) dup2(fd, STDERR_FILENO);
            }
            std::vector<char*> argv;
            for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            execv(argv[0], argv.data());
            _exit(127);
        }
        close(out[1]);
        out_ = out[0];
    }
    ~Process() {
        if (pid_ > 0 && !reaped_) {
            kill(pid_, SIGKILL);
            waitpid(pid_, nullptr, 0);
        }
        if (out_ >= 0) close(out_);
    }
    Process(const Process&) = delete;
    Process& operator=(const Process&) = delete;

    [[nodiscard]] pid_t pid() const { return pid_; }

    // One line of stdout, waiting at most `timeout`; empty on timeout or EOF.
    std::string read_line(std::chrono::milliseconds timeout) {
        const auto end = std::chrono::steady_clock::now() + timeout;
        for (;;) {
            if (const auto nl = buffer_.find('\n'); nl != std::string::npos) {
                std::string line = buffer_.substr(0, nl);
                buffer_.erase(0, nl + 1);
                return line;
            }
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                end - std::chrono::steady_clock::now());
            if (left.count() <= 0) return {};
            pollfd p{out_, POLLIN, 0};
            if (poll(&p, 1, static_cast<int>(left.count())) <= 0) return {};
            char buf[512];
            const auto n = ::read(out_, buf, sizeof buf);
            if (n <= 0) return {};
            buffer_.append(buf, static_cast<std::size_t>(n));
        }
    }

    // Everything until EOF (the child closed stdout or exited).
    std::string read_all() {
        std::string out = std::move(buffer_);
        buffer_.clear();
        char buf[4096];
        for (;;) {
            const auto n = ::read(out_, buf, sizeof buf);
            if (n <= 0) return out;
            out.append(buf, static_cast<std::size_t>(n));
        }
    }

    void signal(int sig) { if (pid_ > 0 && !reaped_) kill(pid_, sig); }
    // Waits for the exit; returns the exit code, or 128 + signal.
    int wait() {
        if (reaped_) return status_;
        int st = 0;
        waitpid(pid_, &st, 0);
        reaped_ = true;
        status_ = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
        return status_;
    }

private:
    pid_t pid_ = -1;
    int out_ = -1;
    bool reaped_ = false;
    int status_ = 0;
    std::string buffer_;
};

// Runs to completion; returns {exit code, stdout}.
inline std::pair<int, std::string> run(const std::vector<std::string>& args) {
    Process p(args);
    std::string out = p.read_all();
    return {p.wait(), out};
}

inline std::string read_text(const std::string& path) {
    std::string out;
    if (FILE* f = std::fopen(path.c_str(), "rb")) {
        char buf[4096];
        std::size_t n;
        while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) out.append(buf, n);
        std::fclose(f);
    }
    return out;
}

}  // namespace tactus::spool::test
