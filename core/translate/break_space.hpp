// The spaces that separate words for line breaking and word division: ASCII
// space and tab, the ideographic space of Chinese text and the no-break space.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace tactus::translate {

inline bool is_break_space(char32_t c) { return c == U' ' || c == U'\t' || c == 0x3000 || c == 0xA0; }

}  // namespace tactus::translate
