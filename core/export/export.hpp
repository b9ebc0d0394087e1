// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Paged braille to the formats embossers and braille readers take.
#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "layout/page.hpp"

namespace tactus::exporter {

enum class ExportFormat { brf, pef, unicode };

Result<ExportFormat> parse_export_format(std::string_view);

struct PefMetadata {
    std::string title = "Untitled";
    std::string identifier;  // empty: derived from the content
    std::string language;    // BCP 47, e.g. "en" or "zh-TW"; empty: omitted
    std::string date;        // YYYY-MM-DD; empty: omitted
    // The dc: elements of a source PEF, in its order: when present they are
    // written as they are instead of the fields above, so metadata survives a
    // round trip (dc:format is always application/x-pef+xml).
    std::vector<document::MetadataItem> source;
};

// The metadata to write: the source's own (a PEF's dc: elements) when it has
// any besides its main language, else a title and date made for this export.
// `language` (BCP 47, translate::table_language_tag) is written when the
// source has no metadata of its own. The CLI and the app both ask here.
PefMetadata pef_metadata(const std::vector<document::MetadataItem>& source, std::string title, std::string date,
                         std::string language = {});

// Braille ASCII: CRLF after every line, a form feed after every page (blank
// backs included, so an interpoint embosser stays in step). Fails on dots 7-8,
// which BRF cannot carry, naming the page and line.
Result<std::string> to_brf(const layout::PagedDocument& doc);

// PEF 2008-1: one volume of one section with the geometry's page and duplex,
// or the source's volumes and sections (ready-made braille,
// layout::PageSection), each with its own cols, rows, rowgap and duplex: a
// volume's are its first section's, a section that differs carries its own.
Result<std::string> to_pef(const layout::PagedDocument& doc, const PefMetadata& meta = {});

// Unicode braille text: LF line ends, a form feed between pages.
std::string to_unicode(const layout::PagedDocument& doc);

Result<std::string> export_document(const layout::PagedDocument& doc, ExportFormat format,
                                    const PefMetadata& meta = {});

// Streaming forms: a book is written without holding its output in memory.
Result<void> write_brf(const layout::PagedDocument& doc, std::ostream& out);
Result<void> write_pef(const layout::PagedDocument& doc, const PefMetadata& meta, std::ostream& out);
void write_unicode(const layout::PagedDocument& doc, std::ostream& out);
Result<void> write_document(const layout::PagedDocument& doc, ExportFormat format, const PefMetadata& meta,
                            std::ostream& out);
// Atomically (temporary file, fsync, rename).
Result<void> export_to_file(const layout::PagedDocument& doc, ExportFormat format, const PefMetadata& meta,
                            const std::filesystem::path& path);

}  // namespace tactus::exporter
