// SPDX-License-Identifier: GPL-3.0-or-later
#include "edit/editor_lines.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "common/utf8.hpp"
#include "document/markdown_html.hpp"
#include "edit/editor_pictures.hpp"
#include "export/document_save.hpp"
#include "export/office_export.hpp"
#include "export/markdown_syntax.hpp"
#include "export/text_export.hpp"
#include "import/import.hpp"
#include "import/markdown_footnotes.hpp"
#include "import/text_lines.hpp"

namespace tactus::edit {
namespace {

using namespace exporter::markdown;  // the line syntax the writer and the editor share

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

// Inline Markdown (emphasis, escapes) and note references "[^label]" (an
// escaped "\[^1]" is text), read by core's importer as the text of a
// paragraph, so the editor and a saved file read a line alike (a reference is
// a mark of its own there, and emphasis around it opens and closes as it does
// in the file). Plain text takes the fast path, which is nearly every line of a
// real book.
// `whole_line`: `content` is a heading's whole line, read as the importer
// reads it in a file (its closing "#"s, raw HTML in it), not as a paragraph.
// A picture's mark (edit/editor_pictures.hpp) is its description, a
// transcriber's note, and its picture, by name, added to `images`.
std::vector<document::Span> parse_inline(std::string_view content, bool whole_line = false,
                                         std::vector<document::Image>* images = nullptr) {
    // The references' labels, in order; the importer numbers them 1, 2, 3 so.
    std::vector<std::string> labels;
    for (auto i = content.find("[^"); i != std::string_view::npos; i = content.find("[^", i + 1))
        if (const auto id = import::note_reference_id(content, i); id && std::ranges::find(labels, *id) == labels.end())
            labels.emplace_back(*id);
    if (!whole_line && labels.empty() && content.find_first_of(kInlineSpecials) == std::string_view::npos)
        return content.empty() ? std::vector<document::Span>{} : std::vector<document::Span>{document::Span{std::string(content)}};
    import::ImportOptions options;
    options.format = import::SourceFormat::markdown;
    options.encoding = "UTF-8";
    options.picture_marks = true;
    // Read as the text of a paragraph: a no-break space in front keeps "- *x*"
    // or "# *x*" from starting a list or a heading (it is Unicode whitespace, so
    // emphasis opens after it as at a line start), and is taken off again.
    constexpr std::string_view kGuard = "\u00a0";
    std::string source = (whole_line ? std::string() : std::string(kGuard)) + std::string(content);
    // Every reference in a line is one: its note is on a line of its own.
    for (const auto& label : labels) source += "\n\n[^" + label + "]: x";
    auto doc = import::import_bytes(source, "line.md", options);
    if (!doc) return {document::Span{std::string(content)}};
    std::vector<document::Span> spans;
    for (const auto& b : doc->blocks) {
        if (b.kind == document::BlockKind::note) continue;
        if (images) images->insert(images->end(), b.images.begin(), b.images.end());
        for (auto s : b.spans) {
            if (s.note_reference) {
                // The importer's number back to the line's own label.
                const auto n = static_cast<std::size_t>(std::stoul(s.text));
                if (n >= 1 && n <= labels.size()) s.text = labels[n - 1];
                spans.push_back(std::move(s));
            } else if (!spans.empty() && !spans.back().note_reference && spans.back().emphasis == s.emphasis &&
                       spans.back().position == s.position && spans.back().language == s.language &&
                       spans.back().transcriber_note == s.transcriber_note && !s.transcriber_note) {
                spans.back().text += s.text;
            } else {
                spans.push_back(std::move(s));
            }
        }
    }
    if (!whole_line && !spans.empty() && !spans.front().note_reference && spans.front().text.starts_with(kGuard)) {
        spans.front().text.erase(0, kGuard.size());
        if (spans.front().text.empty()) spans.erase(spans.begin());
    }
    return spans;
}

}  // namespace

bool is_braille_line(std::string_view utf8) {
    if (utf8.empty()) return false;
    auto text = utf8_to_utf32(utf8);
    if (!text || text->empty()) return false;
    return std::ranges::all_of(*text, [](char32_t c) { return document::Cell::is_unicode_braille(c); });
}

Dialect dialect_for(std::string_view name) {
    const auto dot = name.rfind('.');
    if (dot == std::string_view::npos) return Dialect::markdown;
    std::string ext(name.substr(dot + 1));
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == "txt" || ext == "text" ? Dialect::text : Dialect::markdown;
}

int box_line(std::string_view line, Dialect dialect) {
    if (dialect != Dialect::markdown) return 0;
    const auto t = trim(line);
    if (t == document::markdown_html::kBoxStart) return +1;
    if (t == document::markdown_html::kBoxEnd) return -1;
    return 0;
}

bool is_table_delimiter(std::string_view line) { return exporter::is_markdown_table_delimiter(line); }

std::vector<document::Block> parse_table_cells(std::string_view line) {
    auto t = trim(line);
    if (t.starts_with('|')) t.remove_prefix(1);
    std::vector<document::Block> cells;
    std::size_t from = 0;
    const auto cell = [&](std::size_t end) {
        document::Block c;
        c.kind = document::BlockKind::table_cell;
        c.level = static_cast<int>(cells.size());
        c.spans = parse_inline(trim(t.substr(from, end - from)), false, &c.images);
        cells.push_back(std::move(c));
    };
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] == '\\') {
            ++i;
        } else if (t[i] == '|') {
            cell(i);
            from = i + 1;
        }
    }
    if (!trim(t.substr(from)).empty()) cell(t.size());
    return cells;
}

