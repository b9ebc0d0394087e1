// SPDX-License-Identifier: GPL-3.0-or-later
// PNG and JPEG pictures as tactile graphics: the readers (round trips through
// libpng's writer, real files from PngSuite and libjpeg-turbo's test images,
// and bad bytes refused with a reason), Otsu's threshold, and the tracer's
// properties: the traced contours have one loop per dark region and per hole,
// stay within the tolerance of the pixels' boundary, and every line dot lies
// on a traced contour; a black square's and a black disc's dots lie on their
// outlines.
#include <gtest/gtest.h>

#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "../common/firmware_tables_fixture.hpp"
#include "../common/process.hpp"
#include "common/file_io.hpp"
#include "graphic/graphic_page.hpp"
#include "graphic/raster_image.hpp"
#include "graphic/raster_trace.hpp"
#include "import/import.hpp"
#include "profile/page_geometry.hpp"
#include "profile/profile.hpp"
#include "translate/catalogue.hpp"

// Its own namespace: the test binary compiles its files as one source.
namespace tactus::raster_tests {
namespace {

using graphic::GreyImage;
using graphic::Point;

const std::string kPictures = std::string(TACTUS_TEST_DATA) + "/graphics/pictures/";

GreyImage canvas(int w, int h, std::uint8_t grey = 255) {
    GreyImage g;
    g.width = w;
    g.height = h;
    g.pixels.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), grey);
    return g;
}

std::uint8_t& px(GreyImage& g, int x, int y) {
    return g.pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(g.width) + static_cast<std::size_t>(x)];
}

void fill_rect(GreyImage& g, int x0, int y0, int x1, int y1, std::uint8_t grey = 0) {
    for (int y = std::max(0, y0); y < std::min(g.height, y1); ++y)
        for (int x = std::max(0, x0); x < std::min(g.width, x1); ++x) px(g, x, y) = grey;
}

// Pixel centres (x + 0.5, y + 0.5) within r of (cx, cy).
void fill_disc(GreyImage& g, double cx, double cy, double r, std::uint8_t grey = 0) {
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x)
            if (std::hypot(x + 0.5 - cx, y + 0.5 - cy) <= r) px(g, x, y) = grey;
}

std::string encode_png(const GreyImage& g) {
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(g.width);
    image.height = static_cast<png_uint_32>(g.height);
    image.format = PNG_FORMAT_GRAY;
    png_alloc_size_t size = 0;
    EXPECT_TRUE(png_image_write_to_memory(&image, nullptr, &size, 0, g.pixels.data(), 0, nullptr));
    std::string out(size, '\0');
    EXPECT_TRUE(png_image_write_to_memory(&image, out.data(), &size, 0, g.pixels.data(), 0, nullptr));
    out.resize(size);
    return out;
}

std::string be32(std::uint32_t v) {
    return {static_cast<char>(v >> 24), static_cast<char>((v >> 16) & 0xFF), static_cast<char>((v >> 8) & 0xFF),
            static_cast<char>(v & 0xFF)};
}

// A PNG with a pHYs chunk (pixels a metre) after its IHDR.
std::string with_resolution(const std::string& png, std::uint32_t per_metre) {
    const std::string body = "pHYs" + be32(per_metre) + be32(per_metre) + std::string(1, '\1');
    const auto crc = static_cast<std::uint32_t>(
        crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size())));
    const std::size_t after_ihdr = 8 + 4 + 4 + 13 + 4;
    return png.substr(0, after_ihdr) + be32(9) + body + be32(crc) + png.substr(after_ihdr);
}

