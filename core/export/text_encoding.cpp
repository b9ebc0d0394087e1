// SPDX-License-Identifier: GPL-3.0-or-later
// A text file written back in the encoding it was read in: ICU, the
// converter the importer decoded it with, stopping at the first character the
// encoding cannot hold instead of writing a substitute.
// Without ICU (TACTUS_WITH_ICU off) only UTF-8 is written.
#if TACTUS_HAVE_ICU
#include <unicode/ucnv.h>
#include <unicode/ustring.h>
#include <unicode/utf16.h>
#else
#include "common/unavailable.hpp"
#endif

#include <array>
#include <cctype>
#include <cstdio>
#include <memory>
#include <string>

#include "common/utf8.hpp"
#include "export/text_export.hpp"

namespace tactus::exporter {
namespace {

constexpr std::string_view kUnrepresentable = "cannot be written in ";

#if TACTUS_HAVE_ICU
struct ConverterCloser {
    void operator()(UConverter* c) const { ucnv_close(c); }
};
using Converter = std::unique_ptr<UConverter, ConverterCloser>;
#endif

bool is_utf8_name(std::string_view name) {
    std::string n;
    for (char c : name)
        if (c != '-' && c != '_') n += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return n.empty() || n == "UTF8";
}

#if TACTUS_HAVE_ICU
// line:column (1-based, in characters) of UTF-16 offset `at`.
std::string position_of(const std::u16string& text, std::size_t at) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < at && i < text.size(); ++i) {
        if (text[i] == u'\n') {
            ++line;
            column = 1;
        } else if (!U16_IS_TRAIL(text[i])) {
            ++column;
        }
    }
    return std::to_string(line) + ":" + std::to_string(column);
}
#endif

}  // namespace

Result<std::string> encode_text(std::string_view utf8, std::string_view encoding, bool byte_order_mark) {
    if (is_utf8_name(encoding)) return byte_order_mark ? "\xEF\xBB\xBF" + std::string(utf8) : std::string(utf8);
    const std::string name(encoding);
#if !TACTUS_HAVE_ICU
    return unavailable("writing text in " + name + " (only UTF-8 is written)", "ICU", "encoding");
#else
    UErrorCode err = U_ZERO_ERROR;
    Converter cnv(ucnv_open(name.c_str(), &err));
    if (U_FAILURE(err) || !cnv) return fail(ErrorKind::input, "unknown encoding '" + name + "'", "encoding");
    ucnv_setFromUCallBack(cnv.get(), UCNV_FROM_U_CALLBACK_STOP, nullptr, nullptr, nullptr, &err);
    if (U_FAILURE(err)) return fail(ErrorKind::internal, "cannot configure converter for '" + name + "'", "encoding");

    // UTF-8 -> UTF-16 (ICU's own form), the byte-order mark as U+FEFF first.
    std::u16string text;
    if (byte_order_mark) text += u'\uFEFF';
    int32_t length = 0;
    err = U_ZERO_ERROR;
    u_strFromUTF8(nullptr, 0, &length, utf8.data(), static_cast<int32_t>(utf8.size()), &err);
    if (err != U_BUFFER_OVERFLOW_ERROR && U_FAILURE(err)) return fail(ErrorKind::internal, "text is not UTF-8", "encoding");
    const auto start = text.size();
    text.resize(start + static_cast<std::size_t>(length));
    err = U_ZERO_ERROR;
    u_strFromUTF8(reinterpret_cast<UChar*>(text.data() + start), length, nullptr, utf8.data(),
                  static_cast<int32_t>(utf8.size()), &err);
    if (U_FAILURE(err)) return fail(ErrorKind::internal, "text is not UTF-8", "encoding");

    std::string out;
    out.reserve(text.size() * 2);
    std::array<char, 32768> buffer{};
    const auto* const begin = reinterpret_cast<const UChar*>(text.data());
    const UChar* source = begin;
    const UChar* const end = begin + text.size();
    for (;;) {
        err = U_ZERO_ERROR;
        char* target = buffer.data();
        ucnv_fromUnicode(cnv.get(), &target, buffer.data() + buffer.size(), &source, end, nullptr, /*flush=*/true,
                         &err);
        out.append(buffer.data(), static_cast<std::size_t>(target - buffer.data()));
        if (err == U_BUFFER_OVERFLOW_ERROR) continue;
        if (U_FAILURE(err)) {
            std::array<UChar, 8> bad{};
            int8_t bad_length = static_cast<int8_t>(bad.size());
            UErrorCode e2 = U_ZERO_ERROR;
            ucnv_getInvalidUChars(cnv.get(), bad.data(), &bad_length, &e2);
            const auto consumed = static_cast<std::size_t>(source - begin);
            const auto skip = U_SUCCESS(e2) ? static_cast<std::size_t>(bad_length) : 0;
            const auto at = consumed >= skip ? consumed - skip : consumed;
            auto c = static_cast<char32_t>(text[at]);
            if (U16_IS_LEAD(text[at]) && at + 1 < text.size() && U16_IS_TRAIL(text[at + 1]))
                c = static_cast<char32_t>(U16_GET_SUPPLEMENTARY(text[at], text[at + 1]));
            std::array<char, 16> hex{};
            std::snprintf(hex.data(), hex.size(), "U+%04X", static_cast<unsigned>(c));
            std::string glyph;
            append_utf8(glyph, c);
            const auto line_start = byte_order_mark ? std::size_t{1} : std::size_t{0};
            return fail(ErrorKind::input,
                        std::string("character ") + hex.data() + " \"" + glyph + "\" " + std::string(kUnrepresentable) +
                            name,
                        position_of(text.substr(line_start), at - line_start));
        }
        break;
    }
    return out;
#endif
}

bool is_unrepresentable_error(const Error& error) {
    return error.kind == ErrorKind::input && error.message.find(kUnrepresentable) != std::string::npos;
}

}  // namespace tactus::exporter
