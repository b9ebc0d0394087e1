// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/db_path.hpp"

#include <cstdlib>

#include "platform/user_dirs.hpp"

namespace tactus::spool {

Result<std::filesystem::path> spool_path(std::string_view explicit_path) {
    if (!explicit_path.empty()) return std::filesystem::path(explicit_path);
    if (const char* v = std::getenv("TACTUS_SPOOL_DB"); v && *v) return std::filesystem::path(v);
    if (const auto data = platform::user_data_home()) return *data / "tactus" / "spool.db";
    return fail(ErrorKind::usage, "cannot tell where the spool database lives: set --db, TACTUS_SPOOL_DB or HOME");
}

}  // namespace tactus::spool
