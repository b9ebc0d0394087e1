// SPDX-License-Identifier: GPL-3.0-or-later
#include "edit/cursor_map.hpp"

#include <algorithm>
#include <vector>

namespace tactus::edit {
namespace {

struct Word {
    std::size_t start = 0, length = 0;
};

template <typename Seq, typename IsBlank>
std::vector<Word> words_of(const Seq& seq, IsBlank blank) {
    std::vector<Word> out;
    for (std::size_t i = 0; i < seq.size();) {
        if (blank(seq[i])) {
            ++i;
            continue;
        }
        Word w{i, 0};
        while (i < seq.size() && !blank(seq[i])) ++i;
        w.length = i - w.start;
        out.push_back(w);
    }
    return out;
}

bool space(char32_t c) { return c == U' ' || c == U'\t' || c == U'\u00a0' || c == U'\u3000'; }

// Position `pos` in a sequence with words `from` -> position in the one with `to`.
std::size_t map(const std::vector<Word>& from, std::size_t from_size, std::size_t pos,
                const std::vector<Word>& to, std::size_t to_size) {
    if (from_size == 0) return 0;
    pos = std::min(pos, from_size);
    if (from.size() == to.size() && !from.empty()) {
        // The word the position is in, or the first word after it.
        std::size_t k = 0;
        while (k + 1 < from.size() && pos >= from[k + 1].start) ++k;
        const auto& f = from[k];
        const auto& t = to[k];
        if (pos <= f.start) return t.start;
        const auto inside = pos - f.start;
        if (inside >= f.length) return std::min(to_size, t.start + t.length + (pos - f.start - f.length));
        return t.start + (inside * t.length + f.length / 2) / f.length;
    }
    return (pos * to_size + from_size / 2) / from_size;
}

}  // namespace

std::size_t print_to_braille(std::u32string_view content, std::size_t column, const document::BrailleLine& cells) {
    const auto pw = words_of(content, space);
    const auto bw = words_of(cells, [](document::Cell c) { return c.blank(); });
    return map(pw, content.size(), column, bw, cells.size());
}

std::size_t braille_to_print(const document::BrailleLine& cells, std::size_t cell, std::u32string_view content) {
    const auto pw = words_of(content, space);
    const auto bw = words_of(cells, [](document::Cell c) { return c.blank(); });
    return map(bw, cells.size(), cell, pw, content.size());
}

std::vector<std::pair<std::size_t, std::size_t>> braille_of_lines(std::span<const std::u32string> lines,
                                                                  const document::BrailleLine& cells) {
    const auto bw = words_of(cells, [](document::Cell c) { return c.blank(); });
    std::vector<std::size_t> counts;
    std::size_t words = 0, length = 0;
    for (const auto& l : lines) {
        counts.push_back(words_of(l, space).size());
        words += counts.back();
        length += l.size();
    }
    std::vector<std::pair<std::size_t, std::size_t>> out;
    if (words == bw.size() && words > 0) {
        std::size_t w = 0;
        for (const auto n : counts) {
            if (n == 0) {
                const auto at = w < bw.size() ? bw[w].start : cells.size();
                out.emplace_back(at, at);
                continue;
            }
            out.emplace_back(bw[w].start, bw[w + n - 1].start + bw[w + n - 1].length);
            w += n;
        }
        return out;
    }
    std::size_t seen = 0;
    for (const auto& l : lines) {
        const auto begin = length ? seen * cells.size() / length : 0;
        seen += l.size();
        out.emplace_back(begin, length ? seen * cells.size() / length : cells.size());
    }
    return out;
}

}  // namespace tactus::edit
