// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The print formats a document is saved in (beside the braille ones,
// export.hpp): Markdown, plain text, DOCX and ODT. One place says which file
// name means which format, for the CLI's convert and the app's Save.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"

namespace tactus::exporter {

enum class DocumentFormat { markdown, text, docx, odt };

// By extension, case-insensitive: .md/.markdown, .txt, .docx, .odt; none for
// any other (a braille format, an input-only one).
std::optional<DocumentFormat> document_format_for(const std::filesystem::path& path);
// "md"/"markdown", "txt"/"text", "docx", "odt".
Result<DocumentFormat> parse_document_format(std::string_view name);
std::string_view document_format_name(DocumentFormat format);

// The document in `format`, written atomically (a failure leaves the old
// file). Markdown and text are written in the document's own encoding
// (Document::encoding, UTF-8 when empty). Gives the warnings: what the format
// does not keep (Markdown: boxes, underline, raised text, an image's
// description as such, languages, the pictures; text: every style and the
// pictures).
Result<std::vector<std::string>> save_document(const document::Document& document, DocumentFormat format,
                                               const std::filesystem::path& path);

}  // namespace tactus::exporter
