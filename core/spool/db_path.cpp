// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/db_path.hpp"

#include <cstdlib>

namespace tactus::spool {

Result<std::filesystem::path> spool_path(std::string_view explicit_path) {
    if (!explicit_path.empty()) return std::filesystem::path(explicit_path);
    auto env = [](const char* name) -> std::string_view {
        const char* v = std::getenv(name);
        return v ? std::string_view(v) : std::string_view{};
    };
    if (const auto v = env("TACTUS_SPOOL_DB"); !v.empty()) return std::filesystem::path(v);
    // XDG: a relative XDG_DATA_HOME is invalid and must be ignored.
    if (const auto v = env("XDG_DATA_HOME"); !v.empty() && v.front() == '/')
        return std::filesystem::path(v) / "tactus" / "spool.db";
    if (const auto home = env("HOME"); !home.empty())
        return std::filesystem::path(home) / ".local" / "share" / "tactus" / "spool.db";
    return fail("cannot tell where the spool database lives: set --db, TACTUS_SPOOL_DB or HOME");
}

}  // namespace tactus::spool
