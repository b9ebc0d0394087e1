// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What every spool command shares: --db and opening the database with the
// command's exit codes.
#include <string>

#include <CLI/CLI.hpp>

#include "spool/spool.hpp"

namespace tactus::cli {

inline void add_db_option(CLI::App& cmd, std::string& db) {
    cmd.add_option("--db", db,
                   "Spool database (default: $TACTUS_SPOOL_DB, else "
                   "$XDG_DATA_HOME/tactus/spool.db, else ~/.local/share/tactus/spool.db)");
}

// Opens the spool or ends the command: a damaged, foreign or locked file is bad
// input (exit 3) and is never replaced.
spool::Spool open_spool(const std::string& db, bool create, bool read_only_ok = false);

// Seconds since the epoch as local "YYYY-MM-DD HH:MM:SS".
std::string local_time(double seconds);

}  // namespace tactus::cli
