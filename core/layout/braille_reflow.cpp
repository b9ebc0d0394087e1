// SPDX-License-Identifier: GPL-3.0-or-later
#include "layout/braille_reflow.hpp"

#include <algorithm>
#include <iterator>
#include <map>
#include <string>

namespace tactus::layout {
namespace {

using document::BrailleLine;
using document::Cell;

constexpr std::uint8_t kNumberSign = 0x3C;  // dots 3456
constexpr std::uint8_t kHyphen = 0x24;      // dots 36

struct SourceLine {
    BrailleLine cells;
    int source_line = 0;
    bool furniture = false;  // a page number or running head alone on its line: left out
    bool numbered = false;   // a page number was taken from its end: the line was full
};
using Page = std::vector<SourceLine>;

bool is_digit_cell(Cell c) {
    // a-j: 1, 12, 14, 145, 15, 124, 1245, 125, 24, 245
    static constexpr std::uint8_t digits[] = {0x01, 0x03, 0x09, 0x19, 0x11, 0x0B, 0x1B, 0x13, 0x0A, 0x1A};
    return std::ranges::find(digits, c.dots) != std::end(digits);
}

// a-z (the braille letters, whatever the code): a hyphen between two letters
// joins the parts of a word ("well-known"); elsewhere it may be a minus sign
// in a formula, a dash or part of an indicator, where no line may break.
bool is_letter_cell(Cell c) {
    static constexpr std::uint8_t letters[] = {0x01, 0x03, 0x09, 0x19, 0x11, 0x0B, 0x1B, 0x13, 0x0A,
                                               0x1A, 0x05, 0x07, 0x0D, 0x1D, 0x15, 0x0F, 0x1F, 0x17,
                                               0x0E, 0x1E, 0x25, 0x27, 0x3A, 0x2D, 0x3D, 0x35};
    return std::ranges::find(letters, c.dots) != std::end(letters);
}

bool line_is_blank(const BrailleLine& l) {
    return std::ranges::all_of(l, [](Cell c) { return c.blank(); });
}

void trim_end(BrailleLine& l) {
    while (!l.empty() && l.back().blank()) l.pop_back();
}

// Removes a page number at the end of the line: a word of at most three
// letters, the numeric indicator and digits, after three or more blank cells
// (or alone on the line). True when one was removed.
bool strip_page_number(BrailleLine& line) {
    trim_end(line);
    std::size_t start = line.size();
    while (start > 0 && !line[start - 1].blank()) --start;
    if (start == line.size()) return false;
    const auto sign = std::find_if(line.begin() + static_cast<std::ptrdiff_t>(start), line.end(),
                                   [](Cell c) { return c.dots == kNumberSign; });
    if (sign == line.end() || sign + 1 == line.end() || sign - line.begin() - static_cast<std::ptrdiff_t>(start) > 3 ||
        !std::all_of(sign + 1, line.end(), is_digit_cell))
        return false;
    std::size_t blanks = 0;
    while (start > blanks && line[start - 1 - blanks].blank()) ++blanks;
    if (blanks < 3 && blanks != start) return false;  // part of the text, not a page number
    line.resize(start - blanks);
    return true;
}

std::vector<Page> pages_of(const document::Document& doc) {
    std::vector<Page> pages(1);
    for (const auto& b : doc.blocks) {
        if (b.kind == document::BlockKind::braille_page_break) {
            pages.emplace_back();
        } else if (b.kind == document::BlockKind::braille) {
            int line = b.source_line;
            for (const auto& l : b.braille_lines) pages.back().push_back({l, line > 0 ? line++ : 0, false, false});
        }
    }
    return pages;
}

std::size_t first_text_line(const Page& p) {
    std::size_t i = 0;
    while (i < p.size() && (p[i].furniture || line_is_blank(p[i].cells))) ++i;
    return i;
}

void remove_furniture(std::vector<Page>& pages) {
    for (auto& p : pages) {
        const auto first = first_text_line(p);
        if (first == p.size()) continue;
        std::size_t last = p.size() - 1;
        while (last > first && line_is_blank(p[last].cells)) --last;
        for (const auto i : {first, last}) {
            auto& cells = p[i].cells;
            if (strip_page_number(cells)) {
                p[i].numbered = true;
                if (line_is_blank(cells)) p[i].furniture = true;
            }
        }
    }
    // Running heads: the same first line on many pages.
    const auto key_of = [](BrailleLine l) {
        trim_end(l);
        std::string key;
        for (const Cell c : l) key.push_back(static_cast<char>(c.dots));
        return key;
    };
    std::map<std::string, std::size_t> firsts;
    std::size_t with_text = 0;
    for (const auto& p : pages) {
        const auto first = first_text_line(p);
        if (first == p.size()) continue;
        ++with_text;
        ++firsts[key_of(p[first].cells)];
    }
    for (auto& p : pages) {
        const auto first = first_text_line(p);
        if (first == p.size()) continue;
        const auto n = firsts[key_of(p[first].cells)];
        if (n >= 2 && 2 * n >= with_text) p[first].furniture = true;
    }
}

class Joiner {
public:
    // `width`: the source's line length (its longest line).
    explicit Joiner(std::size_t width) : width_(width) {}

