// SPDX-License-Identifier: GPL-3.0-or-later
#include "graphic/drawing_file.hpp"

#include <optional>

#include "graphic/raster_image.hpp"
#include "graphic/raster_trace.hpp"
#include "graphic/svg_import.hpp"
#include "profile/firmware_tables.hpp"

namespace tactus::graphic {

DrawingKind drawing_kind(const std::filesystem::path& path) {
    if (is_svg_path(path)) return DrawingKind::svg;
    if (is_raster_path(path)) return DrawingKind::picture;
    return DrawingKind::none;
}

Result<GraphicLayout> lay_out_drawing_file(const std::filesystem::path& path, DrawingKind kind,
                                           const profile::PrinterProfile& machine,
                                           const layout::PageGeometry& geometry, const translate::Translator& table,
                                           const DrawingFileOptions& options) {
    if (kind == DrawingKind::none)
        return fail(ErrorKind::usage, "not a drawing: expected an .svg, .png, .jpg or .jpeg file", path.string());
    std::optional<machine::FirmwareTables> made;
    const machine::FirmwareTables* grid = options.firmware;
    if (!grid && !options.legacy_protocol)
        if (auto tables = profile::make_firmware_tables(machine)) {
            made = std::move(*tables);
            grid = &*made;
        }
    const auto dots = dot_options(machine, grid);
    Result<Drawing> drawing = fail(ErrorKind::internal, "not read");
    if (kind == DrawingKind::svg) {
        drawing = load_svg(path);
    } else {
        TraceOptions trace;
        trace.threshold = options.image_threshold;
        trace.simplify_mm = simplify_tolerance_mm(dots);
        drawing = load_image(path, trace);
    }
    if (!drawing) return std::unexpected(drawing.error());
    return lay_out_drawing(*drawing, machine, geometry, table, dots);
}

}  // namespace tactus::graphic
