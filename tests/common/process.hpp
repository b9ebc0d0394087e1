// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one way tests run a program (tactus-cli, lou_translate, sh): a child
// process with its stdout readable line by line or whole, its stderr to a file,
// merged into stdout or inherited, optional text on its stdin, and killable with
// any signal. No shell unless the test asks for one.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace tactus::test {

class Process {
public:
    // Where the child's stderr goes: inherited, into stdout, or a file (appended).
    struct Options {
        std::string stderr_file;      // empty: inherited (unless merge_stderr)
        bool merge_stderr = false;    // stderr into the stdout pipe
        std::string stdin_text;       // written to the child's stdin, then closed
    };

    // Starts `args`; args[0] is the program, looked up in PATH when it has no '/'.
    explicit Process(const std::vector<std::string>& args, const std::string& stderr_file = {})
        : Process(args, Options{stderr_file, false, {}}) {}

    Process(const std::vector<std::string>& args, const Options& o) {
        int out[2];
        int in[2];
        if (pipe(out) != 0) return;
        if (pipe(in) != 0) {
            close(out[0]);
            close(out[1]);
            return;
        }
        pid_ = fork();
        if (pid_ == 0) {
            dup2(in[0], STDIN_FILENO);
            dup2(out[1], STDOUT_FILENO);
            if (o.merge_stderr) dup2(out[1], STDERR_FILENO);
            close(in[0]);
            close(in[1]);
            close(out[0]);
            close(out[1]);
            if (!o.stderr_file.empty()) {
                const int fd = open(o.stderr_file.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
                if (fd >= 0) dup2(fd, STDERR_FILENO);
            }
            std::vector<char*> argv;
            for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            execvp(argv[0], argv.data());
            _exit(127);
        }
        close(in[0]);
        close(out[1]);
        out_ = out[0];
        // Small inputs only: the pipe buffer (64 KiB) holds them whole, so the
        // write cannot block on a child that has not started reading.
        if (!o.stdin_text.empty())
            [[maybe_unused]] const auto n = ::write(in[1], o.stdin_text.data(), o.stdin_text.size());
        close(in[1]);
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

struct RunResult {
    int exit_code = -1;  // or 128 + signal
    std::string out;
    std::string err;
};

// Runs to completion with `stdin_text` on stdin; stdout and stderr apart.
inline RunResult run_captured(const std::vector<std::string>& args, const std::string& stdin_text = {}) {
    static int counter = 0;
    const std::string err_file = "/tmp/tactus-test-" + std::to_string(getpid()) + "-" +
                                 std::to_string(counter++) + ".err";
    RunResult r;
    {
        Process p(args, Process::Options{err_file, false, stdin_text});
        r.out = p.read_all();
        r.exit_code = p.wait();
    }
    r.err = read_text(err_file);
    std::remove(err_file.c_str());
    return r;
}

// Runs to completion with stderr merged into stdout (err stays empty): for a
// test that reads a command's messages in the order they were written.
inline RunResult run_merged(const std::vector<std::string>& args) {
    Process p(args, Process::Options{{}, true, {}});
    RunResult r;
    r.out = p.read_all();
    r.exit_code = p.wait();
    return r;
}

// tactus-cli with these arguments.
inline std::vector<std::string> cli(std::vector<std::string> args) {
    args.insert(args.begin(), TACTUS_CLI);
    return args;
}


}  // namespace tactus::test
