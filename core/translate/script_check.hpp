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

// A warning naming a better table, or nothing when the table suits the text.
// `tables` is the liblouis table list in use (its first table decides).
std::optional<std::string> check_script(const document::Document& document, const std::string& tables);

}  // namespace tactus::translate
