// SPDX-License-Identifier: GPL-3.0-or-later
#include "edit/editor_lines.hpp"

#include <algorithm>
#include <cctype>

#include "common/utf8.hpp"
#include "import/import.hpp"

namespace tactus::edit {
namespace {

constexpr std::string_view kInlineSpecials = "\\*_[]<>`&~";
constexpr std::string_view kBullet = "\u2022 ";  // the bullet sign, as core's importers write it

bool is_space(char c) { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && (is_space(s.front()) || s.front() == '\r')) s.remove_prefix(1);
    while (!s.empty() && (is_space(s.back()) || s.back() == '\r' || s.back() == '\n'))
        s.remove_suffix(1);
    return s;
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Length of "12." / "3)" at the start of s, 0 when there is none.
std::size_t ordinal_length(std::string_view s) {
    std::size_t i = 0;
    while (i < s.size() && i < 9 && is_digit(s[i])) ++i;
    if (i == 0 || i >= s.size() || (s[i] != '.' && s[i] != ')')) return 0;
    return i + 1;
}

// Thematic break: three or more of one of - * _, nothing else but spaces.
bool is_thematic_break(std::string_view s) {
    if (s.empty() || (s[0] != '-' && s[0] != '*' && s[0] != '_')) return false;
    int count = 0;
    for (char c : s) {
        if (c == s[0]) ++count;
        else if (!is_space(c)) return false;
    }
    return count >= 3;
}

// "<!-- name rest -->" -> rest (trimmed), when the comment starts with `name`.
std::optional<std::string> comment_argument(std::string_view s, std::string_view name) {
    if (!s.starts_with("<!--") || !s.ends_with("-->") || s.size() < 7) return std::nullopt;
    auto body = trim(s.substr(4, s.size() - 7));
    if (!body.starts_with(name)) return std::nullopt;
    auto rest = body.substr(name.size());
    if (!rest.empty() && !is_space(rest.front()) && rest.front() != ':') return std::nullopt;
    rest = trim(rest);
    if (rest.starts_with(':')) rest = trim(rest.substr(1));
    return std::string(rest);
}

std::vector<document::Span> parse_inline_markdown(std::string_view content);

// The length of "[^label]" at the start of `s`, 0 if there is none.
std::size_t note_reference_length(std::string_view s) {
    if (!s.starts_with("[^")) return 0;
    const auto close = s.find(']');
    if (close == std::string_view::npos || close == 2 ||
        s.substr(2, close - 2).find_first_of(" \t[") != std::string_view::npos)
        return 0;
    return close + 1;
}

// Inline Markdown (emphasis, escapes) and note references "[^label]" (an
// escaped "\[^1]" is text). The text between references is read on its own.
std::vector<document::Span> parse_inline(std::string_view content) {
    std::vector<document::Span> out;
    // A piece between references keeps the spaces at its ends (Markdown would trim them).
    const auto piece = [&out](std::string_view text) {
        const auto lead = text.find_first_not_of(' ');
        if (lead == std::string_view::npos) {
            if (!text.empty()) out.push_back(document::Span{std::string(text)});
            return;
        }
        const auto tail = text.size() - 1 - text.find_last_not_of(' ');
        if (lead > 0) out.push_back(document::Span{std::string(lead, ' ')});
        for (auto& span : parse_inline_markdown(text.substr(lead, text.size() - lead - tail)))
            out.push_back(std::move(span));
        if (tail > 0) out.push_back(document::Span{std::string(tail, ' ')});
    };
    std::size_t from = 0;
    for (std::size_t i = content.find("[^"); i != std::string_view::npos; i = content.find("[^", i + 1)) {
        const auto n = note_reference_length(content.substr(i));
        if (n == 0 || (i > 0 && content[i - 1] == '\\')) continue;
        piece(content.substr(from, i - from));
        document::Span reference{std::string(content.substr(i + 2, n - 3))};
        reference.note_reference = true;
        out.push_back(std::move(reference));
        from = i + n;
        i = from - 1;
    }
    if (from == 0) return parse_inline_markdown(content);
    piece(content.substr(from));
    return out;
}

// Emphasis and escapes through core's importer; plain text takes the fast
// path, which is nearly every line of a real book.
std::vector<document::Span> parse_inline_markdown(std::string_view content) {
    if (content.find_first_of(kInlineSpecials) == std::string_view::npos)
        return content.empty() ? std::vector<document::Span>{} : std::vector<document::Span>{document::Span{std::string(content)}};
    import::ImportOptions options;
    options.format = import::SourceFormat::markdown;
    options.encoding = "UTF-8";
    auto doc = import::import_bytes(content, "line.md", options);
    if (!doc) return {document::Span{std::string(content)}};
    std::vector<document::Span> spans;
    for (const auto& b : doc->blocks)
        for (const auto& s : b.spans) {
            if (!spans.empty() && spans.back().emphasis == s.emphasis) spans.back().text += s.text;
            else spans.push_back(s);
        }
    return spans;
}

std::string escape_inline(std::string_view text) {
    std::string out;
    out.reserve(text.size() + 8);
    for (char c : text) {
        if (kInlineSpecials.find(c) != std::string_view::npos) out.push_back('\\');
        out.push_back(c);
    }
    return out;
}

// Keeps a paragraph's first characters from reading as a heading, list or break.
std::string guard_line_start(std::string s) {
    if (s.empty()) return s;
    if (const auto n = ordinal_length(s); n > 0 && n < s.size() + 1) {
        s.insert(n - 1, 1, '\\');
        return s;
    }
    if (std::string_view("#-+=>|").find(s[0]) != std::string_view::npos) s.insert(0, 1, '\\');
    return s;
}

std::string render_spans(const std::vector<document::Span>& spans) {
    std::string out;
    for (const auto& span : spans) {
        if (span.note_reference) {
            out += "[^" + span.text + "]";
            continue;
        }
        std::string_view t = span.text;
        const auto mark = (span.emphasis & document::emphasis_bold) && (span.emphasis & document::emphasis_italic)
                              ? std::string_view("***")
                          : (span.emphasis & document::emphasis_bold)   ? std::string_view("**")
                          : (span.emphasis & document::emphasis_italic) ? std::string_view("*")
                                                              : std::string_view();
        const auto core = trim(t);
        if (mark.empty() || core.empty()) {
            out += escape_inline(t);
            continue;
        }
        // Emphasis marks must touch the words: keep surrounding spaces outside.
        const auto lead = static_cast<std::size_t>(core.data() - t.data());
        out += std::string(t.substr(0, lead));
        out += mark;
        out += escape_inline(core);
        out += mark;
        out += std::string(t.substr(lead + core.size()));
    }
    return out;
}

}  // namespace

bool is_braille_line(std::string_view utf8) {
    if (utf8.empty()) return false;
    auto text = utf8_to_utf32(utf8);
    if (!text || text->empty()) return false;
    return std::ranges::all_of(*text, [](char32_t c) { return document::Cell::is_unicode_braille(c); });
}

std::optional<document::Block> parse_editor_line(std::string_view line) {
    while (!line.empty() && (line.back() == '\r' || line.back() == '\n')) line.remove_suffix(1);
    const auto t = trim(line);
    if (t.empty()) return std::nullopt;
    document::Block b;
    if (is_braille_line(t)) {
        b.kind = document::BlockKind::braille;
        document::BrailleLine cells;
        const auto text = utf8_to_utf32(t);
        for (char32_t c : *text) cells.push_back(document::Cell::from_unicode(c));
        b.braille_lines.push_back(std::move(cells));
        return b;
    }
    if (is_thematic_break(t)) {
        b.kind = document::BlockKind::print_page_break;
        return b;
    }
    if (auto label = comment_argument(t, "pagebreak")) {
        b.kind = document::BlockKind::print_page_break;
        b.label = *label;
        return b;
    }
    if (comment_argument(t, "braillepage")) {
        b.kind = document::BlockKind::braille_page_break;
        return b;
    }
    std::size_t hashes = 0;
    while (hashes < t.size() && t[hashes] == '#') ++hashes;
    if (hashes >= 1 && hashes <= 6 && (hashes == t.size() || is_space(t[hashes]))) {
        b.kind = document::BlockKind::heading;
        b.level = static_cast<int>(hashes);
        b.spans = parse_inline(trim(t.substr(hashes)));
        return b;
    }
    if (t.starts_with('>')) {
        // "> text", "> > text": a block quote, as deep as its marks.
        b.kind = document::BlockKind::quote;
        auto rest = t;
        while (rest.starts_with('>')) {
            ++b.level;
            rest = trim(rest.substr(1));
        }
        b.spans = parse_inline(rest);
        return b;
    }
    if (t.starts_with("[^")) {
        // "[^label]: text": a note, with its reference first.
        const auto close = t.find("]:");
        if (close != std::string_view::npos && close > 2 &&
            t.substr(2, close - 2).find_first_of(" \t[]") == std::string_view::npos) {
            b.kind = document::BlockKind::note;
            document::Span reference{std::string(t.substr(2, close - 2))};
            reference.note_reference = true;
            b.spans.push_back(std::move(reference));
            b.spans.push_back(document::Span{" "});
            for (auto& s : parse_inline(trim(t.substr(close + 2)))) b.spans.push_back(std::move(s));
            return b;
        }
    }
    std::size_t indent = 0;
    while (indent < line.size() && line[indent] == ' ') ++indent;
    const auto rest = line.substr(indent);
    const bool bullet = rest.size() >= 2 && (rest[0] == '-' || rest[0] == '*' || rest[0] == '+') &&
                        is_space(rest[1]);
    const auto ordinal = ordinal_length(rest);
    if (bullet || (ordinal > 0 && ordinal < rest.size() && is_space(rest[ordinal]))) {
        b.kind = document::BlockKind::list_item;
        b.level = static_cast<int>(indent / 2) + 1;
        if (bullet) {
            // Bullets are kept as the bullet sign, as core's Markdown import does.
            b.spans = parse_inline(trim(rest.substr(2)));
            if (!b.spans.empty() && b.spans.front().emphasis == document::emphasis_none && !b.spans.front().note_reference)
                b.spans.front().text.insert(0, kBullet);
            else
                b.spans.insert(b.spans.begin(), document::Span{std::string(kBullet)});
        } else {
            // Numbered items keep their number as text, as core's Markdown import does.
            b.spans = parse_inline(trim(rest.substr(ordinal + 1)));
            const auto number = std::string(rest.substr(0, ordinal)) + " ";
            if (!b.spans.empty() && b.spans.front().emphasis == document::emphasis_none)
                b.spans.front().text.insert(0, number);
            else
                b.spans.insert(b.spans.begin(), document::Span{number});
        }
        return b;
    }
    b.kind = document::BlockKind::paragraph;
    b.spans = parse_inline(t);
    return b;
}

std::string render_editor_line(const document::Block& b) {
    switch (b.kind) {
        case document::BlockKind::heading: {
            auto text = render_spans(b.spans);
            // A heading's text ending in "#" would read as the closing "#"s Markdown drops.
            if (const auto run = text.find_last_not_of('#'); text.ends_with('#'))
                text.insert(run == std::string::npos ? 0 : run + 1, 1, '\\');
            return std::string(static_cast<std::size_t>(std::clamp(b.level, 1, 6)), '#') + " " + text;
        }
        case document::BlockKind::list_item: {
            std::string out(2 * static_cast<std::size_t>(std::max(b.level - 1, 0)), ' ');
            auto spans = b.spans;
            const auto ordinal =
                spans.empty() ? 0 : ordinal_length(spans.front().text);
            if (ordinal > 0 && ordinal < spans.front().text.size() &&
                spans.front().text[ordinal] == ' ') {
                out += spans.front().text.substr(0, ordinal + 1);
                spans.front().text.erase(0, ordinal + 1);
                return out + guard_line_start(render_spans(spans));
            }
            if (!spans.empty() && spans.front().text.starts_with(kBullet)) spans.front().text.erase(0, kBullet.size());
            // The item's own text must not start another list or block.
            return out + "- " + guard_line_start(render_spans(spans));
        }
        case document::BlockKind::quote:
        {
            std::string out;
            for (int i = 0; i < std::clamp(b.level, 1, 6); ++i) out += "> ";
            return out + guard_line_start(render_spans(b.spans));
        }
        case document::BlockKind::note: {
            if (b.spans.empty() || !b.spans.front().note_reference) break;
            auto rest = std::vector<document::Span>(b.spans.begin() + 1, b.spans.end());
            if (!rest.empty() && rest.front().text.starts_with(' ')) rest.front().text.erase(0, 1);
            return "[^" + b.spans.front().text + "]: " + render_spans(rest);
        }
        case document::BlockKind::table_row:
            return {};
        case document::BlockKind::table_cell:
            break;
        case document::BlockKind::print_page_break:
            return b.label.empty() ? "<!-- pagebreak -->" : "<!-- pagebreak " + b.label + " -->";
        case document::BlockKind::braille_page_break:
            return "<!-- braillepage -->";
        case document::BlockKind::braille: {
            std::string out;
            for (std::size_t i = 0; i < b.braille_lines.size(); ++i) {
                if (i) out += '\n';
                out += b.braille_lines[i].empty() ? document::to_unicode_text({document::Cell{}})
                                                  : document::to_unicode_text(b.braille_lines[i]);
            }
            return out;
        }
        case document::BlockKind::paragraph:
            break;
    }
    return guard_line_start(render_spans(b.spans));
}

std::vector<std::string> render_editor_lines(const document::Document& document) {
    std::vector<std::string> lines;
    lines.reserve(document.blocks.size());
    for (const auto& b : document.blocks) {
        if (b.kind == document::BlockKind::braille) {
            for (const auto& l : b.braille_lines)
                lines.push_back(l.empty() ? document::to_unicode_text({document::Cell{}}) : document::to_unicode_text(l));
            continue;
        }
        auto line = render_editor_line(b);
        if ((b.kind == document::BlockKind::paragraph || b.kind == document::BlockKind::table_cell ||
             b.kind == document::BlockKind::table_row) &&
            trim(line).empty())
            continue;
        lines.push_back(std::move(line));
    }
    return lines;
}

std::string editor_line_content(std::string_view line) {
    const auto block = parse_editor_line(line);
    if (!block) return {};
    if (block->kind == document::BlockKind::braille || block->kind == document::BlockKind::print_page_break ||
        block->kind == document::BlockKind::braille_page_break)
        return {};
    return block->text();
}

}  // namespace tactus::edit
