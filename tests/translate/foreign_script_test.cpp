// SPDX-License-Identifier: GPL-3.0-or-later
// Text in a script the table does not know: liblouis writes an escape code
// ('\x0440', up to 12 cells) for every such character, so the braille is many
// times longer than the print. The translator must give all of it, with and
// without emphasis, exactly as liblouis does with room to spare.
#include <gtest/gtest.h>

#include <liblouis/liblouis.h>

#include <string>
#include <vector>

#include "common/utf8.hpp"
#include "document/document.hpp"
#include "translate/translator.hpp"

using namespace tactus;

namespace {

// liblouis called directly, every buffer it may write (output, typeform)
// 64 times the input and more: the whole translation.
std::string oracle(const std::string& table, const std::u32string& text, formtype emphasis) {
    static_assert(sizeof(widechar) == sizeof(char32_t));
    int inlen = static_cast<int>(text.size());
    int outlen = inlen * 64 + 1024;
    std::vector<widechar> out(static_cast<std::size_t>(outlen));
    std::vector<formtype> typeform(static_cast<std::size_t>(outlen), plain_text);
    std::fill_n(typeform.begin(), text.size(), emphasis);
    const std::string list = "unicode.dis," + table;
    if (!lou_translate(list.c_str(), reinterpret_cast<const widechar*>(text.data()), &inlen, out.data(), &outlen,
                       emphasis == plain_text ? nullptr : typeform.data(), nullptr, nullptr, nullptr, nullptr, 0))
        return "liblouis failed";
    std::string s;
    for (int i = 0; i < outlen; ++i) {
        const auto c = static_cast<char32_t>(out[static_cast<std::size_t>(i)]);
        s += utf32_to_utf8(std::u32string(1, c));
    }
    return s;
}

// Print in scripts the English and Chinese tables do not know, short and long.
std::vector<std::u32string> foreign_texts() {
    std::vector<std::u32string> texts = {
        U"Привет", U"Привет мир", U"مرحبا بالعالم", U"Γειά σου κόσμε", U"שלום עולם", U"नमस्ते दुनिया",
        U"\U0001F600\U0001F4D6", U"Ā ē ī ō ū", U"x Привет 42 y"};
    std::u32string ext_b;
    for (char32_t c = 0x20000; c < 0x2000C; ++c) ext_b += c;  // 12 CJK Extension B characters
    texts.push_back(ext_b);
    std::u32string words;
    for (int i = 0; i < 40; ++i) words += U"Съешь же ещё этих мягких французских булок ";
    texts.push_back(words);
    return texts;
}

}  // namespace

TEST(ForeignScript, WholeTranslationWithAndWithoutEmphasis) {
    for (const char* table : {"en-ueb-g2.ctb", "en-ueb-g1.ctb", "en-us-g2.ctb", "zh-tw.ctb", "zhcn-g1.ctb"}) {
        auto tr = translate::Translator::open(table);
        ASSERT_TRUE(tr) << table;
        for (const auto& text : foreign_texts()) {
            for (const auto& [emph, form] : {std::pair{document::emphasis_none, static_cast<formtype>(plain_text)},
                                            std::pair{document::emphasis_bold, static_cast<formtype>(bold)},
                                            std::pair{document::emphasis_italic, static_cast<formtype>(italic)}}) {
                const std::vector<std::uint8_t> marks(text.size(), emph);
                const auto cells = tr->translate(text, emph == document::emphasis_none
                                                           ? std::span<const std::uint8_t>{}
                                                           : std::span<const std::uint8_t>(marks));
                ASSERT_TRUE(cells) << table << ": " << cells.error().to_string();
                EXPECT_EQ(document::to_unicode_text(*cells), oracle(table, text, form))
                    << table << " emphasis " << int(emph) << ": " << utf32_to_utf8(text);
                const auto mapped = tr->translate_mapped(text, marks);
                ASSERT_TRUE(mapped) << table;
                EXPECT_EQ(mapped->cells, *cells) << table << ": " << utf32_to_utf8(text);
                EXPECT_EQ(mapped->source.size(), mapped->cells.size());
            }
        }
    }
}

// Every escape code is there: one per unknown character, none dropped at the
// end of a buffer (the first word of "Привет мир" alone, 6 of 12 rare
// characters, were what came back).
TEST(ForeignScript, OneEscapePerUnknownCharacter) {
    auto tr = translate::Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(tr);
    for (std::size_t n = 1; n <= 40; ++n) {
        std::u32string text;
        for (std::size_t i = 0; i < n; ++i) text += static_cast<char32_t>(0x20000 + i);
        const auto cells = tr->translate(text);
        ASSERT_TRUE(cells);
        // Each escape code begins with dots 3 (the apostrophe) followed by the
        // backslash (dots 1256 with 7: ⡳).
        std::size_t escapes = 0;
        for (std::size_t i = 0; i + 1 < cells->size(); ++i)
            if ((*cells)[i].dots == 0x04 && (*cells)[i + 1].dots == 0x73) ++escapes;
        EXPECT_EQ(escapes, n) << document::to_unicode_text(*cells);
    }
}
