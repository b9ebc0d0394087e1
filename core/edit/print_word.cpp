// SPDX-License-Identifier: GPL-3.0-or-later
#include "edit/print_word.hpp"

#include <algorithm>
#include <vector>

#include "common/utf8.hpp"
#include "edit/cursor_map.hpp"
#include "edit/editor_lines.hpp"

namespace tactus::edit {
namespace {

bool is_space(char32_t c) { return c == U' ' || c == U'\t' || c == 0x3000; }

// Scripts written without spaces: a "word" there is the character itself.
bool unspaced_script(char32_t c) {
    return (c >= 0x3040 && c <= 0x30ff) || (c >= 0x3400 && c <= 0x9fff) || (c >= 0xf900 && c <= 0xfaff) ||
           (c >= 0xac00 && c <= 0xd7af) || (c >= 0x20000 && c <= 0x2ffff);
}

}  // namespace

std::u32string print_word_at(const LiveLayout& layout, const PagePosition& where) {
    if (layout.line_count() == 0) return {};
    const auto i = layout.line_at(where.page, where.line);
    if (i >= layout.line_count() || is_braille_line(layout.line(i))) return {};
    const auto cells = layout.braille_of(i);
    std::size_t k = cells.size();
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const auto p = layout.position_of(i, c);
        // A blank may share its place with the next cell (a space at a line end).
        if (p.page == where.page && p.line == where.line && p.cell == where.cell && !cells[c].blank()) {
            k = c;
            break;
        }
    }
    if (k == cells.size() || cells[k].blank()) return {};
    auto decoded = utf8_to_utf32(editor_line_content(layout.line(i), layout.dialect()));
    if (!decoded || decoded->empty()) return {};
    const std::u32string content = std::move(*decoded);
    // Contractions never cross a space, so the n-th braille word is the n-th
    // print word whenever both have as many words (cursor_map's rule).
    std::vector<std::u32string> words;
    for (std::size_t a = 0; a < content.size();) {
        while (a < content.size() && is_space(content[a])) ++a;
        std::size_t b = a;
        while (b < content.size() && !is_space(content[b])) ++b;
        if (b > a) words.push_back(content.substr(a, b - a));
        a = b;
    }
    std::size_t braille_words = 0, word_of_k = 0;
    for (std::size_t c = 0; c < cells.size(); ++c)
        if (!cells[c].blank() && (c == 0 || cells[c - 1].blank())) {
            if (c <= k) word_of_k = braille_words;
            ++braille_words;
        }
    const bool spaced = std::none_of(content.begin(), content.end(), unspaced_script);
    if (spaced && braille_words == words.size()) return words[word_of_k];
    auto col = std::min(braille_to_print(cells, k, content), content.size() - 1);
    if (is_space(content[col])) return {};
    if (unspaced_script(content[col])) return std::u32string(1, content[col]);
    std::size_t a = col, b = col + 1;
    while (a > 0 && !is_space(content[a - 1]) && !unspaced_script(content[a - 1])) --a;
    while (b < content.size() && !is_space(content[b]) && !unspaced_script(content[b])) ++b;
    return content.substr(a, b - a);
}

}  // namespace tactus::edit