namespace {

// A list item's or a note's text starts at its first word, as in Markdown (a
// tag dropped in front of it leaves no space).
std::vector<document::Span> text_from_first_word(std::vector<document::Span> spans) {
    while (!spans.empty() && !spans.front().note_reference) {
        auto& first = spans.front().text;
        first.erase(0, std::min(first.size(), first.find_first_not_of(" \t")));
        if (!first.empty()) break;
        spans.erase(spans.begin());
    }
    return spans;
}

bool visible(const document::Block& b) {
    // A picture is seen, described or not.
    return !b.images.empty() || std::ranges::any_of(b.spans, [](const document::Span& s) {
        return s.note_reference || s.text.find_first_not_of(" \t\n\r\f\v") != std::string::npos;
    });
}

std::optional<document::Block> parse_line(std::string_view line, Dialect dialect);

}  // namespace

std::optional<document::Block> parse_editor_line(std::string_view line, Dialect dialect) {
    auto b = parse_line(line, dialect);
    // A block without visible text is no block, as the importers drop it.
    if (b && document::is_text_kind(b->kind) && !visible(*b)) return std::nullopt;
    return b;
}

namespace {

std::optional<document::Block> parse_line(std::string_view line, Dialect dialect) {
    while (!line.empty() && (line.back() == '\r' || line.back() == '\n')) line.remove_suffix(1);
    const auto t = trim(line);
    if (t.empty()) return std::nullopt;
    document::Block b;
    if (is_braille_line(t)) {
        b.kind = document::BlockKind::braille;
        document::BrailleLine cells;
        const auto text = utf8_to_utf32(t);
        for (char32_t c : *text) cells.push_back(document::Cell::from_unicode(c));
        // One blank cell is how the writer shows an empty row (a PEF's <row/>,
        // a BRF's empty line: exporter::markdown_lines): an empty row again.
        if (cells.size() == 1 && cells.front().blank()) cells.clear();
        b.braille_lines.push_back(std::move(cells));
        return b;
    }
    // A form feed is a print page break, as both importers read it.
    if (t.find_first_not_of("\f \t") == std::string_view::npos) {
        b.kind = document::BlockKind::print_page_break;
        return b;
    }
    if (dialect == Dialect::text) {
        // The text as written, the spaces at its ends too (a .txt is verbatim).
        b.spans.push_back(document::Span{std::string(line)});
        return b;
    }
    if (t.starts_with('|')) {
        if (is_table_delimiter(t)) return std::nullopt;
        // A table row; the live layout knows from the next line whether it is the header.
        b.kind = document::BlockKind::table_row;
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
        // The whole line through the importer, as the file is read: a closing
        // run of "#"s is no text, nor raw HTML ("# \&  # <b>" reads "&").
        b.spans = parse_inline(t, true, &b.images);
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
        b.spans = parse_inline(rest, false, &b.images);
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
            // The note's text starts at its first word, as the importer joins it.
            for (auto& s : text_from_first_word(parse_inline(trim(t.substr(close + 2)), false, &b.images)))
                b.spans.push_back(std::move(s));
            return b;
        }
    }
    // A bare list mark is an empty list item in Markdown: no block.
    if (t == "-" || t == "*" || t == "+" || (ordinal_length(t) == t.size())) return std::nullopt;
    std::size_t indent = 0;
    while (indent < line.size() && line[indent] == ' ') ++indent;
    const auto rest = line.substr(indent);
    const bool bullet = rest.size() >= 2 && (rest[0] == '-' || rest[0] == '*' || rest[0] == '+') &&
                        is_space(rest[1]);
    const auto ordinal = ordinal_length(rest);
    if (bullet || (ordinal > 0 && ordinal < rest.size() && is_space(rest[ordinal]))) {
        b.kind = document::BlockKind::list_item;
        b.level = static_cast<int>(indent / 2) + 1;
        document::Block text;
        text.spans = parse_inline(trim(rest.substr(bullet ? 2 : ordinal + 1)));
        if (!visible(text)) return std::nullopt;  // an empty item
        const auto item_text = [&] {
            return text_from_first_word(parse_inline(trim(rest.substr(bullet ? 2 : ordinal + 1)), false, &b.images));
        };
        if (bullet) {
            // Bullets are kept as the bullet sign, as core's Markdown import does.
            b.spans = item_text();
            if (!b.spans.empty() && b.spans.front().emphasis == document::emphasis_none &&
                !b.spans.front().note_reference && !b.spans.front().transcriber_note)
                b.spans.front().text.insert(0, kBullet);
            else
                b.spans.insert(b.spans.begin(), document::Span{std::string(kBullet)});
        } else {
            // Numbered items keep their number as text, as core's Markdown import does.
            b.spans = item_text();
            const auto number = std::string(rest.substr(0, ordinal)) + " ";
            if (!b.spans.empty() && b.spans.front().emphasis == document::emphasis_none &&
                !b.spans.front().transcriber_note)
                b.spans.front().text.insert(0, number);
            else
                b.spans.insert(b.spans.begin(), document::Span{number});
        }
        return b;
    }
    b.kind = document::BlockKind::paragraph;
    b.spans = parse_inline(t, false, &b.images);
    return b;
}

}  // namespace

