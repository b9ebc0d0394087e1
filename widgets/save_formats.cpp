// SPDX-License-Identifier: GPL-3.0-or-later
#include "save_formats.hpp"

#include <QCoreApplication>
#include <QFileInfo>

#include "export/document_save.hpp"

namespace tactus::gui {
namespace {

struct Format {
    const char* name;  // translated in the "SaveFormats" context
    const char* suffix;
};

constexpr Format kFormats[] = {
    {QT_TRANSLATE_NOOP("SaveFormats", "Markdown (*.md)"), "md"},
    {QT_TRANSLATE_NOOP("SaveFormats", "Plain text (*.txt)"), "txt"},
    {QT_TRANSLATE_NOOP("SaveFormats", "Word document (*.docx)"), "docx"},
    {QT_TRANSLATE_NOOP("SaveFormats", "OpenDocument text (*.odt)"), "odt"},
    {QT_TRANSLATE_NOOP("SaveFormats", "Braille ASCII (*.brf)"), "brf"},
    {QT_TRANSLATE_NOOP("SaveFormats", "PEF braille (*.pef)"), "pef"},
};

QString filter_name(const Format& f) { return QCoreApplication::translate("SaveFormats", f.name); }

}  // namespace

bool saved_in_place(const QString& path) {
    return exporter::document_format_for(path.toStdString()).has_value();
}

bool is_braille_export(const QString& path) {
    const auto suffix = QFileInfo(path).suffix().toLower();
    return suffix == QLatin1String("brf") || suffix == QLatin1String("pef");
}

QStringList save_as_filters() {
    QStringList out;
    for (const auto& f : kFormats) out << filter_name(f);
    return out;
}

QString save_as_filter_for(const QString& path) {
    const auto suffix = QFileInfo(path).suffix().toLower();
    for (const auto& f : kFormats)
        if (suffix == QLatin1String(f.suffix) || (suffix == QLatin1String("markdown") && f.suffix == std::string_view("md")) ||
            (suffix == QLatin1String("text") && f.suffix == std::string_view("txt")))
            return filter_name(f);
    return filter_name(kFormats[0]);
}

QString with_filter_suffix(const QString& path, const QString& filter) {
    if (!QFileInfo(path).suffix().isEmpty()) return path;
    for (const auto& f : kFormats)
        if (filter == filter_name(f)) return path + QLatin1Char('.') + QLatin1String(f.suffix);
    return path + QStringLiteral(".md");
}

}  // namespace tactus::gui
