// SPDX-License-Identifier: GPL-3.0-or-later
#include "translate/translated_document.hpp"

#include <algorithm>

#include "common/utf8.hpp"

namespace tactus::translate {
namespace {

constexpr std::size_t kChunk = 4096;  // code points per liblouis call

// Joins spans into one string with an emphasis mark per code point. Line breaks
// and tabs inside a block become spaces: layout decides where braille lines end.
Result<void> flatten(const document::Block& block, std::u32string& text, std::vector<std::uint8_t>& emph) {
    for (const auto& span : block.spans) {
        auto u = utf8_to_utf32(span.text);
        if (!u) return std::unexpected(u.error());
        for (char32_t c : *u) {
            if (c == U'\n' || c == U'\r' || c == U'\t' || c == U'\f' || c == U'\v') c = U' ';
            text.push_back(c);
            emph.push_back(span.emphasis);
        }
    }
    return {};
}

Result<document::BrailleLine> translate_text(const Translator& tr, std::u32string_view text,
                                   std::span<const std::uint8_t> emph) {
    const bool any_emphasis =
        std::ranges::any_of(emph, [](std::uint8_t e) { return e != document::emphasis_none; });
    document::BrailleLine out;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = std::min(text.size(), start + kChunk);
        if (end < text.size()) {
            const auto space = text.rfind(U' ', end);
            if (space != std::u32string_view::npos && space > start) end = space + 1;
        }
        auto piece = tr.translate(text.substr(start, end - start),
                                  any_emphasis ? emph.subspan(start, end - start)
                                               : std::span<const std::uint8_t>{});
        if (!piece) return piece;
        out.insert(out.end(), piece->begin(), piece->end());
        start = end;
    }
    return out;
}

}  // namespace

Result<TranslatedBlock> translate_block(const document::Block& block, const Translator& translator) {
    TranslatedBlock tb;
    tb.kind = block.kind;
    tb.level = block.level;
    tb.source_line = block.source_line;
    const auto where = block.source_line > 0 ? "line " + std::to_string(block.source_line)
                                             : std::string{};
    switch (block.kind) {
        case document::BlockKind::braille:
            tb.lines = block.braille_lines;
            break;
        case document::BlockKind::braille_page_break:
            break;
        case document::BlockKind::print_page_break:
            if (!block.label.empty()) {
                auto u = utf8_to_utf32(block.label);
                if (!u) return std::unexpected(located(u.error(), where));
                auto cells = translator.translate(*u);
                if (!cells) return std::unexpected(located(cells.error(), where));
                tb.label = std::move(*cells);
            }
            break;
        case document::BlockKind::heading:
        case document::BlockKind::paragraph:
        case document::BlockKind::list_item: {
            std::u32string text;
            std::vector<std::uint8_t> emph;
            if (auto ok = flatten(block, text, emph); !ok)
                return std::unexpected(located(ok.error(), where));
            auto cells = translate_text(translator, text, emph);
            if (!cells) return std::unexpected(located(cells.error(), where));
            tb.cells = std::move(*cells);
            break;
        }
    }
    return tb;
}

}  // namespace tactus::translate
