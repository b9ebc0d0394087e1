// SPDX-License-Identifier: GPL-3.0-or-later
#include "layout_args.hpp"

#include <chrono>
#include <iostream>
#include <memory>

#include "command.hpp"
#include "graphic/drawing_file.hpp"
#include "layout/braille_pages.hpp"
#include "pipeline/page_range.hpp"
#include "platform/console.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/page_geometry.hpp"

namespace tactus::cli {

void LayoutArgs::add_to(CLI::App& cmd, bool with_interpoint) {
    cmd.add_option("file", file, "Document: .txt, .md, .docx, .odt, .html, .epub, .xml (DTBook), .brf, .pef, or an .svg drawing or a .png/.jpg picture (a tactile graphic)")->required();
    cmd.add_option("--table,-t", tables, "liblouis table list (see `tactus-cli tables`)")
        ->capture_default_str();
    language.add_to(cmd);
    std::string presets;
    for (const auto& p : layout::layout_presets()) presets += "\n  " + p.name + ": " + p.description;
    cmd.add_option("--preset", preset, "Page format preset (default a4):" + presets);
    cmd.add_option("--cells", cells, "Cells per line (default 27)")->check(CLI::Range(4, 200));
    cmd.add_option("--lines", lines, "Lines per page (default 24)")->check(CLI::Range(3, 200));
    if (with_interpoint) {
        cmd.add_flag("--interpoint", interpoint,
                     "Interpoint: both sides of each sheet (the default of the a4, us-braille and letter presets)");
        cmd.add_flag("--single-sided", single_sided, "One side of each sheet (the default of a4-single)")
            ->excludes("--interpoint");
    }
    cmd.add_flag("--reflow", reflow,
                 "BRF/PEF input: lay the braille out again on this page instead of keeping its own pages "
                 "(without it, a file whose pages do not fit is refused with exit status 5)");
    cmd.add_flag("--blank-page", blank_page,
                 "An empty document gives one blank page (without it, an empty document is an error, exit status 3)");
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
    cmd.add_option("--image-threshold", image_threshold,
                   "A .png/.jpg picture: the grey level (0 black to 254) at or below which a pixel is ink; "
                   "default: Otsu's threshold for the picture")
        ->check(CLI::Range(0, 254));
    cmd.add_option("--images", images,
                   "Pictures in DOCX, ODT, Markdown, HTML and EPUB: descriptions (their descriptions only, as transcriber's "
                   "notes) or graphics (each PNG, JPEG or SVG picture also embossed as a graphic page on a sheet "
                   "of its own, after its description)")
        ->capture_default_str()
        ->check(CLI::IsMember({"descriptions", "graphics"}));
    cmd.add_option("--format", format, "Input format: auto, txt, md, docx, odt, html, epub, dtbook, brf, pef")
        ->capture_default_str();
    cmd.add_flag("--volumes", volumes,
                 "Lay out as a braille book (BANA Braille Formats): volumes split at chapters, a title page, "
                 "contents with print and braille page numbers, running heads, p-numbered preliminary pages");
    cmd.add_option("--sheets-per-volume", book.sheets_per_volume, "With --volumes: sheets per volume, about")
        ->capture_default_str()->check(CLI::Range(2, 100000));
    cmd.add_option("--contents-depth", book.contents_depth, "With --volumes: heading levels in the contents")
        ->capture_default_str()->check(CLI::Range(1, 6));
    cmd.add_option("--split-level", book.split_level, "With --volumes: heading levels a volume may start at")
        ->capture_default_str()->check(CLI::Range(1, 6));
    cmd.add_flag("--no-title-page", no_title_page, "With --volumes: no title page");
    cmd.add_flag("--no-contents", no_contents, "With --volumes: no contents pages");
    cmd.add_flag("--no-running-heads", no_running_heads, "With --volumes: no running heads");
    cmd.add_option("--book-title", book.title, "With --volumes: the title (default: the document's)");
    cmd.add_option("--book-author", book.author, "With --volumes: the author (default: the document's)");
    cmd.add_option("--book-publisher", book.publisher, "With --volumes: the publisher (default: the document's)");
    cmd.add_option("--book-year", book.year, "With --volumes: the year (default: the document's date)");
    cmd.add_option("--transcriber", book.transcriber, "With --volumes: \"Transcribed by\" on the title page");
    cmd.add_option("--workers", workers,
                   "Translation processes for a big document: 0 picks by its size and the cores, 1 translates "
                   "in this process (the pages are the same either way)")
        ->capture_default_str()
        ->check(CLI::Range(0, 64));
    cmd.add_option("--encoding", encoding,
                   "Text encoding override (e.g. UTF-8, Big5, GB18030, windows-1252); default: detect");
    cmd.add_option("--ruby", ruby,
                   "Ruby (phonetic guide) in DOCX/ODT: after (the guide after its base, as a transcriber's note) "
                   "or omit (the base only)")
        ->capture_default_str();
}

pipeline::PipelineOptions LayoutArgs::pipeline_options() const {
    pipeline::PipelineOptions o;
    o.tables = tables;
    o.language_switch = language.options();
    o.import.encoding = encoding;
    o.import.ruby = require(import::parse_ruby_guide(ruby), exit_usage);
    o.import.format = require(import::parse_source_format(format), exit_usage);
    o.import.images = images == "graphics";
    if (!preset.empty()) {
        const auto p = layout::find_layout_preset(preset);
        if (!p) fail_with(exit_usage, Error{"unknown preset '" + preset + "'", "--preset", ErrorKind::usage});
        o.layout.geometry = p->geometry;
    }
    // The preset decides sides (a4 is interpoint, as its help says); the flags override it.
    if (interpoint) o.layout.geometry.interpoint = true;
    if (single_sided) o.layout.geometry.interpoint = false;
    o.reflow_braille = reflow;
    o.translation_workers = static_cast<unsigned>(workers);
    o.allow_empty = blank_page;
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
    if (volumes) {
        auto b = book;
        b.title_page = !no_title_page;
        b.contents = !no_contents;
        b.running_heads = !no_running_heads;
        o.book = b;
    }
    return o;
}

pipeline::PipelineOptions LayoutArgs::pipeline_options(const profile::PrinterProfile& machine) const {
    auto o = pipeline_options();
    // The machine's page, narrowed by --cells / --lines, with eight dots when either asks.
    auto g = profile::page_geometry(machine);
    if (cells > 0) g.cells_per_line = cells;
    if (lines > 0) g.lines_per_page = lines;
    g.eight_dot = g.eight_dot || eight_dot;
    o.layout.geometry = g;
    return o;
}

namespace {

// "laying out: 42%" on a terminal, once a job has taken more than a second;
// nothing when stderr is a file or a pipe (scripts read it).
class ProgressLine {
public:
    ProgressLine() : tty_(platform::stderr_is_terminal()), start_(std::chrono::steady_clock::now()) {}
    ~ProgressLine() {
        if (shown_) std::cerr << "\r                         \r" << std::flush;
    }
    void operator()(std::size_t done, std::size_t total) {
        if (!tty_ || total == 0) return;
        const auto percent = static_cast<int>(100 * done / total);
        if (percent == last_) return;
        if (!shown_ && std::chrono::steady_clock::now() - start_ < std::chrono::seconds(1)) return;
        last_ = percent;
        shown_ = true;
        std::cerr << "\rlaying out: " << percent << "%" << std::flush;
    }

private:
    bool tty_;
    std::chrono::steady_clock::time_point start_;
    bool shown_ = false;
    int last_ = -1;
};

}  // namespace

layout::PagedDocument lay_out_for_cli(const LayoutArgs& args, const pipeline::PipelineOptions& options,
                                      const profile::PrinterProfile* machine,
                                      const std::optional<machine::FirmwareTables>& firmware, bool legacy_protocol,
                                      std::vector<std::string>* labels) {
    const auto kind = graphic::drawing_kind(args.file);
    const bool svg = kind == graphic::DrawingKind::svg && (args.format == "auto" || args.format == "svg");
    const bool picture = kind == graphic::DrawingKind::picture && args.format == "auto";
    if (svg || picture) {
        const auto m = machine ? *machine : profile::default_profile();
        const auto table = require(translate::Translator::open(options.tables), exit_usage);
        const graphic::DrawingFileOptions drawing_options{.image_threshold = args.image_threshold,
                                                          .firmware = firmware ? &*firmware : nullptr,
                                                          .legacy_protocol = legacy_protocol};
        auto laid = require(graphic::lay_out_drawing_file(args.file, kind, m, options.layout.geometry, table, drawing_options));
        for (const auto& w : laid.document.warnings)
            std::cerr << "tactus-cli: " << args.file << ": warning: " << w << '\n';
        if (labels) *labels = pipeline::page_labels(laid.document);
        return std::move(laid.document);
    }
    const auto doc = require(import::import_file(args.file, options.import));
    if (layout::is_ready_braille(doc) && !options.reflow_braille)
        if (auto fits = layout::check_braille_fits(doc, options.layout); !fits)
            fail_with(exit_page_too_small, located(fits.error(), args.file));
    Result<layout::PagedDocument> laid = fail(ErrorKind::internal, "not laid out");
    {
        ProgressLine progress;
        auto with_progress = options;
        with_progress.progress = [&progress](std::size_t done, std::size_t total) { progress(done, total); };
        if (options.import.images) {
            // Each picture on the machine's page and grid, as a drawing file of its own would be.
            auto table = std::make_shared<translate::Translator>(
                require(translate::Translator::open(options.tables), exit_usage));
            const auto m = machine ? *machine : profile::default_profile();
            const graphic::DrawingFileOptions drawing_options{.image_threshold = args.image_threshold,
                                                              .firmware = firmware ? &*firmware : nullptr,
                                                              .legacy_protocol = legacy_protocol};
            with_progress.graphic_pages = graphic::picture_pages(table, m, options.layout.geometry, drawing_options);
        }
        laid = pipeline::lay_out(doc, with_progress, labels);
    }
    auto paged = require(std::move(laid));
    for (const auto& w : paged.warnings) std::cerr << "tactus-cli: " << args.file << ": warning: " << w << '\n';
    return paged;
}

}  // namespace tactus::cli
