// SPDX-License-Identifier: GPL-3.0-or-later
#include "text_units.hpp"

#include <algorithm>

namespace tactus::gui {
namespace {

constexpr char16_t kBlankCell = u'\u2800';

bool is_line_break(QChar c) { return c == u'\n' || c == QChar::ParagraphSeparator || c == QChar::LineSeparator; }

bool ends_sentence(QChar c) {
    return c == u'.' || c == u'!' || c == u'?' || c == u'\u3002' || c == u'\uff01' || c == u'\uff1f';
}

TextUnit paragraph_at(const QString& text, int offset) {
    const int n = static_cast<int>(text.size());
    int start = offset;
    while (start > 0 && !is_line_break(text[start - 1])) --start;
    int end = offset;
    while (end < n && !is_line_break(text[end])) ++end;
    if (end < n) ++end;  // the line break belongs to the paragraph it ends
    return {start, end};
}

TextUnit char_at(const QString& text, int offset) {
    const int n = static_cast<int>(text.size());
    if (offset >= n) return {n, n};
    int start = offset;
    if (start > 0 && text[start].isLowSurrogate() && text[start - 1].isHighSurrogate()) --start;
    int end = start + 1;
    if (end < n && text[start].isHighSurrogate() && text[end].isLowSurrogate()) ++end;
    return {start, end};
}

TextUnit word_at(const QString& text, int offset) {
    const int n = static_cast<int>(text.size());
    // The start: back over the gap the offset is in, then over the word before it.
    int start = offset;
    while (start > 0 && is_word_gap(text[start - 1]) && (start >= n || is_word_gap(text[start]))) --start;
    while (start > 0 && !is_word_gap(text[start - 1])) --start;
    // A gap before the first word is a unit of its own.
    if (start == 0 && n > 0 && is_word_gap(text[0])) {
        int first = 0;
        while (first < n && is_word_gap(text[first])) ++first;
        if (offset < first) return {0, first};
        start = first;
    }
    return {start, next_word_start(text, start)};
}

TextUnit sentence_at(const QString& text, int offset) {
    const auto para = paragraph_at(text, offset);
    int start = para.start;
    // Sentences end after their mark and the gap that follows it.
    for (int i = para.start; i < para.end; ++i) {
        if (!ends_sentence(text[i])) continue;
        int j = i + 1;
        if (j < para.end && !is_word_gap(text[j])) continue;  // "3.5", "e.g." inside a word
        while (j < para.end && is_word_gap(text[j])) ++j;
        if (offset < j) return {start, j};
        start = j;
        i = j - 1;
    }
    return {start, para.end};
}

}  // namespace

bool is_word_gap(QChar c) { return c == u' ' || c == kBlankCell || c == u'\t' || is_line_break(c) || c.isSpace(); }

int next_word_start(const QString& text, int offset) {
    const int n = static_cast<int>(text.size());
    int i = std::clamp(offset, 0, n);
    while (i < n && !is_word_gap(text[i])) ++i;
    while (i < n && is_word_gap(text[i])) ++i;
    return i;
}

int previous_word_start(const QString& text, int offset) {
    int i = std::clamp(offset, 0, static_cast<int>(text.size()));
    while (i > 0 && is_word_gap(text[i - 1])) --i;
    while (i > 0 && !is_word_gap(text[i - 1])) --i;
    return i;
}

TextUnit text_unit_at(const QString& text, int offset, QAccessible::TextBoundaryType boundary, const LineUnits& lines) {
    const int n = static_cast<int>(text.size());
    if (offset < 0 || offset > n) offset = n;  // -1 is the end, as for AT-SPI
    if (boundary == QAccessible::CharBoundary) return char_at(text, offset);
    if (boundary == QAccessible::NoBoundary) return {0, n};
    if (n == 0) return {0, 0};
    // At the end, the last unit: what the caret after the last character reads.
    const int at = offset == n ? n - 1 : offset;
    switch (boundary) {
        case QAccessible::WordBoundary: return word_at(text, at);
        case QAccessible::SentenceBoundary: return sentence_at(text, at);
        case QAccessible::LineBoundary:
            if (lines) {
                auto u = lines(offset);
                u.start = std::clamp(u.start, 0, n);
                u.end = std::clamp(u.end, u.start, n);
                if (u.end > u.start || offset == n) return u;
            }
            return paragraph_at(text, at);
        case QAccessible::ParagraphBoundary: return paragraph_at(text, at);
        default: return {0, n};
    }
}

QString text_at_offset(const QString& text, int offset, QAccessible::TextBoundaryType boundary, int* start, int* end,
                       const LineUnits& lines) {
    const auto u = text_unit_at(text, offset, boundary, lines);
    *start = u.start;
    *end = u.end;
    return text.mid(u.start, u.end - u.start);
}

QString text_before_offset(const QString& text, int offset, QAccessible::TextBoundaryType boundary, int* start,
                           int* end, const LineUnits& lines) {
    const int n = static_cast<int>(text.size());
    if (offset < 0 || offset > n) offset = n;
    // The unit that holds the offset (for a character at the end: nothing, so the
    // last character comes before it).
    const auto here = boundary == QAccessible::CharBoundary && offset == n ? TextUnit{n, n}
                                                                           : text_unit_at(text, offset, boundary, lines);
    if (here.start <= 0) {
        *start = *end = 0;
        return {};
    }
    return text_at_offset(text, here.start - 1, boundary, start, end, lines);
}

QString text_after_offset(const QString& text, int offset, QAccessible::TextBoundaryType boundary, int* start,
                          int* end, const LineUnits& lines) {
    const int n = static_cast<int>(text.size());
    if (offset < 0 || offset > n) offset = n;
    const auto here = text_unit_at(text, offset, boundary, lines);
    if (here.end >= n) {
        *start = *end = n;
        return {};
    }
    return text_at_offset(text, here.end, boundary, start, end, lines);
}

}  // namespace tactus::gui
