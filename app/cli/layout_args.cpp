// SPDX-License-Identifier: GPL-3.0-or-later
#include "layout_args.hpp"

#include "command.hpp"

namespace tactus::cli {

void LayoutArgs::add_to(CLI::App& cmd, bool with_interpoint) {
    cmd.add_option("file", file, "Document: .txt, .md, .docx, .odt, .brf or .pef")->required();
    cmd.add_option("--table,-t", tables, "liblouis table list (see `tactus-cli tables`)")
        ->capture_default_str();
    std::string presets;
    for (const auto& p : layout::layout_presets()) presets += "\n  " + p.name + ": " + p.description;
    cmd.add_option("--preset", preset, "Page format preset (default a4):" + presets);
    cmd.add_option("--cells", cells, "Cells per line (default 27)")->check(CLI::Range(4, 200));
    cmd.add_option("--lines", lines, "Lines per page (default 24)")->check(CLI::Range(3, 200));
    if (with_interpoint)
        cmd.add_flag("--interpoint", interpoint,
                     "Interpoint: emboss both sides of each sheet (default single-sided)");
    cmd.add_flag("--eight-dot", eight_dot, "8-dot cells (keeps dots 7 and 8)");
    cmd.add_option("--page-numbers", page_numbers,
                   "Braille page number position: none, top-right, bottom-right, bottom-centre")
        ->capture_default_str();
    cmd.add_flag("--no-print-pages", no_print_pages, "Omit print page indicators");
    cmd.add_option("--indent", indent, "Paragraph first-line indent in cells")->capture_default_str();
    cmd.add_option("--margin-left", margin_left, "Left margin in cells");
    cmd.add_option("--margin-right", margin_right, "Right margin in cells");
    cmd.add_option("--margin-top", margin_top, "Top margin in lines");
    cmd.add_option("--margin-bottom", margin_bottom, "Bottom margin in lines");
    cmd.add_option("--format", format, "Input format: auto, txt, md, docx, odt, brf, pef")
        ->capture_default_str();
    cmd.add_option("--encoding", encoding,
                   "Text encoding override (e.g. UTF-8, Big5, GB18030, windows-1252); default: detect");
}

pipeline::PipelineOptions LayoutArgs::pipeline_options() const {
    pipeline::PipelineOptions o;
    o.tables = tables;
    o.import.encoding = encoding;
    o.import.format = require(import::parse_source_format(format), exit_usage);
    if (!preset.empty()) {
        const auto p = layout::find_layout_preset(preset);
        if (!p) fail_with(exit_usage, Error{"unknown preset '" + preset + "'", "--preset"});
        o.layout.geometry = p->geometry;
    }
    o.layout.geometry.interpoint = interpoint;
    if (cells > 0) o.layout.geometry.cells_per_line = cells;
    if (lines > 0) o.layout.geometry.lines_per_page = lines;
    o.layout.geometry.eight_dot = eight_dot;
    o.layout.page_numbers = require(layout::parse_page_number_position(page_numbers), exit_usage);
    o.layout.print_page_indicators = !no_print_pages;
    o.layout.paragraph_indent = indent;
    o.layout.left_margin = margin_left;
    o.layout.right_margin = margin_right;
    o.layout.top_margin = margin_top;
    o.layout.bottom_margin = margin_bottom;
    require(validate(o.layout), exit_usage);
    return o;
}

pipeline::PipelineOptions LayoutArgs::pipeline_options(const profile::PrinterProfile& machine) const {
    auto o = pipeline_options();
    auto& g = o.layout.geometry;
    g.interpoint = machine.geometry.interpoint;
    if (cells == 0) g.cells_per_line = machine.geometry.cells_per_line;
    if (lines == 0) g.lines_per_page = machine.geometry.lines_per_page;
    g.eight_dot = machine.geometry.eight_dot || eight_dot;
    return o;
}

}  // namespace tactus::cli
