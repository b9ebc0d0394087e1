// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Text -> braille cells and back, through liblouis, always with an explicit
// display table (unicode.dis) so cells come back as Unicode braille whatever the
// table's own display defaults are.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "document/cell.hpp"

namespace tactus::translate {

class LanguageSwitch;

// Cells with the print character each one was made from (liblouis's inputPos):
// an indicator or a contraction carries the position of the characters it
// belongs to, which is what line breaking needs (translate/line_breaks.hpp).
struct MappedBraille {
    document::BrailleLine cells;
    std::vector<std::uint32_t> source;  // index into the translated text, one per cell
};

// What the table's braille code writes when a word is divided at a line end
// (translate/word_division.hpp). Derived from the table when it is opened.
struct DivisionRules {
    // UEB 6.10.3: a number divided between digits ends its line with the one-cell
    // line continuation indicator (dot 5); UEB 6.10.5: the next line goes on in
    // numeric mode, without the numeric indicator. Empty outside UEB, where a
    // number is divided like a word.
    std::optional<document::Cell> number_continuation;
    document::BrailleLine numeric_indicator;
};

class Translator {
public:
    // `tables` is a liblouis table list, e.g. "en-ueb-g2.ctb" or
    // "en-ueb-g1.ctb,my-extra.cti". Fails with liblouis's own reason when a table
    // is missing or does not compile.
    static Result<Translator> open(std::string tables);

    [[nodiscard]] const std::string& tables() const { return tables_; }

    // `emphasis` is empty or one Emphasis bit set per code point of `text`.
    Result<document::BrailleLine> translate(std::u32string_view text,
                                  std::span<const std::uint8_t> emphasis = {}) const;

    // translate() with the print position of every cell.
    Result<MappedBraille> translate_mapped(std::u32string_view text,
                                           std::span<const std::uint8_t> emphasis = {}) const;

    [[nodiscard]] const DivisionRules& division_rules() const { return division_; }
    // True for a table of Unified English Braille (liblouis `#+system:ueb`):
    // the rules that are UEB's alone (number division) apply only then.
    [[nodiscard]] bool is_ueb() const { return ueb_; }
    // The braille system of the table (liblouis `#+system:`, e.g. "ueb", "ebae",
    // "cmn-bopomofo"), read from the first table or, when it has none (en-us-g2.ctb),
    // from the first table it includes that has one; empty when none says.
    [[nodiscard]] const std::string& braille_system() const { return system_; }
    // The language of the table (liblouis `#+region:`, else `#+language:`,
    // e.g. "en", "cmn-TW"), read as braille_system() is; empty when none says.
    [[nodiscard]] const std::string& language() const { return language_; }

    // The tables for passages in another language than the table's
    // (translate/language_switch.hpp); null: one table for everything.
    [[nodiscard]] const LanguageSwitch* language_switch() const { return switch_.get(); }
    void set_language_switch(std::shared_ptr<const LanguageSwitch> s) { switch_ = std::move(s); }
    // The code's note reference indicator, written before a note's reference
    // number (docs/layout.md, "Notes"): in UEB the superscript indicator, dots
    // 35, after the grade 1 indicator, dots 56, in contracted braille (print's
    // superscript number: Rules of Unified English Braille 2013 §3.24.1,
    // §11.4.2; without it in uncontracted braille, §5.11.1); in EBAE dots 2356
    // 2356 (BANA Braille Formats 2011 §16.1.3, "77#a numbered"). Empty for a
    // code Tactus knows none of (Chinese and the rest): the reference is then
    // written in parentheses, as print without superscripts does. The one place
    // this rule lives.
    [[nodiscard]] const document::BrailleLine& note_reference_indicator() const { return note_indicator_; }

    // True when the table can write the start of a word differently because
    // of what comes at its far end (a `compbrl` rule: "://", ".com", "()" and
    // the like anywhere in a word put the whole word in computer braille, as
    // en-us-g2.ctb does). Word division then looks four lines ahead, not one
    // (translate/word_division.cpp).
    [[nodiscard]] bool has_word_wide_rules() const { return word_wide_rules_; }

    // Where `word` may be hyphenated (true before character i), from the
    // hyphenation dictionary liblouis has for the table's language
    // (hyph_en_US.dic for English); all false when there is none.
    [[nodiscard]] std::vector<bool> hyphenation_points(std::u32string_view word) const;

    // Back-translation for proofreading: what a reader of these cells would read.
    Result<std::u32string> back_translate(const document::BrailleLine& cells) const;

    // What liblouis produces for `text` with another display table, e.g.
    // "en-us-brf.dis" for Braille ASCII; used by `tactus-cli translate`.
    Result<std::u32string> translate_with_display(std::u32string_view text,
                                                  std::string_view display_table) const;

private:
    explicit Translator(std::string tables) : tables_(std::move(tables)) {}
    std::string tables_;
    std::string hyphenation_;  // e.g. "hyph_en_US.dic"; empty: none for this language
    DivisionRules division_;
    bool ueb_ = false;
    bool word_wide_rules_ = true;
    std::string system_;
    std::string language_;
    document::BrailleLine note_indicator_;
    std::shared_ptr<const LanguageSwitch> switch_;
};

}  // namespace tactus::translate
