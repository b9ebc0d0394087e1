// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where a braille line may end, found from the print text and liblouis's
// input/output position mapping, never guessed from the cells: a line may end
// only where the print allows it (Unicode line breaking, UAX #14: after a space,
// after a hyphen or dash, between CJK characters) and only where the cells
// before and after come from different print characters, so no sign, indicator
// or contraction is cut in two.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "document/cell.hpp"

namespace tactus::translate {

// What may happen between cell i-1 and cell i (entry 0 is always `never`).
enum class BreakBefore : std::uint8_t {
    never,          // inside the cells of one print character (a sign, an indicator, a contraction)
    between_chars,  // between print characters of one word: only an overlong word is divided here
    blank,          // cell i is blank: a word space, dropped at a line end
    allowed,        // print allows a break here with nothing added (after a hyphen or
                    // dash, between CJK characters)
    forced,         // a divided word goes on here: the line ends before cell i
    paragraph,      // cell i starts the next paragraph of a table cell (document.hpp,
                    // table_cell): the line ends before it and the next line starts
                    // at the block's runover indent
};

using LineBreaks = std::vector<BreakBefore>;

// `source[i]` is the index in `text` of the print character cell i was made
// from (liblouis's inputPos). `source.size() == cells.size()`.
LineBreaks find_line_breaks(std::u32string_view text, const document::BrailleLine& cells,
                            std::span<const std::uint32_t> source);

// True where the print text may be broken before character i (UAX #14 through
// ICU's line break iterator); entry 0 and entry text.size() are true.
std::vector<bool> print_break_opportunities(std::u32string_view text);

// May a line end before cell i? (blank, allowed, forced or paragraph)
constexpr bool is_line_break(BreakBefore b) {
    return b == BreakBefore::blank || b == BreakBefore::allowed || b == BreakBefore::forced ||
           b == BreakBefore::paragraph;
}

}  // namespace tactus::translate
