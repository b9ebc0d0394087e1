// SPDX-License-Identifier: GPL-3.0-or-later
#include "translate/line_breaks.hpp"
#include "translate/break_space.hpp"

// Without ICU (TACTUS_WITH_ICU off) the system's line-breaking service
// (platform/text_breaks.hpp) applies the same rules.
#if TACTUS_HAVE_ICU
#include <unicode/brkiter.h>
#include <unicode/locid.h>
#include <unicode/unistr.h>
#else
#include "platform/text_breaks.hpp"
#endif

#include <algorithm>
#include <memory>

namespace tactus::translate {
namespace {


}  // namespace

std::vector<bool> print_break_opportunities(std::u32string_view text) {
    std::vector<bool> out(text.size() + 1, false);
    out.front() = true;
    out.back() = true;
    if (text.empty()) return out;
#if !TACTUS_HAVE_ICU
    if (auto system = platform::system_line_breaks(text)) return std::move(*system);
    for (std::size_t i = 1; i < text.size(); ++i)
        out[i] = text[i - 1] == U' ' && text[i] != U' ';
    return out;
#else
    // ICU works in UTF-16: remember which UTF-16 unit starts which code point.
    std::vector<std::uint32_t> cp_of_unit;
    cp_of_unit.reserve(text.size() + 1);
    icu::UnicodeString u16;
    for (std::size_t i = 0; i < text.size(); ++i) {
        u16.append(static_cast<UChar32>(text[i]));
        while (cp_of_unit.size() < static_cast<std::size_t>(u16.length()))
            cp_of_unit.push_back(static_cast<std::uint32_t>(i));
    }
    cp_of_unit.push_back(static_cast<std::uint32_t>(text.size()));
    UErrorCode status = U_ZERO_ERROR;
    // The root locale: UAX #14 as is, which already treats CJK ideographs as
    // break-between and keeps closing punctuation (，。) with what it follows.
    std::unique_ptr<icu::BreakIterator> it(
        icu::BreakIterator::createLineInstance(icu::Locale::getRoot(), status));
    if (U_FAILURE(status) || !it) {
        // Without ICU's data only spaces are known to separate words.
        for (std::size_t i = 1; i < text.size(); ++i)
            out[i] = text[i - 1] == U' ' && text[i] != U' ';
        return out;
    }
    it->setText(u16);
    for (int32_t b = it->first(); b != icu::BreakIterator::DONE; b = it->next())
        out[cp_of_unit[static_cast<std::size_t>(b)]] = true;
    return out;
#endif
}

LineBreaks find_line_breaks(std::u32string_view text, const document::BrailleLine& cells,
                            std::span<const std::uint32_t> source) {
    const std::size_t n = cells.size();
    LineBreaks out(n, BreakBefore::never);
    if (n == 0) return out;
    const auto print = print_break_opportunities(text);
    // A cut before cell i is clean when every cell before it comes from an
    // earlier print character than every cell from i on: liblouis puts an
    // indicator (numeric, capital, emphasis) and a contraction at the position
    // of the characters it belongs to, so a clean cut never separates them.
    std::vector<std::uint32_t> suffix_min(n + 1, static_cast<std::uint32_t>(text.size()));
    for (std::size_t i = n; i-- > 0;) suffix_min[i] = std::min(suffix_min[i + 1], source[i]);
    std::uint32_t prefix_max = source[0];
    for (std::size_t i = 1; i < n; ++i) {
        const auto before = prefix_max;
        prefix_max = std::max(prefix_max, source[i]);
        if (cells[i].blank()) {
            out[i] = BreakBefore::blank;
            continue;
        }
        const auto after = suffix_min[i];
        if (before >= after) continue;  // never: inside one print character's cells
        // The next line would start with print character `after`: may print
        // break before it? Characters between `before` and `after` gave no cells
        // of their own (liblouis folded them into a neighbour's), so the cut is
        // before `after` whatever print says about them.
        bool print_allows = after < print.size() && print[after];
        // A space that braille writes as a sign is not a word space: UEB's
        // numeric space (dot 5 inside "84 2") at a line end would read as the
        // line continuation indicator and make 842 of it.
        if (print_allows && !cells[i - 1].blank() && source[i - 1] < text.size() &&
            is_break_space(text[source[i - 1]]))
            print_allows = false;
        out[i] = print_allows ? BreakBefore::allowed : BreakBefore::between_chars;
    }
    return out;
}

}  // namespace tactus::translate
