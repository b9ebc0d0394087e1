// SPDX-License-Identifier: GPL-3.0-or-later
#include "graphic/drawing_file.hpp"

#include <optional>

#include "graphic/raster_image.hpp"
#include "graphic/raster_trace.hpp"
#include "graphic/svg_import.hpp"
#include "common/try.hpp"
#include "profile/firmware_tables.hpp"

namespace tactus::graphic {

DrawingKind drawing_kind(const std::filesystem::path& path) {
    if (is_svg_path(path)) return DrawingKind::svg;
    if (is_raster_path(path)) return DrawingKind::picture;
    return DrawingKind::none;
}

namespace {

// Reads a drawing with `read` (given the trace options a picture needs) and
// lays it out: the one place that picks the grid the dots are rounded to.
template <typename Read>
Result<GraphicLayout> read_and_lay_out(Read read, const profile::PrinterProfile& machine,
                                       const layout::PageGeometry& geometry, const translate::Translator& table,
                                       const DrawingFileOptions& options) {
    std::optional<machine::FirmwareTables> made;
    const machine::FirmwareTables* grid = options.firmware;
    if (!grid && !options.legacy_protocol)
        if (auto tables = profile::make_firmware_tables(machine)) {
            made = std::move(*tables);
            grid = &*made;
        }
    const auto dots = dot_options(machine, grid);
    TraceOptions trace;
    trace.threshold = options.image_threshold;
    trace.simplify_mm = simplify_tolerance_mm(dots);
    Result<Drawing> drawing = read(trace);
    if (!drawing) return std::unexpected(drawing.error());
    return lay_out_drawing(*drawing, machine, geometry, table, dots);
}

}  // namespace

Result<GraphicLayout> lay_out_drawing_file(const std::filesystem::path& path, DrawingKind kind,
                                           const profile::PrinterProfile& machine,
                                           const layout::PageGeometry& geometry, const translate::Translator& table,
                                           const DrawingFileOptions& options) {
    if (kind == DrawingKind::none)
        return fail(ErrorKind::usage, "not a drawing: expected an .svg, .png, .jpg or .jpeg file", path.string());
    return read_and_lay_out(
        [&](const TraceOptions& trace) { return kind == DrawingKind::svg ? load_svg(path) : load_image(path, trace); },
        machine, geometry, table, options);
}

Result<GraphicLayout> lay_out_picture(const document::Image& image, const profile::PrinterProfile& machine,
                                      const layout::PageGeometry& geometry, const translate::Translator& table,
                                      const DrawingFileOptions& options) {
    const bool svg = image.media_type == "image/svg+xml";
    if (!svg && image.media_type != "image/png" && image.media_type != "image/jpeg")
        return fail(ErrorKind::input, "a " + image.media_type + " picture cannot be made a graphic", image.name);
    return read_and_lay_out(
        [&](const TraceOptions& trace) -> Result<Drawing> {
            if (svg) return read_svg(image.bytes);
            TACTUS_TRY(grey, read_raster(image.bytes));
            return trace_image(grey, trace);
        },
        machine, geometry, table, options);
}

std::function<Result<layout::PagedDocument>(const document::Image&)> picture_pages(
    std::shared_ptr<const translate::Translator> table, profile::PrinterProfile machine, layout::PageGeometry geometry,
    DrawingFileOptions options) {
    return [table = std::move(table), machine = std::move(machine), geometry, options](
               const document::Image& image) -> Result<layout::PagedDocument> {
        auto pictured = lay_out_picture(image, machine, geometry, *table, options);
        if (!pictured) return std::unexpected(pictured.error());
        return std::move(pictured->document);
    };
}

}  // namespace tactus::graphic
