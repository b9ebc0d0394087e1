// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Another program run as a child: found on the PATH, started in a folder with
// its output to a log file, stopped when no longer wanted. POSIX: fork + execvp.
// Windows: CreateProcessW with the log and a pipe as its standard handles.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "platform/os_error.hpp"

namespace tactus::platform {

struct ChildOptions {
    std::vector<std::string> args;  // args[0]: the program, looked up on the PATH
    std::filesystem::path dir;      // its working folder
    std::filesystem::path log;      // its standard output and error
    // Standard input from a pipe held open and never written: the child reads
    // no command and never sees an end of file.
    bool idle_input = false;
    bool lower_priority = false;  // nice 10 / below normal: the machine is shared
};

class ChildProcess {
public:
    static OsResult<ChildProcess> spawn(const ChildOptions& options);
    ChildProcess(ChildProcess&& o) noexcept;
    ChildProcess& operator=(ChildProcess&&) = delete;
    ~ChildProcess() { stop(); }

    // False once the child has ended (it is then reaped).
    bool running();
    // Waits for the child to end: its exit status, or -1 when it was ended
    // by a signal or is not running.
    int wait();
    // Asks the child to end, gives it a second, then ends it.
    void stop();
    // Its process id, which process_info.hpp's process_alive() takes.
    [[nodiscard]] std::int64_t id() const { return id_; }

private:
    ChildProcess() = default;
    std::intptr_t process_ = -1;  // pid on POSIX, process handle on Windows
    std::intptr_t input_[2] = {-1, -1};
    std::int64_t id_ = -1;
};

// Whether `program` is on the PATH and can be run.
bool find_in_path(const std::string& program);

}  // namespace tactus::platform
