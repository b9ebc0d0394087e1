// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <pugixml.hpp>

#include <cstdint>
#include <cstdio>
#include <sstream>

#include "common/utf8.hpp"
#include "document/main_language.hpp"
#include "export/export.hpp"
#include "common/try.hpp"

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

void write_page(const layout::Page& page, std::string& row, std::ostream& out) {
    std::size_t used = page.lines.size();
    while (used > 0 && page.lines[used - 1].empty()) --used;
    if (used == 0) {
        out << "        <page />\n";
        return;
    }
    out << "        <page>\n";
    for (std::size_t i = 0; i < used; ++i) {
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

}  // namespace

PefMetadata pef_metadata(const std::vector<document::MetadataItem>& source, std::string title,
                         std::string date, std::string language) {
    PefMetadata m;
    m.title = std::move(title);
    m.date = std::move(date);
    m.language = std::move(language);
    // A main language alone (a DOCX's, an ODT's) is the print's, not a head
    // of the source's own: the head made for this export is written, its
    // title, date and the braille's language kept.
    if (std::ranges::any_of(source, [](const document::MetadataItem& i) { return i.name != document::kLanguageItem; }))
        m.source = source;
    return m;
}

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
    if (!meta.source.empty()) {
        // The source's own metadata, in its order; an identifier is required.
        bool has_identifier = false;
        bool has_date = false;
        std::vector<std::string_view> once_written;
        for (const auto& item : meta.source) {
            if (item.name == "format") continue;
            // PEF allows one identifier, title and description (an EPUB may
            // have a subtitle as a second dc:title): the first is kept.
            if (item.name == "identifier" || item.name == "title" || item.name == "description") {
                if (std::ranges::find(once_written, item.name) != once_written.end()) continue;
                once_written.push_back(item.name);
            }
            has_identifier = has_identifier || item.name == "identifier";
            std::string value = item.value;
            if (item.name == "date") {
                // PEF allows one dc:date, YYYY-MM-DD; an EPUB's is often a
                // timestamp ("2015-05-12T00:01:00Z") or a year: the day is
                // kept, anything else is left out.
                const auto digits = [&value](std::size_t from, std::size_t n) {
                    for (std::size_t i = from; i < from + n; ++i)
                        if (i >= value.size() || value[i] < '0' || value[i] > '9') return false;
                    return true;
                };
                const bool day = digits(0, 4) && value.size() >= 10 && value[4] == '-' && digits(5, 2) &&
                                 value[7] == '-' && digits(8, 2) && (value.size() == 10 || value[10] == 'T');
                if (!day || has_date) continue;
                value.resize(10);
                has_date = true;
            }
            m.append_child(("dc:" + item.name).c_str()).text() = value.c_str();
        }
        if (!has_identifier) m.append_child("dc:identifier").text() = content_id(doc).c_str();
    } else {
        m.append_child("dc:identifier").text() =
            (meta.identifier.empty() ? content_id(doc) : meta.identifier).c_str();
        m.append_child("dc:title").text() = meta.title.c_str();
        if (!meta.language.empty()) m.append_child("dc:language").text() = meta.language.c_str();
        if (!meta.date.empty()) m.append_child("dc:date").text() = meta.date.c_str();
    }

    const auto& g = doc.geometry;
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<pef version=\"2008-1\" xmlns=\"http://www.daisy.org/ns/2008/pef\">\n";
    // One level in, under <pef>: pugixml indents the elements, never the text
    // inside them (a multi-line dc:description stays as the source had it).
    head.print(out, "  ", pugi::format_indent, pugi::encoding_utf8, 1);
    out << "  <body>\n";
    // Ready-made braille keeps its volumes, its sections and each one's grid:
    // a volume's cols, rows, rowgap and duplex are its first section's; a
    // section that differs says so (PEF 2008-1 lets a section override its
    // volume). Laid-out text is one volume of one section, on the layout's page.
    struct Grid {
        int cols = 0, rows = 0, rowgap = 0;
        bool duplex = false;
        bool operator==(const Grid&) const = default;
    };
    const Grid layout_grid{g.cells_per_line, g.lines_per_page, g.eight_dot ? 1 : 0, g.interpoint};
    const auto grid_of = [&](const layout::PageSection& s) {
        return s.cols > 0 ? Grid{s.cols, s.rows, s.rowgap, s.duplex} : Grid{layout_grid.cols, layout_grid.rows,
                                                                           layout_grid.rowgap, s.duplex};
    };
    Grid volume = doc.sections.empty() ? layout_grid : grid_of(doc.sections.front());
    Grid section = volume;
    const auto open_volume = [&](const Grid& v) {
        volume = v;
        out << "    <volume cols=\"" << v.cols << "\" rows=\"" << v.rows << "\" rowgap=\"" << v.rowgap << "\" duplex=\""
            << (v.duplex ? "true" : "false") << "\">\n";
    };
    const auto open_section = [&](const Grid& s) {
        section = s;
        out << "      <section";
        if (s.cols != volume.cols) out << " cols=\"" << s.cols << '"';
        if (s.rows != volume.rows) out << " rows=\"" << s.rows << '"';
        if (s.rowgap != volume.rowgap) out << " rowgap=\"" << s.rowgap << '"';
        if (s.duplex != volume.duplex) out << " duplex=\"" << (s.duplex ? "true" : "false") << '"';
        out << ">\n";
    };
    open_volume(volume);
    open_section(volume);
    std::string row;
    std::size_t next_section = 0;
    bool section_has_page = false;
    for (std::size_t p = 0; p < doc.pages.size(); ++p) {
        const auto& page = doc.pages[p];
        while (next_section < doc.sections.size() && doc.sections[next_section].first_page == p) {
            const auto& s = doc.sections[next_section];
            if (next_section > 0) {
                if (!section_has_page) out << "        <page />\n";  // a section needs a page
                out << "      </section>\n";
                if (s.starts_volume) {
                    out << "    </volume>\n";
                    open_volume(grid_of(s));
                }
                open_section(grid_of(s));
            }
            section_has_page = false;
            ++next_section;
        }
        // Blank backs added for the embosser: PEF's sections and duplex say the same.
        if (page.filler) continue;
        // The rows written (blank ones at the end are the page's padding) fit the section's grid.
        std::size_t used = page.lines.size();
        while (used > 0 && page.lines[used - 1].empty()) --used;
        if (used > static_cast<std::size_t>(section.rows))
            return fail(ErrorKind::internal, "page has more rows than the volume allows",
                        "page " + std::to_string(page.braille_number));
        for (std::size_t i = 0; i < used; ++i)
            if (page.lines[i].size() > static_cast<std::size_t>(section.cols))
                return fail(ErrorKind::internal, "row longer than cols", "page " + std::to_string(page.braille_number) +
                                                        " row " + std::to_string(i + 1));
        write_page(page, row, out);
        section_has_page = true;
    }
    if (!section_has_page) out << "        <page />\n";  // a section needs a page
    out << "      </section>\n    </volume>\n  </body>\n</pef>\n";
    return {};
}

Result<std::string> to_pef(const layout::PagedDocument& doc, const PefMetadata& meta) {
    std::ostringstream out;
    TACTUS_TRY_VOID(write_pef(doc, meta, out));
    return std::move(out).str();
}

}  // namespace tactus::exporter
