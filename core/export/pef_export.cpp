// SPDX-License-Identifier: GPL-3.0-or-later
#include <pugixml.hpp>

#include <cstdint>
#include <cstdio>
#include <sstream>

#include "export/export.hpp"

namespace tactus {
namespace {

// A stable identifier from the content, so the same braille gives the same PEF.
std::string content_id(const PagedDocument& doc) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a
    auto mix = [&h](std::uint8_t b) {
        h ^= b;
        h *= 1099511628211ull;
    };
    for (const auto& page : doc.pages) {
        for (const auto& line : page.lines) {
            for (Cell c : line) mix(c.dots);
            mix(0xFF);
        }
    }
    char buf[40];
    std::snprintf(buf, sizeof buf, "tactus-%016llx", static_cast<unsigned long long>(h));
    return buf;
}

}  // namespace

Result<std::string> to_pef(const PagedDocument& doc, const PefMetadata& meta) {
    pugi::xml_document xml;
    auto decl = xml.append_child(pugi::node_declaration);
    decl.append_attribute("version") = "1.0";
    decl.append_attribute("encoding") = "UTF-8";
    auto pef = xml.append_child("pef");
    pef.append_attribute("version") = "2008-1";
    pef.append_attribute("xmlns") = "http://www.daisy.org/ns/2008/pef";
    auto head = pef.append_child("head");
    auto m = head.append_child("meta");
    m.append_attribute("xmlns:dc") = "http://purl.org/dc/elements/1.1/";
    m.append_child("dc:format").text() = "application/x-pef+xml";
    m.append_child("dc:identifier").text() =
        (meta.identifier.empty() ? content_id(doc) : meta.identifier).c_str();
    m.append_child("dc:title").text() = meta.title.c_str();
    if (!meta.language.empty()) m.append_child("dc:language").text() = meta.language.c_str();
    if (!meta.date.empty()) m.append_child("dc:date").text() = meta.date.c_str();

    const auto& g = doc.geometry;
    auto volume = pef.append_child("body").append_child("volume");
    volume.append_attribute("cols") = g.cells_per_line;
    volume.append_attribute("rows") = g.lines_per_page;
    volume.append_attribute("rowgap") = g.eight_dot ? 1 : 0;
    volume.append_attribute("duplex") = g.interpoint ? "true" : "false";
    auto section = volume.append_child("section");
    for (const auto& page : doc.pages) {
        auto p = section.append_child("page");
        if (page.lines.size() > static_cast<std::size_t>(g.lines_per_page))
            return fail("page has more rows than the volume allows",
                        "page " + std::to_string(page.braille_number));
        std::size_t used = page.lines.size();
        while (used > 0 && page.lines[used - 1].empty()) --used;
        for (std::size_t i = 0; i < used; ++i) {
            if (page.lines[i].size() > static_cast<std::size_t>(g.cells_per_line))
                return fail("row longer than cols", "page " + std::to_string(page.braille_number) +
                                                        " row " + std::to_string(i + 1));
            auto row = p.append_child("row");
            if (!page.lines[i].empty()) row.text() = to_unicode_text(page.lines[i]).c_str();
        }
    }
    if (doc.pages.empty()) section.append_child("page");  // a section needs a page
    std::ostringstream out;
    xml.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
    return out.str();
}

}  // namespace tactus
