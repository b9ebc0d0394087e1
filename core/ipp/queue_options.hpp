// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The job options a Tactus queue takes (`lp -o name=value`, or IPP job
// attributes of the same names): the tactus-layout filter reads them on the
// server, and a client sends them. One list, used by both (docs/cups.md).
#include <string_view>

namespace tactus::ipp::option {

inline constexpr std::string_view braille_table = "braille-table";
inline constexpr std::string_view interpoint = "interpoint";
inline constexpr std::string_view cells_per_line = "cells-per-line";
inline constexpr std::string_view lines_per_page = "lines-per-page";
inline constexpr std::string_view page_numbers = "braille-page-numbers";
inline constexpr std::string_view print_pages = "print-page-indicators";
inline constexpr std::string_view eight_dot = "eight-dot";
inline constexpr std::string_view text_encoding = "text-encoding";

}  // namespace tactus::ipp::option
