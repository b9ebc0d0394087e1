// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A picture a document holds, as the graphic stage can read it: PNG, JPEG or
// SVG, told by its first bytes (SVG by its name); anything else (EMF, WMF,
// GIF, TIFF ...) keeps only its description.
#include <string>
#include <string_view>

namespace tactus::import::detail {

// "image/png", "image/jpeg", "image/svg+xml", or "" for a type a graphic cannot be made of.
std::string picture_media_type(std::string_view bytes, std::string_view name);

// The warning for a picture of a type a graphic cannot be made of, naming it.
std::string unsupported_picture_warning(std::string_view name);

}  // namespace tactus::import::detail
