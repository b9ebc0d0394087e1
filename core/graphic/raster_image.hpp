// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// PNG and JPEG files -> a grey image (docs/graphics.md, "Pictures"). Read
// with libpng and libjpeg (Debian's libpng16 and libjpeg62-turbo); colour is
// turned to luminance and transparency laid on white paper. Bad bytes (not a
// PNG or JPEG, truncated, corrupt, or too large for a page) are an
// ErrorKind::input error that says what and why; nothing is decoded past the
// header of an image above the size limit.
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

#include "common/result.hpp"

namespace tactus::graphic {

struct GreyImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // row by row from the top, 0 black .. 255 white
    // The resolution the file states (PNG pHYs, JPEG JFIF density), pixels an
    // inch across and down; 0 when it states none.
    double dpi_x = 0, dpi_y = 0;
    [[nodiscard]] std::uint8_t at(int x, int y) const {
        return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
    }
};

// A picture larger than this many pixels is refused: 40 megapixels is an A4
// page at 600 pixels an inch, more than a tactile graphic can show
// (its dots are 1.5 mm apart), and the decoded image takes a byte a pixel.
inline constexpr std::uint64_t kMaxImagePixels = 40'000'000;
inline constexpr std::uint32_t kMaxImageSide = 30'000;

enum class RasterFormat : unsigned char { none, png, jpeg };

// What the bytes' signature says they are.
RasterFormat raster_format(std::string_view bytes);

Result<GreyImage> read_png(std::string_view bytes);
Result<GreyImage> read_jpeg(std::string_view bytes);
// PNG or JPEG by the signature; anything else is refused.
Result<GreyImage> read_raster(std::string_view bytes);

// True when the file's name says PNG or JPEG (.png, .jpg, .jpeg, any case).
bool is_raster_path(const std::filesystem::path& path);

}  // namespace tactus::graphic
