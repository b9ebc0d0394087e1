// SPDX-License-Identifier: GPL-3.0-or-later
#include "layout/line_breaker.hpp"

#include <algorithm>

namespace tactus::layout {

std::vector<document::BrailleLine> break_lines(const document::BrailleLine& cells, int width, int first_indent,
                                     int runover_indent) {
    const auto w = static_cast<std::size_t>(std::max(width, 1));
    const auto first = static_cast<std::size_t>(std::clamp(first_indent, 0, width - 1));
    const auto runover = static_cast<std::size_t>(std::clamp(runover_indent, 0, width - 1));
    std::vector<document::BrailleLine> lines;
    document::BrailleLine line(first, document::Cell{});
    bool line_has_word = false;

    auto new_line = [&] {
        lines.push_back(std::move(line));
        line.assign(runover, document::Cell{});
        line_has_word = false;
    };

    std::size_t i = 0;
    const std::size_t n = cells.size();
    while (i < n) {
        if (cells[i].blank()) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < n && !cells[j].blank()) ++j;
        std::size_t word_len = j - i;
        const std::size_t need = word_len + (line_has_word ? 1 : 0);
        if (line.size() + need > w && line_has_word) new_line();
        if (line_has_word) line.push_back(document::Cell{});
        // Cut a word that cannot fit even on a fresh line.
        while (line.size() + word_len > w) {
            const std::size_t room = w - line.size();
            line.insert(line.end(), cells.begin() + static_cast<std::ptrdiff_t>(i),
                        cells.begin() + static_cast<std::ptrdiff_t>(i + room));
            i += room;
            word_len -= room;
            line_has_word = true;
            new_line();
        }
        line.insert(line.end(), cells.begin() + static_cast<std::ptrdiff_t>(i),
                    cells.begin() + static_cast<std::ptrdiff_t>(j));
        line_has_word = line_has_word || word_len > 0;
        i = j;
    }
    if (line_has_word || lines.empty()) lines.push_back(std::move(line));
    // A block of nothing but blanks yields one empty line, not an indented one.
    if (lines.size() == 1 && std::ranges::all_of(lines[0], &document::Cell::blank)) lines[0].clear();
    return lines;
}

}  // namespace tactus::layout
