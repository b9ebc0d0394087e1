// SPDX-License-Identifier: GPL-3.0-or-later
#include "language_args.hpp"

#include "command.hpp"

namespace tactus::cli {

void LanguageArgs::add_to(CLI::App& cmd) {
    cmd.add_flag("--one-table", one_table,
                 "Translate everything with --table, also passages in another language or script "
                 "(by default English inside Chinese text, or Chinese inside any other, gets its own table)");
    cmd.add_option("--second-table", second_table,
                   "The table for the other language: English inside a Chinese document, Chinese inside any "
                   "other (default: from the catalogue: en-ueb-g1.ctb, or en-ueb-g2.ctb with --english-grade 2; "
                   "zh-tw.ctb, zhcn-g1.ctb for passages marked zh-CN or zh-Hans)")
        ->excludes("--one-table");
    cmd.add_option("--english-grade", english_grade, "English inside Chinese without --second-table: UEB grade 1 or 2")
        ->check(CLI::IsMember({"1", "2"}))
        ->capture_default_str();
    cmd.add_option("--switch-indicators", indicators,
                   "Signs around a passage in the other language: auto (the document's code: UEB's non-UEB "
                   "indicators in English, the letter sign in mainland Chinese, UEB's indicators around English "
                   "in Taiwanese), code-switch, letter-sign or none")
        ->check(CLI::IsMember({"auto", "code-switch", "letter-sign", "none"}))
        ->capture_default_str();
}

translate::LanguageSwitchOptions LanguageArgs::options() const {
    translate::LanguageSwitchOptions o;
    o.enabled = !one_table;
    o.second_table = second_table;
    o.english_grade = english_grade;
    const auto rule = translate::parse_switch_indicators(indicators);
    if (!rule) fail_with(exit_usage, Error{"unknown rule '" + indicators + "'", "--switch-indicators", ErrorKind::usage});
    o.indicators = *rule;
    return o;
}

}  // namespace tactus::cli
