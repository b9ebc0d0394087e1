// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Does the chosen table suit the text's script? Chinese under an English table
// comes out as escape sequences for every character, English under a Chinese
// table loses UEB's capitals and numbers; both are easy to do by mistake and
// hard to see in braille. The CLI and the app report this warning.
#include <optional>
#include <string>

#include "document/document.hpp"

namespace tactus::translate {

// Counts the letters of the document's text (the first 20 000) by script.
struct ScriptCounts {
    std::size_t han = 0;
    std::size_t latin = 0;
    std::size_t traditional_only = 0;  // Han characters that Simplified Chinese writes otherwise
};
ScriptCounts count_scripts(const document::Document& document);

// How the text and the table disagree, and the table that suits the text.
struct ScriptMismatch {
    bool chinese_text = false;  // Chinese under a table that is not Chinese; else Latin letters under a Chinese table
    bool traditional = false;   // the Chinese is Traditional
    std::string table;          // the table list in use
    std::string better;         // the table that suits the text, e.g. "zh-tw.ctb"
};
// `tables` is the liblouis table list in use (its first table decides); nothing
// when the table suits the text.
std::optional<ScriptMismatch> find_script_mismatch(const document::Document& document, const std::string& tables);

// The mismatch as a warning for the command line, naming its --table option
// (the desktop app words it in its own language, without command-line syntax).
std::optional<std::string> check_script(const document::Document& document, const std::string& tables);

}  // namespace tactus::translate
