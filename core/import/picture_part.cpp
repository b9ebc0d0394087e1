// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/picture_part.hpp"

#include <algorithm>
#include <cctype>

#include "common/file_io.hpp"
#include "import/import.hpp"

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
    return "picture " + std::string(name) + ": " + std::string(unsupported_picture_reason) + "; its description stays";
}

std::optional<document::Image> picture_file(const std::filesystem::path& folder, std::string_view src,
                                            std::string& why) {
    if (src.empty()) return std::nullopt;
    if (src.find(':') != std::string_view::npos || src.starts_with('/') || src.starts_with('\\')) {
        why = "not a file beside the document (a URL or an absolute path)";
        return std::nullopt;
    }
    std::error_code ec;
    const auto base = std::filesystem::weakly_canonical(folder, ec);
    const auto file = std::filesystem::weakly_canonical(folder / std::filesystem::path(src), ec);
    const auto inside = file.lexically_relative(base);
    if (ec || inside.empty() || *inside.begin() == "..") {
        why = "outside the document's folder, so it is not read";
        return std::nullopt;
    }
    auto bytes = read_file(file, max_import_bytes);
    if (!bytes) {
        why = bytes.error().message;
        return std::nullopt;
    }
    auto type = picture_media_type(*bytes, src);
    if (type.empty()) {
        why = std::string(unsupported_picture_reason);
        return std::nullopt;
    }
    return document::Image{std::move(*bytes), std::move(type), std::string(src)};
}

}  // namespace tactus::import::detail
