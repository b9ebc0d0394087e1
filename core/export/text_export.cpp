// SPDX-License-Identifier: GPL-3.0-or-later
#include "export/markdown_syntax.hpp"
#include "export/text_export.hpp"

#include "document/cell_paragraphs.hpp"
#include "document/main_language.hpp"
#include "document/markdown_html.hpp"
#include "document/soft_break.hpp"

#include <algorithm>
#include <optional>

namespace tactus::exporter {
namespace {

using namespace exporter::markdown;  // the line syntax the writer and the editor share

bool is_alnum(char c) { return is_digit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

// True when the special character at `i` means something to a Markdown
// reader where it stands, so it must be escaped; the text is shown as its
// author wrote it everywhere else ("5 * 3 & co.", not "5 \* 3 \& co."). At a
// span's edge the neighbour is unknown, and it is escaped.
bool needs_escape(std::string_view text, std::size_t i) {
    const char c = text[i];
    switch (c) {
        case '*':
        case '_':
        case '~': {
            // A run of them with a space on both sides neither opens nor closes
            // emphasis or strikethrough (CommonMark "left-flanking").
            auto from = i, to = i + 1;
            while (from > 0 && text[from - 1] == c) --from;
            while (to < text.size() && text[to] == c) ++to;
            const auto around = [&](bool (*test)(char)) {
                return from > 0 && test(text[from - 1]) && to < text.size() && test(text[to]);
            };
            // Nor does a "_" inside a word ("snake_case").
            return !(around(is_space) || (c == '_' && around(is_alnum)));
        }
        case '&': {
            // Only "&name;", "&#123;" and "&#x1F;" are entities.
            auto j = i + 1;
            if (j < text.size() && text[j] == '#') ++j;
            const auto name = j;
            while (j < text.size() && is_alnum(text[j])) ++j;
            return j == text.size() || (j > name && text[j] == ';');
        }
        case '<':
            // A tag, a comment or an autolink starts with one of these.
            return i + 1 == text.size() || (is_alnum(text[i + 1]) && !is_digit(text[i + 1])) ||
                   std::string_view("/!?").find(text[i + 1]) != std::string_view::npos;
        case '>':
            return false;  // only at a line's start (guard_line_start)
        default:
            return kInlineSpecials.find(c) != std::string_view::npos;
    }
}

// `before` and `after`: the characters written around the text, a space at
// the block's edges (CommonMark counts a line's start and end as whitespace),
// so the decision is the same however the text is cut into spans.
std::string escape_inline(std::string_view text, bool in_table, char before, char after) {
    std::string context;
    context.reserve(text.size() + 2);
    context += before;
    context += text;
    context += after;
    std::string out;
    out.reserve(text.size() + 8);
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (needs_escape(context, i + 1) || (in_table && text[i] == '|')) out.push_back('\\');
        out.push_back(text[i]);
    }
    return out;
}

// Keeps a paragraph's first characters from reading as a heading, list, break or table.
std::string guard_line_start(std::string s) {
    // Spaces and tabs at a block's start are not Markdown text (CommonMark
    // strips them from a paragraph; a tab would even open a list or code
    // block): the mark must see the text.
    s.erase(0, std::min(s.size(), s.find_first_not_of(" \t")));
    if (s.empty()) return s;
    if (const auto n = ordinal_length(s); n > 0 && n < s.size() + 1) {
        s.insert(n - 1, 1, '\\');
        return s;
    }
    if (std::string_view("#-+=>|").find(s[0]) != std::string_view::npos) {
        s.insert(0, 1, '\\');
        return s;
    }
    // A run of "*", "_" or "~" with a space after it is text left unescaped
    // (an emphasis mark touches its word): here it would start a list, a
    // thematic break or a code fence.
    if (std::string_view("*_~").find(s[0]) != std::string_view::npos) {
        const auto run = s.find_first_not_of(s[0]);
        if (run == std::string::npos || is_space(s[run])) s.insert(0, 1, '\\');
    }
    return s;
}

std::string_view emphasis_mark(std::uint8_t emphasis) {
    return (emphasis & document::emphasis_bold) && (emphasis & document::emphasis_italic) ? std::string_view("***")
           : (emphasis & document::emphasis_bold)                                         ? std::string_view("**")
           : (emphasis & document::emphasis_italic)                                       ? std::string_view("*")
                                                                                          : std::string_view();
}

std::string render_spans(const std::vector<document::Span>& spans, bool in_table = false) {
    // The first character written for spans[k...]: a space at the block's end.
    const auto first_written = [&spans](std::size_t k) {
        for (; k < spans.size(); ++k) {
            if (spans[k].note_reference) return '[';
            const auto joined = document::soft_breaks_as_spaces(spans[k].text);
            if (joined.empty()) continue;
            if (!document::markdown_html::open_tags(spans[k]).empty()) return '<';
            const auto mark = emphasis_mark(spans[k].emphasis);
            return mark.empty() || is_space(joined.front()) || trim(joined).empty() ? joined.front() : mark.front();
        }
        return ' ';
    };
    std::string out;
    for (std::size_t k = 0; k < spans.size(); ++k) {
        const auto& span = spans[k];
        if (span.note_reference) {
            out += "[^" + span.text + "]";
            continue;
        }
        // A soft line break (a hard-wrapped text paragraph) is a space: one block, one line.
        const auto joined = document::soft_breaks_as_spaces(span.text);
        std::string_view t = joined;
        const auto mark = emphasis_mark(span.emphasis);
        // Underline, raised and lowered text and a language are tags around
        // the whole text, its spaces too, and around the emphasis marks.
        const auto open = document::markdown_html::open_tags(span);
        const auto close = document::markdown_html::close_tags(span);
        out += open;
        const char before = out.empty() ? ' ' : out.back();
        const char after = close.empty() ? first_written(k + 1) : '<';
        const auto core = trim(t);
        if (mark.empty() || core.empty()) {
            out += escape_inline(t, in_table, before, after);
            out += close;
            continue;
        }
        // Emphasis marks must touch the words: keep surrounding spaces outside.
        const auto lead = static_cast<std::size_t>(core.data() - t.data());
        out += std::string(t.substr(0, lead));
        out += mark;
        out += escape_inline(core, in_table, mark.front(), mark.front());
        out += mark;
        out += std::string(t.substr(lead + core.size()));
        out += close;
    }
    return out;
}

std::string braille_lines_text(const document::Block& b, std::string_view separator) {
    std::string out;
    for (std::size_t i = 0; i < b.braille_lines.size(); ++i) {
        if (i) out += separator;
        out += b.braille_lines[i].empty() ? document::to_unicode_text({document::Cell{}})
                                          : document::to_unicode_text(b.braille_lines[i]);
    }
    return out;
}

bool is_table_line(std::string_view line) { return trim(line).starts_with('|'); }

// The cells of a pipe-table row, split at the pipes that are not escaped (their text as written).
std::vector<std::string> split_row(std::string_view line) {
    auto t = trim(line);
    if (t.starts_with('|')) t.remove_prefix(1);
    std::vector<std::string> cells;
    std::string cell;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] == '\\' && i + 1 < t.size()) {
            cell += t.substr(i, 2);
            ++i;
        } else if (t[i] == '|') {
            cells.emplace_back(trim(cell));
            cell.clear();
        } else {
            cell += t[i];
        }
    }
    if (!trim(cell).empty()) cells.emplace_back(trim(cell));
    return cells;
}

