// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Byte offsets -> line:column for error messages. Lines end at LF, CRLF or a lone
// CR; columns count Unicode code points (UTF-8 input), both 1-based.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace tactus::import::detail {

struct TextPosition {
    int line = 1;
    int column = 1;
    [[nodiscard]] std::string to_string() const {
        return std::to_string(line) + ":" + std::to_string(column);
    }
};

TextPosition position_at(std::string_view text, std::size_t offset);

// For many look-ups in one text (line of each Markdown block, each PEF page):
// the offsets where lines start, searched in O(log n).
class LineIndex {
public:
    explicit LineIndex(std::string_view text);
    [[nodiscard]] int line_at(std::size_t offset) const;

private:
    std::vector<std::size_t> starts_;
};

}  // namespace tactus::import::detail
