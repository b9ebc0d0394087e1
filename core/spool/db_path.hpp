// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the spool lives: --db, else $TACTUS_SPOOL_DB, else
// $XDG_DATA_HOME/tactus/spool.db, else ~/.local/share/tactus/spool.db.
#include <filesystem>
#include <string_view>

#include "common/result.hpp"

namespace tactus::spool {

Result<std::filesystem::path> spool_path(std::string_view explicit_path = {});

}  // namespace tactus::spool
