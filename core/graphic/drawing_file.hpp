// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A drawing file (.svg, or a .png/.jpg picture traced) read and laid out as
// braille pages for a machine: what `tactus-cli layout/plan/emboss drawing.svg`
// and the app's File > Open both do, so the two place the same dots.
#include <filesystem>
#include <functional>
#include <memory>

#include "common/result.hpp"
#include "document/document.hpp"
#include "graphic/graphic_page.hpp"
#include "machine/firmware_tables.hpp"
#include "profile/profile.hpp"

namespace tactus::graphic {

enum class DrawingKind : unsigned char { none, svg, picture };

// What a file is by its name: an SVG drawing, a picture to trace, or neither.
DrawingKind drawing_kind(const std::filesystem::path& path);

struct DrawingFileOptions {
    // A picture's ink threshold (TraceOptions::threshold; -1: Otsu's).
    int image_threshold = -1;
    // The firmware's grid the dots are rounded to; without it, the grid of the
    // reference firmware's tables made from the profile (the `sim` device and
    // the source embosser), unless `legacy_protocol` (one motor step instead).
    const machine::FirmwareTables* firmware = nullptr;
    bool legacy_protocol = false;
};

// Reads `path` as `kind` and lays it out on `machine`'s page in `geometry`,
// its labels in `table`'s braille.
Result<GraphicLayout> lay_out_drawing_file(const std::filesystem::path& path, DrawingKind kind,
                                           const profile::PrinterProfile& machine,
                                           const layout::PageGeometry& geometry, const translate::Translator& table,
                                           const DrawingFileOptions& options = {});

// A picture a document holds (document::Block::images: PNG, JPEG or SVG bytes)
// laid out as lay_out_drawing_file lays out the same file: the same dots.
Result<GraphicLayout> lay_out_picture(const document::Image& image, const profile::PrinterProfile& machine,
                                      const layout::PageGeometry& geometry, const translate::Translator& table,
                                      const DrawingFileOptions& options = {});

// A document's pictures as graphic pages, the callback the pipeline takes
// (pipeline::PipelineOptions::graphic_pages): each picture laid out by
// lay_out_picture on `machine`'s page in `geometry`, its labels in `table`'s
// braille. The CLI's `--images graphics` and the app's "Emboss Pictures as
// Graphics" both lay pictures out with it.
std::function<Result<layout::PagedDocument>(const document::Image&)> picture_pages(
    std::shared_ptr<const translate::Translator> table, profile::PrinterProfile machine, layout::PageGeometry geometry,
    DrawingFileOptions options = {});

}  // namespace tactus::graphic
