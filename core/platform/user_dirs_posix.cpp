// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/user_dirs.hpp"

#include <cstdlib>
#include <string_view>

namespace tactus::platform {

std::optional<std::filesystem::path> user_data_home() {
    auto env = [](const char* name) -> std::string_view {
        const char* v = std::getenv(name);
        return v ? std::string_view(v) : std::string_view{};
    };
    // XDG: a relative XDG_DATA_HOME is invalid and must be ignored.
    if (const auto v = env("XDG_DATA_HOME"); !v.empty() && v.front() == '/') return std::filesystem::path(v);
    if (const auto home = env("HOME"); !home.empty()) return std::filesystem::path(home) / ".local" / "share";
    return std::nullopt;
}

}  // namespace tactus::platform
