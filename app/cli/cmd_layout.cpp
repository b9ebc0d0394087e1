// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli layout: import, translate and paginate a document, then write BRF,
// PEF or Unicode braille.
#include <ctime>
#include <filesystem>
#include <iostream>

#include "command.hpp"
#include "export/export.hpp"
#include "layout_args.hpp"
#include "pipeline/pipeline.hpp"
#include "platform/clock.hpp"
#include "translate/catalogue.hpp"

namespace tactus::cli {
namespace {

struct LayoutCommandArgs {
    LayoutArgs layout;
    std::string to;
    std::string output;
    bool summary = false;
    std::string brf_volumes = "breaks";
};

std::string today() {
    const std::time_t now = std::time(nullptr);
    const std::tm tm = platform::utc_time(now);
    char buf[16];
    std::strftime(buf, sizeof buf, "%Y-%m-%d", &tm);
    return buf;
}

void print_summary(std::ostream& out, const layout::PagedDocument& doc, const pipeline::PipelineOptions& o,
                   const std::string& file) {
    std::size_t cells = 0;
    std::size_t dots = 0;
    std::size_t lines = 0;
    for (const auto& p : doc.pages)
        for (const auto& l : p.lines) {
            if (!l.empty()) ++lines;
            for (document::Cell c : l) {
                if (!c.blank()) ++cells;
                dots += static_cast<std::size_t>(__builtin_popcount(c.dots));
            }
        }
    const auto& g = doc.geometry;
    out << "document:   " << file << '\n'
        << "table:      " << o.tables << '\n'
        << "format:     " << g.cells_per_line << " cells x " << g.lines_per_page << " lines, "
        << (g.interpoint ? "interpoint" : "single-sided") << ", "
        << (g.eight_dot ? "8-dot" : "6-dot") << '\n'
        << "pages:      " << doc.pages.size() << " braille pages on " << doc.sheet_count()
        << " sheets\n"
        << "content:    " << lines << " lines, " << cells << " cells, " << dots << " dots\n";
    std::size_t volumes = 0;
    for (const auto& s : doc.sections) volumes += s.starts_volume ? 1 : 0;
    if (volumes > 1) out << "volumes:    " << volumes << '\n';
    std::size_t graphic_dots = 0, graphic_pages = 0;
    std::string numbers;  // the graphic pages' braille page numbers, which a document's pictures move
    for (const auto& p : doc.pages) {
        graphic_dots += p.graphic.size();
        if (p.graphic.empty()) continue;
        ++graphic_pages;
        numbers += (numbers.empty() ? "" : ", ") + std::to_string(p.braille_number);
    }
    if (graphic_pages > 0)
        out << "graphic:    " << graphic_dots << " dots on " << graphic_pages << " graphic page"
            << (graphic_pages == 1 ? " (braille page " : "s (braille pages ") << numbers << ")\n";
    for (const auto& w : doc.warnings) out << "warning:    " << w << '\n';
}

void run_layout(const LayoutCommandArgs& a) {
    const auto options = a.layout.pipeline_options();
    const auto doc = lay_out_for_cli(a.layout, options);
    if (a.summary) {
        print_summary(std::cout, doc, options, a.layout.file);
        if (a.to.empty()) return;
    }
    if (a.to.empty())
        throw CLI::RequiredError("--to (or --summary)");
    const auto format = require(exporter::parse_export_format(a.to), exit_usage);
    // A PEF's own metadata is kept; anything else gets the file's name, today
    // and the table's language (as the app's export does).
    const auto meta = exporter::pef_metadata(doc.metadata, std::filesystem::path(a.layout.file).stem().string(), today(),
                                             translate::table_language_tag(options.tables));
    if (a.output.empty() || a.output == "-") {
        require(exporter::write_document(doc, format, meta, std::cout));
        return;
    }
    if (a.brf_volumes == "files" && format == exporter::ExportFormat::brf) {
        // One BRF per volume: NAME-1.brf, NAME-2.brf, ... beside the output name.
        std::vector<std::size_t> starts;
        for (const auto& s : doc.sections)
            if (s.starts_volume) starts.push_back(s.first_page);
        if (starts.empty() || starts.front() != 0) starts.insert(starts.begin(), 0);
        const std::filesystem::path out(a.output);
        for (std::size_t v = 0; v < starts.size(); ++v) {
            layout::PagedDocument part;
            part.geometry = doc.geometry;
            const auto end = v + 1 < starts.size() ? starts[v + 1] : doc.pages.size();
            part.pages.assign(doc.pages.begin() + static_cast<std::ptrdiff_t>(starts[v]),
                              doc.pages.begin() + static_cast<std::ptrdiff_t>(end));
            const auto name = (out.parent_path() / (out.stem().string() + "-" + std::to_string(v + 1) + out.extension().string())).string();
            require(exporter::export_to_file(part, format, meta, name));
            std::cerr << "wrote " << name << ": volume " << v + 1 << " of " << starts.size() << ", "
                      << part.pages.size() << " pages\n";
        }
        return;
    }
    require(exporter::export_to_file(doc, format, meta, a.output));
    std::cerr << "wrote " << a.output << ": " << doc.pages.size() << " pages on "
              << doc.sheet_count() << " sheets (" << doc.geometry.cells_per_line << "x"
              << doc.geometry.lines_per_page << ", "
              << (doc.geometry.interpoint ? "interpoint" : "single-sided") << ")\n";
}

}  // namespace

void add_layout_command(CLI::App& app) {
    auto args = std::make_shared<LayoutCommandArgs>();
    auto* cmd = app.add_subcommand("layout", "Lay out a document into braille pages (BRF, PEF, Unicode)");
    args->layout.add_to(*cmd);
    cmd->add_option("--to", args->to, "Output format: brf, pef or unicode")
        ->check(CLI::IsMember({"brf", "pef", "unicode"}));
    cmd->add_option("-o,--output", args->output, "Output file (written atomically); default stdout");
    cmd->add_option("--brf-volumes", args->brf_volumes,
                    "With --volumes and --to brf: 'breaks' (one file, volumes one after another on new sheets) "
                    "or 'files' (one file per volume: NAME-1.brf, NAME-2.brf, ...)")
        ->check(CLI::IsMember({"breaks", "files"}))->capture_default_str();
    cmd->add_flag("--summary", args->summary, "Print a summary of the pages instead of (or before) the output");
    cmd->callback([args] { run_layout(*args); });
}

}  // namespace tactus::cli
