// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The writing system of a character, as far as the language switch and the
// script check tell them apart. One rule for both: ICU's script property, or
// (a build without ICU) the Unicode blocks of those scripts.
#include <cstdint>

namespace tactus::translate {

enum class Script : std::uint8_t {
    common,     // spaces, digits, punctuation, symbols: decided by their neighbours
    inherited,  // combining marks: the script of the character they sit on
    latin,
    han,
    bopomofo,
    other,
};

[[nodiscard]] Script script_of(char32_t c);

}  // namespace tactus::translate