std::string join_row(const std::vector<std::string>& cells, std::size_t width) {
    std::string out = "|";
    for (std::size_t c = 0; c < width; ++c) out += " " + (c < cells.size() ? cells[c] : std::string()) + " |";
    return out;
}

// "| --- | :-: |": each column's alignment (none where `aligns` has none).
std::string delimiter_row(std::span<const document::Align> aligns, std::size_t width) {
    std::string out = "|";
    for (std::size_t c = 0; c < width; ++c) {
        switch (c < aligns.size() ? aligns[c] : document::Align::none) {
            case document::Align::left: out += " :-- |"; break;
            case document::Align::centre: out += " :-: |"; break;
            case document::Align::right: out += " --: |"; break;
            case document::Align::none: out += " --- |"; break;
        }
    }
    return out;
}

bool is_text_line_kind(const document::Block& b) {
    return document::is_text_kind(b.kind) || b.kind == document::BlockKind::braille;
}

}  // namespace

std::string markdown_line(const document::Block& b) {
    switch (b.kind) {
        case document::BlockKind::heading: {
            auto text = render_spans(b.spans);
            // Spaces at its end are no text (Markdown strips them), and they
            // would hide a "#" before them from the check below.
            text.erase(std::min(text.size(), text.find_last_not_of(" \t") + 1));
            // A heading's text ending in "#" would read as the closing "#"s Markdown drops.
            if (const auto run = text.find_last_not_of('#'); text.ends_with('#'))
                text.insert(run == std::string::npos ? 0 : run + 1, 1, '\\');
            return std::string(static_cast<std::size_t>(std::clamp(b.level, 1, 6)), '#') + " " + text;
        }
        case document::BlockKind::list_item: {
            std::string out(2 * static_cast<std::size_t>(std::max(b.level - 1, 0)), ' ');
            auto spans = b.spans;
            const auto ordinal = spans.empty() ? 0 : ordinal_length(spans.front().text);
            if (ordinal > 0 && ordinal < spans.front().text.size() && spans.front().text[ordinal] == ' ') {
                out += spans.front().text.substr(0, ordinal + 1);
                spans.front().text.erase(0, ordinal + 1);
                return out + guard_line_start(render_spans(spans));
            }
            if (!spans.empty() && spans.front().text.starts_with(kBullet)) spans.front().text.erase(0, kBullet.size());
            // The item's own text must not start another list or block.
            return out + "- " + guard_line_start(render_spans(spans));
        }
        case document::BlockKind::quote: {
            std::string out;
            for (int i = 0; i < std::clamp(b.level, 1, 6); ++i) out += "> ";
            return out + guard_line_start(render_spans(b.spans));
        }
        case document::BlockKind::note: {
            if (b.spans.empty() || !b.spans.front().note_reference) break;
            auto rest = std::vector<document::Span>(b.spans.begin() + 1, b.spans.end());
            if (!rest.empty() && rest.front().text.starts_with(' ')) rest.front().text.erase(0, 1);
            // The note's text is read as Markdown of its own: it must not start a heading or list.
            return "[^" + b.spans.front().text + "]: " + guard_line_start(render_spans(rest));
        }
        case document::BlockKind::table_row:
        case document::BlockKind::table_cell:
            return {};
        case document::BlockKind::print_page_break:
            // A counted label is left for the reader to count again (document/print_page.hpp).
            return b.label.empty() || b.label_counted ? "<!-- pagebreak -->" : "<!-- pagebreak " + b.label + " -->";
        case document::BlockKind::braille_page_break:
            return "<!-- braillepage -->";
        case document::BlockKind::braille:
            return braille_lines_text(b, "\n");
        case document::BlockKind::paragraph:
            break;
    }
    return guard_line_start(render_spans(b.spans));
}

