// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/snapshot.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "common/utf8.hpp"
#include "common/try.hpp"

namespace tactus::spool {
namespace {

using nlohmann::json;

std::string page_where(std::size_t page, std::size_t line = 0) {
    std::string w = "page " + std::to_string(page);
    if (line) w += " line " + std::to_string(line);
    return w;
}

// More dots than a sheet of A3 holds at the least distance: not a graphic page.
constexpr std::size_t kMaxGraphicDots = 200000;

}  // namespace

std::string to_snapshot(const layout::PagedDocument& doc) {
    json pages = json::array();
    for (const auto& page : doc.pages) {
        json lines = json::array();
        for (const auto& line : page.lines) lines.push_back(document::to_unicode_text(line));
        json entry{{"number", page.braille_number}, {"print_page", page.print_page}, {"lines", std::move(lines)}};
        // A graphic's free dots, as [x, y] in millimetres; absent on a page of text.
        if (!page.graphic.empty()) {
            json dots = json::array();
            for (const auto& d : page.graphic) dots.push_back(json::array({d.x_mm, d.y_mm}));
            entry["graphic"] = std::move(dots);
        }
        pages.push_back(std::move(entry));
    }
    const json j{{"format", kSnapshotFormat},
                 {"geometry",
                  {{"cells_per_line", doc.geometry.cells_per_line},
                   {"lines_per_page", doc.geometry.lines_per_page},
                   {"interpoint", doc.geometry.interpoint},
                   {"eight_dot", doc.geometry.eight_dot}}},
                 {"pages", std::move(pages)}};
    return j.dump();
}

Result<layout::PagedDocument> from_snapshot(std::string_view text) {
    const json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded() || !j.is_object()) return fail(ErrorKind::input, "document snapshot is not valid JSON");
    // Every field's type is checked before it is read: json::value() and get()
    // throw on a wrong type, and one stored job must never abort the server.
    const auto format = j.find("format");
    if (format == j.end() || !format->is_string() || format->get<std::string>() != kSnapshotFormat)
        return fail(ErrorKind::input, "document snapshot has an unknown format (expected " +
                        std::string(kSnapshotFormat) + ")",
                    "format");
    const auto g = j.find("geometry");
    const auto pages = j.find("pages");
    if (g == j.end() || !g->is_object() || pages == j.end() || !pages->is_array())
        return fail(ErrorKind::input, "document snapshot lacks its geometry or pages");

    layout::PagedDocument doc;
    auto int_field = [&](const char* name, int& out) -> Result<void> {
        const auto it = g->find(name);
        if (it == g->end() || !it->is_number_integer() || it->get<std::int64_t>() < 1 ||
            it->get<std::int64_t>() > 1000)
            return fail(ErrorKind::input, "missing or out of range", std::string("geometry.") + name);
        out = static_cast<int>(it->get<std::int64_t>());
        return {};
    };
    auto bool_field = [&](const char* name, bool& out) -> Result<void> {
        const auto it = g->find(name);
        if (it == g->end() || !it->is_boolean()) return fail(ErrorKind::input, "missing or not true/false", std::string("geometry.") + name);
        out = it->get<bool>();
        return {};
    };
    TACTUS_TRY_VOID(int_field("cells_per_line", doc.geometry.cells_per_line));
    TACTUS_TRY_VOID(int_field("lines_per_page", doc.geometry.lines_per_page));
    TACTUS_TRY_VOID(bool_field("interpoint", doc.geometry.interpoint));
    TACTUS_TRY_VOID(bool_field("eight_dot", doc.geometry.eight_dot));

    const auto max_cells = static_cast<std::size_t>(doc.geometry.cells_per_line);
    const auto max_lines = static_cast<std::size_t>(doc.geometry.lines_per_page);
    std::size_t page_no = 0;
    for (const auto& p : *pages) {
        ++page_no;
        const auto lines = p.find("lines");
        const auto number = p.find("number");
        const auto print = p.find("print_page");
        if (!p.is_object() || lines == p.end() || !lines->is_array() || number == p.end() ||
            !number->is_number_integer() || number->get<std::int64_t>() < -1000000 ||
            number->get<std::int64_t>() > 1000000 || print == p.end() || !print->is_string())
            return fail(ErrorKind::input, "malformed page", page_where(page_no));
        if (lines->size() > max_lines)
            return fail(ErrorKind::input, std::to_string(lines->size()) + " lines, the geometry allows " +
                            std::to_string(max_lines),
                        page_where(page_no));
        layout::Page page;
        page.braille_number = number->get<int>();
        page.print_page = print->get<std::string>();
        std::size_t line_no = 0;
        for (const auto& l : *lines) {
            ++line_no;
            if (!l.is_string()) return fail(ErrorKind::input, "line is not text", page_where(page_no, line_no));
            auto cps = utf8_to_utf32(l.get<std::string>());
            if (!cps) return std::unexpected(located(cps.error(), page_where(page_no, line_no)));
            if (cps->size() > max_cells)
                return fail(ErrorKind::input, std::to_string(cps->size()) + " cells, the geometry allows " +
                                std::to_string(max_cells),
                            page_where(page_no, line_no));
            document::BrailleLine line;
            line.reserve(cps->size());
            for (char32_t c : *cps) {
                if (!document::Cell::is_unicode_braille(c))
                    return fail(ErrorKind::input, "not a braille cell", page_where(page_no, line_no));
                line.push_back(document::Cell::from_unicode(c));
            }
            page.lines.push_back(std::move(line));
        }
        if (const auto dots = p.find("graphic"); dots != p.end()) {
            if (!dots->is_array() || dots->size() > kMaxGraphicDots)
                return fail(ErrorKind::input, "graphic dots are not a list of at most " + std::to_string(kMaxGraphicDots),
                            page_where(page_no));
            for (const auto& d : *dots) {
                if (!d.is_array() || d.size() != 2 || !d[0].is_number() || !d[1].is_number())
                    return fail(ErrorKind::input, "a graphic dot is not [x, y]", page_where(page_no));
                const double x = d[0].get<double>(), y = d[1].get<double>();
                if (!(std::abs(x) <= 10000 && std::abs(y) <= 10000))
                    return fail(ErrorKind::input, "a graphic dot is out of range", page_where(page_no));
                page.graphic.push_back({x, y});
            }
        }
        doc.pages.push_back(std::move(page));
    }
    return doc;
}

Result<layout::PagedDocument> select_pages(const layout::PagedDocument& doc, std::size_t first, std::size_t last) {
    const std::size_t n = doc.pages.size();
    if (first == 0) first = 1;
    if (last == 0) last = n;
    if (first > last || last > n)
        return fail(ErrorKind::input, "page range " + std::to_string(first) + "-" + std::to_string(last) +
                        " is outside the document's " + std::to_string(n) + " pages",
                    "--pages");
    layout::PagedDocument out;
    out.geometry = doc.geometry;
    out.pages.assign(doc.pages.begin() + static_cast<std::ptrdiff_t>(first - 1),
                     doc.pages.begin() + static_cast<std::ptrdiff_t>(last));
    return out;
}

}  // namespace tactus::spool
