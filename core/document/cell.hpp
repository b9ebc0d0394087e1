// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A braille cell as its raised dots: bit 0 is dot 1 ... bit 7 is dot 8, the same
// order as the Unicode braille block (U+2800 + dots).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tactus::document {

struct Cell {
    std::uint8_t dots = 0;

    [[nodiscard]] constexpr bool has_dot(int n) const { return (dots >> (n - 1)) & 1u; }
    [[nodiscard]] constexpr bool blank() const { return dots == 0; }
    [[nodiscard]] constexpr char32_t unicode() const { return char32_t{0x2800} + dots; }
    static constexpr bool is_unicode_braille(char32_t c) { return c >= 0x2800 && c <= 0x28FF; }
    static constexpr Cell from_unicode(char32_t c) {
        return Cell{static_cast<std::uint8_t>(c - 0x2800)};
    }
    constexpr bool operator==(const Cell&) const = default;
};

using BrailleLine = std::vector<Cell>;

// North American Braille ASCII (the BRF code page): 64 six-dot patterns.
// Returns false for characters outside it.
bool cell_from_brf(char c, Cell& out);
char cell_to_brf(Cell c);  // dots 7 and 8 are dropped: BRF is six-dot

std::string to_unicode_text(const BrailleLine& line);
// "1-2-5" style dot numbers for screen readers and messages ("blank" for none).
std::string dot_numbers(Cell c);

}  // namespace tactus::document