std::string markdown_table_row(std::span<const document::Block> cells) {
    std::vector<std::string> texts;
    for (const auto& c : cells) {
        // A cell keeps its column (`level`): the columns a merged cell covers
        // before it are empty entries, as Markdown has no merged cells.
        while (static_cast<int>(texts.size()) < c.level) texts.emplace_back();
        // The cell's paragraphs (document/cell_paragraphs.hpp) <br> apart: a
        // pipe table's cell is one line, and the importer reads <br> back as the break.
        std::string text;
        const auto paragraphs = document::cell_paragraphs(c.spans);
        for (std::size_t p = 0; p < paragraphs.size(); ++p) text += (p ? "<br>" : "") + render_spans(paragraphs[p], true);
        // An entry of dashes alone would make the row read as the delimiter row.
        if (!trim(text).empty() && trim(text).find_first_not_of("-: ") == std::string_view::npos)
            text.insert(text.find_first_not_of(' '), 1, '\\');
        texts.push_back(std::move(text));
    }
    return join_row(texts, texts.size());
}

std::vector<document::Align> markdown_table_alignments(std::string_view delimiter) {
    std::vector<document::Align> out;
    for (const auto& cell : split_row(delimiter)) {
        const auto t = trim(cell);
        const bool left = t.starts_with(':'), right = t.size() > 1 && t.ends_with(':');
        out.push_back(left && right ? document::Align::centre
                      : left        ? document::Align::left
                      : right       ? document::Align::right
                                    : document::Align::none);
    }
    return out;
}

