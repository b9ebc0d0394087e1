// SPDX-License-Identifier: GPL-3.0-or-later
#include "translate/translator.hpp"

#include <liblouis/liblouis.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>
#include <algorithm>

#include "document/document.hpp"
#include "translate/louis.hpp"

namespace tactus::translate {
namespace {

static_assert(sizeof(widechar) == sizeof(char32_t),
              "Tactus expects liblouis built with 32-bit widechar (Debian's is)");

constexpr std::string_view kUnicodeDisplay = "unicode.dis";

formtype to_typeform(std::uint8_t e) {
    formtype t = plain_text;
    if (e & document::emphasis_italic) t = static_cast<formtype>(t | italic);
    if (e & document::emphasis_bold) t = static_cast<formtype>(t | bold);
    if (e & document::emphasis_underline) t = static_cast<formtype>(t | underline);
    return t;
}

enum class Direction { forward, backward };

// The output room for one liblouis call, and how much of it a complete result
// leaves unused. liblouis (3.24) does not report a full output buffer reliably:
// an escape code for a character the table does not know (`'\x0440'`, up to 12
// cells) or a rule's dots that do not fit are dropped while the whole input is
// still reported as read ("Привет мир" with room for 52 cells gives the first
// word, 49 cells, and inlen 10 of 10). What it drops is at most one write, so a
// result is complete when it ends further from the end of the buffer than any
// one write reaches: a result closer to the end, or one that did not read the
// whole input, is translated again with four times the room. The headroom
// (64 cells and a quarter of the buffer) is well above the longest escape code
// and the longest rule in the installed tables.
constexpr std::size_t first_capacity(std::size_t in) { return in * 3 + 128; }
constexpr std::size_t headroom(std::size_t capacity) { return 64 + capacity / 4; }

// The typeform array liblouis reads for the input and writes for the output:
// lou_translate copies it in for `inlen` characters and, on success, writes a
// '0' or '8' (dots 7-8 or not) per output cell into it, so it must be as long
// as the output buffer and filled afresh for every call.
void fill_typeform(std::vector<formtype>& typeform, std::span<const std::uint8_t> emphasis,
                   std::size_t in_size, std::size_t capacity) {
    typeform.assign(std::max(in_size, capacity), plain_text);
    for (std::size_t i = 0; i < in_size && i < emphasis.size(); ++i) typeform[i] = to_typeform(emphasis[i]);
}

// One liblouis call, again with more room until the result is known whole
// (first_capacity(), headroom()). Every buffer liblouis may write (output,
// typeform, inputPos) is as long as the output length it is told.
Result<std::u32string> run(const std::string& table_list, std::u32string_view in,
                           std::span<const std::uint8_t> emphasis, Direction dir,
                           std::vector<int>* input_pos = nullptr) {
    if (in.empty()) {
        if (input_pos) input_pos->clear();
        return std::u32string{};
    }
    if (in.size() > 1u << 24) return fail(ErrorKind::input, "text block too long for one translation");
    const auto* inbuf = reinterpret_cast<const widechar*>(in.data());
    std::vector<formtype> typeform;
    std::size_t capacity = first_capacity(in.size());
    for (int attempt = 0; attempt < 6; ++attempt, capacity *= 4) {
        std::u32string out(capacity, U'\0');
        if (input_pos) input_pos->assign(capacity, 0);
        if (!emphasis.empty()) fill_typeform(typeform, emphasis, in.size(), capacity);
        int inlen = static_cast<int>(in.size());
        int outlen = static_cast<int>(capacity);
        int ok = 0;
        std::string log;
        {
            std::lock_guard guard(louis::lock());
            if (dir == Direction::forward) {
                ok = lou_translate(table_list.c_str(), inbuf, &inlen, reinterpret_cast<widechar*>(out.data()),
                                   &outlen, typeform.empty() ? nullptr : typeform.data(), nullptr, nullptr,
                                   input_pos ? input_pos->data() : nullptr, nullptr, 0);
            } else {
                ok = lou_backTranslateString(table_list.c_str(), inbuf, &inlen,
                                             reinterpret_cast<widechar*>(out.data()), &outlen,
                                             nullptr, nullptr, 0);
            }
            log = louis::take_log();
        }
        if (!ok)
            return fail(ErrorKind::internal, "liblouis could not translate with '" + table_list + "'" +
                        (log.empty() ? std::string{} : ": " + log));
        const auto produced = static_cast<std::size_t>(std::max(outlen, 0));
        if (static_cast<std::size_t>(inlen) >= in.size() && produced + headroom(capacity) <= capacity) {
            out.resize(produced);
            if (input_pos) input_pos->resize(produced);
            return out;
        }
    }
    return fail(ErrorKind::internal, "liblouis did not finish the translation of " + std::to_string(in.size()) +
                                         " characters in " + std::to_string(capacity / 4) + " cells");
}

std::string table_info(const std::string& table, const char* key) {
    char* v = lou_getTableInfo(table.c_str(), key);
    if (!v) return {};
    std::string s(v);
    std::free(v);  // NOLINT: liblouis hands ownership to the caller
    return s;
}

// A table's file: a name as liblouis finds it in its data folder, or a path.
std::filesystem::path table_path(const std::string& table) {
    return table.find('/') != std::string::npos ? std::filesystem::path(table)
                                                : louis::tables_dir() / table;
}

// A metadata value of a table (liblouis reads a table's own `#+key:` lines
// only), else of the first table it includes that has one: en-us-g2.ctb has no
// metadata of its own but includes en-us-g1.ctb (#+system:ebae).
std::string table_metadata(const std::string& table, const char* key, int depth = 0) {
    if (auto v = table_info(table, key); !v.empty() || depth >= 4) return v;
    std::ifstream in(table_path(table));
    std::string line;
    while (std::getline(in, line)) {
        if (!line.starts_with("include")) continue;
        std::istringstream words(line.substr(7));
        std::string included;
        if (!(words >> included)) continue;
        if (auto v = table_metadata(included, key, depth + 1); !v.empty()) return v;
    }
    return {};
}

// The next whitespace-separated word of `line` from `at`.
std::string_view next_word(std::string_view line, std::size_t& at) {
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
    const auto start = at;
    while (at < line.size() && line[at] != ' ' && line[at] != '\t' && line[at] != '\r') ++at;
    return line.substr(start, at - start);
}

// Does the table (or a table it includes, at any depth) hold a rule with this
// opcode? Read from the table files, as table_metadata() reads them; a prefix
// (`noback`, `nofor`) before the opcode counts.
bool table_has_opcode(const std::string& table, std::string_view opcode, int depth = 0) {
    if (depth > 8) return false;
    std::ifstream in(table_path(table));
    std::string line;
    while (std::getline(in, line)) {
        std::size_t at = 0;
        auto op = next_word(line, at);
        while (op == "noback" || op == "nofor") op = next_word(line, at);
        if (op == opcode) return true;
        if (op == "include") {
            const auto included = next_word(line, at);
            if (!included.empty() && table_has_opcode(std::string(included), opcode, depth + 1)) return true;
        }
    }
    return false;
}

// The first installed hyphenation dictionary for the language ("en" ->
// hyph_en_US.dic), checked by hyphenating a known word with it.
std::string find_hyphenation(const std::string& first_table, const std::string& language) {
    if (language.empty()) return {};
    const auto lang = language.substr(0, language.find('-'));
    std::vector<std::string> candidates;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(louis::tables_dir(), ec)) {
        const auto name = e.path().filename().string();
        if (name.ends_with(".dic") &&
            (name == "hyph_" + lang + ".dic" || name.starts_with("hyph_" + lang + "_")))
            candidates.push_back(name);
    }
    std::ranges::sort(candidates);
    for (const auto& dic : candidates) {
        const std::u32string probe = U"hyphenation";
        std::vector<char> h(probe.size() + 1, '\0');
        const std::string list = first_table + "," + dic;
        if (lou_hyphenate(list.c_str(), reinterpret_cast<const widechar*>(probe.data()),
                          static_cast<int>(probe.size()), h.data(), 0))
            return dic;
    }
    return {};
}

}  // namespace

