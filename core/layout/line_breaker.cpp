// SPDX-License-Identifier: GPL-3.0-or-later
#include "layout/line_breaker.hpp"

#include <algorithm>

namespace tactus::layout {

std::vector<document::BrailleLine> break_lines(const document::BrailleLine& cells, int width, int first_indent,
                                     int runover_indent) {
    return break_lines(cells, {}, width, first_indent, runover_indent);
}

std::vector<document::BrailleLine> break_lines(const document::BrailleLine& cells, std::span<const translate::BreakBefore> breaks,
                                     int width, int first_indent, int runover_indent) {
    const auto w = static_cast<std::size_t>(std::max(width, 1));
    const auto first = static_cast<std::size_t>(std::clamp(first_indent, 0, width - 1));
    const auto runover = static_cast<std::size_t>(std::clamp(runover_indent, 0, width - 1));
    const std::size_t n = cells.size();
    // Without the translator's breaks (verbatim braille typed as a paragraph),
    // blank cells separate words and a word longer than a line may be cut anywhere.
    const auto kind = [&](std::size_t i) {
        if (i < breaks.size()) return breaks[i];
        return cells[i].blank() ? translate::BreakBefore::blank : translate::BreakBefore::between_chars;
    };
    // A unit is what lies between two places a line may end: a word, a
    // syllable of a divided word, one Chinese character.
    const auto unit_end = [&](std::size_t i) {
        std::size_t j = i + 1;
        while (j < n && !translate::is_line_break(kind(j))) ++j;
        return j;
    };

    std::vector<document::BrailleLine> lines;
    document::BrailleLine line(first, document::Cell{});
    bool line_has_word = false;
    const auto new_line = [&] {
        lines.push_back(std::move(line));
        line.assign(runover, document::Cell{});
        line_has_word = false;
    };
    const auto append = [&](std::size_t from, std::size_t to) {
        line.insert(line.end(), cells.begin() + static_cast<std::ptrdiff_t>(from),
                    cells.begin() + static_cast<std::ptrdiff_t>(to));
    };

    std::size_t i = 0;
    bool space_before = false;
    while (i < n) {
        if (cells[i].blank()) {
            space_before = true;
            ++i;
            continue;
        }
        std::size_t j = unit_end(i);
        if (kind(i) == translate::BreakBefore::paragraph && line_has_word) {
            // The next paragraph of a table cell: a line of its own at the
            // runover indent, under its entry. At the entry's own indent it
            // would read as the next entry (cell 3) or the next row (cell 1).
            new_line();
            space_before = false;
        }
        if (kind(i) == translate::BreakBefore::forced && line_has_word) new_line();
        const bool space = space_before && line_has_word;
        space_before = false;
        if (line_has_word && line.size() + (space ? 1 : 0) + (j - i) > w) new_line();
        if (space && line_has_word) line.push_back(document::Cell{});
        // A unit longer than the room left on an empty line: cut it where it
        // joins two print characters (never inside one character's cells), at
        // the last such place that fits. Only braille without the translator's
        // division (typed braille) gets here; the translator divides overlong
        // words by the code's rules before layout.
        while (line.size() + (j - i) > w) {
            const std::size_t room = w - line.size();
            std::size_t cut = 0;
            for (std::size_t k = i + room; k > i; --k)
                if (k < j && kind(k) == translate::BreakBefore::between_chars) {
                    cut = k;
                    break;
                }
            if (cut == 0) cut = i + room;  // one character wider than the line: keep every cell
            append(i, cut);
            i = cut;
            line_has_word = true;
            new_line();
        }
        append(i, j);
        line_has_word = true;
        i = j;
    }
    if (line_has_word || lines.empty()) lines.push_back(std::move(line));
    // A block of nothing but blanks yields one empty line, not an indented one.
    if (lines.size() == 1 && std::ranges::all_of(lines[0], &document::Cell::blank)) lines[0].clear();
    return lines;
}

}  // namespace tactus::layout
