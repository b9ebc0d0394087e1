// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The signs that tell a reader the braille code changes for a passage in
// another language (translate/language_switch.hpp): the one place these
// rules live. Sources in docs/translation.md, "Passages in another language".
//  - UEB §14.3 (Rules of Unified English Braille 2013): the non-UEB word
//    indicator ⠘⠷ before each symbols-sequence, ended by a space or by the
//    non-UEB word terminator ⠘⠾; for three or more sequences (§14.3.2) the
//    opening ⠐⠷⠄ and closing ⠠⠐⠾ non-UEB passage indicators. §13.7.3: in
//    a text mainly in another language the same indicators enclose the
//    English (UEB) material instead.
//  - The mainland Chinese tables' letter sign: ⠰ (dots 56) before Latin
//    letters that follow Chinese directly, a space between Latin and the
//    Chinese that follows (liblouis zhcn-g1.ctb, zhcn-g2.ctb).
#include <string_view>

#include "document/cell.hpp"
#include "translate/language_switch.hpp"

namespace tactus::translate {

enum class SwitchForm : std::uint8_t {
    none,
    word,         // each symbols-sequence: word indicator before, terminator if unspaced text follows
    passage,      // opening indicator before the run, closing one after it
    letter_sign,  // letter sign before when unspaced after other text, a space after when unspaced before it
};

// How a run of the other language is marked under `rule` (never `automatic`).
SwitchForm switch_form(SwitchIndicators rule, std::u32string_view run);

// UEB §14.3.2: how many symbols-sequences (print text between spaces) a run has.
std::size_t symbols_sequences(std::u32string_view run);

inline constexpr document::Cell kNonUebWord[] = {document::Cell{0x18}, document::Cell{0x37}};       // ⠘⠷
inline constexpr document::Cell kNonUebWordEnd[] = {document::Cell{0x18}, document::Cell{0x3E}};    // ⠘⠾
inline constexpr document::Cell kNonUebOpen[] = {document::Cell{0x10}, document::Cell{0x37}, document::Cell{0x04}};  // ⠐⠷⠄
inline constexpr document::Cell kNonUebClose[] = {document::Cell{0x20}, document::Cell{0x10}, document::Cell{0x3E}}; // ⠠⠐⠾
inline constexpr document::Cell kLetterSign[] = {document::Cell{0x30}};                              // ⠰

}  // namespace tactus::translate
