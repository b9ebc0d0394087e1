// SPDX-License-Identifier: GPL-3.0-or-later
#include "translate/word_division.hpp"
#include "translate/break_space.hpp"
#include "common/try.hpp"

#include <algorithm>
#include <optional>

namespace tactus::translate {
namespace {

bool is_digit(char32_t c) { return c >= U'0' && c <= U'9'; }

// Index of the first cell made from print character `q` or later: where a cut
// before character q falls in the cells, if it is clean (no cell of an earlier
// character after it).
std::optional<std::size_t> cell_cut(const MappedBraille& m, std::uint32_t q) {
    std::size_t k = 0;
    while (k < m.source.size() && m.source[k] < q) ++k;
    for (std::size_t i = k; i < m.source.size(); ++i)
        if (m.source[i] < q) return std::nullopt;
    return k;
}

class Divider {
public:
    Divider(const Translator& tr, std::u32string_view word, std::span<const std::uint8_t> emphasis,
            std::size_t room, const PieceSink& sink)
        : tr_(tr), word_(word), emphasis_(emphasis), room_(room),
          rules_(tr.division_rules()), hyphenation_(tr.hyphenation_points(word)), sink_(sink),
          short_window_(!tr.has_word_wide_rules() && std::ranges::none_of(word, is_break_space) &&
                        std::ranges::all_of(emphasis, [](std::uint8_t e) { return e == 0; })) {}

    Result<void> run() {
        while (pos_ < word_.size()) {
            // The rest of the word as a line starting here shows it, translated
            // through a window just long enough for the line's cells and
            // `kLookahead` characters after them, not through a fixed window
            // of four lines: a text without spaces is a divided word from end
            // to end, and a fixed window would be most of its cost.
            MappedBraille rest;
            std::size_t end = 0;
            std::size_t window = first_window();
            for (;;) {
                end = std::min(word_.size(), pos_ + window);
                TACTUS_TRY(r, translate(end, false));
                rest = std::move(r);
                if (end == word_.size() || enough(rest, end)) break;
                // Too few cells: twice the characters; else the characters
                // the line's cells came from and the lookahead.
                window = rest.cells.size() <= room_ || !short_window_ ? window * 2 : span_ + kLookahead;
            }
            if (end == word_.size() && rest.cells.size() <= room_) {
                sink_(std::move(rest.cells));
                break;
            }
            TACTUS_TRY_VOID(next_piece(end, rest));
        }
        return {};
    }

private:
    // Characters of the word translated after the last one a line's cells
    // come from, so that the end of the window does not change how those
    // cells are written. No lookahead is provably enough: liblouis's `match`
    // rules repeat (en-ueb-chardefs.uti: `%[a#]%[_.$]*`), its capitals and
    // emphasis modes look to the end of a word, and whether `"` opens or
    // closes a quotation depends on what follows it. Measured instead with
    // the equivalence test (tests/translate/word_division_equivalence_test.cpp)
    // over many seeds and the golden lines of
    // tests/data/layout/unspaced-lines.brf: with no lookahead one seed in
    // about ten gives another line (en-ueb-g2, a closing quote before the
    // window's end read as an opening one); with 8 characters every seed
    // gives the old lines. Each character of lookahead is one more character
    // translated for every line (of the 14 to 25 a line of such text holds).
    static constexpr std::size_t kLookahead = 8;

    // The first window: as many characters as the last line's cells came
    // from (a line's worth when none was made yet) and the lookahead.
    [[nodiscard]] std::size_t first_window() const {
        if (!short_window_) return 4 * room_ + 16;
        return (span_ > 0 ? span_ + 2 : room_ + 1) + kLookahead;
    }

    // Does the window hold a line's cells (one more than the line holds, as
    // the division search reads them) with `kLookahead` characters of the
    // word after the last character any of those cells comes from? `span_`
    // is set to the characters those cells came from.
    [[nodiscard]] bool enough(const MappedBraille& rest, std::size_t end) {
        if (!short_window_) return rest.cells.size() > room_ + 8;
        if (rest.cells.size() <= room_) return false;
        std::size_t last = 0;
        for (std::size_t k = 0; k <= room_; ++k) last = std::max<std::size_t>(last, rest.source[k]);
        span_ = last + 1;
        return pos_ + span_ + kLookahead <= end;
    }

    // Translation of word[pos_, to) (+ a hyphen), as a line starting there shows it.
    Result<MappedBraille> translate(std::size_t to, bool with_hyphen) {
        std::u32string text(word_.substr(pos_, to - pos_));
        std::vector<std::uint8_t> emph;
        if (!emphasis_.empty())
            emph.assign(emphasis_.begin() + static_cast<std::ptrdiff_t>(pos_),
                        emphasis_.begin() + static_cast<std::ptrdiff_t>(to));
        if (with_hyphen) {
            text.push_back(U'-');
            if (!emph.empty()) emph.push_back(emph.back());
        }
        auto m = tr_.translate_mapped(text, emph);
        if (!m) return m;
        // After a divided number the next line goes on in numeric mode: its
        // numeric indicator is left out (UEB 6.10.5).
        const auto& ni = rules_.numeric_indicator;
        if (continues_number_ && !ni.empty() && m->cells.size() > ni.size() &&
            std::equal(ni.begin(), ni.end(), m->cells.begin())) {
            const auto n = static_cast<std::ptrdiff_t>(ni.size());
            m->cells.erase(m->cells.begin(), m->cells.begin() + n);
            m->source.erase(m->source.begin(), m->source.begin() + n);
        }
        return m;
    }

