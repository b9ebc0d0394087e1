// SPDX-License-Identifier: GPL-3.0-or-later
#include <sstream>

#include "common/file_io.hpp"
#include "export/export.hpp"
#include "common/try.hpp"

namespace tactus::exporter {
namespace {

std::size_t used_lines(const layout::Page& page) {
    std::size_t used = page.lines.size();
    while (used > 0 && page.lines[used - 1].empty()) --used;
    return used;
}

}  // namespace

Result<void> write_brf(const layout::PagedDocument& doc, std::ostream& out) {
    std::string line;
    for (const auto& page : doc.pages) {
        // Lines up to the last non-empty one; the form feed ends the page.
        const auto used = used_lines(page);
        for (std::size_t i = 0; i < used; ++i) {
            line.clear();
            for (document::Cell c : page.lines[i]) {
                if (c.dots & 0xC0)
                    return fail(ErrorKind::input, "8-dot cell cannot be written as BRF (6-dot only); use PEF",
                                "page " + std::to_string(page.braille_number) + " line " +
                                    std::to_string(i + 1));
                line.push_back(document::cell_to_brf(c));
            }
            line += "\r\n";
            out << line;
        }
        out << '\f';
    }
    return {};
}

void write_unicode(const layout::PagedDocument& doc, std::ostream& out) {
    for (std::size_t p = 0; p < doc.pages.size(); ++p) {
        if (p > 0) out << '\f';
        const auto& page = doc.pages[p];
        const auto used = used_lines(page);
        for (std::size_t i = 0; i < used; ++i) out << document::to_unicode_text(page.lines[i]) << '\n';
    }
}

Result<std::string> to_brf(const layout::PagedDocument& doc) {
    std::ostringstream out;
    TACTUS_TRY_VOID(write_brf(doc, out));
    return std::move(out).str();
}

std::string to_unicode(const layout::PagedDocument& doc) {
    std::ostringstream out;
    write_unicode(doc, out);
    return std::move(out).str();
}

Result<ExportFormat> parse_export_format(std::string_view s) {
    if (s == "brf") return ExportFormat::brf;
    if (s == "pef") return ExportFormat::pef;
    if (s == "unicode" || s == "txt") return ExportFormat::unicode;
    return fail(ErrorKind::usage, "unknown output format '" + std::string(s) + "' (brf, pef, unicode)", "--to");
}

Result<void> write_document(const layout::PagedDocument& doc, ExportFormat format, const PefMetadata& meta,
                            std::ostream& out) {
    // BRF, PEF and Unicode braille hold cells on a grid; a graphic's dots
    // stand anywhere, so writing the page would silently drop the drawing.
    for (std::size_t i = 0; i < doc.pages.size(); ++i)
        if (!doc.pages[i].graphic.empty())
            return fail(ErrorKind::input, "is a tactile graphic (" + std::to_string(doc.pages[i].graphic.size()) +
                            " dots placed freely), which BRF, PEF and Unicode braille cannot hold: "
                            "emboss it, or plan it (tactus-cli plan)",
                        "page " + std::to_string(i + 1));
    switch (format) {
        case ExportFormat::brf: return write_brf(doc, out);
        case ExportFormat::pef: return write_pef(doc, meta, out);
        case ExportFormat::unicode: write_unicode(doc, out); return {};
    }
    return fail(ErrorKind::internal, "unsupported export format");
}

Result<std::string> export_document(const layout::PagedDocument& doc, ExportFormat format,
                                    const PefMetadata& meta) {
    std::ostringstream out;
    TACTUS_TRY_VOID(write_document(doc, format, meta, out));
    return std::move(out).str();
}

Result<void> export_to_file(const layout::PagedDocument& doc, ExportFormat format, const PefMetadata& meta,
                            const std::filesystem::path& path) {
    return write_file_atomic(path, [&](std::ostream& out) { return write_document(doc, format, meta, out); });
}

}  // namespace tactus::exporter
