// SPDX-License-Identifier: GPL-3.0-or-later
#include "export/picture_size.hpp"

#include <cctype>
#include <charconv>
#include <cstdint>

namespace tactus::exporter {

namespace {

std::uint32_t big_endian(std::string_view b, std::size_t at, std::size_t bytes) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < bytes; ++k) v = (v << 8) | static_cast<unsigned char>(b[at + k]);
    return v;
}

std::optional<PixelSize> sized(double width, double height) {
    if (!(width > 0) || !(height > 0)) return std::nullopt;
    return PixelSize{width, height};
}

// The signature, then IHDR first (PNG's rule): width and height, 4 bytes each.
std::optional<PixelSize> png_size(std::string_view b) {
    if (b.size() < 24 || !b.starts_with("\x89PNG\r\n\x1a\n") || b.substr(12, 4) != "IHDR") return std::nullopt;
    return sized(big_endian(b, 16, 4), big_endian(b, 20, 4));
}

// The markers up to the first start-of-frame (SOF0..SOF15 but DHT C4, JPG
// C8, DAC CC): its height and width follow the sample precision.
std::optional<PixelSize> jpeg_size(std::string_view b) {
    if (!b.starts_with("\xff\xd8")) return std::nullopt;
    std::size_t at = 2;
    while (at + 4 <= b.size()) {
        if (static_cast<unsigned char>(b[at]) != 0xff) return std::nullopt;
        const auto marker = static_cast<unsigned char>(b[at + 1]);
        if (marker == 0xff) {  // fill byte
            ++at;
            continue;
        }
        if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd7)) {  // no length
            at += 2;
            continue;
        }
        const auto length = big_endian(b, at + 2, 2);
        if (marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc) {
            if (at + 9 > b.size()) return std::nullopt;
            return sized(big_endian(b, at + 7, 2), big_endian(b, at + 5, 2));
        }
        if (marker == 0xda || marker == 0xd9 || length < 2) return std::nullopt;  // scan data, end: no frame
        at += 2 + length;
    }
    return std::nullopt;
}

// The attribute `name`'s value in the tag text `tag` (name="v" or name='v').
std::optional<std::string_view> attribute(std::string_view tag, std::string_view name) {
    for (std::size_t at = tag.find(name); at != std::string_view::npos; at = tag.find(name, at + 1)) {
        if (at == 0 || !std::isspace(static_cast<unsigned char>(tag[at - 1]))) continue;
        std::size_t k = at + name.size();
        while (k < tag.size() && std::isspace(static_cast<unsigned char>(tag[k]))) ++k;
        if (k >= tag.size() || tag[k] != '=') continue;
        ++k;
        while (k < tag.size() && std::isspace(static_cast<unsigned char>(tag[k]))) ++k;
        if (k >= tag.size() || (tag[k] != '"' && tag[k] != '\'')) continue;
        const auto end = tag.find(tag[k], k + 1);
        if (end == std::string_view::npos) return std::nullopt;
        return tag.substr(k + 1, end - k - 1);
    }
    return std::nullopt;
}

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

// A length in pixels (CSS's units: 96 px to the inch), nothing for a
// percentage, "auto" or anything not a number.
std::optional<double> length_px(std::string_view text) {
    text = trimmed(text);
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc{}) return std::nullopt;
    const std::string_view unit = trimmed(text.substr(static_cast<std::size_t>(end - text.data())));
    if (unit.empty() || unit == "px") return value;
    if (unit == "in") return value * 96;
    if (unit == "cm") return value * 96 / 2.54;
    if (unit == "mm") return value * 96 / 25.4;
    if (unit == "pt") return value * 96 / 72;
    if (unit == "pc") return value * 16;
    return std::nullopt;
}

std::optional<PixelSize> svg_size(std::string_view b) {
    std::size_t at = 0;
    for (at = b.find("<svg"); at != std::string_view::npos; at = b.find("<svg", at + 1))
        if (at + 4 < b.size() && (std::isspace(static_cast<unsigned char>(b[at + 4])) || b[at + 4] == '>')) break;
    if (at == std::string_view::npos) return std::nullopt;
    const auto close = b.find('>', at);
    const auto tag = b.substr(at + 4, close == std::string_view::npos ? std::string_view::npos : close - at - 4);
    const auto length = [&](std::string_view name) -> std::optional<double> {
        const auto value = attribute(tag, name);
        return value ? length_px(*value) : std::nullopt;
    };
    const auto width = length("width");
    const auto height = length("height");
    if (width && height) return sized(*width, *height);
    // viewBox="min-x min-y width height", commas or spaces between.
    double box[4] = {0, 0, 0, 0};
    if (auto view = attribute(tag, "viewBox")) {
        std::string_view v = *view;
        for (double& n : box) {
            while (!v.empty() && (std::isspace(static_cast<unsigned char>(v.front())) || v.front() == ',')) v.remove_prefix(1);
            const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
            if (ec != std::errc{}) return std::nullopt;
            v.remove_prefix(static_cast<std::size_t>(end - v.data()));
        }
    } else {
        return std::nullopt;
    }
    if (!(box[2] > 0) || !(box[3] > 0)) return std::nullopt;
    if (width) return sized(*width, *width * box[3] / box[2]);
    if (height) return sized(*height * box[2] / box[3], *height);
    return sized(box[2], box[3]);
}

}  // namespace

std::optional<PixelSize> picture_pixel_size(std::string_view bytes, std::string_view media_type) {
    if (media_type == "image/png") return png_size(bytes);
    if (media_type == "image/jpeg") return jpeg_size(bytes);
    if (media_type == "image/svg+xml") return svg_size(bytes);
    return std::nullopt;
}

}  // namespace tactus::exporter
