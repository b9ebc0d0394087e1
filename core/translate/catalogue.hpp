// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The tables a user can pick, by language name rather than file name: built from
// liblouis's own table metadata (lou_listTables / lou_getTableInfo).
#include <string>
#include <string_view>
#include <vector>

namespace tactus::translate {

struct TableInfo {
    std::string file;          // what to pass as --table, e.g. "en-ueb-g2.ctb"
    std::string language_tag;  // BCP 47 from the table, e.g. "en", "cmn-TW"
    std::string language;      // in the display locale, e.g. "English", "Chinese (Taiwan)", "中文（台灣）"
    std::string name;          // the table's display name, e.g. "Unified English contracted braille"
    std::string grade;         // "1", "2" or ""
    std::string contraction;   // liblouis metadata: "no", "partial", "full" or ""
    std::string system;        // liblouis metadata, e.g. "ueb", "cmn-bopomofo", or ""
    bool recommended = false;  // the tables Tactus is specified and tested with
};

// Every installed table with metadata, recommended ones first, then by language.
// Language names come from ICU in display_locale (a BCP 47 tag such as "en" or
// "zh-TW"), so a Chinese interface lists "中文（台灣）" rather than English names.
std::vector<TableInfo> table_catalogue(std::string_view display_locale = "en");

// The BCP 47 language of a table list (its first table's language_tag in the
// catalogue, e.g. "en", "cmn-TW"), or "" for a table the catalogue does not
// list. What a PEF's dc:language says, for the CLI and the app alike.
std::string table_language_tag(std::string_view tables);

// The recommended table for a language given as a BCP 47 tag ("en", "zh-TW",
// "zh-Hans", "cmn-CN"), first in the catalogue's order; `grade` ("1", "2")
// picks among a language's tables when given. Chinese without a region or
// script is Taiwan's (the product's table for Chinese); Simplified script or a
// mainland region is China's. Empty when no recommended table is for it.
std::string recommended_table(std::string_view language_tag, std::string_view grade = {});

// A language a passage can be marked in (document::Span::language) for a
// table of its own.
struct PassageLanguage {
    std::string tag;   // BCP 47 as word processors write it: "en", "zh-TW", "zh-CN"
    std::string name;  // in the display locale: "Chinese (Taiwan)", "中文（台灣）"
};

// The languages of the recommended tables, one each, in the catalogue's
// order: those recommended_table gives a table for, so a passage marked in
// one is translated with it (translate/language_switch.hpp). A table's
// "cmn" (Mandarin) is written "zh", the tag Word and LibreOffice use.
std::vector<PassageLanguage> passage_languages(std::string_view display_locale = "en");

// A BCP 47 tag's name in the display locale ("zh-TW" -> "Chinese (Taiwan)"),
// from ICU; the tag itself without ICU or for one ICU cannot name.
std::string language_display_name(std::string_view tag, std::string_view display_locale = "en");

// True for a tag of Chinese ("zh", "cmn", "yue", ...).
bool is_chinese_tag(std::string_view tag);

// The table Tactus uses when none is chosen.
inline constexpr const char* kDefaultTable = "en-ueb-g2.ctb";

}  // namespace tactus::translate
