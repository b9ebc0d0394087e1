// SPDX-License-Identifier: GPL-3.0-or-later
#include "translate/language_switch.hpp"

// Without ICU (TACTUS_WITH_ICU off) Simplified and Traditional characters
// are not told apart: Chinese passages take the Traditional table.
#if TACTUS_HAVE_ICU
#include <unicode/translit.h>
#endif

#include <algorithm>
#include <map>
#include <memory>

#include "common/utf8.hpp"
#include "translate/catalogue.hpp"
#include "translate/script_of.hpp"

namespace tactus::translate {
namespace {

constexpr std::size_t slot_index(TableSlot s) { return static_cast<std::size_t>(s); }

bool is_mainland_tag(std::string_view tag) {
    std::string lower;
    for (char c : tag) lower += c == '_' ? '-' : static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return lower.find("-hans") != std::string::npos || lower.ends_with("-cn") ||
           lower.find("-cn-") != std::string::npos || lower.ends_with("-sg");
}

// May a character no script claims (space, digit, punctuation) go with a
// passage in this slot's language? An English table knows no CJK punctuation
// (，。「」 give dots 7-8 escapes); a Chinese passage takes CJK and full-width
// punctuation and spaces, while ASCII punctuation after a Chinese word in an
// English sentence is the sentence's ("say 你好, then").
bool suits(TableSlot slot, char32_t c) {
    if (slot == TableSlot::english) return c < 0x3000;
    return c == U' ' || c == 0x3000 || c == 0xA0 || c >= 0x2E80;
}

// The installed tables do not change while Tactus runs, and an opened
// translator does not change at all: both are looked up once per process.
// Every editor paragraph layout and every document opens a switch of its own;
// listing the catalogue and reading zh-tw.ctb's files again each time cost a
// random-edit test run minutes.
std::mutex& cache_mutex() {
    static std::mutex m;
    return m;
}

std::string catalogue_table(const std::string& language, const std::string& grade) {
    static std::map<std::string, std::string> known;
    const auto key = language + "/" + grade;
    {
        std::lock_guard guard(cache_mutex());
        if (auto it = known.find(key); it != known.end()) return it->second;
    }
    auto table = recommended_table(language, grade);
    std::lock_guard guard(cache_mutex());
    return known.emplace(key, std::move(table)).first->second;
}

Result<std::shared_ptr<const Translator>> shared_translator(const std::string& table) {
    static std::map<std::string, std::shared_ptr<const Translator>> opened;
    {
        std::lock_guard guard(cache_mutex());
        if (auto it = opened.find(table); it != opened.end()) return it->second;
    }
    auto t = Translator::open(table);
    if (!t) return std::unexpected(t.error());
    auto shared = std::make_shared<const Translator>(std::move(*t));
    std::lock_guard guard(cache_mutex());
    return opened.emplace(table, std::move(shared)).first->second;
}

}  // namespace

std::optional<SwitchIndicators> parse_switch_indicators(std::string_view name) {
    if (name == "auto") return SwitchIndicators::automatic;
    if (name == "code-switch") return SwitchIndicators::code_switch;
    if (name == "letter-sign") return SwitchIndicators::letter_sign;
    if (name == "none") return SwitchIndicators::none;
    return std::nullopt;
}

std::string_view to_string(SwitchIndicators s) {
    switch (s) {
        case SwitchIndicators::automatic: return "auto";
        case SwitchIndicators::code_switch: return "code-switch";
        case SwitchIndicators::letter_sign: return "letter-sign";
        case SwitchIndicators::none: return "none";
    }
    return "auto";
}

LanguageSwitch::LanguageSwitch(const Translator& primary, LanguageSwitchOptions options)
    : options_(std::move(options)),
      primary_chinese_(is_chinese_tag(primary.language())),
      primary_ueb_(primary.is_ueb()),
      primary_mainland_(is_mainland_tag(primary.language())) {}

SwitchIndicators LanguageSwitch::indicators() const {
    if (options_.indicators != SwitchIndicators::automatic) return options_.indicators;
    if (primary_ueb_) return SwitchIndicators::code_switch;  // UEB §13.7.1, §14.3
    if (primary_mainland_) return SwitchIndicators::letter_sign;
    if (primary_chinese_) return SwitchIndicators::code_switch;  // reversed: UEB §13.7.3
    return SwitchIndicators::none;
}

TableSlot LanguageSwitch::slot_for_language(std::string_view tag) const {
    if (tag.empty()) return TableSlot::unmarked;
    if (is_chinese_tag(tag)) {
        // Chinese in Latin letters (pinyin: "zh-Latn-pinyin") is Latin print,
        // which the Chinese tables write in computer braille.
        std::string lower(tag);
        for (auto& c : lower) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
        if (primary_chinese_ || lower.find("-latn") != std::string::npos) return TableSlot::primary;
        return is_mainland_tag(tag) ? TableSlot::chinese_cn : TableSlot::chinese_tw;
    }
    const auto lang = tag.substr(0, tag.find_first_of("-_"));
    if ((lang == "en" || lang == "EN") && primary_chinese_) return TableSlot::english;
    return TableSlot::primary;
}

std::vector<LanguageRun> LanguageSwitch::split(std::u32string_view text, std::span<const TableSlot> marks) const {
    std::vector<LanguageRun> runs;
    if (text.empty()) return runs;
    const std::size_t n = text.size();
    std::vector<TableSlot> slot(n, TableSlot::unmarked);
    bool any_other = false;
    for (std::size_t i = 0; i < n; ++i) {
        if (i < marks.size() && marks[i] != TableSlot::unmarked) {
            slot[i] = marks[i];
        } else {
            switch (script_of(text[i])) {
                case Script::han:
                case Script::bopomofo:
                    slot[i] = primary_chinese_ ? TableSlot::primary : TableSlot::chinese_tw;
                    break;
                case Script::latin:
                    slot[i] = primary_chinese_ ? TableSlot::english : TableSlot::primary;
                    break;
                case Script::common:
                case Script::inherited:
                    break;  // decided by its neighbours below
                default:
                    slot[i] = TableSlot::primary;
                    break;
            }
        }
        any_other = any_other || (slot[i] != TableSlot::primary && slot[i] != TableSlot::unmarked);
    }
    if (!any_other) return {LanguageRun{0, n, TableSlot::primary}};
    // Characters of no script (spaces, digits, punctuation): with the other
    // language when it is on both sides and its table writes them all ("New
    // York", "中文，好"); else punctuation touching a passage of the other
    // language and written by its table is the passage's ("apple.", "(apple)"),
    // and the rest, spaces above all, the document's own.
    const auto is_space = [](char32_t c) { return c == U' ' || c == 0x3000 || c == 0xA0; };
    for (std::size_t i = 0; i < n;) {
        if (slot[i] != TableSlot::unmarked) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < n && slot[j] == TableSlot::unmarked) ++j;
        const auto left = i > 0 ? slot[i - 1] : TableSlot::unmarked;
        const auto right = j < n ? slot[j] : TableSlot::unmarked;
        const auto fill = [&](std::size_t a, std::size_t b, TableSlot s) {
            std::fill(slot.begin() + static_cast<std::ptrdiff_t>(a), slot.begin() + static_cast<std::ptrdiff_t>(b), s);
        };
        const auto foreign = [](TableSlot s) { return s != TableSlot::primary && s != TableSlot::unmarked; };
        if (foreign(left) && left == right &&
            std::all_of(text.begin() + static_cast<std::ptrdiff_t>(i), text.begin() + static_cast<std::ptrdiff_t>(j),
                        [left](char32_t c) { return suits(left, c); })) {
            fill(i, j, left);
        } else {
            std::size_t a = i, b = j;
            if (foreign(left))
                while (a < b && !is_space(text[a]) && suits(left, text[a])) slot[a++] = left;
            if (foreign(right))
                while (b > a && !is_space(text[b - 1]) && suits(right, text[b - 1])) slot[--b] = right;
            fill(a, b, TableSlot::primary);
        }
        i = j;
    }
    for (std::size_t i = 0; i < n;) {
        std::size_t j = i + 1;
        while (j < n && slot[j] == slot[i]) ++j;
        auto s = slot[i];
        const bool unmarked = std::all_of(marks.begin() + static_cast<std::ptrdiff_t>(std::min(i, marks.size())),
                                          marks.begin() + static_cast<std::ptrdiff_t>(std::min(j, marks.size())),
                                          [](TableSlot m) { return m == TableSlot::unmarked; });
        if (s == TableSlot::chinese_tw && unmarked && simplified_only(text.substr(i, j - i))) s = TableSlot::chinese_cn;
        runs.push_back(LanguageRun{i, j, s});
        i = j;
    }
    return runs;
}

