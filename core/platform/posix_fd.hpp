// The POSIX side of the platform layer keeps descriptors in the intptr_t
// handles its portable headers declare (a HANDLE on Windows).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>

namespace tactus::platform {

inline int fd_of(std::intptr_t h) { return static_cast<int>(h); }

}  // namespace tactus::platform
