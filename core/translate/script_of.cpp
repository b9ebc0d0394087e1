// SPDX-License-Identifier: GPL-3.0-or-later
#include "translate/script_of.hpp"

#if TACTUS_HAVE_ICU
#include <unicode/uscript.h>
#else
#include <algorithm>
#include <array>
#endif

namespace tactus::translate {

#if TACTUS_HAVE_ICU

Script script_of(char32_t c) {
    UErrorCode status = U_ZERO_ERROR;
    const auto script = uscript_getScript(static_cast<UChar32>(c), &status);
    if (U_FAILURE(status)) return Script::common;
    switch (script) {
        case USCRIPT_COMMON: return Script::common;
        case USCRIPT_INHERITED: return Script::inherited;
        case USCRIPT_LATIN: return Script::latin;
        case USCRIPT_HAN: return Script::han;
        case USCRIPT_BOPOMOFO: return Script::bopomofo;
        default: return Script::other;
    }
}

#else

namespace {

struct Range {
    char32_t first, last;
    Script script;
};

// The blocks (and the parts of blocks) Unicode's Scripts.txt gives to these
// scripts, in code point order; everything else is `other`. Coarser than
// ICU's per-character data at a few edges (e.g. a Latin letter in a block of
// symbols), which docs/windows.md names.
constexpr std::array kRanges{
    Range{0x0000, 0x0040, Script::common},    Range{0x0041, 0x005A, Script::latin},
    Range{0x005B, 0x0060, Script::common},    Range{0x0061, 0x007A, Script::latin},
    Range{0x007B, 0x00A9, Script::common},    Range{0x00AA, 0x00AA, Script::latin},
    Range{0x00AB, 0x00B9, Script::common},    Range{0x00BA, 0x00BA, Script::latin},
    Range{0x00BB, 0x00BF, Script::common},    Range{0x00C0, 0x00D6, Script::latin},
    Range{0x00D7, 0x00D7, Script::common},    Range{0x00D8, 0x00F6, Script::latin},
    Range{0x00F7, 0x00F7, Script::common},    Range{0x00F8, 0x02B8, Script::latin},
    Range{0x02B9, 0x02E9, Script::common},    Range{0x02EA, 0x02EB, Script::bopomofo},
    Range{0x02EC, 0x02FF, Script::common},    Range{0x0300, 0x036F, Script::inherited},
    Range{0x1AB0, 0x1AFF, Script::inherited}, Range{0x1D00, 0x1D25, Script::latin},
    Range{0x1DC0, 0x1DFF, Script::inherited}, Range{0x1E00, 0x1EFF, Script::latin},
    Range{0x2000, 0x200B, Script::common},    Range{0x200C, 0x200D, Script::inherited},
    Range{0x200E, 0x2064, Script::common},    Range{0x2070, 0x2070, Script::common},
    Range{0x2071, 0x2071, Script::latin},     Range{0x2074, 0x207E, Script::common},
    Range{0x207F, 0x207F, Script::latin},     Range{0x2080, 0x208E, Script::common},
    Range{0x2090, 0x209C, Script::latin},     Range{0x20A0, 0x20C0, Script::common},
    Range{0x20D0, 0x20FF, Script::inherited}, Range{0x2100, 0x2BFF, Script::common},
    Range{0x2C60, 0x2C7F, Script::latin},     Range{0x2E00, 0x2E7F, Script::common},
    Range{0x2E80, 0x2FD5, Script::han},       Range{0x2FF0, 0x3004, Script::common},
    Range{0x3005, 0x3005, Script::han},       Range{0x3006, 0x3006, Script::common},
    Range{0x3007, 0x3007, Script::han},       Range{0x3008, 0x3020, Script::common},
    Range{0x3021, 0x3029, Script::han},       Range{0x302A, 0x302D, Script::inherited},
    Range{0x302E, 0x3037, Script::common},    Range{0x3038, 0x303B, Script::han},
    Range{0x303C, 0x303F, Script::common},    Range{0x3099, 0x309A, Script::inherited},
    Range{0x309B, 0x309C, Script::common},    Range{0x30FB, 0x30FC, Script::common},
    Range{0x3105, 0x312F, Script::bopomofo},  Range{0x3190, 0x319F, Script::common},
    Range{0x31A0, 0x31BF, Script::bopomofo},  Range{0x31C0, 0x31E3, Script::common},
    Range{0x3220, 0x325F, Script::common},    Range{0x327F, 0x32CF, Script::common},
    Range{0x3358, 0x33FF, Script::common},    Range{0x3400, 0x4DBF, Script::han},
    Range{0x4DC0, 0x4DFF, Script::common},    Range{0x4E00, 0x9FFF, Script::han},
    Range{0xA700, 0xA721, Script::common},    Range{0xA722, 0xA787, Script::latin},
    Range{0xA788, 0xA78A, Script::common},    Range{0xA78B, 0xA7FF, Script::latin},
    Range{0xAB30, 0xAB5A, Script::latin},     Range{0xAB5C, 0xAB64, Script::latin},
    Range{0xF900, 0xFAFF, Script::han},       Range{0xFB00, 0xFB06, Script::latin},
    Range{0xFE00, 0xFE0F, Script::inherited}, Range{0xFE10, 0xFE19, Script::common},
    Range{0xFE20, 0xFE2F, Script::inherited}, Range{0xFE30, 0xFE6B, Script::common},
    Range{0xFEFF, 0xFEFF, Script::common},    Range{0xFF01, 0xFF20, Script::common},
    Range{0xFF21, 0xFF3A, Script::latin},     Range{0xFF3B, 0xFF40, Script::common},
    Range{0xFF41, 0xFF5A, Script::latin},     Range{0xFF5B, 0xFF65, Script::common},
    Range{0xFF70, 0xFF70, Script::common},    Range{0xFF9E, 0xFF9F, Script::common},
    Range{0xFFE0, 0xFFFD, Script::common},    Range{0x1F000, 0x1FAFF, Script::common},
    Range{0x20000, 0x2FA1F, Script::han},     Range{0x30000, 0x323AF, Script::han},
    Range{0xE0001, 0xE007F, Script::common},  Range{0xE0100, 0xE01EF, Script::inherited},
};

}  // namespace

Script script_of(char32_t c) {
    const auto* it = std::upper_bound(kRanges.begin(), kRanges.end(), c,
                                      [](char32_t v, const Range& r) { return v < r.first; });
    if (it == kRanges.begin()) return Script::other;
    --it;
    return c <= it->last ? it->script : Script::other;
}

#endif

}  // namespace tactus::translate
