// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Variable-length integers for the job stream (LEB128, zig-zag for signed):
// step intervals and counts are mostly below 128, so most fields take one byte
// and the firmware decodes them with a shift and an add.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace tactus::encode {

inline void put_uvar(std::vector<std::uint8_t>& out, std::uint32_t v) {
    while (v >= 0x80) {
        out.push_back(static_cast<std::uint8_t>((v & 0x7F) | 0x80));
        v >>= 7;
    }
    out.push_back(static_cast<std::uint8_t>(v));
}

inline std::uint32_t zigzag(std::int32_t v) {
    return (static_cast<std::uint32_t>(v) << 1) ^ static_cast<std::uint32_t>(v >> 31);
}
inline std::int32_t unzigzag(std::uint32_t v) {
    return static_cast<std::int32_t>(v >> 1) ^ -static_cast<std::int32_t>(v & 1);
}

inline void put_svar(std::vector<std::uint8_t>& out, std::int32_t v) { put_uvar(out, zigzag(v)); }

// Reads a varint of at most `max_bytes` from `in` at `pos`; nullopt if truncated,
// too long, or above `max_value`.
inline std::optional<std::uint32_t> get_uvar(std::span<const std::uint8_t> in, std::size_t& pos,
                                             std::uint32_t max_value = 0xFFFFFFFFU,
                                             std::size_t max_bytes = 5) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < max_bytes; ++i) {
        if (pos >= in.size()) return std::nullopt;
        const std::uint8_t b = in[pos++];
        v |= static_cast<std::uint64_t>(b & 0x7F) << (7 * i);
        if ((b & 0x80) == 0) {
            if (v > max_value) return std::nullopt;
            return static_cast<std::uint32_t>(v);
        }
    }
    return std::nullopt;
}

inline std::optional<std::int32_t> get_svar(std::span<const std::uint8_t> in, std::size_t& pos) {
    const auto u = get_uvar(in, pos);
    if (!u) return std::nullopt;
    return unzigzag(*u);
}

}  // namespace tactus::encode
