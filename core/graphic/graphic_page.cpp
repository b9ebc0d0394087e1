// SPDX-License-Identifier: GPL-3.0-or-later
#include "graphic/graphic_page.hpp"

#include <algorithm>
#include <cmath>

#include "common/utf8.hpp"
#include "common/try.hpp"

namespace tactus::graphic {

DotOptions dot_options(const profile::PrinterProfile& m, const machine::FirmwareTables* firmware) {
    DotOptions o;
    o.x_step_mm = (firmware ? firmware->carriage.grid_steps : 1U) / m.carriage.steps_per_mm;
    o.y_step_mm = (firmware ? firmware->feed.grid_steps : 1U) / m.feed.steps_per_mm;
    o.dot_pitch_mm = m.geometry.dot_pitch_mm;
    o.cell_pitch_mm = m.geometry.cell_pitch_mm;
    // Half the dot pitch: the distance the back offset keeps between the dots
    // of the two sides so that neither crushes the other (plan::min_dot_separation_mm).
    o.min_distance_mm = m.geometry.dot_pitch_mm / 2;
    // The spacings the profile gives (profile::validate keeps a line's at
    // least 1.2 times the least distance).
    o.spacing_mm = m.graphic.line_dot_spacing_mm;
    o.dotted_spacing_mm = m.graphic.dotted_dot_spacing_mm;
    o.dash_gap_mm = m.graphic.dash_gap_mm;
    o.texture_pitch_mm = m.graphic.texture_pitch_mm;
    o.texture_spacing_mm = m.graphic.texture_dot_spacing_mm;
    o.label_clearance_mm = 2 * m.geometry.dot_pitch_mm;
    return o;
}

double simplify_tolerance_mm(const DotOptions& o) { return std::min(o.x_step_mm, o.y_step_mm); }

Area page_area(const profile::PrinterProfile& m) {
    return {m.paper.margin_left_mm, m.paper.margin_top_mm, m.paper.width_mm - m.paper.margin_right_mm,
            m.paper.height_mm - m.paper.margin_bottom_mm};
}

Result<GraphicLayout> lay_out_drawing(const Drawing& drawing, const profile::PrinterProfile& machine,
                                      const layout::PageGeometry& geometry, const translate::Translator& table,
                                      const DotOptions& options) {
    GraphicLayout out;
    const Area area = page_area(machine);
    if (area.right <= area.left || area.bottom <= area.top)
        return fail(ErrorKind::input, "the profile's margins leave no room on the paper for a graphic", "field paper");
    out.placed = fit_to_area(drawing, area, &out.scale);
    const Braille braille = [&table](const std::string& utf8) -> Result<document::BrailleLine> {
        TACTUS_TRY(text, utf8_to_utf32(utf8));
        return table.translate(text);
    };
    TACTUS_TRY(dots, place_dots(out.placed, area, options, braille));
    out.dots = std::move(dots);

    auto& doc = out.document;
    doc.geometry = geometry;
    doc.warnings = drawing.warnings;
    if (out.scale < 1)
        doc.warnings.push_back("the drawing (" + std::to_string(std::lround(drawing.width_mm)) + " x " +
                               std::to_string(std::lround(drawing.height_mm)) + " mm) is larger than the page area; "
                               "shrunk to " + std::to_string(std::lround(out.scale * 100)) + "%");
    for (const auto& w : out.dots.warnings) doc.warnings.push_back(w);
    layout::Page page;
    page.braille_number = 1;
    page.graphic.reserve(out.dots.dots.size());
    for (const auto& d : out.dots.dots) page.graphic.push_back({d.at.x, d.at.y});
    doc.pages.push_back(std::move(page));
    if (!out.dots.key.empty()) {
        // The key: each label that did not fit, on its own line(s), on a sheet of its own.
        if (geometry.interpoint) {
            layout::Page back;
            back.braille_number = 2;
            back.filler = true;
            doc.pages.push_back(std::move(back));
        }
        layout::Page key;
        key.braille_number = static_cast<int>(doc.pages.size()) + 1;
        const auto width = static_cast<std::size_t>(std::max(1, geometry.cells_per_line));
        for (int li : out.dots.key) {
            auto text = utf8_to_utf32(drawing.labels[static_cast<std::size_t>(li)].text);
            if (!text) continue;
            auto cells = table.translate(*text);
            if (!cells) continue;
            for (std::size_t at = 0; at < cells->size(); at += width) {
                if (key.lines.size() >= static_cast<std::size_t>(geometry.lines_per_page)) break;
                key.lines.emplace_back(cells->begin() + static_cast<std::ptrdiff_t>(at),
                                       cells->begin() + static_cast<std::ptrdiff_t>(std::min(cells->size(), at + width)));
            }
        }
        doc.pages.push_back(std::move(key));
    }
    return out;
}

}  // namespace tactus::graphic
