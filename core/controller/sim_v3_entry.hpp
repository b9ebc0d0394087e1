// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Private to the simulated controller's protocol 3 files: the bits of a pass
// record's strike entry (h e dddddd [d], encode/stream_v3.hpp), read by both
// the link's job-stream check and the executor.
#include <cstdint>

namespace tactus::controller {

inline constexpr std::uint8_t kEntryConcave = 0x80;
inline constexpr std::uint8_t kEntryExt = 0x40;
inline constexpr std::uint8_t kEntryDist = 0x3F;

}  // namespace tactus::controller
