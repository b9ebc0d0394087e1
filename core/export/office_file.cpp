// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/file_io.hpp"
#include "export/office_export.hpp"

namespace tactus::exporter {

Result<OfficeFile> to_office(const document::Document& document, OfficeFormat format) {
    return format == OfficeFormat::docx ? to_docx(document) : to_odt(document);
}

Result<std::vector<std::string>> write_office_file(const document::Document& document, OfficeFormat format,
                                                   const std::filesystem::path& path) {
    auto file = to_office(document, format);
    if (!file) return std::unexpected(file.error());
    if (auto written = write_file_atomic(path, file->bytes); !written) return std::unexpected(written.error());
    return std::move(file->warnings);
}

}  // namespace tactus::exporter