    void accept(document::BrailleLine cells, std::size_t next, bool continues_number) {
        sink_(std::move(cells));
        pos_ = next;
        continues_number_ = continues_number;
    }

    Result<void> next_piece(std::size_t end, const MappedBraille& rest) {
        // The last print character whose cells still start within the line.
        std::size_t hint = pos_ + 1;
        for (std::size_t k = 0; k < rest.cells.size() && k < room_; ++k)
            hint = std::max<std::size_t>(hint, pos_ + rest.source[k] + 1);
        hint = std::min(hint, end - 1);
        // First syllable boundaries (and digit boundaries, which a number has
        // instead), then any boundary between two print characters.
        for (int pass = 0; pass < 2; ++pass) {
            for (std::size_t q = hint; q > pos_; --q) {
                const bool digits = is_digit(word_[q - 1]) && is_digit(word_[q]);
                // A space inside a word is UEB's numeric space ("6 1" is one number).
                const bool numeric_space = q >= pos_ + 2 && is_break_space(word_[q - 1]) && is_digit(word_[q - 2]) &&
                                           is_digit(word_[q]);
                if ((is_break_space(word_[q - 1]) || is_break_space(word_[q])) && !numeric_space) continue;
                const bool syllable = q < hyphenation_.size() && hyphenation_[q];
                if (pass == 0 && !digits && !numeric_space && !syllable) continue;
                if ((digits || numeric_space) && rules_.number_continuation) {
                    // UEB 6.10.3: between digits, the one-cell continuation
                    // indicator; 6.10.4: at a numeric space, the two-cell one in
                    // its place.
                    const auto at = numeric_space ? q - 1 : q;
                    const std::size_t signs = numeric_space ? 2 : 1;
                    const auto k = cell_cut(rest, static_cast<std::uint32_t>(at - pos_));
                    if (!k || *k == 0 || *k + signs > room_) continue;
                    document::BrailleLine cells(rest.cells.begin(),
                                                rest.cells.begin() + static_cast<std::ptrdiff_t>(*k));
                    cells.insert(cells.end(), signs, *rules_.number_continuation);
                    accept(std::move(cells), q, true);
                    return {};
                }
                if (numeric_space) continue;
                TACTUS_TRY(left, translate(q, true));
                if (left.cells.size() <= room_) {
                    accept(std::move(left.cells), q, false);
                    return {};
                }
            }
        }
        // Nothing fits: the first print character alone is wider than the line
        // (a long escape for a character the table does not know). Its cells go
        // on as many lines as they need; no cell is lost.
        std::size_t q = pos_ + 1;
        std::optional<std::size_t> k;
        for (; q < end; ++q)
            if ((k = cell_cut(rest, static_cast<std::uint32_t>(q - pos_))) && *k > 0) break;
        const std::size_t cells_of_first = q < end && k ? *k : rest.cells.size();
        for (std::size_t s = 0; s < cells_of_first; s += room_) {
            const auto e = std::min(cells_of_first, s + room_);
            sink_(document::BrailleLine(rest.cells.begin() + static_cast<std::ptrdiff_t>(s),
                                        rest.cells.begin() + static_cast<std::ptrdiff_t>(e)));
        }
        pos_ = q;
        continues_number_ = false;
        return {};
    }

    const Translator& tr_;
    std::u32string_view word_;
    std::span<const std::uint8_t> emphasis_;
    std::size_t room_;
    const DivisionRules& rules_;
    std::vector<bool> hyphenation_;
    const PieceSink& sink_;
    std::size_t pos_ = 0;
    bool continues_number_ = false;
    std::size_t span_ = 0;  // characters the last window's line of cells came from
    // A window of one line and the lookahead, for a word without spaces or
    // emphasis, in a table without word-wide rules. Emphasis and capitals over
    // several words are marked by a passage indicator, which liblouis chooses
    // by counting the words of the passage to its end, and a `compbrl` rule
    // writes a whole word in computer braille when a character anywhere in it
    // asks for it: there the window stays four lines long, as before.
    bool short_window_;
};

}  // namespace

Result<std::vector<document::BrailleLine>> divide_word(const Translator& translator, std::u32string_view word,
                                             std::span<const std::uint8_t> emphasis,
                                             std::size_t room) {
    std::vector<document::BrailleLine> pieces;
    auto ok = divide_word(translator, word, emphasis, room,
                          [&pieces](document::BrailleLine&& piece) { pieces.push_back(std::move(piece)); });
    if (!ok) return std::unexpected(ok.error());
    return pieces;
}

Result<void> divide_word(const Translator& translator, std::u32string_view word, std::span<const std::uint8_t> emphasis,
                         std::size_t room, const PieceSink& sink) {
    if (room == 0) return fail(ErrorKind::internal, "no room to divide a word into");
    return Divider(translator, word, emphasis, room, sink).run();
}

}  // namespace tactus::translate
