// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF, no reflection, no final xor):
// cheap on an 8051 with a nibble table and catches every 1- and 2-bit error and
// every burst up to 16 bits in a frame of our size.
#include <cstdint>
#include <span>

namespace tactus::encode {

[[nodiscard]] std::uint16_t crc16_ccitt(std::span<const std::uint8_t> bytes,
                                        std::uint16_t crc = 0xFFFF);

// Protocol v3's DATA check: CRC-16 with polynomial 0x8BB7 (init 0xFFFF) over a
// DATA payload's ops, appended to them. An error pattern the frame's CCITT CRC
// misses is a multiple of its generator; the second generator does not divide
// it for the same reason, so together they act as a 32-bit check
// (docs/protocol.md, "Integrity").
[[nodiscard]] std::uint16_t data_check_v3(std::span<const std::uint8_t> ops);

}  // namespace tactus::encode
