// SPDX-License-Identifier: GPL-3.0-or-later
#include "command.hpp"

namespace tactus::cli {
void add_tables_command(CLI::App& app) { app.add_subcommand("tables", "(not yet implemented)"); }
}  // namespace tactus::cli