std::size_t markdown_table_width(std::span<const std::string> lines) {
    std::size_t width = 1;
    for (const auto& l : lines)
        if (!is_markdown_table_delimiter(l)) width = std::max(width, split_row(l).size());
    return width;
}

bool is_markdown_table_delimiter(std::string_view line) {
    const auto t = trim(line);
    if (!t.starts_with('|') || t.find('-') == std::string_view::npos) return false;
    return t.find_first_not_of("|-: \t") == std::string_view::npos;
}

std::vector<std::string> markdown_lines(const document::Document& document) {
    std::vector<std::string> lines;
    lines.reserve(document.blocks.size());
    const auto& blocks = document.blocks;
    // A box's blocks stand between its box lines (document/markdown_html.hpp).
    int box = 0;
    const auto enter_box = [&](int next) {
        if (next == box) return;
        if (box != 0) lines.emplace_back(document::markdown_html::kBoxEnd);
        if (next != 0) lines.emplace_back(document::markdown_html::kBoxStart);
        box = next;
    };
    for (std::size_t i = 0; i < blocks.size();) {
        const auto& b = blocks[i];
        enter_box(b.box);
        if (document::is_table_kind(b.kind)) {
            // One table: its rows, each with the cells after it.
            std::vector<std::pair<bool, std::vector<document::Block>>> rows;
            for (; i < blocks.size() && document::is_table_kind(blocks[i].kind); ++i) {
                if (blocks[i].kind == document::BlockKind::table_row || rows.empty())
                    rows.emplace_back(blocks[i].kind == document::BlockKind::table_row && blocks[i].level == 1,
                                      std::vector<document::Block>{});
                if (blocks[i].kind == document::BlockKind::table_cell) rows.back().second.push_back(blocks[i]);
            }
            // A header row after body rows starts a table of its own (a blank
            // line apart: one Markdown table has one header row, at its top),
            // and so does a row whose columns are aligned otherwise (all the
            // cells of a Markdown table's column have the delimiter row's).
            const auto same_alignment = [](const std::vector<document::Block>& one,
                                           const std::vector<document::Block>& other) {
                for (const auto& x : one)
                    for (const auto& y : other)
                        if (x.level == y.level && x.align != y.align) return false;
                return true;
            };
            for (std::size_t from = 0; from < rows.size();) {
                std::size_t to = from + 1;
                while (to < rows.size() && !(rows[to].first && !rows[to - 1].first) &&
                       same_alignment(rows[from].second, rows[to].second))
                    ++to;
                // As wide as its widest row, counted in columns (a cell keeps its
                // column: a merged cell's other columns are empty entries).
                std::vector<std::vector<std::string>> entries;
                std::size_t width = 1;
                // A column's alignment: its cells' (the first that has one).
                std::vector<document::Align> aligns;
                for (std::size_t r = from; r < to; ++r) {
                    entries.push_back(split_row(markdown_table_row(rows[r].second)));
                    width = std::max(width, entries.back().size());
                    for (const auto& cell : rows[r].second) {
                        const auto c = static_cast<std::size_t>(std::max(cell.level, 0));
                        if (cell.align == document::Align::none) continue;
                        if (aligns.size() <= c) aligns.resize(c + 1);
                        if (aligns[c] == document::Align::none) aligns[c] = cell.align;
                    }
                }
                std::vector<std::string> table;
                for (const auto& e : entries) table.push_back(join_row(e, width));
                if (!rows[from].first) table.insert(table.begin(), join_row({}, width));
                table.insert(table.begin() + 1, delimiter_row(aligns, width));
                if (from > 0) lines.emplace_back();
                for (auto& l : table) lines.push_back(std::move(l));
                from = to;
            }
            continue;
        }
        if (b.kind == document::BlockKind::braille) {
            // An empty row is one blank cell (the editor reads it back as an
            // empty row); a page without rows (a PEF's <page/>) one empty row.
            for (const auto& l : b.braille_lines)
                lines.push_back(l.empty() ? document::to_unicode_text({document::Cell{}}) : document::to_unicode_text(l));
            if (b.braille_lines.empty()) lines.push_back(document::to_unicode_text({document::Cell{}}));
        } else if (auto line = markdown_line(b); !trim(line).empty()) {
            lines.push_back(std::move(line));
        }
        ++i;
    }
    enter_box(0);
    return lines;
}

