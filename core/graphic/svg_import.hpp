// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// SVG -> Drawing: the shapes, strokes, fills and <text> labels of an SVG 1.1
// (or SVG 2) file, as geometry in millimetres (docs/graphics.md). Read with
// pugixml and this stage's own attribute parsers (svg_syntax.hpp): Tactus
// needs the geometry, not pixels. What is not read (images, <use>, style
// sheets, clipping, markers...) is named in Drawing::warnings, never dropped
// silently. Malformed SVG is an ErrorKind::input error saying what and where.
#include <filesystem>
#include <string_view>

#include "common/result.hpp"
#include "graphic/drawing.hpp"

namespace tactus::graphic {

Result<Drawing> read_svg(std::string_view bytes);
Result<Drawing> load_svg(const std::filesystem::path& path);

// True when the file's name says SVG (.svg, any case).
bool is_svg_path(const std::filesystem::path& path);

}  // namespace tactus::graphic