Result<Translator> Translator::open(std::string tables) {
    if (tables.empty()) return fail(ErrorKind::input, "no translation table given");
    louis::install_log_capture();
    const std::string list = std::string(kUnicodeDisplay) + "," + tables;
    std::string log;
    int ok = 0;
    {
        std::lock_guard guard(louis::lock());
        ok = lou_checkTable(list.c_str());
        log = louis::take_log();
    }
    if (!ok)
        return fail(ErrorKind::input, "unknown or broken braille table '" + tables + "'" +
                        (log.empty() ? std::string{} : " (liblouis: " + log + ")"),
                    "--table");
    Translator t(std::move(tables));
    const auto first = t.tables_.substr(0, t.tables_.find(','));
    {
        std::lock_guard guard(louis::lock());
        t.hyphenation_ = find_hyphenation(first, table_info(first, "language"));
        t.system_ = table_metadata(first, "system");
        t.language_ = table_metadata(first, "region");
        if (t.language_.empty()) t.language_ = table_metadata(first, "language");
        t.ueb_ = t.system_ == "ueb";
        if (t.ueb_) t.division_.number_continuation = document::Cell{0x10};  // dot 5
        // `compbrl` switches a whole word to computer braille when any of its
        // characters asks for it (en-us-g2.ctb does so for a word holding
        // "://", ".com", "()" and the like): how the start of a word is written
        // then depends on its end.
        t.word_wide_rules_ = false;
        for (std::size_t at = 0; at <= t.tables_.size() && !t.word_wide_rules_;) {
            const auto comma = std::min(t.tables_.find(',', at), t.tables_.size());
            t.word_wide_rules_ = table_has_opcode(t.tables_.substr(at, comma - at), "compbrl");
            at = comma + 1;
        }
        if (t.ueb_) {
            // UEB has no note indicator (⠶⠶ is its double prime): a numbered
            // reference is print's superscript number, the superscript
            // indicator (dots 35) before it, in grade 1 mode in contracted
            // braille (Rules of UEB 2013 §3.24.1, "clarion¹" as ;9#a, and
            // §11.4.2, a footnote "paper⁵⁶" as pap];9#ef), without the grade 1
            // indicator in a work entirely in grade 1 (§5.11.1).
            if (table_metadata(first, "contraction") != "no") t.note_indicator_.push_back(document::Cell{0x30});  // dots 56
            t.note_indicator_.push_back(document::Cell{0x14});  // dots 35
        } else if (t.system_ == "ebae") {
            t.note_indicator_.assign(2, document::Cell{0x36});  // dots 2356 2356 (Braille Formats 2011 §16.1.3)
        }
        louis::take_log();
    }
    if (t.division_.number_continuation) {
        // The numeric indicator is what liblouis writes before a digit: "1" is
        // the indicator and the digit's own cell.
        auto one = t.translate(U"1");
        if (one && one->size() >= 2) t.division_.numeric_indicator.assign(one->begin(), one->end() - 1);
    }
    return t;
}

