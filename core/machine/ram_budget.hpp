// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the 89C52's 256 bytes of internal RAM go. The protocol's window is the
// ring left over once the firmware's fixed needs are met; the simulator refuses
// to buffer a byte more than this (docs/protocol.md, "RAM budget").
#include <cstddef>

namespace tactus::machine::ram {

// The largest frame payload: two of them fit the ring, one being executed from
// while the next arrives.
inline constexpr std::size_t kMaxPayload = 80;

inline constexpr std::size_t kTotal = 256;
inline constexpr std::size_t kRegisterBank = 8;   // R0-R7, bank 0 only
inline constexpr std::size_t kBitFlags = 2;       // 0x20-0x21: state bits
inline constexpr std::size_t kStack = 28;         // deepest call chain + two interrupt frames
inline constexpr std::size_t kLink = 10;          // rx state, LEN, SEQ, TYPE, CRC, expected seq, nonce
inline constexpr std::size_t kMotion = 20;        // positions, current segment, next tick
inline constexpr std::size_t kJob = 12;           // job, sheet, pass, executed, strikes, skip, faults
inline constexpr std::size_t kConfig = 10;        // travel, homing rate, hammer pulse, keep-alive
inline constexpr std::size_t kStaging = 6;        // frame header staged before the ring write
inline constexpr std::size_t kRingBytes = kTotal - kRegisterBank - kBitFlags - kStack - kLink -
                                          kMotion - kJob - kConfig - kStaging;
static_assert(kRingBytes == 160);
// Two full DATA frames fit: one being executed from while the next arrives.
static_assert(kRingBytes >= 2 * kMaxPayload);
inline constexpr std::size_t kWindowFrames = 4;

}  // namespace tactus::machine::ram
