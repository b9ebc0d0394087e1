// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where this user's application data lives: $XDG_DATA_HOME or ~/.local/share on
// POSIX (the XDG base directory rules), %LOCALAPPDATA% on Windows.
#include <filesystem>
#include <optional>

namespace tactus::platform {

// The folder applications keep this user's data under (Tactus adds its own
// folder); nullopt when the environment names none.
std::optional<std::filesystem::path> user_data_home();

}  // namespace tactus::platform
