// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/text_position.hpp"

#include <algorithm>

namespace tactus::import::detail {

TextPosition position_at(std::string_view text, std::size_t offset) {
    TextPosition pos;
    offset = std::min(offset, text.size());
    for (std::size_t i = 0; i < offset; ++i) {
        const char c = text[i];
        if (c == '\n' || (c == '\r' && (i + 1 >= text.size() || text[i + 1] != '\n'))) {
            ++pos.line;
            pos.column = 1;
        } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80 && c != '\r') {
            ++pos.column;  // continuation bytes do not start a new character
        }
    }
    return pos;
}

LineIndex::LineIndex(std::string_view text) {
    starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n' || (c == '\r' && (i + 1 >= text.size() || text[i + 1] != '\n')))
            starts_.push_back(i + 1);
    }
}

int LineIndex::line_at(std::size_t offset) const {
    const auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
    return static_cast<int>(it - starts_.begin());
}

}  // namespace tactus::import::detail
