// SPDX-License-Identifier: GPL-3.0-or-later
#include "picture_pages.hpp"

#include <QString>
#include <algorithm>
#include <memory>

#include "graphic/drawing_file.hpp"
#include "pipeline/pipeline.hpp"

namespace tactus::gui {

PictureChoice picture_choice_named(const QString& name) {
    return name == QLatin1String("graphics") ? PictureChoice::graphics : PictureChoice::descriptions;
}

QString picture_choice_name(PictureChoice choice) {
    return choice == PictureChoice::graphics ? QStringLiteral("graphics") : QStringLiteral("descriptions");
}

std::optional<Result<layout::PagedDocument>> lay_out_with_pictures(const edit::LiveLayout& layout,
                                                                   const profile::PrinterProfile& machine) {
    const auto document = layout.document();
    if (std::none_of(document.blocks.begin(), document.blocks.end(),
                     [](const document::Block& b) { return !b.images.empty(); }))
        return std::nullopt;
    auto table = translate::Translator::open(layout.tables());
    if (!table) return Result<layout::PagedDocument>(std::unexpected(table.error()));
    pipeline::PipelineOptions options;
    options.tables = layout.tables();
    options.layout = layout.options();
    options.translation_workers = 1;  // the GUI's process is not forked
    options.graphic_pages = graphic::picture_pages(std::make_shared<const translate::Translator>(std::move(*table)),
                                                   machine, options.layout.geometry);
    return pipeline::lay_out(document, options);
}

}  // namespace tactus::gui
