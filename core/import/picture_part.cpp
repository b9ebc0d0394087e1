// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/picture_part.hpp"

#include <algorithm>
#include <cctype>

namespace tactus::import::detail {

namespace {

bool ends_with_no_case(std::string_view name, std::string_view suffix) {
    if (name.size() < suffix.size()) return false;
    return std::equal(suffix.begin(), suffix.end(), name.end() - static_cast<std::ptrdiff_t>(suffix.size()),
                      [](char a, char b) {
                          return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
                      });
}

}  // namespace

std::string picture_media_type(std::string_view bytes, std::string_view name) {
    if (bytes.starts_with("\x89PNG\r\n\x1a\n")) return "image/png";
    if (bytes.starts_with("\xff\xd8\xff")) return "image/jpeg";
    if (ends_with_no_case(name, ".svg")) return "image/svg+xml";
    return {};
}

std::string unsupported_picture_warning(std::string_view name) {
    return "picture " + std::string(name) +
           ": not PNG, JPEG or SVG, so it cannot be embossed as a graphic; its description stays";
}

}  // namespace tactus::import::detail