double gap_to_segment(Point p, Point a, Point b) {
    const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
    const double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0;
    return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

// The traced outline's straight pieces (every segment the tracer makes is straight).
std::vector<std::pair<Point, Point>> pieces(const graphic::Drawing& d) {
    std::vector<std::pair<Point, Point>> out;
    for (const auto& s : d.shapes)
        for (const auto& sp : s.subpaths) {
            Point at = sp.start;
            for (const auto& seg : sp.segments) {
                EXPECT_TRUE(seg.line);
                out.emplace_back(at, seg.p[2]);
                at = seg.p[2];
            }
        }
    return out;
}

double distance_to_outline(Point p, const std::vector<std::pair<Point, Point>>& outline) {
    double best = 1e300;
    for (const auto& [a, b] : outline) best = std::min(best, gap_to_segment(p, a, b));
    return best;
}

std::size_t loops(const graphic::Drawing& d) {
    std::size_t n = 0;
    for (const auto& s : d.shapes) n += s.subpaths.size();
    return n;
}

// Regions counted by flood fill, independently of the tracer: the dark ones
// 8-connected, the light ones 4-connected (the complementary connectivity),
// and only the light ones not reaching the picture's edge (holes).
std::size_t regions_and_holes(const GreyImage& g, int threshold) {
    const int w = g.width, h = g.height;
    std::vector<int> label(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
    std::size_t count = 0;
    const auto dark = [&](int x, int y) { return g.at(x, y) <= threshold; };
    for (int y0 = 0; y0 < h; ++y0)
        for (int x0 = 0; x0 < w; ++x0) {
            const auto i0 = static_cast<std::size_t>(y0 * w + x0);
            if (label[i0] != 0) continue;
            const bool ink = dark(x0, y0);
            bool edge = false;
            std::vector<std::pair<int, int>> todo{{x0, y0}};
            label[i0] = 1;
            while (!todo.empty()) {
                const auto [x, y] = todo.back();
                todo.pop_back();
                if (x == 0 || y == 0 || x == w - 1 || y == h - 1) edge = true;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        if ((dx == 0 && dy == 0) || (!ink && dx != 0 && dy != 0)) continue;
                        const int nx = x + dx, ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= w || ny >= h || dark(nx, ny) != ink) continue;
                        auto& l = label[static_cast<std::size_t>(ny * w + nx)];
                        if (l == 0) l = 1, todo.emplace_back(nx, ny);
                    }
            }
            if (ink || !edge) ++count;
        }
    return count;
}

graphic::GraphicLayout lay_out(const graphic::Drawing& d) {
    const auto prof = profile::default_profile();
    const auto t = translate::Translator::open(translate::kDefaultTable);
    EXPECT_TRUE(t);
    auto g = graphic::lay_out_drawing(d, prof, profile::page_geometry(prof), *t,
                                      graphic::dot_options(prof, &test::firmware_tables()));
    EXPECT_TRUE(g) << g.error().to_string();
    return std::move(*g);
}

graphic::TraceOptions options_for_grid() {
    graphic::TraceOptions o;
    o.simplify_mm = graphic::simplify_tolerance_mm(graphic::dot_options(profile::default_profile(), &test::firmware_tables()));
    return o;
}

// The farthest a dot moves when it is put on the grid.
double snap_distance() {
    const auto o = graphic::dot_options(profile::default_profile(), &test::firmware_tables());
    return std::hypot(o.x_step_mm / 2, o.y_step_mm / 2) + 1e-9;
}

constexpr double kMmPerPx = 25.4 / 96;

TEST(RasterThreshold, OtsuSplitsTwoGreysBetweenThem) {
    auto g = canvas(100, 100, 200);
    fill_rect(g, 0, 0, 30, 100, 60);
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> noise(-15, 15);
    for (auto& v : g.pixels) v = static_cast<std::uint8_t>(v + noise(rng));
    const int t = graphic::otsu_threshold(g);
    EXPECT_GE(t, 75);
    EXPECT_LT(t, 185);
    // One grey all over: no split; the middle grey.
    EXPECT_EQ(graphic::otsu_threshold(canvas(10, 10, 40)), 127);
}

TEST(RasterTrace, ABlackSquareIsItsFourSides) {
    auto g = canvas(200, 200);
    fill_rect(g, 50, 50, 150, 150);
    const auto d = graphic::trace_image(g, options_for_grid());
    ASSERT_TRUE(d) << d.error().to_string();
    EXPECT_NEAR(d->width_mm, 200 * kMmPerPx, 1e-9);
    ASSERT_EQ(d->shapes.size(), 1U);
    ASSERT_EQ(loops(*d), 1U);
    const auto& s = d->shapes[0];
    EXPECT_TRUE(s.stroked);
    EXPECT_TRUE(s.filled);
    EXPECT_TRUE(s.even_odd);
    EXPECT_TRUE(s.subpaths[0].closed);
    // The sides at pixel 50 and 150 (pixel edges); the corners cut by half a pixel.
    EXPECT_LE(s.subpaths[0].segments.size(), 8U);
    double length = 0;
    for (const auto& [a, b] : pieces(*d)) {
        length += std::hypot(b.x - a.x, b.y - a.y);
        for (const auto p : {a, b}) {
            const double off = std::min({std::abs(p.x - 50 * kMmPerPx), std::abs(p.x - 150 * kMmPerPx),
                                         std::abs(p.y - 50 * kMmPerPx), std::abs(p.y - 150 * kMmPerPx)});
            EXPECT_LE(off, 0.5 * kMmPerPx + 1e-9);
        }
    }
    EXPECT_NEAR(length, 400 * kMmPerPx, 4 * kMmPerPx);
}

