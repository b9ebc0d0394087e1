// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A passage in another language than the document's is translated with that
// language's table: English words in Chinese text with an English table,
// Chinese in English text with a Chinese one (docs/translation.md, "Passages
// in another language"). A passage is what the source marks with a language
// (HTML and EPUB `lang`/`xml:lang`, document::Span::language) or, unmarked,
// a run of another script: Han and Bopomofo against Latin letters (ICU's
// uscript). The second language's table comes from the catalogue.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"
#include "translate/translator.hpp"

namespace tactus::translate {

// What marks a passage of the other language (translate/code_switch.hpp).
enum class SwitchIndicators : std::uint8_t {
    automatic,    // the rule of the document's code: UEB's code switch indicators in
                  // English; in Chinese ones, the mainland tables' letter sign, and
                  // UEB's indicators enclosing English (UEB §13.7.3) in Taiwan's
    code_switch,  // UEB §14: non-UEB word or passage indicators (reversed in a Chinese document)
    letter_sign,  // ⠰ (dots 56) before Latin letters that follow Chinese directly, a space after
    none,         // nothing: the change of table is the only sign
};
std::optional<SwitchIndicators> parse_switch_indicators(std::string_view name);
std::string_view to_string(SwitchIndicators s);

struct LanguageSwitchOptions {
    bool enabled = true;  // false: one table for everything
    // The table for the other language (English inside a Chinese document,
    // Chinese inside any other); empty: the catalogue's recommended one.
    std::string second_table;
    // English inside Chinese without a second_table: UEB grade "1" or "2".
    std::string english_grade = "1";
    SwitchIndicators indicators = SwitchIndicators::automatic;
    bool operator==(const LanguageSwitchOptions&) const = default;
};

// Which table a print character goes to.
enum class TableSlot : std::uint8_t { primary, english, chinese_tw, chinese_cn, unmarked = 0xFF };
inline constexpr std::size_t kTableSlots = 4;

// A stretch of text for one table: [begin, end) in code points.
struct LanguageRun {
    std::size_t begin = 0;
    std::size_t end = 0;
    TableSlot slot = TableSlot::primary;
};

class LanguageSwitch {
public:
    LanguageSwitch(const Translator& primary, LanguageSwitchOptions options);

    [[nodiscard]] const LanguageSwitchOptions& options() const { return options_; }
    [[nodiscard]] bool primary_is_chinese() const { return primary_chinese_; }
    [[nodiscard]] bool primary_is_ueb() const { return primary_ueb_; }
    // `options().indicators` with `automatic` resolved for the document's code.
    [[nodiscard]] SwitchIndicators indicators() const;

    // The table a passage marked with `language_tag` (BCP 47) goes to:
    // primary for the document's own language and for a language Tactus has
    // no second table for.
    [[nodiscard]] TableSlot slot_for_language(std::string_view language_tag) const;

    // The text cut into runs of one table each. `marks` is empty or one slot
    // per code point (TableSlot::unmarked: decided by its script; unmarked
    // Chinese in Simplified characters only, none of them Traditional, goes
    // to the mainland table, other Chinese to Taiwan's). A space,
    // digit or punctuation mark between two runs of the same other language
    // belongs to them ("New York", "中文，好"); elsewhere to the document's
    // own table. Always at least one run for non-empty text; one primary run
    // when nothing is of another language.
    [[nodiscard]] std::vector<LanguageRun> split(std::u32string_view text,
                                                 std::span<const TableSlot> marks = {}) const;

    // The translator for a slot other than primary (the caller's own), opened on first use (the Chinese tables take
    // half a second to compile, which an English-only document never pays).
    [[nodiscard]] Result<const Translator*> translator(TableSlot slot) const;

    // Opens every table `document` needs now: call before forking workers so
    // that each does not compile them again.
    Result<void> prepare(const document::Document& document) const;

private:
    LanguageSwitchOptions options_;
    bool primary_chinese_ = false;
    bool primary_ueb_ = false;
    bool primary_mainland_ = false;
    [[nodiscard]] bool simplified_only(std::u32string_view han) const;

    mutable std::mutex mutex_;
    mutable std::array<std::shared_ptr<const Translator>, kTableSlots> tables_;
    struct Transliterators;  // ICU's Hans-Hant and Hant-Hans, made on first use
    mutable std::shared_ptr<Transliterators> transliterators_;
};

// The document's table with the switch in it (off when `options.enabled` is
// false): what the pipeline and the CLI translate with.
Result<Translator> open_translator(std::string tables, const LanguageSwitchOptions& options);

}  // namespace tactus::translate
