// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A grey picture -> a Drawing (docs/graphics.md, "Pictures"): the dark pixels
// (at or below a threshold, Otsu's by default) are the ink; the outlines of
// the dark regions are traced by marching squares between pixel centres,
// simplified by Douglas-Peucker, and become one shape whose outline is a solid
// line and whose inside is a filled area (even-odd, so a hole in a region
// stays paper), as a black-filled, black-stroked SVG path would be.
#include <filesystem>

#include "common/result.hpp"
#include "graphic/drawing.hpp"
#include "graphic/raster_image.hpp"

namespace tactus::graphic {

struct TraceOptions {
    // Pixels whose grey (0 black .. 255 white) is at or below this are ink;
    // -1: Otsu's threshold for the picture.
    int threshold = -1;
    // The traced outline stays within this of the pixel contour (Douglas-Peucker),
    // in millimetres on the drawing, or within half a pixel when that is more:
    // the machine's resolution (graphic_page's simplify_tolerance_mm), finer
    // than which a vertex moves no dot.
    double simplify_mm = 0.25;
    // Pixels an inch when the file states no resolution: SVG's and CSS's px.
    double default_dpi = 96;
    // Dark regions whose outline fits in a square this wide are specks (scanner
    // noise, JPEG artefacts, a stray pixel): left out, counted in a warning.
    double speck_mm = 1.0;
};

// Otsu's method: the grey level that best splits the histogram in two classes
// (dark: at or below it). A picture of one grey gives 127.
int otsu_threshold(const GreyImage& image);

// The outlines of the dark regions, in millimetres at the picture's size.
Result<Drawing> trace_image(const GreyImage& image, const TraceOptions& options);

// A .png or .jpg file, read and traced; errors say the file.
Result<Drawing> load_image(const std::filesystem::path& path, const TraceOptions& options);

}  // namespace tactus::graphic
