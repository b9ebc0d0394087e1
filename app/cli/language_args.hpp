// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The options for passages in another language (translate/language_switch.hpp),
// the same for `layout`, `plan`, `emboss` and `translate`.
#include <string>

#include <CLI/CLI.hpp>

#include "translate/language_switch.hpp"

namespace tactus::cli {

struct LanguageArgs {
    bool one_table = false;
    std::string second_table;
    std::string english_grade = "1";
    std::string indicators = "auto";

    void add_to(CLI::App& cmd);
    // Validated; a bad value ends the command with a usage error.
    [[nodiscard]] translate::LanguageSwitchOptions options() const;
};

}  // namespace tactus::cli