    void line(const SourceLine& l) {
        std::size_t indent = 0;
        while (indent < l.cells.size() && l.cells[indent].blank()) ++indent;
        if (indent == l.cells.size()) {
            end();
            return;
        }
        if (indent >= 3) {
            end();
            start(document::BlockKind::heading, l.source_line);
            append(l.cells, indent);
            end();
            return;
        }
        // A line in cell 1 goes on with the paragraph when the line before it
        // ended because this line's first word did not fit there; a short line
        // before it (a list item, a line of verse, an address) ends its own.
        std::size_t word = indent;
        while (word < l.cells.size() && !l.cells[word].blank()) ++word;
        const bool wrapped = open_ && previous_length_ + 1 + word > width_;
        if (indent > 0 || !wrapped) {
            end();
            start(document::BlockKind::paragraph, l.source_line);
        }
        append(l.cells, indent);
        previous_length_ = l.numbered ? width_ : l.cells.size();
        while (previous_length_ > 0 && !l.numbered && l.cells[previous_length_ - 1].blank()) --previous_length_;
    }

    std::vector<translate::TranslatedBlock> finish() && {
        end();
        return std::move(blocks_);
    }

private:
    void start(document::BlockKind kind, int source_line) {
        current_ = {};
        current_.kind = kind;
        current_.level = kind == document::BlockKind::heading ? 1 : 0;
        current_.source_line = source_line;
        open_ = true;
    }

    void end() {
        if (open_ && !current_.cells.empty()) blocks_.push_back(std::move(current_));
        current_ = {};
        open_ = false;
    }

    void append(const BrailleLine& cells, std::size_t from) {
        auto& out = current_.cells;
        auto& breaks = current_.breaks;
        std::size_t to = cells.size();
        while (to > from && cells[to - 1].blank()) --to;
        bool after_hyphen = false;
        if (!out.empty()) {
            if (out.back().dots == kHyphen) {
                after_hyphen = true;  // a word divided or a compound broken at its hyphen: joined
            } else {
                out.push_back(Cell{});
                breaks.push_back(translate::BreakBefore::blank);
            }
        }
        for (std::size_t i = from; i < to; ++i) {
            const Cell c = cells[i];
            translate::BreakBefore b = translate::BreakBefore::never;
            if (out.empty()) b = translate::BreakBefore::never;
            else if (c.blank()) b = translate::BreakBefore::blank;
            else if (is_letter_cell(c) && (after_hyphen || (out.back().dots == kHyphen && out.size() >= 2 &&
                                                            is_letter_cell(out[out.size() - 2]))))
                b = translate::BreakBefore::allowed;
            after_hyphen = false;
            out.push_back(c);
            breaks.push_back(b);
        }
    }

    std::size_t width_;
    std::size_t previous_length_ = 0;  // cells of the last line joined, to its last non-blank
    std::vector<translate::TranslatedBlock> blocks_;
    translate::TranslatedBlock current_;
    bool open_ = false;
};

}  // namespace

std::vector<translate::TranslatedBlock> reflow_braille(const document::Document& doc) {
    auto pages = pages_of(doc);
    remove_furniture(pages);
    std::size_t width = 0;
    for (const auto& p : pages)
        for (const auto& l : p) width = std::max(width, l.cells.size());
    Joiner joiner(width);
    for (const auto& p : pages)
        for (const auto& l : p)
            if (!l.furniture) joiner.line(l);
    return std::move(joiner).finish();
}

}  // namespace tactus::layout
