// SPDX-License-Identifier: GPL-3.0-or-later
#include "export/export.hpp"

namespace tactus {

Result<std::string> to_brf(const PagedDocument& doc) {
    std::string out;
    out.reserve(doc.pages.size() * static_cast<std::size_t>(doc.geometry.lines_per_page) *
                (static_cast<std::size_t>(doc.geometry.cells_per_line) / 2 + 2));
    for (const auto& page : doc.pages) {
        // Lines up to the last non-empty one; the form feed ends the page.
        std::size_t used = page.lines.size();
        while (used > 0 && page.lines[used - 1].empty()) --used;
        for (std::size_t i = 0; i < used; ++i) {
            for (Cell c : page.lines[i]) {
                if (c.dots & 0xC0)
                    return fail("8-dot cell cannot be written as BRF (6-dot only); use PEF",
                                "page " + std::to_string(page.braille_number) + " line " +
                                    std::to_string(i + 1));
                out.push_back(cell_to_brf(c));
            }
            out += "\r\n";
        }
        out.push_back('\f');
    }
    return out;
}

std::string to_unicode(const PagedDocument& doc) {
    std::string out;
    for (std::size_t p = 0; p < doc.pages.size(); ++p) {
        if (p > 0) out += "\f";
        const auto& page = doc.pages[p];
        std::size_t used = page.lines.size();
        while (used > 0 && page.lines[used - 1].empty()) --used;
        for (std::size_t i = 0; i < used; ++i) {
            out += to_unicode_text(page.lines[i]);
            out += '\n';
        }
    }
    return out;
}

Result<ExportFormat> parse_export_format(std::string_view s) {
    if (s == "brf") return ExportFormat::brf;
    if (s == "pef") return ExportFormat::pef;
    if (s == "unicode" || s == "txt") return ExportFormat::unicode;
    return fail("unknown output format '" + std::string(s) + "' (brf, pef, unicode)", "--to");
}

Result<std::string> export_document(const PagedDocument& doc, ExportFormat format,
                                    const PefMetadata& meta) {
    switch (format) {
        case ExportFormat::brf: return to_brf(doc);
        case ExportFormat::pef: return to_pef(doc, meta);
        case ExportFormat::unicode: return to_unicode(doc);
    }
    return fail("unsupported export format");
}

}  // namespace tactus
