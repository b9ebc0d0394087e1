// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// liblouis keeps global state (table cache, static translation buffers) and is
// not thread-safe (liblouis issue #543, still open; its Java bindings serialise
// every call). Every call into liblouis in Tactus therefore holds this lock.
// The pipeline gets its parallelism elsewhere: import and layout overlap with
// translation instead of running several translations at once.
#include <filesystem>
#include <mutex>
#include <string>

namespace tactus::translate::louis {

std::mutex& lock();

// The log messages liblouis emitted since the last call, for error messages
// (e.g. "Cannot resolve table 'xx.ctb'"). Call with the lock held.
std::string take_log();

// Installs the log callback once (and on Windows tells liblouis the folder of
// tables_dir()); called by everything that opens tables.
void install_log_capture();

// The folder liblouis's tables and hyphenation dictionaries are read from: the
// one the build was configured with (liblouis.pc's tablesdir), or, in a build
// that carries its tables (the Windows installer), <the program's folder>/
// TACTUS_LOUIS_TABLES_BESIDE_PROGRAM when that holds unicode.dis.
const std::filesystem::path& tables_dir();

}  // namespace tactus::translate::louis