// Simplified characters are those ICU's Simplified-to-Traditional
// transliteration changes, Traditional ones those Traditional-to-Simplified
// changes (as translate/script_check.cpp counts them).
#if TACTUS_HAVE_ICU
struct LanguageSwitch::Transliterators {
    std::unique_ptr<icu::Transliterator> to_traditional, to_simplified;
};
#else
struct LanguageSwitch::Transliterators {};
#endif

bool LanguageSwitch::simplified_only(std::u32string_view han) const {
#if !TACTUS_HAVE_ICU
    (void)han;
    return false;
#else
    std::lock_guard guard(mutex_);
    if (!transliterators_) {
        auto t = std::make_shared<Transliterators>();
        UErrorCode status = U_ZERO_ERROR;
        t->to_traditional.reset(icu::Transliterator::createInstance("Hans-Hant", UTRANS_FORWARD, status));
        if (U_SUCCESS(status))
            t->to_simplified.reset(icu::Transliterator::createInstance("Hant-Hans", UTRANS_FORWARD, status));
        if (U_FAILURE(status)) t = std::make_shared<Transliterators>();
        transliterators_ = std::move(t);
    }
    auto& to_traditional_ = transliterators_->to_traditional;
    auto& to_simplified_ = transliterators_->to_simplified;
    if (!to_traditional_ || !to_simplified_) return false;
    bool simplified = false;
    for (char32_t c : han) {
        if (script_of(c) != Script::han) continue;
        const icu::UnicodeString original(static_cast<UChar32>(c));
        icu::UnicodeString s = original;
        to_simplified_->transliterate(s);
        if (s != original) return false;  // a Traditional character
        icu::UnicodeString t = original;
        to_traditional_->transliterate(t);
        simplified = simplified || t != original;
    }
    return simplified;
#endif
}

