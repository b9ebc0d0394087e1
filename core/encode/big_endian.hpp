// Multi-byte fields on the wire are big-endian: the byte order 8051 C
// compilers use in RAM, so the firmware copies them without swapping.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace tactus::encode {

inline void put16(std::vector<std::uint8_t>& o, std::uint16_t v) {
    o.push_back(static_cast<std::uint8_t>(v >> 8));
    o.push_back(static_cast<std::uint8_t>(v & 0xFF));
}
inline void put32(std::vector<std::uint8_t>& o, std::uint32_t v) {
    put16(o, static_cast<std::uint16_t>(v >> 16));
    put16(o, static_cast<std::uint16_t>(v & 0xFFFF));
}
inline std::uint16_t get16(std::span<const std::uint8_t> p, std::size_t at) {
    return static_cast<std::uint16_t>((p[at] << 8) | p[at + 1]);
}
inline std::uint32_t get32(std::span<const std::uint8_t> p, std::size_t at) {
    return (static_cast<std::uint32_t>(get16(p, at)) << 16) | get16(p, at + 2);
}

}  // namespace tactus::encode
