// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The running program's own file, to find what is installed beside it (an
// installed Windows program carries liblouis's tables in its own folder).
// /proc/self/exe on Linux, _NSGetExecutablePath on macOS, GetModuleFileNameW on Windows.
#include <filesystem>

#include "platform/os_error.hpp"

namespace tactus::platform {

// The absolute path of the executable this process runs.
OsResult<std::filesystem::path> program_file();

}  // namespace tactus::platform