Result<const Translator*> LanguageSwitch::translator(TableSlot slot) const {
    if (slot == TableSlot::primary || slot_index(slot) >= kTableSlots)
        return fail(ErrorKind::internal, "no second table for the document's own language");
    std::lock_guard guard(mutex_);
    auto& t = tables_[slot_index(slot)];
    if (t) return t.get();
    const bool second = slot == TableSlot::english ? primary_chinese_ : !primary_chinese_;
    std::string table = second ? options_.second_table : std::string{};
    if (table.empty()) {
        table = slot == TableSlot::english      ? catalogue_table("en", options_.english_grade)
                : slot == TableSlot::chinese_cn ? catalogue_table("zh-CN", {})
                                                : catalogue_table("zh-TW", {});
    }
    if (table.empty())
        return fail(ErrorKind::input, std::string("no installed braille table for ") +
                                          (slot == TableSlot::english ? "English" : "Chinese") +
                                          " passages (liblouis catalogue)");
    auto opened = shared_translator(table);
    if (!opened) return std::unexpected(opened.error());
    t = std::move(*opened);
    return t.get();
}

Result<void> LanguageSwitch::prepare(const document::Document& document) const {
    std::array<bool, kTableSlots> needed{};
    std::u32string text;
    for (const auto& block : document.blocks) {
        if (!document::is_text_kind(block.kind)) continue;
        for (const auto& span : block.spans) {
            text.clear();
            if (!append_utf32(text, span.text)) continue;
            std::vector<TableSlot> marks;
            if (!span.language.empty()) marks.assign(text.size(), slot_for_language(span.language));
            for (const auto& run : split(text, marks)) needed[slot_index(run.slot)] = true;
        }
    }
    for (std::size_t s = 1; s < kTableSlots; ++s)
        if (needed[s])
            if (auto t = translator(static_cast<TableSlot>(s)); !t) return std::unexpected(t.error());
    return {};
}

Result<Translator> open_translator(std::string tables, const LanguageSwitchOptions& options) {
    auto t = Translator::open(std::move(tables));
    if (!t || !options.enabled) return t;
    auto s = std::make_shared<LanguageSwitch>(*t, options);
    // A second table the user named is checked now, where the mistake is made.
    if (!options.second_table.empty()) {
        auto second = s->translator(s->primary_is_chinese() ? TableSlot::english : TableSlot::chinese_tw);
        if (!second) {
            auto e = second.error();
            e.where = "--second-table";
            return std::unexpected(std::move(e));
        }
    }
    t->set_language_switch(std::move(s));
    return t;
}

}  // namespace tactus::translate
