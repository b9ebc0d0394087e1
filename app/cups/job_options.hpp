// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What `lp -o name=value` means to a Tactus queue (the PPD lists the same
// options for print dialogs; docs/cups.md has the table). The page format is
// the embosser's profile on the server; options may only narrow it. A value
// the option does not take is an error naming the option and what it takes,
// so the job fails before anything is embossed.
#include <map>
#include <string>
#include <string_view>

#include "common/result.hpp"
#include "import/import.hpp"
#include "ipp/queue_options.hpp"
#include "pipeline/pipeline.hpp"
#include "profile/profile.hpp"

namespace tactus::cups {

// CUPS option name -> value, as cupsParseOptions gives them (a bare "name" is
// "true", "noname" is "false"). Options Tactus does not know are CUPS's own
// (job-uuid, number-up, ...) and are ignored.
using CupsOptions = std::map<std::string, std::string, std::less<>>;

// Every option the filter reads; the PPD and docs/cups.md list the same. The
// names live in core (ipp/queue_options.hpp), where clients that send jobs to
// a Tactus queue (tactus-cli emboss --device ipp://...) take them from too.
inline constexpr std::string_view kBrailleTable = ipp::option::braille_table;
inline constexpr std::string_view kInterpoint = ipp::option::interpoint;
inline constexpr std::string_view kCellsPerLine = ipp::option::cells_per_line;
inline constexpr std::string_view kLinesPerPage = ipp::option::lines_per_page;
inline constexpr std::string_view kPageNumbers = ipp::option::page_numbers;
inline constexpr std::string_view kPrintPages = ipp::option::print_pages;
inline constexpr std::string_view kEightDot = ipp::option::eight_dot;
inline constexpr std::string_view kTextEncoding = ipp::option::text_encoding;

// "en-ueb-g2" or "en-ueb-g2.ctb" (or a comma-separated list) -> the liblouis
// table list; each must be an installed table (`tactus-cli tables`).
Result<std::string> braille_table(std::string_view value);

// The pipeline options for one job: the profile's page format, narrowed by
// the options.
Result<pipeline::PipelineOptions> pipeline_options(const CupsOptions& options, const profile::PrinterProfile& profile);

// The source format from the MIME type CUPS decided on (CONTENT_TYPE):
// text/plain, text/markdown, DOCX, ODT, BRF, PEF; anything else is an error.
Result<import::SourceFormat> source_format(std::string_view mime_type);

}  // namespace tactus::cups
