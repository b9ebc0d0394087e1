// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The reference firmware's link (firmware/src/fw.h, docs/protocol.md): the
// protocol it speaks and the sizes of its receive buffer, which HELLO_REPLY
// reports. One copy for every stage: the plan file records the protocol, the
// encoder cuts DATA payloads to the buffer, the simulated controller reports
// the same sizes, and the dry run counts frames with them.
#include <cstddef>
#include <cstdint>

namespace tactus::machine::reference_firmware {

// Protocol 3: table moves and dot-grid passes. Protocol 2 is the legacy one
// (step schedules in the job stream), spoken only where asked for.
inline constexpr std::uint8_t kProtocol = 3;
inline constexpr std::uint8_t kLegacyProtocol = 2;

// A 64-byte buffer, 17 of it kept for a control frame; DATA payloads of at
// most two thirds of the ring plus the two-byte check.
inline constexpr std::size_t kBufferBytes = 64;
inline constexpr std::size_t kSlack = 17;
inline constexpr std::size_t kRingBytes = kBufferBytes - kSlack;    // 47
inline constexpr std::size_t kMaxPayload = kRingBytes * 2 / 3 + 2;  // 33
inline constexpr std::size_t kDataCheckBytes = 2;
inline constexpr std::size_t kMaxOps = kMaxPayload - kDataCheckBytes;  // 31 bytes of ops
inline constexpr std::size_t kWindowFrames = 4;
inline constexpr std::uint8_t kFirmwareMajor = 1;
inline constexpr std::uint8_t kFirmwareMinor = 0;

}  // namespace tactus::machine::reference_firmware
