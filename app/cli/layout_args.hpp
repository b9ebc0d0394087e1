// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The options every command that lays out a document shares (layout, plan,
// emboss), so they read the same everywhere.
#include <string>

#include <CLI/CLI.hpp>

#include "language_args.hpp"
#include "pipeline/pipeline.hpp"
#include "machine/firmware_tables.hpp"
#include "profile/profile.hpp"

namespace tactus::cli {

struct LayoutArgs {
    std::string file;
    std::string tables = translate::kDefaultTable;
    LanguageArgs language;
    std::string preset;
    std::string format = "auto";
    int image_threshold = -1;  // a picture's ink threshold; -1: Otsu's
    // Pictures in a DOCX, ODT, Markdown, HTML or EPUB document: "descriptions" (their
    // descriptions only, as transcriber's notes) or "graphics" (each also a
    // graphic page on a sheet of its own; docs/graphics.md).
    std::string images = "descriptions";
    std::string encoding;
    std::string ruby = "after";
    std::string page_numbers = "bottom-right";
    int cells = 0;  // 0: from the preset
    int lines = 0;
    bool interpoint = false;    // --interpoint: both sides, whatever the preset says
    bool single_sided = false;  // --single-sided: one side, whatever the preset says
    bool reflow = false;        // lay ready-made braille out again instead of keeping its pages
    bool blank_page = false;    // an empty document gives one blank page instead of an error
    bool eight_dot = false;
    bool no_print_pages = false;
    int indent = 2;
    int workers = 0;  // translation processes (PipelineOptions::translation_workers)
    int margin_left = 0, margin_right = 0, margin_top = 0, margin_bottom = 0;
    // Book layout (pipeline/book_layout.hpp): --volumes and its rules.
    bool volumes = false;
    pipeline::BookOptions book;
    bool no_title_page = false, no_contents = false, no_running_heads = false;

    void add_to(CLI::App& cmd, bool with_interpoint = true);
    // Validated options; a bad value ends the command with a usage error.
    [[nodiscard]] pipeline::PipelineOptions pipeline_options() const;
    // For embossing and planning: the page format is the machine's unless the
    // command line overrides it (the planner then refuses pages that do not fit).
    [[nodiscard]] pipeline::PipelineOptions pipeline_options(const profile::PrinterProfile& machine) const;
};

// Imports `args.file`, tells the user before anything else happens when
// ready-made braille does not fit the page (exit_page_too_small) or the table
// does not suit the text (a warning), then lays it out. Warnings go to stderr.
// An SVG drawing or a PNG/JPEG picture (its dark regions traced) becomes a graphic page for `machine` (the bundled profile
// when none is given): its dots are placed on that machine's step grid.
// `firmware`: the tables of a protocol-3 plan, whose grid the dots then keep
// (graphic::dot_options); without them, the grid of the tables the profile
// makes (protocol 3, the default everywhere), or the motor steps when the
// reference firmware cannot run the profile. `labels`: the number each page
// shows (pipeline::page_labels), for --pages.
layout::PagedDocument lay_out_for_cli(const LayoutArgs& args, const pipeline::PipelineOptions& options,
                                      const profile::PrinterProfile* machine = nullptr,
                                      const std::optional<machine::FirmwareTables>& firmware = std::nullopt,
                                      bool legacy_protocol = false,
                                      std::vector<std::string>* labels = nullptr);

}  // namespace tactus::cli
