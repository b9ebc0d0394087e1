// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A worker that is a copy of this process: it starts with this process's memory
// (a compiled table, a parsed document) and its own copy of every library's
// globals, runs one function and streams what it finds back through a pipe.
// POSIX: fork() and a pipe. Windows has no fork(): there a worker would be this
// program started again (CreateProcessW) and given its input through a pipe,
// which needs an entry point no caller has yet, so supported() is false there
// and callers stay in one process.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>

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

class WorkerProcess {
public:
    // Whether this system can start workers at all.
    static bool supported();

    // Starts a worker that runs `body` and exits with the status it returns.
    // The caller holds every lock that another thread could hold while the
    // memory is copied; `body` runs with this thread's copies of them locked.
    // The worker closes its copies of `siblings`' pipes, so a sibling sees the
    // end of its reader when the parent goes.
    static OsResult<WorkerProcess> start(const std::function<int(WorkerOutput&)>& body,
                                         std::span<const WorkerProcess> siblings);

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
};

}  // namespace tactus::platform
