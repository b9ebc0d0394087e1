// SPDX-License-Identifier: GPL-3.0-or-later
#include "translate/script_check.hpp"

#include <liblouis/liblouis.h>
// Without ICU (TACTUS_WITH_ICU off) Traditional Chinese is not told from
// Simplified; the warning then says so.
#if TACTUS_HAVE_ICU
#include <unicode/translit.h>
#include <unicode/unistr.h>
#else
#include "common/unavailable.hpp"
#endif

#include <cstdlib>
#include <memory>
#include <mutex>

#include "common/utf8.hpp"
#include "translate/louis.hpp"
#include "translate/script_of.hpp"

namespace tactus::translate {
namespace {

constexpr std::size_t kSample = 20'000;  // letters looked at; a book's first pages decide
constexpr std::size_t kEnough = 20;      // fewer letters than this say nothing

std::string table_language(const std::string& tables) {
    const auto first = tables.substr(0, tables.find(','));
    louis::install_log_capture();
    std::lock_guard guard(louis::lock());
    char* v = lou_getTableInfo(first.c_str(), "language");
    louis::take_log();
    if (!v) return {};
    std::string s(v);
    std::free(v);  // NOLINT: liblouis hands ownership to the caller
    return s;
}

bool chinese_language(const std::string& tag) {
    const auto lang = tag.substr(0, tag.find('-'));
    return lang == "zh" || lang == "cmn" || lang == "yue" || lang == "wuu" || lang == "nan";
}

bool english_language(const std::string& tag) { return tag.substr(0, tag.find('-')) == "en"; }

}  // namespace

ScriptCounts count_scripts(const document::Document& document) {
    ScriptCounts counts;
    std::u32string han;
    for (const auto& block : document.blocks) {
        if (counts.han + counts.latin >= kSample) break;
        for (const auto& span : block.spans) {
            const auto text = utf8_to_utf32(span.text);
            if (!text) continue;
            for (char32_t c : *text) {
                const auto script = script_of(c);
                if (script == Script::han) {
                    ++counts.han;
                    han.push_back(c);
                } else if (script == Script::latin) {
                    ++counts.latin;
                }
            }
        }
    }
    if (han.empty()) return counts;
#if TACTUS_HAVE_ICU
    // Traditional characters are those ICU's Traditional-to-Simplified
    // transliteration changes; Simplified text passes through unchanged.
    UErrorCode status = U_ZERO_ERROR;
    std::unique_ptr<icu::Transliterator> to_simplified(
        icu::Transliterator::createInstance("Hant-Hans", UTRANS_FORWARD, status));
    if (U_FAILURE(status) || !to_simplified) return counts;
    for (char32_t c : han) {
        icu::UnicodeString s(static_cast<UChar32>(c));
        const icu::UnicodeString before = s;
        to_simplified->transliterate(s);
        if (s != before) ++counts.traditional_only;
    }
#endif
    return counts;
}

std::optional<ScriptMismatch> find_script_mismatch(const document::Document& document, const std::string& tables) {
    const auto counts = count_scripts(document);
    const auto language = table_language(tables);
    if (counts.han >= kEnough && counts.han > counts.latin && !chinese_language(language)) {
        const bool traditional = counts.traditional_only * 20 >= counts.han;  // 5% or more
        return ScriptMismatch{true, traditional, tables, traditional ? "zh-tw.ctb" : "zhcn-g2.ctb"};
    }
    if (counts.latin >= kEnough && counts.latin > counts.han && chinese_language(language) &&
        !english_language(language))
        return ScriptMismatch{false, false, tables, "en-ueb-g2.ctb"};
    return std::nullopt;
}

std::optional<std::string> check_script(const document::Document& document, const std::string& tables) {
    const auto m = find_script_mismatch(document, tables);
    if (!m) return std::nullopt;
#if !TACTUS_HAVE_ICU
    if (m->chinese_text)
        return "the text is mostly Chinese but " + tables + " is not a Chinese table; zh-tw.ctb (Traditional) or "
               "zhcn-g2.ctb (Simplified) suits it (" +
               unavailable_message("telling Traditional from Simplified Chinese", "ICU") + ")";
#endif
    if (m->chinese_text)
        return "the text is mostly Chinese (" + std::string(m->traditional ? "Traditional" : "Simplified") +
               ") but " + tables + " is not a Chinese table; " + m->better +
               (m->traditional ? " (Taiwanese bopomofo braille)" : " (Chinese double-phonic braille; or zhcn-g1.ctb)") +
               " suits it: --table " + m->better;
    return "the text is mostly in Latin letters but " + tables +
           " is a Chinese table; for English en-ueb-g2.ctb (Unified English Braille) suits it:"
           " --table en-ueb-g2.ctb";
}

}  // namespace tactus::translate
