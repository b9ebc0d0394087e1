// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The edge between the command line and core: commands turn core errors into
// exit codes and "where: why" lines on stderr.
#include <charconv>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

#include "common/result.hpp"

namespace tactus::cli {

// The documented exit codes (README, `tactus-cli --help`).
enum ExitCode : int {
    exit_ok = 0,
    exit_failure = 1,    // the job ran but did not complete (e.g. controller fault)
    exit_usage = 2,      // bad arguments
    exit_bad_input = 3,  // unreadable or malformed input file, profile, table
    exit_device = 4,     // device missing, busy or gone
    exit_page_too_small = 5,  // ready-made braille (BRF, PEF) has pages larger than the
                              // target page; nothing was embossed (--reflow lays it out again)
    exit_internal = 6,   // a bug in Tactus (or liblouis): a broken invariant, a translation
                         // worker that crashed; never the input's fault
};

// The one table from a core error's kind to the exit code.
[[nodiscard]] constexpr int exit_code(ErrorKind kind) {
    switch (kind) {
        case ErrorKind::usage: return exit_usage;
        case ErrorKind::input: return exit_bad_input;
        case ErrorKind::device: return exit_device;
        case ErrorKind::io:
        case ErrorKind::protocol: return exit_failure;
        case ErrorKind::internal: return exit_internal;
    }
    return exit_failure;
}

// Thrown by commands, caught once in main: the only exception in the CLI.
struct CommandFailed : std::runtime_error {
    int code;
    CommandFailed(int c, const std::string& what) : std::runtime_error(what), code(c) {}
};

[[noreturn]] inline void fail_with(int code, const Error& e) {
    throw CommandFailed(code, e.to_string());
}

[[noreturn]] inline void fail_with(const Error& e) { fail_with(exit_code(e.kind), e); }

// Unwraps a Result or fails the command with the exit code of the error's kind.
template <typename T>
T require(Result<T> r) {
    if (!r) fail_with(r.error());
    if constexpr (!std::is_void_v<T>) return std::move(*r);
}

// Unwraps a Result or fails the command with `code`: for a value whose meaning
// the command knows better than core (a malformed string typed on the command
// line is a usage error even though the parser calls it bad input).
template <typename T>
T require(Result<T> r, int code) {
    if (!r) fail_with(code, r.error());
    if constexpr (!std::is_void_v<T>) return std::move(*r);
}

// The largest value of an int option, as whole_number_from_one's bound.
inline constexpr std::uint64_t kMaxInt = static_cast<std::uint64_t>(std::numeric_limits<int>::max());

// A whole number from 1 to `max`, checked on the text as typed: CLI11's
// PositiveNumber names a range of doubles (up to 1.8e308) and its integer
// conversion clamps an overflowing number to the type's largest.
inline CLI::Validator whole_number_from_one(
    std::uint64_t max = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
    return CLI::Validator(
        [max](std::string& text) -> std::string {
            std::uint64_t v = 0;
            const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
            if (ec != std::errc{} || end != text.data() + text.size() || v < 1 || v > max)
                return "\"" + text + "\" is not a whole number from 1 to " + std::to_string(max);
            return {};
        },
        "N");
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
void add_convert_command(CLI::App& app);

}  // namespace tactus::cli