// Dots on the outline of a black square and of a black disc, as laid out on
// the firmware's grid: every line dot within the tracing's tolerance, half a
// pixel and the grid's rounding of the true outline; the texture inside.
TEST(RasterTrace, TheDotsOfASquareAndADiscLieOnTheirOutlines) {
    auto g = canvas(400, 240);
    fill_rect(g, 20, 40, 180, 200);           // 160 px: 42.3 mm
    fill_disc(g, 300, 120, 80);               // radius 21.2 mm
    const auto opts = options_for_grid();
    const auto d = graphic::trace_image(g, opts);
    ASSERT_TRUE(d) << d.error().to_string();
    ASSERT_EQ(loops(*d), 2U);
    const auto laid = lay_out(*d);
    ASSERT_EQ(laid.scale, 1.0);
    const auto area = graphic::page_area(profile::default_profile());
    const double slack = std::max(opts.simplify_mm, 0.5 * kMmPerPx) + 0.5 * kMmPerPx + snap_distance();
    const auto page = [&](double px_x, double px_y) { return Point{area.left + px_x * kMmPerPx, area.top + px_y * kMmPerPx}; };
    const Point sq0 = page(20, 40), sq1 = page(180, 200), centre = page(300, 120);
    const double radius = 80 * kMmPerPx;
    std::size_t on_square = 0, on_disc = 0, textured = 0;
    for (const auto& dot : laid.dots.dots) {
        const Point p = dot.at;
        const double to_square = std::min({gap_to_segment(p, sq0, Point{sq1.x, sq0.y}), gap_to_segment(p, Point{sq1.x, sq0.y}, sq1),
                                           gap_to_segment(p, sq1, Point{sq0.x, sq1.y}), gap_to_segment(p, Point{sq0.x, sq1.y}, sq0)});
        const double to_disc = std::abs(std::hypot(p.x - centre.x, p.y - centre.y) - radius);
        if (dot.kind == graphic::DotKind::line) {
            EXPECT_LE(std::min(to_square, to_disc), slack) << "a line dot at " << p.x << ", " << p.y;
            (to_square < to_disc ? on_square : on_disc) += 1;
        } else if (dot.kind == graphic::DotKind::texture) {
            ++textured;
            const bool in_square = p.x > sq0.x && p.x < sq1.x && p.y > sq0.y && p.y < sq1.y;
            const bool in_disc = std::hypot(p.x - centre.x, p.y - centre.y) < radius;
            EXPECT_TRUE(in_square || in_disc) << "a texture dot outside the ink at " << p.x << ", " << p.y;
        }
    }
    // About one dot every 1.5 mm around each (a few left out at the corners).
    EXPECT_NEAR(static_cast<double>(on_square), 4 * 160 * kMmPerPx / 1.5, 8);
    EXPECT_NEAR(static_cast<double>(on_disc), 2 * M_PI * radius / 1.5, 8);
    EXPECT_GT(textured, 50U);
}

