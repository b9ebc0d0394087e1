// SPDX-License-Identifier: GPL-3.0-or-later
#include "translate/translator.hpp"

#include <liblouis/liblouis.h>

#include <vector>

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

// One liblouis call with a growing output buffer: liblouis stops silently when the
// buffer is full, so a short `inlen` afterwards means "try again with more room".
Result<std::u32string> run(const std::string& table_list, std::u32string_view in,
                           std::span<const std::uint8_t> emphasis, Direction dir) {
    if (in.empty()) return std::u32string{};
    if (in.size() > 1u << 24) return fail("text block too long for one translation");
    const auto* inbuf = reinterpret_cast<const widechar*>(in.data());
    std::vector<formtype> typeform;
    if (!emphasis.empty()) {
        typeform.resize(in.size() * 4 + 16, plain_text);
        for (std::size_t i = 0; i < in.size() && i < emphasis.size(); ++i)
            typeform[i] = to_typeform(emphasis[i]);
    }
    std::size_t capacity = in.size() * 2 + 32;
    for (int attempt = 0; attempt < 6; ++attempt, capacity *= 4) {
        std::u32string out(capacity, U'\0');
        int inlen = static_cast<int>(in.size());
        int outlen = static_cast<int>(capacity);
        int ok = 0;
        std::string log;
        {
            std::lock_guard guard(louis::lock());
            if (dir == Direction::forward) {
                ok = lou_translateString(table_list.c_str(), inbuf, &inlen,
                                         reinterpret_cast<widechar*>(out.data()), &outlen,
                                         typeform.empty() ? nullptr : typeform.data(), nullptr,
                                         0);
            } else {
                ok = lou_backTranslateString(table_list.c_str(), inbuf, &inlen,
                                             reinterpret_cast<widechar*>(out.data()), &outlen,
                                             nullptr, nullptr, 0);
            }
            log = louis::take_log();
        }
        if (!ok)
            return fail("liblouis could not translate with '" + table_list + "'" +
                        (log.empty() ? std::string{} : ": " + log));
        if (static_cast<std::size_t>(inlen) >= in.size() &&
            static_cast<std::size_t>(outlen) < capacity) {
            out.resize(static_cast<std::size_t>(outlen));
            return out;
        }
        if (!typeform.empty()) typeform.resize(capacity * 4, plain_text);
    }
    return fail("translation output kept overflowing its buffer");
}

}  // namespace

Result<Translator> Translator::open(std::string tables) {
    if (tables.empty()) return fail("no translation table given");
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
        return fail("unknown or broken braille table '" + tables + "'" +
                        (log.empty() ? std::string{} : " (liblouis: " + log + ")"),
                    "--table");
    return Translator(std::move(tables));
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
