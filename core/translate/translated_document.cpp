// SPDX-License-Identifier: GPL-3.0-or-later
#include "translate/translated_document.hpp"

#include <algorithm>
#include <array>
#include <span>

#include "common/utf8.hpp"
#include "document/cell_paragraphs.hpp"
#include "document/soft_break.hpp"
#include "translate/code_switch.hpp"
#include "translate/language_switch.hpp"
#include "translate/word_division.hpp"
#include "common/try.hpp"

namespace tactus::translate {
namespace {

constexpr std::size_t kChunk = 4096;  // code points per liblouis call

// Joins spans into one string with an emphasis mark per code point. Line breaks
// and tabs inside a block become spaces: layout decides where braille lines end;
// a soft line break with the spaces around it is one space (document/soft_break.hpp).
// Decoded straight into `text`, reserved once: decoding a 50 MB paragraph into
// a copy and then pushing it code point by code point peaked at 720 MB.
// `marks`, when the translator switches tables by language and a span is
// marked with one, gets the table of every code point (TableSlot::unmarked
// for a span without a language); it stays empty otherwise.
Result<void> flatten(std::span<const document::Span> spans, std::u32string& text, std::vector<std::uint8_t>& emph,
                     const LanguageSwitch* language_switch, std::vector<TableSlot>& marks) {
    const bool marked = language_switch && std::ranges::any_of(spans, [](const document::Span& s) { return !s.language.empty(); });
    std::size_t bytes = 0;
    for (const auto& span : spans) bytes += span.text.size();
    text.reserve(text.size() + bytes);
    emph.reserve(emph.size() + bytes);
    for (const auto& span : spans) {
        const bool soft_break = span.text.find_first_of("\r\n") != std::string::npos;
        const auto start = text.size();
        if (auto ok = append_utf32(text, soft_break ? document::soft_breaks_as_spaces(span.text) : span.text); !ok)
            return ok;
        for (auto i = start; i < text.size(); ++i)
            if (const auto c = text[i]; c == U'\n' || c == U'\r' || c == U'\t' || c == U'\f' || c == U'\v') text[i] = U' ';
        emph.resize(text.size(), span.emphasis);
        if (marked) marks.resize(text.size(), language_switch->slot_for_language(span.language));
    }
    return {};
}

// Appends one piece of text (at most kChunk code points) to the block's cells
// and breaks; a unit longer than `room` cells is divided by the code's rules.
class BlockWriter {
public:
    BlockWriter(const Translator& tr, std::size_t room, TranslatedBlock& out)
        : tr_(tr), room_(room), out_(out) {}

    Result<void> add(std::u32string_view text, std::span<const std::uint8_t> emph, BreakBefore join) {
        TACTUS_TRY(m, tr_.translate_mapped(text, emph));
        auto breaks = find_line_breaks(text, m.cells, m.source);
        if (!breaks.empty()) breaks[0] = m.cells[0].blank() ? BreakBefore::blank : join;
        const std::size_t n = m.cells.size();
        std::size_t i = 0;
        while (i < n) {
            std::size_t j = i + 1;
            while (j < n && !is_line_break(breaks[j])) ++j;
            if (room_ > 0 && j - i > room_ && !m.cells[i].blank()) {
                if (auto ok = divide(text, emph, m, breaks[i], i, j); !ok) return ok;
            } else {
                out_.cells.insert(out_.cells.end(), m.cells.begin() + static_cast<std::ptrdiff_t>(i),
                                  m.cells.begin() + static_cast<std::ptrdiff_t>(j));
                out_.breaks.insert(out_.breaks.end(), breaks.begin() + static_cast<std::ptrdiff_t>(i),
                                   breaks.begin() + static_cast<std::ptrdiff_t>(j));
            }
            i = j;
        }
        return {};
    }