Result<MappedBraille> Translator::translate_mapped(std::u32string_view text,
                                                   std::span<const std::uint8_t> emphasis) const {
    std::vector<int> positions;
    auto out = run(std::string(kUnicodeDisplay) + "," + tables_, text, emphasis, Direction::forward,
                   &positions);
    if (!out) return std::unexpected(out.error());
    MappedBraille m;
    m.cells.reserve(out->size());
    m.source.reserve(out->size());
    for (std::size_t i = 0; i < out->size(); ++i) {
        const char32_t c = (*out)[i];
        m.cells.push_back(document::Cell::is_unicode_braille(c) ? document::Cell::from_unicode(c) : document::Cell{});
        const int p = positions[i];
        m.source.push_back(static_cast<std::uint32_t>(
            std::clamp(p, 0, static_cast<int>(text.size()) - 1)));
    }
    return m;
}

std::vector<bool> Translator::hyphenation_points(std::u32string_view word) const {
    std::vector<bool> out(word.size() + 1, false);
    // A dictionary knows words, not kilobytes of letters: longer runs are not asked.
    if (hyphenation_.empty() || word.size() < 4 || word.size() > 200) return out;
    std::vector<char> h(word.size() + 1, '\0');
    const auto first = tables_.substr(0, tables_.find(','));
    const std::string list = first + "," + hyphenation_;
    int ok = 0;
    {
        std::lock_guard guard(louis::lock());
        ok = lou_hyphenate(list.c_str(), reinterpret_cast<const widechar*>(word.data()),
                           static_cast<int>(word.size()), h.data(), 0);
        louis::take_log();
    }
    if (!ok) return out;
    for (std::size_t i = 1; i < word.size(); ++i) out[i] = h[i] == '1';
    return out;
}

Result<document::BrailleLine> Translator::translate(std::u32string_view text,
                                          std::span<const std::uint8_t> emphasis) const {
    auto out = run(std::string(kUnicodeDisplay) + "," + tables_, text, emphasis,
                   Direction::forward);
    if (!out) return std::unexpected(out.error());
    document::BrailleLine cells;
    cells.reserve(out->size());
    for (char32_t c : *out) {
        // unicode.dis maps every dot pattern into U+2800..U+28FF; anything else
        // would be a table passing text through, which we treat as blank rather
        // than invent dots.
        cells.push_back(document::Cell::is_unicode_braille(c) ? document::Cell::from_unicode(c) : document::Cell{});
    }
    return cells;
}

Result<std::u32string> Translator::back_translate(const document::BrailleLine& cells) const {
    std::u32string in;
    in.reserve(cells.size());
    for (document::Cell c : cells) in.push_back(c.unicode());
    return run(std::string(kUnicodeDisplay) + "," + tables_, in, {}, Direction::backward);
}

Result<std::u32string> Translator::translate_with_display(std::u32string_view text,
                                                          std::string_view display_table) const {
    return run(std::string(display_table) + "," + tables_, text, {}, Direction::forward);
}

}  // namespace tactus::translate
