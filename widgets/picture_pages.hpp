// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The document's pictures embossed as graphic pages, as `tactus-cli layout
// --images graphics` lays them out: the editor's document (its pictures'
// bytes with it) through the pipeline with the core's picture stage
// (graphic::picture_pages), on the machine's page. "Emboss Pictures as
// Graphics" in the app's File menu; docs/graphics.md, "Pictures in documents".
#include <QString>
#include <optional>

#include "common/result.hpp"
#include "edit/live_layout.hpp"
#include "layout/page.hpp"
#include "profile/profile.hpp"

namespace tactus::gui {

// How the app lays out a document's pictures: the CLI's --images choices.
enum class PictureChoice { descriptions, graphics };

// "descriptions", "graphics": the CLI's names, as the setting is stored.
PictureChoice picture_choice_named(const QString& name);
QString picture_choice_name(PictureChoice choice);

// The document's pages with each picture a graphic page after its block;
// nothing when the document holds no picture (its pages are the editor's).
std::optional<Result<layout::PagedDocument>> lay_out_with_pictures(const edit::LiveLayout& layout,
                                                                   const profile::PrinterProfile& machine);

}  // namespace tactus::gui
