// SPDX-License-Identifier: GPL-3.0-or-later
#include "translate/code_switch.hpp"

namespace tactus::translate {

std::size_t symbols_sequences(std::u32string_view run) {
    std::size_t n = 0;
    bool in = false;
    for (char32_t c : run) {
        const bool space = c == U' ' || c == 0x3000 || c == 0xA0;
        if (!space && !in) ++n;
        in = !space;
    }
    return n;
}

SwitchForm switch_form(SwitchIndicators rule, std::u32string_view run) {
    switch (rule) {
        case SwitchIndicators::code_switch:
            return symbols_sequences(run) >= 3 ? SwitchForm::passage : SwitchForm::word;
        case SwitchIndicators::letter_sign:
            return SwitchForm::letter_sign;
        case SwitchIndicators::automatic:
        case SwitchIndicators::none:
            break;
    }
    return SwitchForm::none;
}

}  // namespace tactus::translate
