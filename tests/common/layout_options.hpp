// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Pipeline options for layout tests that look at the body lines alone, as the
// line breaker and the block rules made them.
#include <string>

#include "pipeline/pipeline.hpp"

namespace tactus::test {

// `table`, one translation worker, `width` cells on a one-sided page of 200
// lines, no braille page numbers and no print page indicators.
inline pipeline::PipelineOptions body_lines_options(const std::string& table, int width) {
    pipeline::PipelineOptions o;
    o.tables = table;
    o.translation_workers = 1;
    o.layout.geometry = {width, 200, false, false};
    o.layout.page_numbers = layout::PageNumberPosition::none;
    o.layout.print_page_indicators = false;
    return o;
}

}  // namespace tactus::test
