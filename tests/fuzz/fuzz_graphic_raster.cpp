// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the PNG and JPEG readers and the tracer behind them.
// Whatever the bytes, read_raster returns a grey image or an error with a
// reason, never crashes; an image has the pixels its size says; its traced
// drawing's dots all lie inside the page area.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "graphic/dots.hpp"
#include "graphic/graphic_page.hpp"
#include "graphic/raster_image.hpp"
#include "graphic/raster_trace.hpp"
#include "profile/profile.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tactus;
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    auto image = graphic::read_raster(bytes);
    if (!image) {
        if (image.error().message.empty()) std::abort();
        return 0;
    }
    if (image->width <= 0 || image->height <= 0 ||
        image->pixels.size() != static_cast<std::size_t>(image->width) * static_cast<std::size_t>(image->height))
        std::abort();
    // A small file can inflate to the 40-megapixel limit; tracing that is
    // right but slow, and the fuzzer's time is better spent on other inputs.
    if (image->pixels.size() > 1'000'000) return 0;
    auto d = graphic::trace_image(*image, {});
    if (!d) {
        if (d.error().message.empty()) std::abort();
        return 0;
    }
    static const auto machine = profile::default_profile();
    const auto area = graphic::page_area(machine);
    const graphic::Braille braille = [](const std::string&) -> Result<document::BrailleLine> {
        return document::BrailleLine{};
    };
    auto g = graphic::place_dots(graphic::fit_to_area(*d, area), area, graphic::dot_options(machine), braille);
    if (!g) return 0;
    for (const auto& dot : g->dots)
        if (!area.contains(dot.at)) std::abort();
    return 0;
}
