// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The language of a passage in a word processor's document. Word (w:lang:
// w:val, w:eastAsia, w:bidi) and OpenDocument (fo:language/fo:country,
// style:language-asian/-country-asian, style:language-complex/-country-complex)
// give every run of text three languages, one per class of script, and each
// character is in the language of its own class: a run marked Chinese for East
// Asian text keeps its Latin letters in the Latin language. The DOCX and ODT
// importers read the three from their styles; this file is the per-character
// rule they share (docs/import.md, "Languages in DOCX and ODT").
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "document/document.hpp"

namespace tactus::import::detail {

enum class ScriptClass : std::uint8_t { latin, east_asian, complex };

// A run's languages as BCP 47 tags; unset = what the style or default below
// says. An empty tag is "no language" (Word's "x-none", ODF's "none").
struct OfficeLanguages {
    std::optional<std::string> latin, east_asian, complex;
    // Word's w:rtl or w:cs: every character of the run is complex script.
    std::optional<bool> complex_run;
    void apply(const OfficeLanguages& over);
    [[nodiscard]] std::string_view of(ScriptClass c) const;
};

// A tag as the formats write it, normalised: "none", "x-none" and "zxx"
// are no language (""); ODF's language and country are joined ("zh", "TW" ->
// "zh-TW"; a country "none" is left out).
std::string language_tag(std::string_view language, std::string_view country = {});

// The script class a character belongs to; nullopt for one of no script
// (space, digit, punctuation of the Basic Latin and General Punctuation
// blocks, symbols), which goes with the letters around it.
std::optional<ScriptClass> script_class(char32_t c);

struct LanguagePiece {
    std::string_view text;
    std::string language;  // "" = the document's own
};

// `utf8` cut where the language changes. Each character is in the language
// `run` gives its script class. A character of no script class takes the
// class of the letter before it in `utf8`, else of the letter after it, else
// (a run of spaces or digits alone) Latin: LibreOffice's rule for "weak"
// characters, and Word's for a run without letters. A language equal to what
// `document` gives the same class is the document's own and left unmarked
// (""), so an ordinary document carries no marks.
std::vector<LanguagePiece> language_pieces(std::string_view utf8, const OfficeLanguages& run,
                                           const OfficeLanguages& document);

// The document's main language (document/main_language.hpp) from its own
// languages: that of the script class most of its unmarked text is in
// (a Taiwanese document's defaults say English for Latin letters and Chinese
// for Han, and its text is Han), else, without such text, the first class
// that names one (Latin, East Asian, complex); "" when none does.
std::string main_language(const OfficeLanguages& document, const document::Document& text);

}  // namespace tactus::import::detail