std::string render_editor_line(const document::Block& b, Dialect dialect) {
    if (dialect == Dialect::text) return exporter::text_line(b);
    if (b.images.empty()) return exporter::markdown_line(b);
    document::Document one;
    one.blocks.push_back(b);
    return render_with_picture_marks(one, [](const document::Document& d) {
        return std::vector<std::string>{exporter::markdown_line(d.blocks.front())};
    }).front();
}

std::vector<std::string> render_editor_lines(const document::Document& document, Dialect dialect) {
    if (dialect == Dialect::markdown) return render_with_picture_marks(document, &exporter::markdown_lines);
    // The lines of the file core's text writer writes: a hard-wrapped
    // paragraph is its lines, as the author wrote them.
    return import::split_text_lines(exporter::to_text(document));
}

namespace {

// True when the text of a paragraph, list item or quote line starts with a
// character Markdown could read as the start of another block.
bool risky_start(std::string_view line, document::BlockKind kind) {
    auto t = trim(line);
    switch (kind) {
        case document::BlockKind::paragraph:
            return !t.empty() && std::string_view("<`~[").find(t.front()) != std::string_view::npos;
        case document::BlockKind::list_item: {
            const auto n = t.starts_with('-') || t.starts_with('*') || t.starts_with('+') ? 1 : ordinal_length(t);
            t = trim(t.substr(std::min(n, t.size())));
            break;
        }
        case document::BlockKind::quote:
            while (t.starts_with('>')) t = trim(t.substr(1));
            break;
        case document::BlockKind::note:
            // "[^1]: text": the importer reads a note's text as Markdown of its own.
            t = trim(t.substr(std::min(t.find("]:") + 2, t.size())));
            break;
        default:
            return false;
    }
    return !t.empty() && std::string_view("#-+*_=>|<`~[0123456789").find(t.front()) != std::string_view::npos;
}

// A writer's text (each line ended by LF) with `line_ending` instead: the file's own.
std::string with_line_ending(std::string text, std::string_view line_ending) {
    if (line_ending == "\n" || line_ending.empty()) return text;
    std::string out;
    out.reserve(text.size() + text.size() / 16);
    for (const char c : text) {
        if (c == '\n') out += line_ending;
        else out += c;
    }
    return out;
}

}  // namespace

