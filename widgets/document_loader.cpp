// SPDX-License-Identifier: GPL-3.0-or-later
#include "document_loader.hpp"

#include <QFileInfo>
#include <QCoreApplication>
#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>

#include "edit/editor_lines.hpp"
#include "graphic/drawing_file.hpp"
#include "import/import.hpp"
#include "import/text_lines.hpp"

namespace tactus::gui {
namespace {

constexpr int kImportShare = 10;  // percent of the progress bar for reading the file

LoadResultPtr build(std::vector<std::string> lines, const std::string& tables, const layout::LayoutOptions& options,
                    edit::Dialect dialect, const std::function<bool(int)>& progress,
                    edit::BrailleStructure structure = {}) {
    auto result = std::make_shared<LoadResult>();
    auto layout = edit::LiveLayout::create(tables, options);
    if (!layout) {
        result->error = layout.error();
        return result;
    }
    layout->set_dialect(dialect);
    const bool done = layout->reset(std::move(lines), [&](std::size_t i, std::size_t n) {
        const int pct = kImportShare + static_cast<int>((100 - kImportShare) * (n ? static_cast<double>(i) / static_cast<double>(n) : 1.0));
        return progress ? progress(pct) : false;
    }, std::move(structure));
    if (!done) {
        result->cancelled = true;
        return result;
    }
    result->layout = std::move(*layout);
    return result;
}

// A text file is shown as its own lines, byte for byte (a hard-wrapped
// paragraph's lines, blank lines with their spaces, form feeds where they
// are), and saved with its line end.
LoadResultPtr load_text(const QString& path, const std::string& tables, const layout::LayoutOptions& options,
                        const std::function<bool(int)>& progress) {
    auto text = import::read_text_file(path.toStdString());
    if (!text) {
        auto r = std::make_shared<LoadResult>();
        r->error = text.error();
        r->path = path;
        return r;
    }
    auto r = build(import::split_text_lines(text->text), tables, options, edit::Dialect::text, progress);
    if (r->layout) {
        r->layout->set_line_ending(import::line_ending_of(text->text));
        r->layout->set_encoding(text->encoding, text->byte_order_mark);  // saved in it again
    }
    r->path = path;
    return r;
}

// A drawing: its pages from the core (the CLI's function), and the print
// pane's lines saying what it is, in the text dialect (read, not edited).
LoadResultPtr load_drawing(const QString& path, graphic::DrawingKind kind, const std::string& tables,
                           const layout::LayoutOptions& options, const profile::PrinterProfile& machine,
                           const std::function<bool(int)>& progress) {
    const auto failed = [&path](Error e) {
        auto r = std::make_shared<LoadResult>();
        r->error = std::move(e);
        r->path = path;
        return r;
    };
    auto table = translate::Translator::open(tables);
    if (!table) return failed(table.error());
    auto laid = graphic::lay_out_drawing_file(path.toStdString(), kind, machine, options.geometry, *table);
    if (!laid) return failed(laid.error());
    GraphicView view;
    view.title = QString::fromStdString(laid->placed.title).simplified();
    if (view.title.isEmpty()) view.title = QFileInfo(path).fileName();
    view.description = QString::fromStdString(laid->placed.description).simplified();
    for (const auto& label : laid->placed.labels) view.labels << QString::fromStdString(label.text);
    for (const auto& page : laid->document.pages) view.dots += page.graphic.size();
    view.paged = std::move(laid->document);
    std::vector<std::string> lines;
    for (const auto& line : view.summary().split(QLatin1Char('\n'))) lines.push_back(line.toStdString());
    auto r = build(std::move(lines), tables, options, edit::Dialect::text, progress);
    r->graphic = std::move(view);
    r->path = path;
    return r;
}

LoadResultPtr load(const QString& path, const std::string& tables, const layout::LayoutOptions& options,
                   const profile::PrinterProfile& machine, const std::function<bool(int)>& progress) {
    if (const auto kind = graphic::drawing_kind(path.toStdString()); kind != graphic::DrawingKind::none)
        return load_drawing(path, kind, tables, options, machine, progress);
    if (edit::dialect_for(path.toStdString()) == edit::Dialect::text) return load_text(path, tables, options, progress);
    // With its pictures, each a mark in its line whose bytes the layout
    // keeps (edit/editor_pictures.hpp), so saving writes them again.
    import::ImportOptions import_options;
    import_options.images = true;
    import_options.picture_marks = true;
    auto doc = import::import_file(path.toStdString(), import_options);
    if (!doc) {
        auto r = std::make_shared<LoadResult>();
        r->error = doc.error();
        r->path = path;
        return r;
    }
    if (progress && progress(kImportShare)) {
        auto r = std::make_shared<LoadResult>();
        r->cancelled = true;
        return r;
    }
    if (import::detect_source_format({}, path.toStdString()) != import::SourceFormat::markdown) edit::number_pictures(*doc);
    edit::PictureStore pictures;
    edit::store_pictures(*doc, pictures);
    // Ready-made braille's sections, volumes, grid and metadata go with its lines (core's one rule).
    auto r = build(edit::render_editor_lines(*doc, edit::Dialect::markdown), tables, options, edit::Dialect::markdown,
                   progress, edit::braille_structure(*doc));
    if (r->layout) r->layout->set_pictures(std::move(pictures));
    // A Markdown file is saved in the encoding it was read in, with its line
    // end, as a text file is (edit::file_bytes); a DOCX, PEF or BRF has neither
    // and is saved as UTF-8 with LF.
    if (r->layout && !doc->encoding.empty()) r->layout->set_encoding(doc->encoding, doc->byte_order_mark);
    if (r->layout && !doc->line_ending.empty()) r->layout->set_line_ending(doc->line_ending);
    r->path = path;
    return r;
}

std::function<bool(int)> reporter(QPromise<LoadResultPtr>& promise) {
    promise.setProgressRange(0, 100);
    return [&promise](int pct) {
        promise.setProgressValue(pct);
        return promise.isCanceled();
    };
}

}  // namespace

QString GraphicView::summary() const {
    QString text = QCoreApplication::translate("tactus::gui::GraphicView", "Graphic: %1.").arg(title);
    if (!description.isEmpty()) text += QLatin1Char(' ') + description;
    if (!labels.isEmpty())
        text += QLatin1Char('\n') +
                QCoreApplication::translate("tactus::gui::GraphicView", "Labels: %1.").arg(labels.join(QStringLiteral("; ")));
    const int count = static_cast<int>(dots);  // lupdate misses a cast inside translate()
    text += QLatin1Char('\n') +
            QCoreApplication::translate("tactus::gui::GraphicView", "%n dot(s).", "on all the graphic's pages", count);
    return text;
}

QFuture<LoadResultPtr> load_file(const QString& path, const std::string& tables, const layout::LayoutOptions& options,
                                 const profile::PrinterProfile& machine) {
    return QtConcurrent::run([path, tables, options, machine](QPromise<LoadResultPtr>& promise) {
        promise.addResult(load(path, tables, options, machine, reporter(promise)));
    });
}

QFuture<LoadResultPtr> lay_out_lines(std::vector<std::string> lines, const std::string& tables,
                                     const layout::LayoutOptions& options, edit::Dialect dialect,
                                     edit::BrailleStructure structure) {
    return QtConcurrent::run([lines = std::move(lines), tables, options, dialect,
                              structure = std::move(structure)](QPromise<LoadResultPtr>& promise) mutable {
        promise.addResult(build(std::move(lines), tables, options, dialect, reporter(promise), std::move(structure)));
    });
}

LoadResultPtr load_file_now(const QString& path, const std::string& tables, const layout::LayoutOptions& options,
                            const profile::PrinterProfile& machine) {
    return load(path, tables, options, machine, {});
}

}  // namespace tactus::gui
