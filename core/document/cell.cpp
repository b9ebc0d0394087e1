// SPDX-License-Identifier: GPL-3.0-or-later
#include "document/cell.hpp"

#include <array>

#include "common/utf8.hpp"

namespace tactus::document {
namespace {

// Braille ASCII, indexed by ASCII - 0x20: the dot pattern of each character.
constexpr std::array<std::uint8_t, 64> kBrfDots = {
    0x00, 0x2E, 0x10, 0x3C, 0x2B, 0x29, 0x2F, 0x04,  //  !"#$%&'
    0x37, 0x3E, 0x21, 0x2C, 0x20, 0x24, 0x28, 0x0C,  // ()*+,-./
    0x34, 0x02, 0x06, 0x12, 0x32, 0x22, 0x16, 0x36,  // 01234567
    0x26, 0x14, 0x31, 0x30, 0x23, 0x3F, 0x1C, 0x39,  // 89:;<=>?
    0x08, 0x01, 0x03, 0x09, 0x19, 0x11, 0x0B, 0x1B,  // @ABCDEFG
    0x13, 0x0A, 0x1A, 0x05, 0x07, 0x0D, 0x1D, 0x15,  // HIJKLMNO
    0x0F, 0x1F, 0x17, 0x0E, 0x1E, 0x25, 0x27, 0x3A,  // PQRSTUVW
    0x2D, 0x3D, 0x35, 0x2A, 0x33, 0x3B, 0x18, 0x38,  // XYZ[\]^_
};

constexpr std::array<char, 64> make_reverse() {
    std::array<char, 64> r{};
    for (std::size_t i = 0; i < kBrfDots.size(); ++i)
        r[kBrfDots[i]] = static_cast<char>(0x20 + i);
    return r;
}
constexpr auto kDotsToBrf = make_reverse();

}  // namespace

bool cell_from_brf(char c, Cell& out) {
    auto u = static_cast<unsigned char>(c);
    if (u >= 'a' && u <= 'z') u = static_cast<unsigned char>(u - 0x20);
    else if (u == '`') u = '@';
    else if (u == '{') u = '[';
    else if (u == '|') u = '\\';
    else if (u == '}') u = ']';
    else if (u == '~') u = '^';
    if (u < 0x20 || u > 0x5F) return false;
    out = Cell{kBrfDots[u - 0x20]};
    return true;
}

char cell_to_brf(Cell c) { return kDotsToBrf[c.dots & 0x3F]; }

std::string to_unicode_text(const BrailleLine& line) {
    std::string out;
    out.reserve(line.size() * 3);
    for (Cell c : line) append_utf8(out, c.unicode());
    return out;
}

std::string dot_numbers(Cell c) {
    if (c.blank()) return "blank";
    std::string out;
    for (int d = 1; d <= 8; ++d) {
        if (!c.has_dot(d)) continue;
        if (!out.empty()) out += '-';
        out += static_cast<char>('0' + d);
    }
    return out;
}

}  // namespace tactus::document
