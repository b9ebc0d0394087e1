// SPDX-License-Identifier: GPL-3.0-or-later
// The document as a word-processor file: DOCX (WordprocessingML) and ODT
// (OpenDocument text), written so that core's importers read back the same
// blocks (docs/import.md, "Saving DOCX and ODT"). What a format cannot hold
// is named in a warning, never dropped silently.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"

namespace tactus::exporter {

enum class OfficeFormat { docx, odt };

struct OfficeFile {
    std::string bytes;                  // the ZIP package
    std::vector<std::string> warnings;  // what the file does not keep, one line per kind
};

Result<OfficeFile> to_docx(const document::Document& document);
Result<OfficeFile> to_odt(const document::Document& document);
Result<OfficeFile> to_office(const document::Document& document, OfficeFormat format);

// Atomically (temporary file, fsync, rename): a failure leaves the old file.
// Gives the warnings.
Result<std::vector<std::string>> write_office_file(const document::Document& document, OfficeFormat format,
                                                   const std::filesystem::path& path);

}  // namespace tactus::exporter