// Random blobs (discs and bars, some overlapping, some with holes): one loop a
// dark region and a hole, the outline within tolerance of the pixel boundary,
// and every line dot on a traced contour, to the grid's rounding.
TEST(RasterTrace, EveryLoopIsARegionOrAHoleAndEveryDotIsOnAContour) {
    for (unsigned seed = 1; seed <= 12; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(0, 1);
        auto g = canvas(300, 220);
        for (int k = 0; k < 6; ++k) {
            const double cx = 20 + 260 * u(rng), cy = 20 + 180 * u(rng);
            if (u(rng) < 0.5) {
                const double r = 10 + 40 * u(rng);
                fill_disc(g, cx, cy, r);
                if (u(rng) < 0.4) fill_disc(g, cx, cy, r / 2, 255);  // a hole
            } else {
                fill_rect(g, static_cast<int>(cx), static_cast<int>(cy), static_cast<int>(cx + 10 + 60 * u(rng)),
                          static_cast<int>(cy + 5 + 30 * u(rng)));
            }
        }
        auto exact = options_for_grid();
        exact.speck_mm = 0;
        exact.simplify_mm = 0;
        const auto d = graphic::trace_image(g, exact);
        ASSERT_TRUE(d) << d.error().to_string();
        EXPECT_EQ(loops(*d), regions_and_holes(g, graphic::otsu_threshold(g)));
        // Unsimplified, every vertex is half a pixel from a dark and a light
        // pixel's centre: between them.
        for (const auto& [a, b] : pieces(*d)) {
            const double x = a.x / kMmPerPx, y = a.y / kMmPerPx;
            EXPECT_NEAR(2 * x, std::round(2 * x), 1e-6);
            EXPECT_NEAR(2 * y, std::round(2 * y), 1e-6);
        }
        const auto opts = options_for_grid();
        const auto simple = graphic::trace_image(g, opts);
        ASSERT_TRUE(simple);
        const auto exact_outline = pieces(*d);
        const double tolerance = std::max(opts.simplify_mm, 0.5 * kMmPerPx);
        for (const auto& [a, b] : pieces(*simple))
            for (int k = 0; k <= 4; ++k) {
                const Point p{a.x + (b.x - a.x) * k / 4, a.y + (b.y - a.y) * k / 4};
                EXPECT_LE(distance_to_outline(p, exact_outline), tolerance + 1e-9);
            }
        const auto laid = lay_out(*simple);
        const auto placed = pieces(laid.placed);
        std::size_t line_dots = 0;
        for (const auto& dot : laid.dots.dots)
            if (dot.kind == graphic::DotKind::line) {
                ++line_dots;
                EXPECT_LE(distance_to_outline(dot.at, placed), snap_distance());
            }
        EXPECT_GT(line_dots, 20U);
    }
}

// Ink touching only at a corner is one region (a diagonal line of single
// pixels stays one line); paper touching only at a corner is two (the hole
// next to the ink's corner is closed).
TEST(RasterTrace, InkTouchingAtACornerIsOneRegion) {
    auto g = canvas(100, 100);
    fill_rect(g, 10, 10, 40, 40);
    fill_rect(g, 40, 40, 70, 70);
    for (int k = 0; k < 25; ++k) px(g, 70 + k, 70 - k - 1) = 0;  // a staircase on from the corner
    auto exact = graphic::TraceOptions{};
    exact.speck_mm = 0;
    const auto d = graphic::trace_image(g, exact);
    ASSERT_TRUE(d);
    EXPECT_EQ(loops(*d), 1U);
    EXPECT_EQ(regions_and_holes(g, 127), 1U);
    // Two light squares in a dark field touching at a corner: two holes.
    auto h = canvas(100, 100, 0);
    fill_rect(h, 10, 10, 40, 40, 255);
    fill_rect(h, 40, 40, 70, 70, 255);
    const auto holes = graphic::trace_image(h, exact);
    ASSERT_TRUE(holes);
    EXPECT_EQ(loops(*holes), 3U);  // the field's outline and the two holes
    EXPECT_EQ(regions_and_holes(h, 127), 3U);
}

TEST(RasterTrace, SpecksAreLeftOutWithAWarningAndABlankPictureSaysSo) {
    auto g = canvas(200, 200);
    fill_rect(g, 20, 20, 120, 120);
    fill_rect(g, 150, 150, 152, 152);  // 0.5 mm
    fill_rect(g, 170, 20, 171, 21);
    const auto d = graphic::trace_image(g, {});
    ASSERT_TRUE(d);
    EXPECT_EQ(loops(*d), 1U);
    ASSERT_EQ(d->warnings.size(), 1U);
    EXPECT_NE(d->warnings[0].find("2 dark specks smaller than 1.0 mm"), std::string::npos) << d->warnings[0];
    const auto blank = graphic::trace_image(canvas(50, 50), {});
    ASSERT_TRUE(blank);
    EXPECT_TRUE(blank->shapes.empty());
    ASSERT_EQ(blank->warnings.size(), 1U);
    EXPECT_NE(blank->warnings[0].find("the graphic is empty"), std::string::npos);
    // A threshold out of range is the caller's mistake.
    graphic::TraceOptions bad;
    bad.threshold = 255;
    const auto refused = graphic::trace_image(g, bad);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().kind, ErrorKind::usage);
}

