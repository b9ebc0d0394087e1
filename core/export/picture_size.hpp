// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The size a picture gives itself, read from its header alone (nothing is
// decoded): PNG's IHDR, JPEG's start-of-frame, SVG's root width and height.
// The office writers size a picture by it (office_common.hpp, picture_extent).
#include <optional>
#include <string_view>

namespace tactus::exporter {

// In CSS pixels, 96 to the inch.
struct PixelSize {
    double width = 0;
    double height = 0;
};

// `media_type` as document::Image holds it ("image/png", "image/jpeg",
// "image/svg+xml"). An SVG's width and height may be in px, pt, pc, mm, cm or
// in; a percentage or a missing one is taken from the viewBox (its units
// as pixels), keeping its shape. Nothing when the bytes do not say, or say
// a size of zero.
std::optional<PixelSize> picture_pixel_size(std::string_view bytes, std::string_view media_type);

}  // namespace tactus::exporter
