// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// liblouis keeps global state (table cache, static translation buffers) and is
// not thread-safe (liblouis issue #543, still open; its Java bindings serialise
// every call). Every call into liblouis in Tactus therefore holds this lock.
// The pipeline gets its parallelism elsewhere: import and layout overlap with
// translation instead of running several translations at once.
#include <mutex>
#include <string>

namespace tactus::translate::louis {

std::mutex& lock();

// The log messages liblouis emitted since the last call, for error messages
// (e.g. "Cannot resolve table 'xx.ctb'"). Call with the lock held.
std::string take_log();

// Installs the log callback once; called by everything that opens tables.
void install_log_capture();

}  // namespace tactus::translate::louis
