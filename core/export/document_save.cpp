// SPDX-License-Identifier: GPL-3.0-or-later
#include "export/document_save.hpp"

#include <algorithm>

#include "common/file_io.hpp"
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
    return std::vector<std::string>{};
}

}  // namespace tactus::exporter
