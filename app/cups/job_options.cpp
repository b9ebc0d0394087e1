// SPDX-License-Identifier: GPL-3.0-or-later
#include "job_options.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "profile/page_geometry.hpp"
#include "translate/translator.hpp"

namespace tactus::cups {
namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    std::ranges::transform(out, out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

const std::string* find(const CupsOptions& o, std::string_view name) {
    const auto it = o.find(name);
    return it == o.end() ? nullptr : &it->second;
}

Result<bool> boolean(const CupsOptions& o, std::string_view name, bool fallback) {
    const auto* v = find(o, name);
    if (!v) return fallback;
    const auto s = lower(*v);
    if (s == "true" || s == "yes" || s == "on" || s == "1") return true;
    if (s == "false" || s == "no" || s == "off" || s == "0") return false;
    return fail(ErrorKind::usage, "'" + *v + "' is not true or false", "option " + std::string(name));
}

Result<int> count(const CupsOptions& o, std::string_view name, int fallback, int lo, int hi) {
    const auto* v = find(o, name);
    if (!v) return fallback;
    int n = 0;
    const auto [end, ec] = std::from_chars(v->data(), v->data() + v->size(), n);
    if (ec != std::errc{} || end != v->data() + v->size() || n < lo || n > hi)
        return fail(ErrorKind::usage, "'" + *v + "' is not a whole number from " + std::to_string(lo) + " to " + std::to_string(hi),
                    "option " + std::string(name));
    return n;
}

}  // namespace

Result<std::string> braille_table(std::string_view value) {
    if (value.empty()) return fail(ErrorKind::usage, "no table named", "option " + std::string(kBrailleTable));
    std::string list;
    std::size_t start = 0;
    while (start <= value.size()) {
        const auto comma = std::min(value.find(',', start), value.size());
        const std::string one(value.substr(start, comma - start));
        std::string chosen;
        // A table is named as liblouis names it, or without its extension.
        for (const auto& candidate : {one, one + ".ctb", one + ".utb"}) {
            if (one.empty() || one.find('/') != std::string::npos) break;  // no paths from the network
            if (translate::Translator::open(candidate)) {
                chosen = candidate;
                break;
            }
        }
        if (chosen.empty())
            return fail(ErrorKind::usage, "'" + one + "' is not an installed braille table (`tactus-cli tables` lists them, e.g. en-ueb-g2)",
                        "option " + std::string(kBrailleTable));
        list += (list.empty() ? "" : ",") + chosen;
        start = comma + 1;
    }
    return list;
}

Result<pipeline::PipelineOptions> pipeline_options(const CupsOptions& o, const profile::PrinterProfile& profile) {
    pipeline::PipelineOptions out;
    const auto& machine = profile.geometry;
    auto& g = out.layout.geometry;
    g = tactus::profile::page_geometry(profile);
    if (const auto* t = find(o, kBrailleTable)) {
        auto tables = braille_table(*t);
        if (!tables) return std::unexpected(tables.error());
        out.tables = *tables;
    }
    auto interpoint = boolean(o, kInterpoint, machine.interpoint);
    if (!interpoint) return std::unexpected(interpoint.error());
    if (*interpoint != machine.interpoint)
        return fail(ErrorKind::usage, std::string("this embosser is set up for ") + (machine.interpoint ? "interpoint" : "single-sided") +
                        " embossing (its profile on the print server); " + std::string(kInterpoint) + "=" +
                        (*interpoint ? "true" : "false") + " cannot be honoured",
                    "option " + std::string(kInterpoint));
    // Narrower or shorter pages fit the machine; larger ones would not.
    auto cells = count(o, kCellsPerLine, machine.cells_per_line, 4, machine.cells_per_line);
    if (!cells) return std::unexpected(cells.error());
    auto lines = count(o, kLinesPerPage, machine.lines_per_page, 3, machine.lines_per_page);
    if (!lines) return std::unexpected(lines.error());
    g.cells_per_line = *cells;
    g.lines_per_page = *lines;
    auto eight = boolean(o, kEightDot, machine.eight_dot);
    if (!eight) return std::unexpected(eight.error());
    g.eight_dot = machine.eight_dot || *eight;
    if (const auto* v = find(o, kPageNumbers)) {
        auto pos = layout::parse_page_number_position(*v);
        if (!pos) return std::unexpected(located(pos.error(), "option " + std::string(kPageNumbers)));
        out.layout.page_numbers = *pos;
    }
    auto print_pages = boolean(o, kPrintPages, true);
    if (!print_pages) return std::unexpected(print_pages.error());
    out.layout.print_page_indicators = *print_pages;
    if (const auto* v = find(o, kTextEncoding)) out.import.encoding = *v;
    if (auto ok = layout::validate(out.layout); !ok) return std::unexpected(ok.error());
    return out;
}

Result<import::SourceFormat> source_format(std::string_view mime_type) {
    using import::SourceFormat;
    const auto t = lower(mime_type);
    if (t == "text/plain") return SourceFormat::text;
    if (t == "text/markdown") return SourceFormat::markdown;
    if (t == "application/vnd.openxmlformats-officedocument.wordprocessingml.document") return SourceFormat::docx;
    if (t == "application/vnd.oasis.opendocument.text") return SourceFormat::odt;
    if (t == "application/x-brf") return SourceFormat::brf;
    if (t == "application/x-pef+xml") return SourceFormat::pef;
    return fail(ErrorKind::input, "Tactus cannot lay out " + std::string(mime_type) +
                    " documents; send plain text, Markdown, DOCX, ODT, BRF or PEF",
                "CONTENT_TYPE");
}

}  // namespace tactus::cups
