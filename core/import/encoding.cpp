// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/encoding.hpp"

// Without ICU (TACTUS_WITH_ICU off) only UTF-8 is read; without uchardet
// (TACTUS_WITH_UCHARDET off) an encoding is never guessed. Other text is
// refused, naming what is missing.
#if TACTUS_HAVE_ICU
#include <unicode/ucnv.h>
#include <unicode/utf16.h>
#endif
#if TACTUS_HAVE_UCHARDET
#include <uchardet.h>
#endif

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <memory>

#include "common/utf8.hpp"
#include "import/text_position.hpp"
#include "common/try.hpp"
#include "common/unavailable.hpp"

namespace tactus::import::detail {
namespace {

#if TACTUS_HAVE_ICU
struct ConverterCloser {
    void operator()(UConverter* c) const { ucnv_close(c); }
};
using Converter = std::unique_ptr<UConverter, ConverterCloser>;
#endif

#if TACTUS_HAVE_UCHARDET
struct DetectorFree {
    void operator()(uchardet_t d) const { uchardet_delete(d); }
};
using Detector = std::unique_ptr<std::remove_pointer_t<uchardet_t>, DetectorFree>;
#endif

std::string upper(std::string_view s) {
    std::string out(s);
    for (auto& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

std::string byte_at(std::size_t offset) { return "byte " + std::to_string(offset); }

struct Bom {
    std::string_view encoding;
    std::size_t length = 0;
};

Bom sniff_bom(std::string_view b) {
    auto starts = [&](std::string_view p) { return b.substr(0, p.size()) == p; };
    using namespace std::string_view_literals;
    if (starts("\xEF\xBB\xBF"sv)) return {"UTF-8", 3};
    if (starts("\xFF\xFE\x00\x00"sv)) return {"UTF-32LE", 4};
    if (starts("\x00\x00\xFE\xFF"sv)) return {"UTF-32BE", 4};
    if (starts("\xFF\xFE"sv)) return {"UTF-16LE", 2};
    if (starts("\xFE\xFF"sv)) return {"UTF-16BE", 2};
    return {};
}

#if TACTUS_HAVE_ICU
Result<Converter> open_converter(const std::string& name) {
    UErrorCode err = U_ZERO_ERROR;
    Converter cnv(ucnv_open(name.c_str(), &err));
    if (U_FAILURE(err) || !cnv)
        return fail(ErrorKind::usage, "unknown encoding '" + name +
                        "' (try UTF-8, UTF-16LE, GB18030, Big5, windows-1252, ...)",
                    "encoding");
    // Stop at the first byte sequence the encoding does not define: a silent
    // substitution character would lose the teacher's text without a word.
    ucnv_setToUCallBack(cnv.get(), UCNV_TO_U_CALLBACK_STOP, nullptr, nullptr, nullptr, &err);
    if (U_FAILURE(err)) return fail(ErrorKind::usage, "cannot configure converter for '" + name + "'", "encoding");
    return cnv;
}

bool is_utf8_converter(UConverter* cnv) {
    UErrorCode err = U_ZERO_ERROR;
    return std::strcmp(ucnv_getName(cnv, &err), "UTF-8") == 0;
}

// Streams `bytes` through ICU into UTF-8 in bounded chunks, so the peak is the
// input plus the output; a byte-order mark comes out as U+FEFF (removed by the caller).
Result<std::string> convert(std::string_view bytes, UConverter* cnv, const std::string& label) {
    std::string out;
    out.reserve(bytes.size() + bytes.size() / 2);  // CJK: 2 bytes -> 3 bytes of UTF-8
    std::array<UChar, 16384> buffer{};
    const char* const begin = bytes.data();
    const char* source = begin;
    const char* const end = begin + bytes.size();
    UChar pending_high = 0;  // a surrogate pair split across two chunks
    for (;;) {
        UErrorCode err = U_ZERO_ERROR;
        UChar* target = buffer.data();
        ucnv_toUnicode(cnv, &target, buffer.data() + buffer.size(), &source, end, nullptr,
                       /*flush=*/true, &err);
        for (const UChar* p = buffer.data(); p != target; ++p) {
            const UChar u = *p;
            if (pending_high != 0) {
                if (U16_IS_TRAIL(u)) {
                    append_utf8(out, static_cast<char32_t>(U16_GET_SUPPLEMENTARY(pending_high, u)));
                    pending_high = 0;
                    continue;
                }
                pending_high = 0;  // cannot happen: ICU emits well-formed UTF-16
            }
            if (U16_IS_LEAD(u))
                pending_high = u;
            else
                append_utf8(out, u);
        }
        if (err == U_BUFFER_OVERFLOW_ERROR) continue;
        if (U_FAILURE(err)) {
            std::array<char, 32> bad{};
            auto bad_length = static_cast<std::int8_t>(bad.size());
            UErrorCode e2 = U_ZERO_ERROR;
            ucnv_getInvalidChars(cnv, bad.data(), &bad_length, &e2);
            const auto consumed = static_cast<std::size_t>(source - begin);
            const auto skip = U_SUCCESS(e2) ? static_cast<std::size_t>(bad_length) : 0;
            const auto offset = consumed >= skip ? consumed - skip : consumed;
            std::string what = err == U_TRUNCATED_CHAR_FOUND ? "text ends inside a character"
                                                             : "byte sequence not valid";
            return fail(ErrorKind::input, what + " in " + label + " (wrong encoding? name it explicitly)",
                        byte_at(offset));
        }
        break;
    }
    return out;
}

#endif

#if TACTUS_HAVE_UCHARDET
// uchardet returns "" when unsure; it may be fed in pieces and settles early.
std::string detect_with_uchardet(std::string_view bytes) {
    Detector det(uchardet_new());
    constexpr std::size_t chunk = 64 * 1024;
    constexpr std::size_t enough = 16u << 20;  // more does not change its mind
    for (std::size_t i = 0; i < bytes.size() && i < enough; i += chunk) {
        const auto piece = bytes.substr(i, chunk);
        if (uchardet_handle_data(det.get(), piece.data(), piece.size()) != 0) break;
    }
    uchardet_data_end(det.get());
    return uchardet_get_charset(det.get());
}

// uchardet is unreliable on short texts (a one-line Chinese note may come back as
// ISO-8859-16, a Spanish one as ISO-8859-10), so its answer is only trusted
// within the shape of the text:
//  - CJK multi-byte encodings are taken as they are;
//  - a text whose non-ASCII bytes come in runs (as CJK characters do) but that
//    uchardet calls single-byte is refused: mojibake is worse than a question;
//  - single-byte Latin-script guesses become Windows-1252, the legacy Western
//    encoding teachers actually have; other scripts (Cyrillic, Greek, ...) are kept.
bool is_cjk(const std::string& e) {
    static constexpr std::string_view cjk[] = {"BIG5", "GB18030", "GB2312", "GBK", "EUC-TW",
                                               "EUC-JP", "EUC-KR", "SHIFT_JIS", "UHC",
                                               "ISO-2022-JP", "ISO-2022-KR", "ISO-2022-CN",
                                               "HZ-GB-2312", "JOHAB"};
    return std::find(std::begin(cjk), std::end(cjk), e) != std::end(cjk);
}

bool is_latin_single_byte(const std::string& e) {
    static constexpr std::string_view latin[] = {
        "ISO-8859-1",  "ISO-8859-2",   "ISO-8859-3",   "ISO-8859-4",   "ISO-8859-9",
        "ISO-8859-10", "ISO-8859-13",  "ISO-8859-14",  "ISO-8859-15",  "ISO-8859-16",
        "WINDOWS-1250", "WINDOWS-1252", "WINDOWS-1254", "WINDOWS-1257", "WINDOWS-1258",
        "IBM852",      "IBM850",       "MAC-CENTRALEUROPE", "MAC-ROMAN", "VISCII"};
    return std::find(std::begin(latin), std::end(latin), e) != std::end(latin);
}

// Share of non-ASCII bytes that have a non-ASCII neighbour: near 1 for CJK
// double-byte text, near 0 for accented Latin text ("café", "niño").
bool non_ascii_comes_in_runs(std::string_view bytes) {
    std::size_t high = 0, paired = 0;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        if (static_cast<unsigned char>(bytes[i]) < 0x80) continue;
        ++high;
        const bool prev = i > 0 && static_cast<unsigned char>(bytes[i - 1]) >= 0x80;
        const bool next = i + 1 < bytes.size() && static_cast<unsigned char>(bytes[i + 1]) >= 0x80;
        if (prev || next) ++paired;
    }
    return high > 0 && paired * 2 >= high;
}
#endif

// Control characters mean binary data or a wrong decoding, never teacher text.
Result<void> check_controls(std::string_view utf8) {
    for (std::size_t i = 0; i < utf8.size(); ++i) {
        const auto b = static_cast<unsigned char>(utf8[i]);
        unsigned code = 0;
        if ((b < 0x20 && b != '\t' && b != '\n' && b != '\v' && b != '\f' && b != '\r') ||
            b == 0x7F)
            code = b;
        else if (b == 0xC2 && i + 1 < utf8.size() &&
                 static_cast<unsigned char>(utf8[i + 1]) >= 0x80 &&
                 static_cast<unsigned char>(utf8[i + 1]) <= 0x9F)
            code = static_cast<unsigned char>(utf8[i + 1]);
        else
            continue;
        std::array<char, 16> hex{};
        std::snprintf(hex.data(), hex.size(), "U+%04X", code);
        return fail(ErrorKind::input, std::string("not text: control character ") + hex.data(),
                    position_at(utf8, i).to_string());
    }
    return {};
}

Result<DecodedText> decode_utf8(std::string_view bytes, std::size_t bom, std::string label) {
    const auto invalid = find_invalid_utf8(bytes.substr(bom));
    if (invalid != std::string_view::npos)
        return fail(ErrorKind::input, "invalid UTF-8 (wrong encoding? name it explicitly)",
                    byte_at(invalid + bom));
    DecodedText out;
    out.bom_bytes = bom;
    out.byte_order_mark = bom != 0;
    out.encoding = std::move(label);
    return out;
}

Result<DecodedText> decode_with(std::string_view bytes, const std::string& name,
                                std::string label) {
#if !TACTUS_HAVE_ICU
    if (upper(name) == "UTF-8" || upper(name) == "UTF8")
        return decode_utf8(bytes, sniff_bom(bytes).encoding == "UTF-8" ? 3 : 0, std::move(label));
    return unavailable("reading text in " + name + " (only UTF-8 is read)", "ICU", "encoding");
#else
    TACTUS_TRY(cnv, open_converter(name));
    if (is_utf8_converter(cnv.get()))
        return decode_utf8(bytes, sniff_bom(bytes).encoding == "UTF-8" ? 3 : 0, std::move(label));
    TACTUS_TRY(text, convert(bytes, cnv.get(), label));
    DecodedText out;
    out.converted = std::move(text);
    // Explicit UTF-16LE/BE and friends keep a byte-order mark as U+FEFF.
    if (std::string_view(out.converted).starts_with("\xEF\xBB\xBF")) {
        out.converted.erase(0, 3);
        out.byte_order_mark = true;
    }
    out.is_copy = true;
    out.encoding = std::move(label);
    return out;
#endif
}

Result<DecodedText> detect_and_decode(std::string_view bytes) {
    if (const auto bom = sniff_bom(bytes); bom.length != 0) {
        if (bom.encoding == "UTF-8") return decode_utf8(bytes, 3, "UTF-8");
        return decode_with(bytes, std::string(bom.encoding), std::string(bom.encoding));
    }
    if (const auto* nul = static_cast<const char*>(std::memchr(bytes.data(), 0, bytes.size()))) {
        const auto at = static_cast<std::size_t>(nul - bytes.data());
        const bool utf16_like = bytes.size() >= 4 && (bytes[1] == 0 || bytes[0] == 0);
        return fail(ErrorKind::input, std::string("not text: NUL byte") +
                        (utf16_like ? " (UTF-16 without a byte-order mark? name the encoding)"
                                    : ""),
                    byte_at(at));
    }
    const auto invalid = find_invalid_utf8(bytes);
    if (invalid == std::string_view::npos) return decode_utf8(bytes, 0, "UTF-8");
#if !TACTUS_HAVE_UCHARDET
    return unavailable("guessing the encoding of text that is not UTF-8 (invalid UTF-8 at " + byte_at(invalid) + ")",
                       "uchardet");
#else

    std::string detected = upper(detect_with_uchardet(bytes));
    const bool runs = non_ascii_comes_in_runs(bytes);
    if (detected.empty() || detected == "ASCII" || detected == "UTF-8" ||
        (runs && !is_cjk(detected)))
        return fail(ErrorKind::input, "not valid UTF-8 and the encoding cannot be told reliably" +
                        (detected.empty() ? std::string{} : " (a guess would be " + detected + ")") +
                        "; name it explicitly (e.g. GB18030, Big5, windows-1252)",
                    byte_at(invalid));
    // Latin-1 text with curly quotes or a euro sign is really Windows-1252 (in
    // ISO-8859-1 those bytes would be invisible C1 controls), and short Western
    // texts get wild Latin guesses.
    if (is_latin_single_byte(detected)) detected = "WINDOWS-1252";
    auto decoded = decode_with(bytes, detected, detected);
    if (!decoded && decoded.error().where == "encoding")
        return fail(ErrorKind::input, "detected encoding " + detected +
                        " is not supported; convert the file to UTF-8 or name the encoding",
                    byte_at(invalid));
    return decoded;
#endif
}

}  // namespace

Result<DecodedText> decode_text(std::string_view bytes, std::string_view declared) {
    auto name = std::string(declared);
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    if (!declared.empty() && name.empty()) return fail(ErrorKind::usage, "empty encoding name", "encoding");
    auto decoded = declared.empty() ? detect_and_decode(bytes) : decode_with(bytes, name, name);
    if (!decoded) return decoded;
    TACTUS_TRY_VOID(check_controls(decoded->text(bytes)));
    return decoded;
}

}  // namespace tactus::import::detail
