// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A picture a document holds, as the graphic stage can read it: PNG, JPEG or
// SVG, told by its first bytes (SVG by its name); anything else (EMF, WMF,
// GIF, TIFF ...) keeps only its description.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "document/document.hpp"

namespace tactus::import::detail {

// "image/png", "image/jpeg", "image/svg+xml", or "" for a type a graphic cannot be made of.
std::string picture_media_type(std::string_view bytes, std::string_view name);

// The warning for a picture of a type a graphic cannot be made of, naming it.
std::string unsupported_picture_warning(std::string_view name);

// A picture file a document names (Markdown's ![](src), HTML's <img src>),
// read relative to the document's `folder`: nothing, with `why` set, for a
// URL, an absolute path, a path that leaves the folder, an unreadable file
// or a type a graphic cannot be made of.
std::optional<document::Image> picture_file(const std::filesystem::path& folder, std::string_view src,
                                            std::string& why);

// The reason a picture's bytes of type `name` cannot be a graphic.
inline constexpr std::string_view unsupported_picture_reason =
    "not PNG, JPEG or SVG, so it cannot be embossed as a graphic";

}  // namespace tactus::import::detail
