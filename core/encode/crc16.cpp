// SPDX-License-Identifier: GPL-3.0-or-later
#include "encode/crc16.hpp"

#include <array>

namespace tactus::encode {
namespace {
// The same 16-entry nibble table the firmware keeps in flash (32 bytes).
constexpr std::array<std::uint16_t, 16> make_table(unsigned poly) {
    std::array<std::uint16_t, 16> t{};
    for (unsigned n = 0; n < 16; ++n) {
        unsigned crc = n << 12;
        for (int bit = 0; bit < 4; ++bit) crc = (crc & 0x8000U) ? (crc << 1) ^ poly : crc << 1;
        t[n] = static_cast<std::uint16_t>(crc & 0xFFFFU);
    }
    return t;
}
constexpr auto kTable = make_table(0x1021U);
constexpr auto kCheckTable = make_table(0x8BB7U);

std::uint16_t crc16(const std::array<std::uint16_t, 16>& table, std::span<const std::uint8_t> bytes,
                    std::uint16_t crc) {
    unsigned c = crc;
    for (const std::uint8_t b : bytes) {
        c = ((c << 4) & 0xFFFFU) ^ table[((c >> 12) ^ (b >> 4)) & 0x0FU];
        c = ((c << 4) & 0xFFFFU) ^ table[((c >> 12) ^ (b & 0x0FU)) & 0x0FU];
    }
    return static_cast<std::uint16_t>(c);
}
}  // namespace

std::uint16_t crc16_ccitt(std::span<const std::uint8_t> bytes, std::uint16_t crc) {
    return crc16(kTable, bytes, crc);
}

std::uint16_t data_check_v3(std::span<const std::uint8_t> ops) { return crc16(kCheckTable, ops, 0xFFFF); }

}  // namespace tactus::encode
