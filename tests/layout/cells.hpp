// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Test helpers: write braille as Braille ASCII so expectations stay readable.
#include <string>
#include <string_view>

#include "document/cell.hpp"

inline tactus::document::BrailleLine brf(std::string_view s) {
    tactus::document::BrailleLine out;
    for (char c : s) {
        tactus::document::Cell cell;
        if (!tactus::document::cell_from_brf(c, cell)) throw std::invalid_argument("not BRF");
        out.push_back(cell);
    }
    return out;
}

inline std::string brf(const tactus::document::BrailleLine& line) {
    std::string out;
    for (auto c : line) out.push_back(tactus::document::cell_to_brf(c));
    return out;
}
