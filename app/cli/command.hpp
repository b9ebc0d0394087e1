// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The edge between the command line and core: commands turn core errors into
// exit codes and "where: why" lines on stderr.
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

#include "common/result.hpp"

namespace tactus::cli {

enum ExitCode : int {
    exit_ok = 0,
    exit_failure = 1,    // the job ran but did not complete (e.g. controller fault)
    exit_usage = 2,      // bad arguments
    exit_bad_input = 3,  // unreadable or malformed input file, profile, table
    exit_device = 4,     // device missing, busy or gone
    exit_page_too_small = 5,  // ready-made braille (BRF, PEF) has pages larger than the
                              // target page; nothing was embossed (--reflow lays it out again)
};

// Thrown by commands, caught once in main: the only exception in the CLI.
struct CommandFailed : std::runtime_error {
    int code;
    CommandFailed(int c, const std::string& what) : std::runtime_error(what), code(c) {}
};

[[noreturn]] inline void fail_with(int code, const Error& e) {
    throw CommandFailed(code, e.to_string());
}

// Unwraps a Result or fails the command with `code`.
template <typename T>
T require(Result<T> r, int code = exit_bad_input) {
    if (!r) fail_with(code, r.error());
    if constexpr (!std::is_void_v<T>) return std::move(*r);
}

// Each command file provides one of these; main.cpp calls them all.
void add_translate_command(CLI::App& app);
void add_layout_command(CLI::App& app);
void add_tables_command(CLI::App& app);
void add_queue_command(CLI::App& app);
void add_serve_command(CLI::App& app);
void add_plan_command(CLI::App& app);
void add_profile_command(CLI::App& app);
void add_vibration_command(CLI::App& app);
void add_sim_command(CLI::App& app);
void add_ports_command(CLI::App& app);
void add_emboss_command(CLI::App& app);

}  // namespace tactus::cli
