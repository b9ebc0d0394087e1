// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli translate: line-by-line liblouis translation, no layout; each output
// line is exactly what liblouis gives for the input line.
#include <algorithm>
#include <iostream>
#include <iterator>

#include "command.hpp"
#include "language_args.hpp"
#include "common/file_io.hpp"
#include "common/utf8.hpp"
#include "import/import.hpp"
#include "translate/catalogue.hpp"
#include "translate/language_switch.hpp"
#include "translate/translated_document.hpp"
#include "translate/translator.hpp"

namespace tactus::cli {
namespace {

struct TranslateArgs {
    std::string tables = translate::kDefaultTable;
    std::string to = "unicode";
    std::string file = "-";
    bool back = false;
    LanguageArgs language;
};

// A piece with a passage in another language: translated as a paragraph is
// (translate_block), each language with its table and the signs around it,
// then written in the display asked for. Text all in the table's language
// never comes here: it stays exactly what liblouis gives.
std::optional<std::u32string> translate_mixed(const translate::Translator& translator, std::u32string_view piece,
                                              bool brf, const std::string& where) {
    const auto* sw = translator.language_switch();
    if (!sw) return std::nullopt;
    const auto runs = sw->split(piece);
    if (runs.size() <= 1 && (runs.empty() || runs.front().slot == translate::TableSlot::primary)) return std::nullopt;
    document::Block block;
    block.spans.push_back(document::Span{utf32_to_utf8(piece)});
    const auto tb = translate::translate_block(block, translator);
    if (!tb) fail_with(located(tb.error(), where));
    std::u32string out;
    for (const auto c : tb->cells) out += brf ? static_cast<char32_t>(document::cell_to_brf(c)) : c.unicode();
    return out;
}

// A line of braille (Unicode braille or Braille ASCII) as cells.
document::BrailleLine braille_cells(std::u32string_view text, const std::string& where) {
    document::BrailleLine cells;
    for (char32_t c : text) {
        document::Cell cell;
        if (document::Cell::is_unicode_braille(c)) cell = document::Cell::from_unicode(c);
        else if (c > 0x7F || !document::cell_from_brf(static_cast<char>(c), cell))
            fail_with(exit_bad_input, Error{"not braille (Unicode braille or Braille ASCII expected)", where, ErrorKind::input});
        cells.push_back(cell);
    }
    return cells;
}

// One line of input, translated or back-translated. A form feed (a BRF's page
// break) is kept where it is: each piece between form feeds is translated by
// itself, so the output has its lines and pages where the input has them.
std::string translate_line(const translate::Translator& translator, const TranslateArgs& a, std::string_view line,
                           const std::string& where) {
    auto text = utf8_to_utf32(line);
    if (!text) fail_with(exit_bad_input, located(text.error(), where));
    const auto display = a.to == "brf" ? "en-us-brf.dis" : "unicode.dis";
    std::string out;
    std::size_t from = 0;
    for (;;) {
        const auto feed = std::min(text->find(U'\f', from), text->size());
        const std::u32string_view piece = std::u32string_view(*text).substr(from, feed - from);
        const auto mixed = a.back ? std::nullopt : translate_mixed(translator, piece, a.to == "brf", where);
        const auto braille = a.back  ? translator.back_translate(braille_cells(piece, where))
                             : mixed ? Result<std::u32string>(*mixed)
                                     : translator.translate_with_display(piece, display);
        if (!braille) fail_with(located(braille.error(), where));
        out += utf32_to_utf8(*braille);
        if (feed == text->size()) break;
        out += '\f';
        from = feed + 1;
    }
    return out;
}

// A PEF's pages back-translated row for row, a form feed between pages.
void back_translate_pef(const translate::Translator& translator, const std::string& bytes, const std::string& name) {
    import::ImportOptions options;
    options.format = import::SourceFormat::pef;
    const auto doc = import::import_bytes(bytes, name, options);
    if (!doc) fail_with(doc.error());
    for (const auto& block : doc->blocks) {
        if (block.kind == document::BlockKind::braille_page_break) {
            std::cout << '\f';
            continue;
        }
        for (const auto& row : block.braille_lines) {
            const auto where = name + ":" + std::to_string(block.source_line);
            auto text = translator.back_translate(row);
            if (!text) fail_with(located(text.error(), where));
            std::cout << utf32_to_utf8(*text) << '\n';
        }
    }
}

void run_translate(const TranslateArgs& a) {
    auto language = a.language.options();
    if (a.back) language.enabled = false;  // braille has no script to tell languages by
    const auto translator = require(translate::open_translator(a.tables, language));
    const std::string name = a.file == "-" ? "<stdin>" : a.file;
    int number = 0;
    if (a.file == "-" && !a.back) {
        // Line by line as it comes, never all of a pipe held at once.
        std::string line;
        while (std::getline(std::cin, line)) {
            if (!line.empty() && line.back() == '\r') line.pop_back();
            std::cout << translate_line(translator, a, line, name + ":" + std::to_string(++number)) << '\n';
        }
        if (std::cin.bad()) fail_with(exit_bad_input, Error{"read error", name, ErrorKind::input});
        return;
    }
    std::string bytes;
    if (a.file == "-") {
        bytes.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
        if (std::cin.bad()) fail_with(exit_bad_input, Error{"read error", name, ErrorKind::input});
    } else {
        // A regular file only: a named pipe with no writer would wait for ever.
        bytes = require(read_file(a.file), exit_bad_input);
    }
    if (a.back && import::detect_source_format(bytes, name) == import::SourceFormat::pef) {
        back_translate_pef(translator, bytes, name);
        return;
    }
    for (std::size_t from = 0; from < bytes.size();) {
        const auto end = std::min(bytes.find('\n', from), bytes.size());
        std::string_view line(bytes.data() + from, end - from);
        from = end + 1;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        std::cout << translate_line(translator, a, line, name + ":" + std::to_string(++number)) << '\n';
    }
}

}  // namespace

void add_translate_command(CLI::App& app) {
    auto args = std::make_shared<TranslateArgs>();
    auto* cmd = app.add_subcommand("translate",
                                   "Translate text to braille line by line (no layout)");
    cmd->add_option("--table,-t", args->tables, "liblouis table list, e.g. en-ueb-g2.ctb")
        ->capture_default_str();
    args->language.add_to(*cmd);
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
