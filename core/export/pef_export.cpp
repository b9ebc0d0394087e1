// SPDX-License-Identifier: GPL-3.0-or-later
#include <pugixml.hpp>

#include <cstdint>
#include <cstdio>
#include <sstream>

#include "common/utf8.hpp"
#include "export/export.hpp"

namespace tactus::exporter {
namespace {

// A stable identifier from the content, so the same braille gives the same PEF.
std::string content_id(const layout::PagedDocument& doc) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a
    auto mix = [&h](std::uint8_t b) {
        h ^= b;
        h *= 1099511628211ull;
    };
    for (const auto& page : doc.pages) {
        for (const auto& line : page.lines) {
            for (document::Cell c : line) mix(c.dots);
            mix(0xFF);
        }
    }
    char buf[40];
    std::snprintf(buf, sizeof buf, "tactus-%016llx", static_cast<unsigned long long>(h));
    return buf;
}


}  // namespace

Result<void> write_pef(const layout::PagedDocument& doc, const PefMetadata& meta, std::ostream& out) {
    // The head carries user text (title), so pugixml writes and escapes it. The
    // body is only braille code points (U+2800..U+28FF), which never need
    // escaping; it is streamed row by row, so a book-length PEF is never held in
    // memory, neither as a DOM nor as one string.
    pugi::xml_document head_xml;
    auto head = head_xml.append_child("head");
    auto m = head.append_child("meta");
    m.append_attribute("xmlns:dc") = "http://purl.org/dc/elements/1.1/";
    m.append_child("dc:format").text() = "application/x-pef+xml";
    m.append_child("dc:identifier").text() =
        (meta.identifier.empty() ? content_id(doc) : meta.identifier).c_str();
    m.append_child("dc:title").text() = meta.title.c_str();
    if (!meta.language.empty()) m.append_child("dc:language").text() = meta.language.c_str();
    if (!meta.date.empty()) m.append_child("dc:date").text() = meta.date.c_str();
    std::ostringstream head_text;
    head_xml.save(head_text, "  ", pugi::format_indent | pugi::format_no_declaration,
                  pugi::encoding_utf8);

    const auto& g = doc.geometry;
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<pef version=\"2008-1\" xmlns=\"http://www.daisy.org/ns/2008/pef\">\n";
    std::istringstream head_lines(head_text.str());
    for (std::string line; std::getline(head_lines, line);) out << "  " << line << '\n';
    out << "  <body>\n    <volume cols=\"" << g.cells_per_line << "\" rows=\"" << g.lines_per_page
        << "\" rowgap=\"" << (g.eight_dot ? 1 : 0) << "\" duplex=\""
        << (g.interpoint ? "true" : "false") << "\">\n      <section>\n";
    std::string row;
    for (const auto& page : doc.pages) {
        if (page.lines.size() > static_cast<std::size_t>(g.lines_per_page))
            return fail("page has more rows than the volume allows",
                        "page " + std::to_string(page.braille_number));
        std::size_t used = page.lines.size();
        while (used > 0 && page.lines[used - 1].empty()) --used;
        if (used == 0) {
            out << "        <page />\n";
            continue;
        }
        out << "        <page>\n";
        for (std::size_t i = 0; i < used; ++i) {
            if (page.lines[i].size() > static_cast<std::size_t>(g.cells_per_line))
                return fail("row longer than cols", "page " + std::to_string(page.braille_number) +
                                                        " row " + std::to_string(i + 1));
            if (page.lines[i].empty()) {
                out << "          <row />\n";
                continue;
            }
            row = "          <row>";
            for (document::Cell c : page.lines[i]) append_utf8(row, c.unicode());
            row += "</row>\n";
            out << row;
        }
        out << "        </page>\n";
    }
    if (doc.pages.empty()) out << "        <page />\n";  // a section needs a page
    out << "      </section>\n    </volume>\n  </body>\n</pef>\n";
    return {};
}

Result<std::string> to_pef(const layout::PagedDocument& doc, const PefMetadata& meta) {
    std::ostringstream out;
    if (auto ok = write_pef(doc, meta, out); !ok) return std::unexpected(ok.error());
    return std::move(out).str();
}

}  // namespace tactus::exporter
