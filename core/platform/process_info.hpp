// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// This process and others on this machine: who and where we are, and whether a
// process another run left a mark for is still there (the spool's runner token,
// the desktop app's autosave of a crashed session).
#include <cstdint>
#include <string>

namespace tactus::platform {

// This machine's network name; "localhost" when it has none.
std::string host_name();
std::int64_t current_process_id();
// The account this process runs for: $USER (POSIX) or %USERNAME% (Windows), else
// the system's account name, else a number.
std::string user_name();
// Whether process `pid` exists on this machine (one owned by another user counts).
bool process_alive(std::int64_t pid);
// Whether this process runs with the system's highest rights (root).
bool running_as_root();

}  // namespace tactus::platform
