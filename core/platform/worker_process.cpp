// SPDX-License-Identifier: GPL-3.0-or-later
// What a worker process's handle does the same way on every system: moving
// it and letting go of it (stop() is the system's own).
#include "platform/worker_process.hpp"

#include <utility>

namespace tactus::platform {

WorkerProcess::WorkerProcess(WorkerProcess&& o) noexcept
    : pid_(std::exchange(o.pid_, -1)),
      read_end_(std::exchange(o.read_end_, -1)),
      write_end_(std::exchange(o.write_end_, -1)),
      process_(std::exchange(o.process_, -1)),
      ahead_(std::exchange(o.ahead_, {})),
      ahead_at_(std::exchange(o.ahead_at_, 0)) {}

WorkerProcess& WorkerProcess::operator=(WorkerProcess&& o) noexcept {
    if (this != &o) {
        stop();
        pid_ = std::exchange(o.pid_, -1);
        read_end_ = std::exchange(o.read_end_, -1);
        write_end_ = std::exchange(o.write_end_, -1);
        process_ = std::exchange(o.process_, -1);
        ahead_ = std::exchange(o.ahead_, {});
        ahead_at_ = std::exchange(o.ahead_at_, 0);
    }
    return *this;
}

WorkerProcess::~WorkerProcess() { stop(); }

}  // namespace tactus::platform