TEST(RasterRead, APngRoundTripsAndItsResolutionSetsTheSize) {
    auto g = canvas(37, 23, 255);
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) px(g, x, y) = static_cast<std::uint8_t>((x * 7 + y * 11) % 256);
    const auto png = encode_png(g);
    const auto back = graphic::read_raster(png);
    ASSERT_TRUE(back) << back.error().to_string();
    EXPECT_EQ(back->width, 37);
    EXPECT_EQ(back->height, 23);
    EXPECT_EQ(back->pixels, g.pixels);
    EXPECT_EQ(back->dpi_x, 0);
    // 11811 pixels a metre: 300 an inch.
    const auto dense = graphic::read_png(with_resolution(png, 11811));
    ASSERT_TRUE(dense) << dense.error().to_string();
    EXPECT_NEAR(dense->dpi_x, 300, 0.01);
    EXPECT_EQ(dense->pixels, g.pixels);
    auto square = canvas(300, 300);
    fill_rect(square, 0, 0, 150, 300);
    square.dpi_x = square.dpi_y = 300;
    const auto d = graphic::trace_image(square, {});
    ASSERT_TRUE(d);
    EXPECT_NEAR(d->width_mm, 25.4, 1e-9);
}

TEST(RasterRead, BadBytesAreRefusedWithTheReason) {
    auto g = canvas(64, 64);
    fill_disc(g, 32, 32, 20);
    const auto png = encode_png(g);
    const auto expect_refused = [](const Result<GreyImage>& r, const std::string& says) {
        ASSERT_FALSE(r) << "decoded " << r->width << " x " << r->height;
        EXPECT_EQ(r.error().kind, ErrorKind::input);
        EXPECT_NE(r.error().message.find(says), std::string::npos) << r.error().message;
    };
    expect_refused(graphic::read_raster(png.substr(0, png.size() / 2)), "PNG");
    expect_refused(graphic::read_raster(""), "not a PNG or JPEG");
    expect_refused(graphic::read_raster("GIF89a......"), "not a PNG or JPEG");
    expect_refused(graphic::read_png("\xFF\xD8\xFF\xE0"), "not a PNG");
    // A header claiming 100 000 x 100 000 pixels: refused before anything is decoded.
    std::string huge = png;
    const std::string size = be32(100000) + be32(100000);
    huge.replace(16, 8, size);
    const std::string ihdr = huge.substr(12, 17);
    const auto crc = static_cast<std::uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(ihdr.data()), 17));
    huge.replace(29, 4, be32(crc));
    expect_refused(graphic::read_raster(huge), "above the limit of 40 megapixels");
    // A JPEG cut short, and one whose data is overwritten.
    const auto jpeg = read_file(kPictures + "testorig.jpg", 1 << 20);
    ASSERT_TRUE(jpeg);
    expect_refused(graphic::read_raster(jpeg->substr(0, 2000)), "damaged JPEG");
    expect_refused(graphic::read_raster(jpeg->substr(0, 100)), "JPEG");
    std::string scrambled = *jpeg;
    for (std::size_t i = 600; i < scrambled.size(); i += 7) scrambled[i] = static_cast<char>(0xFF);
    expect_refused(graphic::read_raster(scrambled), "JPEG");
}

