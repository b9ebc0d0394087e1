// SPDX-License-Identifier: GPL-3.0-or-later
#include "export/document_save.hpp"

#include <algorithm>

#include "common/file_io.hpp"
#include "document/main_language.hpp"
#include "export/markdown_syntax.hpp"
#include "export/office_common.hpp"
#include "export/office_export.hpp"
#include "export/text_export.hpp"

namespace tactus::exporter {
namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; });
    return out;
}

// A list item's text starts with its bullet or number, as every Markdown
// item has one (a roman "IV." from a DOCX list is text, not a mark).
bool has_item_mark(const document::Block& b) {
    if (b.spans.empty() || b.spans.front().note_reference) return false;
    const auto& t = b.spans.front().text;
    const auto n = markdown::ordinal_length(t);
    return t.starts_with(markdown::kBullet) || (n > 0 && n < t.size() && t[n] == ' ');
}

// What Markdown and plain text do not hold, named as the office writers name
// theirs (office::Losses): the construct, how many, the first block.
std::vector<std::string> print_losses(const document::Document& document, DocumentFormat format) {
    office::Losses losses;
    const bool text = format == DocumentFormat::text;
    for (std::size_t i = 0; i < document.blocks.size(); ++i) {
        const auto& b = document.blocks[i];
        if (b.kind == document::BlockKind::table_cell && b.span > 1)
            losses.add("a merged cell is written as its columns", i);
        if (text && b.box != 0) losses.add("a box is written as the blocks in it, without the box", i);
        if (!b.images.empty()) losses.add("a picture is left out (its description stays)", i);
        if (!text && b.kind == document::BlockKind::list_item && !has_item_mark(b))
            losses.add("a list item without a bullet or number is written with a bullet", i);
        if (text) {
            switch (b.kind) {
                case document::BlockKind::heading: losses.add("a heading is written as a plain line", i); break;
                case document::BlockKind::list_item: losses.add("a list item is written as a plain line", i); break;
                case document::BlockKind::quote: losses.add("a quote is written as a plain line", i); break;
                case document::BlockKind::note: losses.add("a note is written as a plain line", i); break;
                case document::BlockKind::table_cell: losses.add("a table cell is written as a plain line", i); break;
                default: break;
            }
        }
        for (const auto& s : b.spans) {
            if (text && (s.emphasis & (document::emphasis_bold | document::emphasis_italic)))
                losses.add("bold and italic are left out", i);
            if (s.transcriber_note) losses.add("an image's description is written as plain text", i);
            if (!text) continue;  // Markdown keeps the rest (document/markdown_html.hpp)
            if (s.emphasis & document::emphasis_underline) losses.add("underline is left out", i);
            if (s.position != document::Position::baseline) losses.add("raised and lowered text is written on the line", i);
            if (!s.language.empty()) losses.add("a passage's language is left out", i);
        }
    }
    // Markdown's front matter holds the main language only (markdown_front_matter).
    if (text ? !document.metadata.empty() : document::has_other_metadata(document))
        losses.add(text ? "the document's metadata (title, author, language) is not written"
                        : "the document's metadata (title, author) besides its language is not written",
                   0);
    return losses.lines(text ? "text" : "Markdown");
}

}  // namespace

Result<DocumentFormat> parse_document_format(std::string_view name) {
    const auto n = lower(name);
    if (n == "md" || n == "markdown") return DocumentFormat::markdown;
    if (n == "txt" || n == "text") return DocumentFormat::text;
    if (n == "docx") return DocumentFormat::docx;
    if (n == "odt") return DocumentFormat::odt;
    return fail(ErrorKind::usage, "unknown document format \"" + std::string(name) + "\" (md, txt, docx, odt)");
}

std::optional<DocumentFormat> document_format_for(const std::filesystem::path& path) {
    auto ext = path.extension().string();
    if (ext.empty()) return std::nullopt;
    auto f = parse_document_format(std::string_view(ext).substr(1));
    if (!f) return std::nullopt;
    return *f;
}

std::string_view document_format_name(DocumentFormat format) {
    switch (format) {
        case DocumentFormat::markdown: return "md";
        case DocumentFormat::text: return "txt";
        case DocumentFormat::docx: return "docx";
        case DocumentFormat::odt: return "odt";
    }
    return "md";
}

Result<std::vector<std::string>> save_document(const document::Document& document, DocumentFormat format,
                                               const std::filesystem::path& path) {
    if (format == DocumentFormat::docx) return write_office_file(document, OfficeFormat::docx, path);
    if (format == DocumentFormat::odt) return write_office_file(document, OfficeFormat::odt, path);
    const auto utf8 = format == DocumentFormat::markdown ? to_markdown(document) : to_text(document);
    auto bytes = encode_text(utf8, document.encoding, document.byte_order_mark);
    if (!bytes) return std::unexpected(bytes.error());
    if (auto written = write_file_atomic(path, *bytes); !written) return std::unexpected(written.error());
    return print_losses(document, format);
}

}  // namespace tactus::exporter
