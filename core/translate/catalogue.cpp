// SPDX-License-Identifier: GPL-3.0-or-later
#include "translate/catalogue.hpp"

#include <liblouis/liblouis.h>
// Without ICU (TACTUS_WITH_ICU off) a language is shown as its tag ("en-US").
#if TACTUS_HAVE_ICU
#include <unicode/locid.h>
#include <unicode/unistr.h>
#endif

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string_view>

#include "translate/louis.hpp"

namespace tactus::translate {
namespace {

// The tables the product is specified with: English UEB and both Chinese
// systems, in the order the picker lists them. Taiwan's comes before China's:
// it is the product's table for Chinese text (the Chinese interface's default),
// so typing "Chinese" in the picker lands on it.
constexpr std::array<std::string_view, 5> kRecommended = {
    "en-ueb-g1.ctb", "en-ueb-g2.ctb", "zh-tw.ctb", "zhcn-g1.ctb", "zhcn-g2.ctb"};

std::string info(const char* table, const char* key) {
    char* v = lou_getTableInfo(table, key);
    if (!v) return {};
    std::string s(v);
    std::free(v);  // NOLINT: liblouis hands ownership to the caller
    return s;
}

// "cmn-TW" -> "Chinese (Taiwan)" (or "中文（台灣）" for a zh-TW reader) via
// ICU's locale display names; falls back to the tag.
#if TACTUS_HAVE_ICU
using Reader = icu::Locale;
#else
using Reader = std::string_view;
#endif

std::string language_name(const std::string& tag, const Reader& reader) {
    if (tag.empty()) return "Other";
#if !TACTUS_HAVE_ICU
    (void)reader;
    return tag;
#else
    UErrorCode status = U_ZERO_ERROR;
    const icu::Locale locale = icu::Locale::forLanguageTag(tag, status);
    if (U_FAILURE(status)) return tag;
    icu::UnicodeString display;
    locale.getDisplayName(reader, display);
    std::string out;
    display.toUTF8String(out);
    return out.empty() ? tag : out;
#endif
}

// The locale names are given in: English for a tag ICU cannot read.
#if TACTUS_HAVE_ICU
Reader reader_for(std::string_view display_locale) {
    UErrorCode status = U_ZERO_ERROR;
    icu::Locale reader = icu::Locale::forLanguageTag(std::string(display_locale), status);
    if (U_FAILURE(status) || reader.isBogus()) reader = icu::Locale::getEnglish();
    return reader;
}
#else
Reader reader_for(std::string_view display_locale) { return display_locale; }
#endif

}  // namespace

std::vector<TableInfo> table_catalogue(std::string_view display_locale) {
    const Reader reader = reader_for(display_locale);
    louis::install_log_capture();
    std::vector<TableInfo> out;
    std::lock_guard guard(louis::lock());
    char** tables = lou_listTables();
    if (!tables) return out;
    for (char** t = tables; *t; ++t) {
        TableInfo ti;
        ti.file = std::filesystem::path(*t).filename().string();
        ti.language_tag = info(*t, "language");
        const auto region = info(*t, "region");
        if (!region.empty()) ti.language_tag = region;  // region tags are fuller: "cmn-TW"
        ti.language = language_name(ti.language_tag, reader);
        ti.name = info(*t, "display-name");
        if (ti.name.empty()) ti.name = info(*t, "index-name");
        ti.grade = info(*t, "grade");
        ti.contraction = info(*t, "contraction");
        ti.system = info(*t, "system");
        ti.recommended = std::ranges::find(kRecommended, ti.file) != kRecommended.end();
        out.push_back(std::move(ti));
        std::free(*t);  // NOLINT
    }
    std::free(tables);  // NOLINT
    louis::take_log();
    std::ranges::sort(out, [](const TableInfo& a, const TableInfo& b) {
        if (a.recommended != b.recommended) return a.recommended;
        if (a.recommended) return std::ranges::find(kRecommended, a.file) < std::ranges::find(kRecommended, b.file);
        if (a.language != b.language) return a.language < b.language;
        return a.file < b.file;
    });
    return out;
}

bool is_chinese_tag(std::string_view tag) {
    const auto lang = tag.substr(0, tag.find_first_of("-_"));
    return lang == "zh" || lang == "cmn" || lang == "yue" || lang == "wuu" || lang == "nan";
}

namespace {

// "zh-Hant-HK" -> "cmn-TW", "zh-CN" -> "cmn-CN", "en-GB" -> "en": the tag as
// the catalogue's tables carry it.
std::string catalogue_tag(std::string_view tag) {
    std::string lower;
    for (char c : tag) lower += c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!is_chinese_tag(lower)) return lower.substr(0, lower.find('-'));
    const bool mainland = lower.find("-hans") != std::string::npos || lower.ends_with("-cn") ||
                          lower.find("-cn-") != std::string::npos || lower.ends_with("-sg");
    return mainland ? "cmn-CN" : "cmn-TW";
}

}  // namespace

std::string recommended_table(std::string_view language_tag, std::string_view grade) {
    const auto wanted = catalogue_tag(language_tag);
    for (const auto& t : table_catalogue()) {
        if (!t.recommended) break;  // recommended tables come first
        if (t.language_tag == wanted && (grade.empty() || t.grade == grade)) return t.file;
    }
    return {};
}

std::string language_display_name(std::string_view tag, std::string_view display_locale) {
    if (tag.empty()) return {};
    return language_name(std::string(tag), reader_for(display_locale));
}

std::vector<PassageLanguage> passage_languages(std::string_view display_locale) {
    const auto reader = reader_for(display_locale);
    std::vector<PassageLanguage> out;
    for (const auto& t : table_catalogue()) {
        if (!t.recommended) break;  // recommended tables come first
        if (t.language_tag.empty()) continue;
        auto tag = t.language_tag;
        if (tag.starts_with("cmn-")) tag.replace(0, 3, "zh");
        if (std::ranges::any_of(out, [&](const PassageLanguage& l) { return l.tag == tag; })) continue;
        out.push_back({tag, language_name(tag, reader)});
    }
    return out;
}

std::string table_language_tag(std::string_view tables) {
    const auto first = tables.substr(0, tables.find(','));
    for (const auto& t : table_catalogue())
        if (t.file == first) return t.language_tag;
    return {};
}

}  // namespace tactus::translate