namespace {

// A list item line as the editor writes it: two spaces a level, then "- " or "12. ".
struct ItemLine {
    std::size_t level = 0;  // 1-based
    std::string_view marker;  // "- ", "12. "
    std::string_view rest;
    bool ordered = false;
    long number = 0;
    char delimiter = 0;
};

std::optional<ItemLine> item_line(std::string_view line) {
    std::size_t indent = 0;
    while (indent < line.size() && line[indent] == ' ') ++indent;
    const auto rest = line.substr(indent);
    ItemLine item;
    item.level = indent / 2 + 1;
    if (rest.size() >= 2 && (rest[0] == '-' || rest[0] == '*' || rest[0] == '+') && is_space(rest[1])) {
        item.marker = rest.substr(0, 2);
        item.rest = rest.substr(2);
        return item;
    }
    const auto n = ordinal_length(rest);
    if (n == 0 || n >= rest.size() || !is_space(rest[n])) return std::nullopt;
    item.marker = rest.substr(0, n + 1);
    item.rest = rest.substr(n + 1);
    item.ordered = true;
    item.number = std::stol(std::string(rest.substr(0, n - 1)));
    item.delimiter = rest[n - 1];
    return item;
}

}  // namespace

std::string join_markdown_lines(std::span<const std::string> lines) {
    std::string out;
    const auto block = [&out](std::string_view text) {
        if (!out.empty()) out += "\n\n";
        out += text;
    };
    // The list items open at each level: where their content starts (a nested
    // item is indented to it, as Markdown nests), and an ordered item's number.
    struct Open {
        std::size_t content = 0;
        bool ordered = false;
        long number = 0;
        char delimiter = 0;
    };
    std::vector<Open> open;
    for (std::size_t i = 0; i < lines.size();) {
        if (trim(lines[i]).empty()) {  // blank: no block
            ++i;
            continue;
        }
        if (const auto item = item_line(lines[i]); item && !trim(item->rest).empty()) {
            // An item deeper than the one above it gets empty parents: Markdown
            // nests a list only inside an item (the importer drops empty items).
            while (open.size() + 1 < item->level) {
                const auto indent = open.empty() ? 0 : open.back().content;
                block(std::string(indent, ' ') + "- <!-- -->");
                open.push_back(Open{indent + 2});
            }
            const auto indent = item->level > 1 ? open[item->level - 2].content : 0;
            // Markdown counts an ordered list on from its first number: an item
            // whose number does not follow its sibling's starts a list of its own.
            if (item->ordered && open.size() >= item->level) {
                const auto& sibling = open[item->level - 1];
                if (sibling.ordered && sibling.delimiter == item->delimiter && item->number != sibling.number + 1)
                    block(std::string(indent, ' ') + "<!-- -->");
            }
            block(std::string(indent, ' ') + std::string(item->marker) + std::string(trim(item->rest)));
            open.resize(item->level - 1);
            open.push_back(Open{indent + item->marker.size(), item->ordered, item->number, item->delimiter});
            ++i;
            continue;
        }
        if (!is_table_line(lines[i])) {
            open.clear();
            block(trim(lines[i]));
            ++i;
            continue;
        }
        // A run of table lines is one table: made whole (header, delimiter, width).
        std::size_t end = i;
        while (end < lines.size() && is_table_line(lines[end])) ++end;
        // The header row is the run's first line when the delimiter row follows it.
        const bool header = end - i >= 2 && !is_markdown_table_delimiter(lines[i]) &&
                            is_markdown_table_delimiter(lines[i + 1]);
        std::vector<std::vector<std::string>> rows;
        for (std::size_t j = i; j < end; ++j)
            if (!is_markdown_table_delimiter(lines[j])) rows.push_back(split_row(lines[j]));
        if (rows.empty()) {  // delimiter rows alone: no table (nor the end of a list above)
            i = end;
            continue;
        }
        open.clear();
        const auto width = markdown_table_width(lines.subspan(i, end - i));
        // The columns' alignments, as the (first) delimiter row gives them.
        const auto delimiter = std::find_if(lines.begin() + static_cast<std::ptrdiff_t>(i),
                                            lines.begin() + static_cast<std::ptrdiff_t>(end),
                                            [](const std::string& l) { return is_markdown_table_delimiter(l); });
        const auto aligns = delimiter == lines.begin() + static_cast<std::ptrdiff_t>(end)
                                ? std::vector<document::Align>{}
                                : markdown_table_alignments(*delimiter);
        std::string table;
        if (!header) table = join_row({}, width) + "\n" + delimiter_row(aligns, width);
        for (std::size_t r = 0; r < rows.size(); ++r) {
            if (!table.empty()) table += "\n";
            table += join_row(rows[r], width);
            if (header && r == 0) table += "\n" + delimiter_row(aligns, width);
        }
        block(table);
        i = end;
    }
    out += '\n';
    return out;
}

