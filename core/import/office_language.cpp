// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/office_language.hpp"

#include <array>

namespace tactus::import::detail {
namespace {

bool in(char32_t c, char32_t first, char32_t last) { return c >= first && c <= last; }

// The next code point of valid UTF-8 (pugixml gives valid text) and its length.
char32_t decode(std::string_view s, std::size_t i, std::size_t& length) {
    const auto b = static_cast<unsigned char>(s[i]);
    length = b < 0x80 ? 1 : b < 0xE0 ? 2 : b < 0xF0 ? 3 : 4;
    if (i + length > s.size()) {
        length = 1;
        return b;
    }
    char32_t c = length == 1 ? b : length == 2 ? b & 0x1Fu : length == 3 ? b & 0x0Fu : b & 0x07u;
    for (std::size_t k = 1; k < length; ++k) c = (c << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3Fu);
    return c;
}

}  // namespace

void OfficeLanguages::apply(const OfficeLanguages& over) {
    if (over.latin) latin = over.latin;
    if (over.east_asian) east_asian = over.east_asian;
    if (over.complex) complex = over.complex;
    if (over.complex_run) complex_run = over.complex_run;
}

std::string_view OfficeLanguages::of(ScriptClass c) const {
    const auto& tag = c == ScriptClass::east_asian ? east_asian : c == ScriptClass::complex ? complex : latin;
    return tag ? std::string_view(*tag) : std::string_view{};
}

std::string language_tag(std::string_view language, std::string_view country) {
    // "zxx" (no linguistic content) is what LibreOffice sets on its link
    // styles to keep a URL from being spell-checked: the link's words are
    // still the text's, so their script decides as for unmarked text.
    if (language.empty() || language == "none" || language == "x-none" || language == "zxx") return {};
    std::string tag(language);
    if (!country.empty() && country != "none") tag += "-" + std::string(country);
    return tag;
}

// The classes of ECMA-376 Part 1, 17.3.2.26 (w:rFonts: which font, and so
// which language, a character takes), in outline: CJK, kana, hangul, Yi,
// bopomofo, their punctuation and full-width forms are East Asian; Hebrew,
// Arabic, Syriac, Thaana, N'Ko, the Indic scripts, Thai, Lao and Khmer are
// complex; other letters are Latin.
std::optional<ScriptClass> script_class(char32_t c) {
    if (c < 0x80) {
        const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
        return letter ? std::optional(ScriptClass::latin) : std::nullopt;
    }
    if (in(c, 0x80, 0xBF) || c == 0xD7 || c == 0xF7 || in(c, 0x300, 0x36F) || in(c, 0x2000, 0x2BFF) ||
        in(c, 0x2E00, 0x2E7F) || in(c, 0xFE00, 0xFE0F))
        return std::nullopt;  // Latin-1 signs, combining marks, punctuation, symbols, variation selectors
    if (in(c, 0x1100, 0x11FF) || in(c, 0x2E80, 0xA4CF) || in(c, 0xA960, 0xA97F) || in(c, 0xAC00, 0xD7FF) ||
        in(c, 0xF900, 0xFAFF) || in(c, 0xFE30, 0xFE4F) || in(c, 0xFF00, 0xFFEF) || in(c, 0x20000, 0x3FFFF))
        return ScriptClass::east_asian;
    if (in(c, 0x590, 0x8FF) || in(c, 0x900, 0xDFF) || in(c, 0xE00, 0xEFF) || in(c, 0x1780, 0x17FF) ||
        in(c, 0xFB1D, 0xFDFF) || in(c, 0xFE70, 0xFEFF))
        return ScriptClass::complex;
    return ScriptClass::latin;
}

std::vector<LanguagePiece> language_pieces(std::string_view utf8, const OfficeLanguages& run,
                                           const OfficeLanguages& document) {
    // Each character's class (nullopt: of no script), then the weak ones
    // filled from the letter before, else after, else Latin.
    struct Char {
        std::size_t at, length;
        std::optional<ScriptClass> cls;
    };
    std::vector<Char> chars;
    for (std::size_t i = 0, n = 0; i < utf8.size(); i += n) {
        const char32_t c = decode(utf8, i, n);
        chars.push_back({i, n, run.complex_run.value_or(false) ? std::optional(ScriptClass::complex) : script_class(c)});
    }
    std::optional<ScriptClass> last;
    for (auto& ch : chars) {
        if (ch.cls)
            last = ch.cls;
        else
            ch.cls = last;
    }
    std::optional<ScriptClass> next;
    for (auto it = chars.rbegin(); it != chars.rend(); ++it) {
        if (it->cls)
            next = it->cls;
        else
            it->cls = next;
    }
    std::vector<LanguagePiece> out;
    std::size_t begin = 0;  // where the last piece starts
    for (const auto& ch : chars) {
        const auto cls = ch.cls.value_or(ScriptClass::latin);
        const auto own = run.of(cls);
        std::string language = own == document.of(cls) ? std::string{} : std::string(own);
        if (out.empty() || out.back().language != language) {
            begin = ch.at;
            out.push_back({{}, std::move(language)});
        }
        out.back().text = utf8.substr(begin, ch.at + ch.length - begin);
    }
    return out;
}

std::string main_language(const OfficeLanguages& document, const document::Document& text) {
    constexpr std::array classes = {ScriptClass::latin, ScriptClass::east_asian, ScriptClass::complex};
    std::array<std::size_t, 3> count{};
    for (const auto& b : text.blocks)
        for (const auto& s : b.spans) {
            if (!s.language.empty() || s.transcriber_note) continue;  // a passage's own, or not print's
            for (std::size_t i = 0, n = 0; i < s.text.size(); i += n)
                if (const auto c = script_class(decode(s.text, i, n))) ++count[static_cast<std::size_t>(*c)];
        }
    std::string best;
    std::size_t most = 0;
    for (const auto c : classes)
        if (const auto tag = document.of(c); !tag.empty() && (best.empty() || count[static_cast<std::size_t>(c)] > most)) {
            best = std::string(tag);
            most = count[static_cast<std::size_t>(c)];
        }
    return best;
}

}  // namespace tactus::import::detail