    // A word too long to translate in one piece: divided straight away.
    Result<void> add_long_word(std::u32string_view word, std::span<const std::uint8_t> emph, BreakBefore join) {
        if (room_ == 0) return add(word, emph, join);
        // Each line straight into the block's cells, never all the lines at once.
        bool first = true;
        return divide_word(tr_, word, emph, room_, [&](document::BrailleLine&& piece) { append_piece(piece, first, join); });
    }

private:
    void append_piece(const document::BrailleLine& piece, bool& first, BreakBefore first_break) {
        if (piece.empty()) return;
        out_.breaks.push_back(first ? first_break : BreakBefore::forced);
        out_.breaks.insert(out_.breaks.end(), piece.size() - 1, BreakBefore::never);
        out_.cells.insert(out_.cells.end(), piece.begin(), piece.end());
        first = false;
    }

    Result<void> append_pieces(Result<std::vector<document::BrailleLine>> pieces, BreakBefore first_break) {
        if (!pieces) return std::unexpected(pieces.error());
        bool first = true;
        for (const auto& piece : *pieces) append_piece(piece, first, first_break);
        return {};
    }

    // The print word behind cells [i, j) is translated again piece by piece.
    Result<void> divide(std::u32string_view text, std::span<const std::uint8_t> emph,
                        const MappedBraille& m, BreakBefore first_break, std::size_t i, std::size_t j) {
        const auto [lo, hi] = std::minmax_element(m.source.begin() + static_cast<std::ptrdiff_t>(i),
                                                  m.source.begin() + static_cast<std::ptrdiff_t>(j));
        const std::size_t a = *lo, b = std::min<std::size_t>(*hi + 1, text.size());
        return append_pieces(divide_word(tr_, text.substr(a, b - a),
                                         emph.empty() ? emph : emph.subspan(a, b - a), room_),
                             first_break);
    }

