// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The small languages inside SVG attributes, read as SVG 1.1 defines them
// (https://www.w3.org/TR/SVG11/): numbers and lengths (§4.2), transform
// lists (§7.6), path data (§8.3, its grammar in §8.3.9) and elliptical arcs
// (implementation notes F.6). Each returns an error that says what and where
// in the attribute (a character offset), never a partial result.
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "graphic/drawing.hpp"

namespace tactus::graphic::svg {

// Millimetres per CSS pixel (96 per inch), SVG's user unit when nothing scales it.
inline constexpr double kMmPerPx = 25.4 / 96.0;

// A length with an optional unit (px, mm, cm, in, pt, pc; none = px) in mm.
// `percent_of` is what 100% means, in mm (0: a percentage is an error).
Result<double> parse_length_mm(std::string_view text, double percent_of = 0);

// A list of numbers separated by white space and/or commas (viewBox, points).
Result<std::vector<double>> parse_numbers(std::string_view text);

// A transform list (matrix, translate, scale, rotate, skewX, skewY).
Result<Affine> parse_transform(std::string_view text);

// Path data, in user units, every command made absolute; quadratic curves
// become the cubic they are, arcs cubics of at most 45° each. An empty
// attribute is an empty path; an error stops at its offset (SVG asks to
// render up to the error; Tactus refuses it instead, saying where).
Result<std::vector<Subpath>> parse_path(std::string_view d);

// The cubics of an arc from `from` to `to` (SVG's endpoint parameters),
// appended to `out`; a zero radius is a straight line (F.6.6).
void append_arc(std::vector<Segment>& out, Point from, double rx, double ry, double x_axis_rotation_deg,
                bool large_arc, bool sweep, Point to);

// An ellipse centred at c as a closed subpath of eight cubics.
Subpath ellipse(Point c, double rx, double ry);

}  // namespace tactus::graphic::svg