std::string markdown_front_matter(const document::Document& document) {
    const auto language = document::main_language(document);
    if (language.empty()) return {};
    // A tag is letters, digits and hyphens; anything else is quoted, so the
    // YAML reads it as one string.
    const bool plain = std::ranges::all_of(language, [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
    });
    std::string value;
    for (char c : language) value += c == '\n' || c == '\r' ? ' ' : c;
    return "---\nlang: " + (plain ? value : "\"" + value + "\"") + "\n---\n\n";
}

std::string to_markdown(const document::Document& document) {
    const auto lines = markdown_lines(document);
    return markdown_front_matter(document) + join_markdown_lines(lines);
}

std::string text_line(const document::Block& b) {
    switch (b.kind) {
        case document::BlockKind::print_page_break:
        case document::BlockKind::braille_page_break:
            return "\f";
        case document::BlockKind::braille:
            return braille_lines_text(b, "\n");
        case document::BlockKind::table_row:
            return {};
        default:
            break;
    }
    std::string out;
    for (const auto& s : b.spans) out += s.note_reference ? "[" + s.text + "]" : s.text;
    return out;
}

std::vector<std::string> text_lines(const document::Document& document) {
    struct Line {
        std::string text;
        int source_line;
        int last_line;  // the source line of its last line (a hard-wrapped paragraph has several)
        bool text_block;
    };
    std::vector<Line> blocks;
    for (const auto& b : document.blocks) {
        if (b.kind == document::BlockKind::table_row) continue;
        auto text = text_line(b);
        const bool text_block = is_text_line_kind(b);
        if (text_block && trim(text).empty()) continue;
        // A paragraph's soft line breaks (a braille block's lines are its rows).
        const bool paragraph = document::is_text_kind(b.kind);
        const auto breaks = paragraph ? static_cast<int>(std::ranges::count(text, '\n')) : 0;
        blocks.push_back(Line{std::move(text), b.source_line, b.source_line == 0 ? 0 : b.source_line + breaks, text_block});
    }
    // Paragraphs apart by a blank line somewhere: the importer then joins lines,
    // so every two paragraphs need one.
    bool apart = false;
    for (std::size_t i = 1; i < blocks.size(); ++i)
        if (blocks[i - 1].text_block && blocks[i].text_block &&
            (blocks[i].source_line == 0 || blocks[i].source_line != blocks[i - 1].last_line + 1))
            apart = true;
    std::vector<std::string> out;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        if (i > 0 && apart) {
            const auto& p = blocks[i - 1];
            const auto& b = blocks[i];
            const bool gap = b.source_line == 0 || p.last_line == 0 || b.source_line > p.last_line + 1;
            if ((p.text_block && b.text_block) || gap) out.emplace_back();
        }
        out.push_back(std::move(blocks[i].text));
    }
    return out;
}

std::string to_text(const document::Document& document) {
    std::string out;
    for (const auto& l : text_lines(document)) {
        out += l;
        out += '\n';
    }
    return out;
}

}  // namespace tactus::exporter
