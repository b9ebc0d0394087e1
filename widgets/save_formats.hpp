// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The formats Save and Save As write: the print formats (Markdown, text,
// DOCX, ODT: a file opened in one is saved in it again) and the braille ones
// (BRF, PEF: exported from the pages, the document's own file unchanged).
#include <QString>
#include <QStringList>

namespace tactus::gui {

// True when Save writes this file in place: its format is a print format
// Tactus writes (exporter::document_format_for).
bool saved_in_place(const QString& path);

// True for a braille format (exported, not saved).
bool is_braille_export(const QString& path);

// The Save As dialog's filters, print formats first, and the one for `path`.
QStringList save_as_filters();
QString save_as_filter_for(const QString& path);

// `path` with the extension of the filter chosen when it has none.
QString with_filter_suffix(const QString& path, const QString& filter);

}  // namespace tactus::gui
