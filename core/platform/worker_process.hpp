// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A worker process that translates (or does other work) beside this one and
// streams what it finds back through a pipe, started the way the system
// starts one. POSIX: fork(), a copy of this process that starts with its
// memory (a compiled table, a parsed document) and its own copy of every
// library's globals, running one function. Windows has no fork(): a worker is
// this program started again (CreateProcessW of program_file()) with a hidden
// first argument that main() checks before anything else (worker_side()),
// given its input through a second pipe.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "platform/os_error.hpp"

namespace tactus::platform {

// The worker's end of its pipe.
class WorkerOutput {
public:
    explicit WorkerOutput(std::intptr_t handle) : handle_(handle) {}
    // False when the reader is gone.
    bool write_all(const void* data, std::size_t n);

private:
    std::intptr_t handle_;
};

// How this system starts a worker.
enum class WorkerStart : std::uint8_t {
    copy,     // a copy of this process runs a function (start())
    program,  // this program started again, its input written to it (start_program())
};

// The worker's side of start_program(): all its input, and its output pipe.
struct WorkerSide {
    std::string input;
    WorkerOutput output;
};

class WorkerProcess {
public:
    // Whether this system can start workers at all.
    static bool supported();
    static WorkerStart how();

    // Starts a worker that runs `body` and exits with the status it returns.
    // The caller holds every lock that another thread could hold while the
    // memory is copied; `body` runs with this thread's copies of them locked.
    // The worker closes its copies of `siblings`' pipes, so a sibling sees the
    // end of its reader when the parent goes.
    static OsResult<WorkerProcess> start(const std::function<int(WorkerOutput&)>& body,
                                         std::span<const WorkerProcess> siblings);

    // Where how() is `program`: starts this program again as a worker; its
    // input follows with send_input(). The worker inherits its two pipe ends
    // and nothing else, so a sibling sees the end of its reader when the parent goes.
    static OsResult<WorkerProcess> start_program();
    // Writes all of the worker's input and closes the pipe; false with why
    // when the worker is gone before it read it.
    OsResult<void> send_input(std::string_view input);
    // In main(), before anything else: when this process was started by
    // start_program(), its input (read to the end) and output; nullopt when
    // it was not (argv does not begin with the worker argument); an error
    // when the pipes it was given cannot be read.
    static std::optional<OsResult<WorkerSide>> worker_side(int argc, char** argv);

    WorkerProcess(WorkerProcess&& o) noexcept;
    WorkerProcess& operator=(WorkerProcess&& o) noexcept;
    ~WorkerProcess();

    // 1: read all n bytes, 0: end of stream before any, -1: error or short read.
    int read_all(void* data, std::size_t n);
    // Waits for the worker to end and says how: "exit status N", "killed by signal N".
    std::string wait_for_end();
    // Closes the pipe, terminates the worker and waits for it.
    void stop();

private:
    WorkerProcess(std::int64_t pid, std::intptr_t read_end) : pid_(pid), read_end_(read_end) {}
    std::int64_t pid_ = -1;
    std::intptr_t read_end_ = -1;
    std::intptr_t write_end_ = -1;  // start_program(): the worker's input until it is sent
    std::intptr_t process_ = -1;    // start_program(): the process's handle
    // Bytes read from the pipe ahead of the caller (Windows: one ReadFile
    // takes all the pipe holds, rather than one call per record's part).
    std::string ahead_;
    std::size_t ahead_at_ = 0;
};

}  // namespace tactus::platform