    const Translator& tr_;
    std::size_t room_;
    TranslatedBlock& out_;
};

Result<void> translate_text(const Translator& tr, std::u32string_view text,
                            std::span<const std::uint8_t> emph, std::size_t room, TranslatedBlock& out,
                            const std::function<void(std::size_t)>& progress, BreakBefore join) {
    const bool any_emphasis =
        std::ranges::any_of(emph, [](std::uint8_t e) { return e != document::emphasis_none; });
    const auto emph_of = [&](std::size_t from, std::size_t n) {
        return any_emphasis ? emph.subspan(from, n) : std::span<const std::uint8_t>{};
    };
    BlockWriter writer(tr, room, out);
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = std::min(text.size(), start + kChunk);
        if (end < text.size()) {
            // Cut after a space, searching this chunk only; without a space (Chinese
            // has none) at the last place print allows a break. Either way no
            // contraction or sign spans the cut.
            const auto piece = text.substr(start, end - start);
            const auto space = piece.rfind(U' ');
            std::size_t cut = space != std::u32string_view::npos && space > 0 ? space + 1 : 0;
            if (cut == 0) {
                const auto print = print_break_opportunities(piece);
                for (std::size_t i = piece.size(); i-- > 1;)
                    if (print[i]) {
                        cut = i;
                        break;
                    }
            }
            if (cut == 0) {
                // One word of more than kChunk characters: divided as a whole, up
                // to the next space, without translating it first.
                const auto next_space = text.find(U' ', start);
                const std::size_t word_end = next_space == std::u32string_view::npos ? text.size() : next_space;
                if (auto ok = writer.add_long_word(text.substr(start, word_end - start),
                                                   emph_of(start, word_end - start), join);
                    !ok)
                    return ok;
                start = word_end;
                join = BreakBefore::allowed;
                if (progress) progress(start);
                continue;
            }
            end = start + cut;
        }
        if (auto ok = writer.add(text.substr(start, end - start), emph_of(start, end - start), join); !ok)
            return ok;
        join = BreakBefore::allowed;
        start = end;
        if (progress) progress(start);
    }
    return {};
}

void attach_cells(TranslatedBlock& out, std::span<const document::Cell> cells, BreakBefore first) {
    if (cells.empty()) return;
    const auto at = out.cells.size();
    out.cells.insert(out.cells.end(), cells.begin(), cells.end());
    out.breaks.resize(out.cells.size(), BreakBefore::never);
    out.breaks[at] = first;
}

bool is_word_space(char32_t c) { return c == U' ' || c == 0x3000 || c == 0xA0; }

// A run of the other language with the signs its rule puts around it
// (translate/code_switch.hpp). `text` is the whole text the run is part of,
// for what comes before and after it; the first cell written may start a
// line as `first` says, the signs are never parted from the run.
Result<void> translate_foreign_run(const Translator& tr, SwitchForm form, std::u32string_view text, LanguageRun run,
                                   std::span<const std::uint8_t> emph, std::size_t room, TranslatedBlock& out,
                                   BreakBefore first) {
    const auto emph_of = [&](std::size_t from, std::size_t n) {
        return emph.empty() ? emph : emph.subspan(from, n);
    };
    const bool unspaced_before = run.begin > 0 && !is_word_space(text[run.begin - 1]);
    const bool unspaced_after = run.end < text.size() && !is_word_space(text[run.end]);
    const auto body = text.substr(run.begin, run.end - run.begin);
    switch (form) {
        case SwitchForm::none:
            return translate_text(tr, body, emph_of(run.begin, body.size()), room, out, {}, first);
        case SwitchForm::passage: {
            attach_cells(out, kNonUebOpen, first);
            if (auto ok = translate_text(tr, body, emph_of(run.begin, body.size()), room, out, {}, BreakBefore::never); !ok)
                return ok;
            attach_cells(out, kNonUebClose, BreakBefore::never);
            return {};
        }
        case SwitchForm::letter_sign: {
            BreakBefore next = first;
            if (unspaced_before) {
                attach_cells(out, kLetterSign, first);
                next = BreakBefore::never;
            }
            if (auto ok = translate_text(tr, body, emph_of(run.begin, body.size()), room, out, {}, next); !ok) return ok;
            // The space the code puts between Latin letters and the Chinese after them.
            if (unspaced_after) attach_cells(out, std::array{document::Cell{}}, BreakBefore::blank);
            return {};
        }
        case SwitchForm::word:
            break;
    }
    // UEB §14.3.1: the word indicator before every symbols-sequence; its
    // effect ends at the next space, else at the word terminator.
    BreakBefore next = first;
    for (std::size_t i = run.begin; i < run.end;) {
        if (is_word_space(text[i])) {
            attach_cells(out, std::array{document::Cell{}}, BreakBefore::blank);
            while (i < run.end && is_word_space(text[i])) ++i;
            next = BreakBefore::allowed;
            continue;
        }
        std::size_t j = i;
        while (j < run.end && !is_word_space(text[j])) ++j;
        attach_cells(out, kNonUebWord, next);
        if (auto ok = translate_text(tr, text.substr(i, j - i), emph_of(i, j - i), room, out, {}, BreakBefore::never); !ok)
            return ok;
        if (j == run.end && unspaced_after) attach_cells(out, kNonUebWordEnd, BreakBefore::never);
        i = j;
    }
    return {};
}

// Text of a block, each run of another language with its own table when the
// translator switches tables (translate/language_switch.hpp); otherwise, or
// when the text is all in the document's language, exactly translate_text.
Result<void> translate_languages(const Translator& tr, std::u32string_view text, std::span<const std::uint8_t> emph,
                                 std::span<const TableSlot> marks, std::size_t room, TranslatedBlock& out,
                                 const std::function<void(std::size_t)>& progress, BreakBefore join) {
    const auto* sw = tr.language_switch();
    if (!sw) return translate_text(tr, text, emph, room, out, progress, join);
    const auto runs = sw->split(text, marks);
    if (runs.size() <= 1 && (runs.empty() || runs.front().slot == TableSlot::primary))
        return translate_text(tr, text, emph, room, out, progress, join);
    const bool any_emphasis =
        std::ranges::any_of(emph, [](std::uint8_t e) { return e != document::emphasis_none; });
    const auto whole_emph = any_emphasis ? emph : std::span<const std::uint8_t>{};
    const auto print = print_break_opportunities(text);
    for (const auto& run : runs) {
        // Where the run meets what came before: after a word space a line may
        // end, else where print allows a break (between Chinese and Latin).
        BreakBefore first = join;
        if (run.begin > 0)
            first = !out.cells.empty() && out.cells.back().blank() ? BreakBefore::allowed
                    : print[run.begin]                              ? BreakBefore::allowed
                                                                    : BreakBefore::between_chars;
        const auto body = text.substr(run.begin, run.end - run.begin);
        if (run.slot == TableSlot::primary) {
            if (auto ok = translate_text(tr, body, whole_emph.empty() ? whole_emph : whole_emph.subspan(run.begin, body.size()),
                                         room, out, {}, first);
                !ok)
                return ok;
        } else {
            auto other = sw->translator(run.slot);
            if (!other) return std::unexpected(other.error());
            if (auto ok = translate_foreign_run(**other, switch_form(sw->indicators(), body), text, run, whole_emph,
                                                room, out, first);
                !ok)
                return ok;
        }
        if (progress) progress(run.end);
    }
    return {};
}

// A note reference, attached to the word before it (never a line break in
// front of it or inside it): the code's note reference indicator and the
// number, or, for a code without one, the number in parentheses as the code
// writes them (every table Tactus lists knows them; square brackets are unknown
// to zh-tw), the way print without superscripts marks a note
// (Translator::note_reference_indicator, docs/layout.md "Notes").
// `number`: the reference's number. Empty: only the indicator is written; the
// number goes in front of the print text that follows it unspaced, translated
// with it (translate_spans).
Result<void> translate_note_reference(const Translator& tr, std::u32string number, TranslatedBlock& out) {
    const auto& indicator = tr.note_reference_indicator();
    out.cells.insert(out.cells.end(), indicator.begin(), indicator.end());
    if (!number.empty()) {
        if (indicator.empty()) number = U"(" + number + U")";
        TACTUS_TRY(cells, tr.translate(number));
        out.cells.insert(out.cells.end(), cells.begin(), cells.end());
    }
    out.breaks.resize(out.cells.size(), BreakBefore::never);
    return {};
}

// Spans written by a rule of their own rather than as running print text.
bool is_marked(const document::Span& s) {
    return s.note_reference || s.transcriber_note || s.position != document::Position::baseline;
}

// Whether print text follows a note reference with no space between: its
// first character is not a space.
bool follows_unspaced(std::span<const document::Span> spans, std::size_t i) {
    return i + 1 < spans.size() && !is_marked(spans[i + 1]) && !spans[i + 1].text.empty() &&
           spans[i + 1].text.front() != ' ';
}

constexpr document::Cell kSuperscript{0x14};    // dots 35: UEB superscript indicator
constexpr document::Cell kSubscript{0x22};      // dots 26: UEB subscript indicator
constexpr document::Cell kOpenGroup{0x23};      // dots 126: UEB grouping indicators
constexpr document::Cell kCloseGroup{0x1C};     // dots 345

// UEB is the code whose note reference indicator is its superscript
// indicator (Translator::note_reference_indicator: ⠔, after ⠰ in
// contracted braille).
bool is_ueb(const Translator& tr) {
    const auto& n = tr.note_reference_indicator();
    return !n.empty() && n.back() == kSuperscript;
}

void attach(TranslatedBlock& out, std::span<const document::Cell> cells) {
    out.cells.insert(out.cells.end(), cells.begin(), cells.end());
    out.breaks.resize(out.cells.size(), BreakBefore::never);
}

Result<void> translate_run(const Translator& tr, std::string_view utf8, std::uint8_t emphasis,
                           std::size_t room, TranslatedBlock& out, BreakBefore join) {
    TACTUS_TRY(u, utf8_to_utf32(utf8));
    std::vector<std::uint8_t> emph(u.size(), emphasis);
    return translate_text(tr, u, emph, room, out, {}, join);
}

// One item after a level indicator needs no grouping (UEB §3.24: the
// indicator applies to the next symbol, number or group): a number, or one
// print character.
bool is_one_item(std::u32string_view t) {
    if (t.size() == 1) return true;
    return !t.empty() && std::ranges::all_of(t, [](char32_t c) { return (c >= U'0' && c <= U'9') || c == U'.' || c == U','; }) &&
           t.front() >= U'0' && t.front() <= U'9';
}

// A raised or lowered run (UEB §3.24, Rules of Unified English Braille 2013):
// the level indicator, ⠔ superscript or ⠢ subscript (after ⠰, grade 1 mode,
// in contracted braille, as the code's note reference indicator has it),
// then the run; more than one item is enclosed in grouping indicators ⠣ ⠜.
// Other codes: Tactus knows no level indicators of theirs; the run is
// written as running text.
Result<void> translate_positioned(const Translator& tr, const document::Span& s, std::size_t room,
                                  TranslatedBlock& out) {
    if (!is_ueb(tr)) return translate_run(tr, s.text, s.emphasis, room, out, BreakBefore::never);
    TACTUS_TRY(u, utf8_to_utf32(s.text));
    const auto first = u.find_first_not_of(U' ');
    const auto last = u.find_last_not_of(U' ');
    if (first == std::u32string::npos) return translate_run(tr, s.text, s.emphasis, room, out, BreakBefore::never);
    const std::u32string_view item = std::u32string_view(u).substr(first, last - first + 1);
    document::BrailleLine indicator = tr.note_reference_indicator();
    indicator.back() = s.position == document::Position::superscript ? kSuperscript : kSubscript;
    const bool group = !is_one_item(item);
    if (group) indicator.push_back(kOpenGroup);
    attach(out, indicator);
    std::vector<std::uint8_t> emph(item.size(), s.emphasis);
    if (auto ok = translate_text(tr, item, emph, room, out, {}, BreakBefore::never); !ok) return ok;
    if (group) attach(out, std::array{kCloseGroup});
    return {};
}

// Transcriber's note indicators (Braille Formats 2016 §2.3, UEB §3.27):
// ⠈⠨⠣ before the note, ⠈⠨⠜ after it. Other codes: in parentheses.
Result<void> translate_transcriber_note(const Translator& tr, const document::Span& s, std::size_t room,
                                        TranslatedBlock& out) {
    const bool ueb = is_ueb(tr);
    const auto open_at = out.cells.size();
    if (ueb) {
        attach(out, std::array{document::Cell{0x08}, document::Cell{0x28}, kOpenGroup});
        if (auto ok = translate_run(tr, s.text, s.emphasis, room, out, BreakBefore::never); !ok) return ok;
        attach(out, std::array{document::Cell{0x08}, document::Cell{0x28}, kCloseGroup});
    } else if (auto ok = translate_run(tr, "(" + s.text + ")", s.emphasis, room, out, BreakBefore::never); !ok) {
        return ok;
    }
    // The note starts a word of its own when a space comes before it.
    if (open_at > 0 && open_at < out.breaks.size() && out.cells[open_at - 1].blank())
        out.breaks[open_at] = BreakBefore::allowed;
    return {};
}

// The spans of a text block: runs of print text translated as one text each,
// note references between them written by their own rule.
Result<void> translate_spans(const Translator& tr, std::span<const document::Span> spans, std::size_t room,
                             TranslatedBlock& out, const std::function<void(std::size_t)>& progress) {
    std::size_t done = 0;
    // A note's number whose print text follows unspaced: translated with that
    // text, so the code's rule for what follows a number holds (UEB's grade 1
    // indicator before a letter a-j, "clarion¹and" ⠼⠁⠰⠁⠝⠙, which read ⠼⠁⠯
    // as 1 and a sign when the two were translated apart).
    std::u32string number;
    for (std::size_t i = 0; i < spans.size();) {
        if (spans[i].transcriber_note || (spans[i].position != document::Position::baseline && !spans[i].note_reference)) {
            auto ok = spans[i].transcriber_note ? translate_transcriber_note(tr, spans[i], room, out)
                                                : translate_positioned(tr, spans[i], room, out);
            if (!ok) return ok;
            ++i;
            continue;
        }
        if (spans[i].note_reference) {
            TACTUS_TRY(u, utf8_to_utf32(spans[i].text));
            const bool joined = !tr.note_reference_indicator().empty() && follows_unspaced(spans, i);
            if (joined) number = std::move(u);
            if (auto ok = translate_note_reference(tr, joined ? std::u32string() : std::move(u), out); !ok) return ok;
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < spans.size() && !is_marked(spans[j])) ++j;
        std::u32string text;
        std::vector<std::uint8_t> emph;
        std::vector<TableSlot> marks;
        if (auto ok = flatten(spans.subspan(i, j - i), text, emph, tr.language_switch(), marks); !ok) return ok;
        const std::size_t prefix = number.size();
        if (prefix) {
            text.insert(0, number);
            emph.insert(emph.begin(), prefix, document::emphasis_none);
            if (!marks.empty()) marks.insert(marks.begin(), prefix, TableSlot::unmarked);
            number.clear();
        }
        // Spaces at a block's ends are print's (a text file's indent, a line
        // kept verbatim), not braille: the layout's formats place the text.
        if (j == spans.size()) {
            const auto end = text.find_last_not_of(U' ');
            const auto keep = end == std::u32string::npos ? 0 : end + 1;
            text.resize(keep);
            emph.resize(keep);
            if (!marks.empty()) marks.resize(keep);
        }
        if (i == 0) {
            const auto lead = std::min(text.size(), text.find_first_not_of(U' '));
            text.erase(0, lead);
            emph.erase(emph.begin(), emph.begin() + static_cast<std::ptrdiff_t>(lead));
            if (!marks.empty()) marks.erase(marks.begin(), marks.begin() + static_cast<std::ptrdiff_t>(lead));
        }
        if (text.empty()) {
            i = j;
            continue;
        }
        // The first cell of a run never starts a line by itself: the block's
        // first cell, or text going on unspaced after a note reference (a space
        // after it gives a blank break anyway).
        constexpr auto join = BreakBefore::never;
        const std::function<void(std::size_t)> shifted = [&](std::size_t n) {
            progress(done + (n > prefix ? n - prefix : 0));
        };
        if (auto ok = translate_languages(tr, text, emph, marks, room, out, progress ? shifted : progress, join); !ok)
            return ok;
        done += text.size() - prefix;
        i = j;
    }
    return {};
}

// Each paragraph of a table cell translated on its own; the first cell of each
// after the first starts a line (BreakBefore::paragraph). An empty paragraph
// leaves nothing.
Result<void> translate_cell(const Translator& tr, std::span<const document::Span> spans, std::size_t room,
                            TranslatedBlock& out, const std::function<void(std::size_t)>& progress) {
    if (!document::has_cell_paragraphs(spans)) return translate_spans(tr, spans, room, out, progress);
    for (const auto& paragraph : document::cell_paragraphs(spans)) {
        const auto at = out.cells.size();
        if (auto ok = translate_spans(tr, paragraph, room, out, progress); !ok) return ok;
        if (at > 0 && at < out.cells.size()) out.breaks[at] = BreakBefore::paragraph;
    }
    return {};
}

}  // namespace