// Real pictures nobody here made: PngSuite's 1-bit grey (a triangle with a
// letter cut out and a W beside it), its transparent variant (the background
// laid on white), and the IJG's photograph from libjpeg-turbo's test images.
TEST(RasterRead, RealFilesTrace) {
    const auto bw = read_file(kPictures + "basn0g01.png", 1 << 20);
    ASSERT_TRUE(bw);
    const auto img = graphic::read_raster(*bw);
    ASSERT_TRUE(img) << img.error().to_string();
    ASSERT_EQ(img->width, 32);
    auto exact = graphic::TraceOptions{};
    exact.speck_mm = 0;
    const auto d = graphic::trace_image(*img, exact);
    ASSERT_TRUE(d);
    EXPECT_EQ(loops(*d), regions_and_holes(*img, graphic::otsu_threshold(*img)));
    EXPECT_GE(loops(*d), 3U);  // the triangle, the W, the letter's holes

    const auto transparent = graphic::read_raster(*read_file(kPictures + "ftbbn0g01.png", 1 << 20));
    ASSERT_TRUE(transparent) << transparent.error().to_string();
    EXPECT_EQ(std::count(transparent->pixels.begin(), transparent->pixels.end(), 255) +
                  std::count(transparent->pixels.begin(), transparent->pixels.end(), 0),
              32 * 32);
    const auto rgba = graphic::read_raster(*read_file(kPictures + "basn6a08.png", 1 << 20));
    ASSERT_TRUE(rgba) << rgba.error().to_string();
    EXPECT_EQ(rgba->width, 32);

    const auto photo_bytes = read_file(kPictures + "testorig.jpg", 1 << 20);
    ASSERT_TRUE(photo_bytes);
    const auto photo = graphic::read_raster(*photo_bytes);
    ASSERT_TRUE(photo) << photo.error().to_string();
    EXPECT_EQ(photo->width, 227);
    EXPECT_EQ(photo->height, 149);
    const auto traced = graphic::trace_image(*photo, options_for_grid());
    ASSERT_TRUE(traced) << traced.error().to_string();
    EXPECT_GT(loops(*traced), 0U);
    const auto laid = lay_out(*traced);
    const auto area = graphic::page_area(profile::default_profile());
    EXPECT_GT(laid.dots.dots.size(), 50U);
    for (const auto& dot : laid.dots.dots) EXPECT_TRUE(area.contains(dot.at));
}

// tactus-cli with these arguments, its messages merged into its output.
test::RunResult cli(const std::vector<std::string>& args) { return test::run_merged(test::cli(args)); }

TEST(RasterCli, LayoutPlanAndEmbossTakeAPictureLikeAnSvg) {
    const auto picture = kPictures + "shapes.png";
    const auto layout = cli({"layout", picture, "--summary"});
    ASSERT_EQ(layout.exit_code, 0) << layout.out;
    EXPECT_NE(layout.out.find("graphic:"), std::string::npos) << layout.out;
    const auto plan = cli({"plan", kPictures + "testorig.jpg"});
    ASSERT_EQ(plan.exit_code, 0) << plan.out;
    const auto emboss = cli({"emboss", "--device", "sim?speed=max", picture});
    ASSERT_EQ(emboss.exit_code, 0) << emboss.out;
    EXPECT_NE(emboss.out.find("embossed"), std::string::npos) << emboss.out;
    // The threshold option: everything below 1 is ink (nothing here), so the graphic is empty.
    const auto dark_only = cli({"layout", picture, "--summary", "--image-threshold", "0"});
    EXPECT_EQ(dark_only.exit_code, 0) << dark_only.out;
    const auto bad = cli({"layout", picture, "--image-threshold", "300"});
    EXPECT_EQ(bad.exit_code, 2) << bad.out;
    // Bad bytes in a .png: exit status 3 (input), the file and the reason.
    const auto broken = std::filesystem::temp_directory_path() / ("tactus-broken-" + std::to_string(getpid()) + ".png");
    {
        const auto bytes = read_file(picture, 1 << 20);
        ASSERT_TRUE(bytes);
        ASSERT_TRUE(write_file_atomic(broken, bytes->substr(0, bytes->size() / 3)));
    }
    const auto refused = cli({"plan", broken.string()});
    std::filesystem::remove(broken);
    EXPECT_EQ(refused.exit_code, 3) << refused.out;
    EXPECT_NE(refused.out.find(broken.string() + ": unreadable PNG"), std::string::npos) << refused.out;
    // Where a document's text is imported, a picture is refused with the reason.
    const auto imported = import::import_file(picture, {});
    ASSERT_FALSE(imported);
    EXPECT_NE(imported.error().message.find("is a PNG picture"), std::string::npos) << imported.error().message;
}

}  // namespace
}  // namespace tactus::raster_tests
