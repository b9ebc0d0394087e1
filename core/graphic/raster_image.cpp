// SPDX-License-Identifier: GPL-3.0-or-later
#include "graphic/raster_image.hpp"

// libjpeg reports a fatal error through a callback that must not return: it
// jumps back to the decoding function (setjmp/longjmp, the way the library's
// own example does it). That function holds only trivially destructible
// objects, so the jump skips no destructor.
#include <csetjmp>
#include <cstdio>  // jpeglib.h needs FILE
#include <cstdlib>
#include <cstring>
// Without libpng and libjpeg (TACTUS_WITH_RASTER off) a picture is still
// recognised by its first bytes, then refused.
#if TACTUS_HAVE_RASTER
#include <jpeglib.h>
#include <png.h>
#else
#include "common/unavailable.hpp"
#endif

#include <algorithm>
#include <cctype>
#include <string>

namespace tactus::graphic {

namespace {

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

const unsigned char* bytes_of(std::string_view s) { return reinterpret_cast<const unsigned char*>(s.data()); }

#if TACTUS_HAVE_RASTER
std::uint32_t be32(const unsigned char* p) {
    return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
}

Result<void> check_size(std::uint64_t width, std::uint64_t height) {
    if (width == 0 || height == 0)
        return fail(ErrorKind::input, "the picture has no pixels (" + std::to_string(width) + " x " +
                                          std::to_string(height) + ")");
    if (width > kMaxImageSide || height > kMaxImageSide || width * height > kMaxImagePixels)
        return fail(ErrorKind::input, "the picture is " + std::to_string(width) + " x " + std::to_string(height) +
                                          " pixels, above the limit of " + std::to_string(kMaxImagePixels / 1'000'000) +
                                          " megapixels (" + std::to_string(kMaxImageSide) +
                                          " a side): scale it down first");
    return {};
}

// The pHYs chunk, if one comes before the image data: pixels a metre -> an inch.
void png_resolution(std::string_view bytes, GreyImage& out) {
    std::size_t at = 8;
    while (at + 12 <= bytes.size()) {
        const auto* p = bytes_of(bytes) + at;
        const std::uint32_t length = be32(p);
        const std::string_view type(bytes.data() + at + 4, 4);
        if (type == "IDAT" || type == "IEND" || length > bytes.size() - at - 12) return;
        if (type == "pHYs" && length == 9 && p[16] == 1) {
            const double x = be32(p + 8) * 0.0254, y = be32(p + 12) * 0.0254;
            // Only a resolution a picture could have: 10 to 10 000 pixels an inch.
            if (x >= 10 && x <= 10000 && y >= 10 && y <= 10000) out.dpi_x = x, out.dpi_y = y;
            return;
        }
        at += std::size_t{length} + 12;
    }
}

struct JpegErrors {
    jpeg_error_mgr mgr;  // first: libjpeg's pointer to it is a pointer to this
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
    char warning[JMSG_LENGTH_MAX];
};

extern "C" void jpeg_fatal(j_common_ptr c) {
    auto* e = reinterpret_cast<JpegErrors*>(c->err);
    (*c->err->format_message)(c, e->message);
    std::longjmp(e->jump, 1);
}

// Level -1 is a warning: corrupt or truncated data the library would paper
// over with grey. The first is kept, and the picture refused with it.
extern "C" void jpeg_note(j_common_ptr c, int level) {
    auto* e = reinterpret_cast<JpegErrors*>(c->err);
    if (level < 0 && e->warning[0] == '\0') (*c->err->format_message)(c, e->warning);
}

struct JpegOut {
    std::uint32_t width = 0, height = 0;
    unsigned char* pixels = nullptr;  // malloc'd; the caller frees it
    double dpi_x = 0, dpi_y = 0;
    bool too_large = false;
};

// 0 on success; 1 after a fatal error (errors->message) or a warning (errors->warning).
int decode_jpeg(const unsigned char* data, unsigned long size, JpegErrors* errors, JpegOut* out) {
    jpeg_decompress_struct info;
    info.err = jpeg_std_error(&errors->mgr);
    errors->mgr.error_exit = jpeg_fatal;
    errors->mgr.emit_message = jpeg_note;
    if (setjmp(errors->jump)) {
        jpeg_destroy_decompress(&info);
        return 1;
    }
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, data, size);
    jpeg_read_header(&info, TRUE);
    out->width = info.image_width;
    out->height = info.image_height;
    const std::uint64_t pixels = std::uint64_t{info.image_width} * info.image_height;
    if (info.image_width == 0 || info.image_height == 0 || info.image_width > kMaxImageSide ||
        info.image_height > kMaxImageSide || pixels > kMaxImagePixels) {
        out->too_large = true;
        jpeg_destroy_decompress(&info);
        return 1;
    }
    if (info.saw_JFIF_marker && info.X_density > 0 && info.Y_density > 0 &&
        (info.density_unit == 1 || info.density_unit == 2)) {
        const double per_inch = info.density_unit == 1 ? 1.0 : 2.54;
        out->dpi_x = info.X_density * per_inch;
        out->dpi_y = info.Y_density * per_inch;
    }
    info.out_color_space = JCS_GRAYSCALE;
    jpeg_start_decompress(&info);
    out->pixels = static_cast<unsigned char*>(std::malloc(static_cast<std::size_t>(pixels)));
    if (out->pixels == nullptr) {
        std::snprintf(errors->message, sizeof errors->message, "out of memory for %u x %u pixels", out->width, out->height);
        jpeg_destroy_decompress(&info);
        return 1;
    }
    while (info.output_scanline < info.output_height && errors->warning[0] == '\0') {
        JSAMPROW row = out->pixels + std::size_t{info.output_scanline} * info.output_width;
        jpeg_read_scanlines(&info, &row, 1);
    }
    if (errors->warning[0] != '\0') {
        jpeg_destroy_decompress(&info);
        return 1;
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    return errors->warning[0] != '\0' ? 1 : 0;
}
#endif

std::string ascii_lower(std::string s) {
    for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace

RasterFormat raster_format(std::string_view bytes) {
    if (bytes.size() >= 8 && std::memcmp(bytes.data(), kPngSignature, 8) == 0) return RasterFormat::png;
    if (bytes.size() >= 3 && bytes_of(bytes)[0] == 0xFF && bytes_of(bytes)[1] == 0xD8 && bytes_of(bytes)[2] == 0xFF)
        return RasterFormat::jpeg;
    return RasterFormat::none;
}

Result<GreyImage> read_png(std::string_view bytes) {
    if (raster_format(bytes) != RasterFormat::png)
        return fail(ErrorKind::input, "not a PNG file (its first 8 bytes are not the PNG signature)");
#if !TACTUS_HAVE_RASTER
    return unavailable("reading PNG pictures", "libpng");
#else
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()))
        return fail(ErrorKind::input, std::string("unreadable PNG (damaged or cut short): ") + image.message);
    if (auto ok = check_size(image.width, image.height); !ok) {
        png_image_free(&image);
        return std::unexpected(ok.error());
    }
    GreyImage out;
    out.width = static_cast<int>(image.width);
    out.height = static_cast<int>(image.height);
    image.format = PNG_FORMAT_GRAY;
    out.pixels.resize(PNG_IMAGE_SIZE(image));
    // Transparent parts are the paper: white.
    const png_color white{255, 255, 255};
    if (!png_image_finish_read(&image, &white, out.pixels.data(), 0, nullptr))
        return fail(ErrorKind::input, std::string("unreadable PNG (damaged or cut short): ") + image.message);
    png_resolution(bytes, out);
    return out;
#endif
}

Result<GreyImage> read_jpeg(std::string_view bytes) {
    if (raster_format(bytes) != RasterFormat::jpeg)
        return fail(ErrorKind::input, "not a JPEG file (it does not start with a JPEG start-of-image marker)");
#if !TACTUS_HAVE_RASTER
    return unavailable("reading JPEG pictures", "libjpeg");
#else
    JpegErrors errors;
    std::memset(&errors, 0, sizeof errors);
    JpegOut out;
    const int failed = decode_jpeg(bytes_of(bytes), static_cast<unsigned long>(bytes.size()), &errors, &out);
    GreyImage image;
    if (failed == 0) {
        image.width = static_cast<int>(out.width);
        image.height = static_cast<int>(out.height);
        image.pixels.assign(out.pixels, out.pixels + std::size_t{out.width} * out.height);
        image.dpi_x = out.dpi_x;
        image.dpi_y = out.dpi_y;
    }
    std::free(out.pixels);
    if (failed == 0) return image;
    if (out.too_large) {
        auto size = check_size(out.width, out.height);
        return std::unexpected(size ? Error{"the picture's size is unusable", "", ErrorKind::input} : size.error());
    }
    if (errors.warning[0] != '\0')
        return fail(ErrorKind::input, std::string("damaged JPEG: ") + errors.warning);
    return fail(ErrorKind::input, std::string("unreadable JPEG: ") + errors.message);
#endif
}

Result<GreyImage> read_raster(std::string_view bytes) {
    switch (raster_format(bytes)) {
        case RasterFormat::png: return read_png(bytes);
        case RasterFormat::jpeg: return read_jpeg(bytes);
        case RasterFormat::none: break;
    }
    return fail(ErrorKind::input, "not a PNG or JPEG picture (its first bytes are neither signature)");
}

bool is_raster_path(const std::filesystem::path& path) {
    const auto e = ascii_lower(path.extension().string());
    return e == ".png" || e == ".jpg" || e == ".jpeg";
}

}  // namespace tactus::graphic