Result<TranslatedBlock> translate_block(const document::Block& block, const Translator& translator,
                                        std::size_t word_room,
                                        const std::function<void(std::size_t)>& progress) {
    TranslatedBlock tb;
    tb.kind = block.kind;
    tb.level = block.level;
    tb.source_line = block.source_line;
    tb.span = std::max(1, block.span);
    tb.box = block.box;
    const auto where = block.source_line > 0 ? "line " + std::to_string(block.source_line)
                                             : std::string{};
    switch (block.kind) {
        case document::BlockKind::braille:
            tb.lines = block.braille_lines;
            break;
        case document::BlockKind::braille_page_break:
            break;
        case document::BlockKind::print_page_break:
            if (!block.label.empty()) {
                auto u = utf8_to_utf32(block.label);
                if (!u) return std::unexpected(located(u.error(), where));
                auto cells = translator.translate(*u);
                if (!cells) return std::unexpected(located(cells.error(), where));
                tb.label = std::move(*cells);
            }
            break;
        case document::BlockKind::table_row:
            break;
        case document::BlockKind::heading:
        case document::BlockKind::paragraph:
        case document::BlockKind::list_item:
        case document::BlockKind::quote:
        case document::BlockKind::note:
            if (auto ok = translate_spans(translator, block.spans, word_room, tb, progress); !ok)
                return std::unexpected(located(ok.error(), where));
            break;
        case document::BlockKind::table_cell:
            if (auto ok = translate_cell(translator, block.spans, word_room, tb, progress); !ok)
                return std::unexpected(located(ok.error(), where));
            break;
    }
    return tb;
}

}  // namespace tactus::translate
