// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli translate: line-by-line liblouis translation, no layout; each output
// line is exactly what liblouis gives for the input line.
#include <fstream>
#include <iostream>
#include <iterator>

#include "command.hpp"
#include "common/utf8.hpp"
#include "translate/catalogue.hpp"
#include "translate/translator.hpp"

namespace tactus::cli {
namespace {

struct TranslateArgs {
    std::string tables = translate::kDefaultTable;
    std::string to = "unicode";
    std::string file = "-";
    bool back = false;
};

void run_translate(const TranslateArgs& a) {
    const auto display = a.to == "brf" ? "en-us-brf.dis" : "unicode.dis";
    const auto translator = require(translate::Translator::open(a.tables));
    std::ifstream file;
    if (a.file != "-") {
        file.open(a.file, std::ios::binary);
        if (!file) fail_with(exit_bad_input, Error{"cannot open file", a.file});
    }
    std::istream& in = a.file == "-" ? std::cin : file;
    const std::string name = a.file == "-" ? "<stdin>" : a.file;
    std::string line;
    std::string out;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const auto where = name + ":" + std::to_string(number);
        auto text = utf8_to_utf32(line);
        if (!text) fail_with(exit_bad_input, located(text.error(), where));
        Result<std::u32string> braille;
        if (a.back) {
            document::BrailleLine cells;
            for (char32_t c : *text) {
                document::Cell cell;
                if (document::Cell::is_unicode_braille(c)) cell = document::Cell::from_unicode(c);
                else if (c > 0x7F || !document::cell_from_brf(static_cast<char>(c), cell))
                    fail_with(exit_bad_input, Error{"not braille (Unicode braille or Braille ASCII expected)", where});
                cells.push_back(cell);
            }
            braille = translator.back_translate(cells);
        } else {
            braille = translator.translate_with_display(*text, display);
        }
        if (!braille) fail_with(exit_bad_input, located(braille.error(), where));
        out = utf32_to_utf8(*braille);
        out += '\n';
        std::cout << out;
    }
    if (in.bad()) fail_with(exit_bad_input, Error{"read error", name});
}

}  // namespace

void add_translate_command(CLI::App& app) {
    auto args = std::make_shared<TranslateArgs>();
    auto* cmd = app.add_subcommand("translate",
                                   "Translate text to braille line by line (no layout)");
    cmd->add_option("--table,-t", args->tables, "liblouis table list, e.g. en-ueb-g2.ctb")
        ->capture_default_str();
    cmd->add_option("--to", args->to, "Output: unicode braille or brf (Braille ASCII)")
        ->check(CLI::IsMember({"unicode", "brf"}))
        ->capture_default_str();
    cmd->add_flag("--back", args->back,
                  "Back-translate braille (Unicode or Braille ASCII) to text for proofreading");
    cmd->add_option("file", args->file, "Input file (UTF-8), or - for standard input")
        ->capture_default_str();
    cmd->callback([args] { run_translate(*args); });
}

}  // namespace tactus::cli
