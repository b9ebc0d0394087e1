// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The test's own oracle for "no line break inside a symbol": liblouis called
// directly (not through Tactus), with its input position of every output cell.
#include <liblouis/liblouis.h>

#include <algorithm>
#include <string>
#include <vector>

#include "document/cell.hpp"

struct LouisOracle {
    tactus::document::BrailleLine cells;
    std::vector<int> source;  // print character index of each cell

    // A cut before cell i keeps every print character's cells together.
    [[nodiscard]] bool clean_cut(std::size_t i) const {
        if (i == 0 || i >= cells.size()) return true;
        const int before = *std::max_element(source.begin(), source.begin() + static_cast<std::ptrdiff_t>(i));
        const int after = *std::min_element(source.begin() + static_cast<std::ptrdiff_t>(i), source.end());
        return before < after;
    }
};

inline LouisOracle louis_oracle(const std::string& table, const std::u32string& text) {
    static_assert(sizeof(widechar) == sizeof(char32_t));
    LouisOracle o;
    int inlen = static_cast<int>(text.size());
    int outlen = inlen * 8 + 64;
    std::vector<widechar> out(static_cast<std::size_t>(outlen));
    std::vector<int> in_pos(static_cast<std::size_t>(outlen));
    const std::string list = "unicode.dis," + table;
    if (!lou_translate(list.c_str(), reinterpret_cast<const widechar*>(text.data()), &inlen, out.data(),
                       &outlen, nullptr, nullptr, nullptr, in_pos.data(), nullptr, 0))
        return o;
    for (int i = 0; i < outlen; ++i) {
        const auto c = static_cast<char32_t>(out[static_cast<std::size_t>(i)]);
        o.cells.push_back(tactus::document::Cell::is_unicode_braille(c) ? tactus::document::Cell::from_unicode(c) : tactus::document::Cell{});
        o.source.push_back(in_pos[static_cast<std::size_t>(i)]);
    }
    return o;
}
