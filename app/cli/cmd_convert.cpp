// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli convert: a document saved in another print format (Markdown,
// text, DOCX, ODT), as the app's Save As does, pictures kept in DOCX and ODT;
// what the format does not keep is named on stderr.
#include <iostream>

#include "command.hpp"
#include "export/document_save.hpp"
#include "import/import.hpp"

namespace tactus::cli {

void add_convert_command(CLI::App& app) {
    struct Args {
        std::string input, output, to;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand(
        "convert",
        "Save a document (any format Tactus reads) as Markdown, text, DOCX or ODT; the format is the output's "
        "extension or --to. What the format does not keep is named on stderr. Exit 3 if the input cannot be read, "
        "2 for an unknown output format.");
    cmd->add_option("input", args->input, "Document to read")->required()->check(CLI::ExistingFile);
    cmd->add_option("output", args->output, "File to write (replaced atomically)")->required();
    cmd->add_option("--to", args->to, "Output format: md, txt, docx, odt (default: from the output's extension)");
    cmd->callback([args] {
        exporter::DocumentFormat format{};
        if (!args->to.empty()) {
            format = require(exporter::parse_document_format(args->to));
        } else if (const auto by_name = exporter::document_format_for(args->output)) {
            format = *by_name;
        } else {
            fail_with(exit_usage, Error{"cannot tell the format from the name; give --to md, txt, docx or odt",
                                        args->output, ErrorKind::usage});
        }
        // DOCX and ODT keep pictures (docs/import.md, "Saving DOCX and ODT"):
        // opened with them, they are saved; Markdown and text keep their
        // descriptions only.
        import::ImportOptions options;
        options.images = format == exporter::DocumentFormat::docx || format == exporter::DocumentFormat::odt;
        const auto document = require(import::import_file(args->input, options));
        for (const auto& w : document.warnings) std::cerr << "tactus-cli: " << args->input << ": " << w << '\n';
        const auto warnings = require(exporter::save_document(document, format, args->output));
        for (const auto& w : warnings) std::cerr << "tactus-cli: " << args->output << ": " << w << '\n';
    });
}

}  // namespace tactus::cli