std::string file_text(std::span<const std::string> lines, Dialect dialect, const document::Document& blocks,
                      std::string_view file_name, std::string_view line_ending) {
    if (dialect_for(file_name) == Dialect::text) {
        if (dialect == Dialect::markdown) return with_line_ending(exporter::to_text(blocks), line_ending);
        // A text file's lines are the editor's: written as they are.
        std::string out;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            if (i) out += line_ending;
            out += lines[i];
        }
        return out;
    }
    if (dialect == Dialect::markdown) {
        // A line that stands for no block is not written: in a file it could
        // mean something (an unclosed "<!--" would swallow the rest).
        std::vector<std::string> kept;
        kept.reserve(lines.size());
        for (const auto& l : lines) {
            const auto block = parse_editor_line(l, dialect);
            if (block && risky_start(l, block->kind))
                // In a file this text could open a block of its own (an HTML
                // block, a code fence, a list inside an item): the writer's
                // escaped form, which reads back as the same block.
                kept.push_back(render_editor_line(*block, dialect));
            else
                kept.push_back(block || is_table_delimiter(l) || box_line(l) != 0 ? l : std::string());
        }
        return with_line_ending(exporter::markdown_front_matter(blocks) + exporter::join_markdown_lines(kept), line_ending);
    }
    return with_line_ending(exporter::to_markdown(blocks), line_ending);
}

Result<std::string> file_bytes(std::span<const std::string> lines, Dialect dialect, const document::Document& blocks,
                               std::string_view file_name, std::string_view line_ending,
                               std::vector<std::string>* warnings) {
    if (const auto format = exporter::document_format_for(std::filesystem::path(file_name));
        format == exporter::DocumentFormat::docx || format == exporter::DocumentFormat::odt) {
        auto file = exporter::to_office(blocks, format == exporter::DocumentFormat::docx ? exporter::OfficeFormat::docx
                                                                                        : exporter::OfficeFormat::odt);
        if (!file) return std::unexpected(file.error());
        if (warnings) warnings->insert(warnings->end(), file->warnings.begin(), file->warnings.end());
        return std::move(file->bytes);
    }
    // One rule for every print file the editor writes, text or Markdown: the
    // encoding the document was opened with.
    return exporter::encode_text(file_text(lines, dialect, blocks, file_name, line_ending), blocks.encoding,
                                 blocks.byte_order_mark);
}

std::string editor_line_content(std::string_view line, Dialect dialect) {
    const auto block = parse_editor_line(line, dialect);
    if (!block) return {};
    if (block->kind == document::BlockKind::braille || block->kind == document::BlockKind::print_page_break ||
        block->kind == document::BlockKind::braille_page_break)
        return {};
    if (block->kind == document::BlockKind::table_row) {
        std::string out;
        for (const auto& cell : parse_table_cells(line)) out += (out.empty() ? "" : "  ") + cell.text();
        return out;
    }
    return block->text();
}

}  // namespace tactus::edit
