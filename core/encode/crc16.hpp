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

}  // namespace tactus::encode
