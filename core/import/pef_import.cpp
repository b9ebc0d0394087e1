// SPDX-License-Identifier: GPL-3.0-or-later
// PEF 2008-1: every <page> becomes one verbatim braille block (its <row>s), with
// a braille page break between pages. The page grid (cols, rows, rowgap, duplex of
// each volume and section, sections overriding their volume), the sections
// themselves and the dc: metadata are kept in the document, so the pages can be
// embossed and exported as they are (layout/braille_pages.hpp). Impossible
// attribute values (cols="0", rows="-5", duplex="maybe", rowgap="-1") are refused with their line.
#include <array>
#include <charconv>
#include <cstdio>

#include "common/utf8.hpp"
#include "import/document_builder.hpp"
#include "import/trim.hpp"
#include "import/importers.hpp"
#include "import/text_position.hpp"
#include "import/xml_util.hpp"
#include "common/try.hpp"

namespace tactus::import::detail {
namespace {

constexpr std::string_view pef_ns = "http://www.daisy.org/ns/2008/pef";
constexpr std::string_view dc_ns = "http://purl.org/dc/elements/1.1/";

// The grid in force for a section: its volume's attributes, overridden by its own.
struct Grid {
    int cols = 0;
    int rows = 0;
    bool duplex = false;
    int rowgap = 0;
};

class PefReader {
public:
    explicit PefReader(std::string_view bytes) : lines_(bytes) {}

    Result<document::Document> read(const pugi::xml_node& root) {
        if (local_name(root) != "pef" || namespace_uri(root) != pef_ns)
            return fail(ErrorKind::input, "not a PEF 2008-1 document: root element is <" +
                            std::string(root.name()) + "> in namespace '" +
                            std::string(namespace_uri(root)) + "', expected <pef> in '" +
                            std::string(pef_ns) + "'",
                        std::to_string(line_of(root)));
        read_metadata(pef_child(root, "head"));
        const auto body = pef_child(root, "body");
        if (!body) return fail(ErrorKind::input, "PEF has no <body>", std::to_string(line_of(root)));
        bool any_volume = false;
        for (const auto& volume : pef_children(body, "volume")) {
            any_volume = true;
            Grid volume_grid;
            TACTUS_TRY_VOID(read_grid(volume, volume_grid, true));
            bool first_section = true;
            for (const auto& section : pef_children(volume, "section")) {
                Grid grid = volume_grid;
                TACTUS_TRY_VOID(read_grid(section, grid, false));
                sections_.push_back(document::BrailleSection{builder_.size(), grid.cols, grid.rows, grid.duplex,
                                                             first_section, grid.rowgap});
                first_section = false;
                max_cols_ = std::max(max_cols_, grid.cols);
                max_rows_ = std::max(max_rows_, grid.rows);
                for (const auto& page : pef_children(section, "page"))
                    TACTUS_TRY_VOID(read_page(page, grid));
            }
        }
        if (!any_volume) return fail(ErrorKind::input, "PEF <body> has no <volume>", std::to_string(line_of(body)));
        auto doc = builder_.finish();
        if (!doc) return doc;
        doc->braille_sections = std::move(sections_);
        doc->braille_grid = document::BrailleGrid{max_cols_, max_rows_};
        doc->metadata = std::move(metadata_);
        return doc;
    }

private:
    // Every Dublin Core element of <meta>, in document order (dc:format included),
    // so an exported PEF can carry them again.
    void read_metadata(const pugi::xml_node& head) {
        if (!head) return;
        for (const auto& meta : head.children()) {
            if (!is_pef(meta, "meta")) continue;
            for (const auto& e : meta.children())
                if (e.type() == pugi::node_element && namespace_uri(e) == dc_ns)
                    metadata_.push_back(document::MetadataItem{std::string(local_name(e)), std::string(trim(e.child_value()))});
        }
    }

    // xsd:positiveInteger / xsd:boolean as the schema defines them.
    Result<void> read_grid(const pugi::xml_node& n, Grid& grid, bool required) {
        const auto where = std::to_string(line_of(n));
        const auto element = "<" + std::string(local_name(n)) + ">";
        for (const auto& [name, field] : {std::pair{"cols", &grid.cols}, std::pair{"rows", &grid.rows}}) {
            const auto a = n.attribute(name);
            if (!a) {
                if (required) return fail(ErrorKind::input, element + " has no " + name + " attribute", where);
                continue;
            }
            auto v = trim(a.value());
            if (v.starts_with('+')) v.remove_prefix(1);
            int value = 0;
            const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), value);
            if (v.empty() || ec != std::errc{} || end != v.data() + v.size() || value < 1 || value > 1000)
                return fail(ErrorKind::input, element + " " + name + "=\"" + a.value() +
                                "\" is not a page size: it must be a whole number from 1 to 1000",
                            where);
            *field = value;
        }
        if (auto ok = read_rowgap(n, required, &grid.rowgap); !ok) return ok;
        if (const auto a = n.attribute("duplex")) {
            const auto v = trim(a.value());
            if (v == "true" || v == "1") grid.duplex = true;
            else if (v == "false" || v == "0") grid.duplex = false;
            else
                return fail(ErrorKind::input, element + " duplex=\"" + std::string(a.value()) + "\" must be true or false", where);
        } else if (required) {
            return fail(ErrorKind::input, element + " has no duplex attribute", where);
        }
        return {};
    }

    // rowgap (xsd:nonNegativeInteger) on a volume (required), section, page or
    // row. Tactus writes its own (0, or 1 for 8-dot), but a value the schema
    // forbids marks a broken file, refused like cols="0".
    // `value`, when given, receives it (a volume's or a section's: kept in the grid).
    Result<void> read_rowgap(const pugi::xml_node& n, bool required, int* value_out = nullptr) const {
        const auto a = n.attribute("rowgap");
        const auto element = "<" + std::string(local_name(n)) + ">";
        if (!a) {
            if (required) return fail(ErrorKind::input, element + " has no rowgap attribute", std::to_string(line_of(n)));
            return {};
        }
        auto v = trim(a.value());
        if (v.starts_with('+')) v.remove_prefix(1);
        int value = 0;
        const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), value);
        if (v.empty() || ec != std::errc{} || end != v.data() + v.size() || value < 0)
            return fail(ErrorKind::input, element + " rowgap=\"" + std::string(a.value()) + "\" must be a whole number, 0 or more",
                        std::to_string(line_of(n)));
        if (value_out) *value_out = value;
        return {};
    }

    Result<void> read_page(const pugi::xml_node& page, const Grid& grid) {
        if (builder_.full()) return {};
        if (auto ok = read_rowgap(page, false); !ok) return ok;
        builder_.braille_page_break(line_of(page));
        std::vector<document::BrailleLine> rows;
        for (const auto& row : pef_children(page, "row")) {
            TACTUS_TRY(line, read_row(row));
            if (static_cast<int>(line.size()) > grid.cols)
                return fail(ErrorKind::input, "row of " + std::to_string(line.size()) + " cells is longer than cols=\"" +
                                std::to_string(grid.cols) + "\"",
                            std::to_string(line_of(row)));
            rows.push_back(std::move(line));
        }
        if (static_cast<int>(rows.size()) > grid.rows)
            return fail(ErrorKind::input, "page has " + std::to_string(rows.size()) + " rows but rows=\"" + std::to_string(grid.rows) +
                            "\"",
                        std::to_string(line_of(page)));
        builder_.braille_block(std::move(rows), line_of(page));
        return {};
    }

    Result<document::BrailleLine> read_row(const pugi::xml_node& row) {
        TACTUS_TRY_VOID(read_rowgap(row, false));
        const auto decoded = utf8_to_utf32(row.child_value());
        if (!decoded) return std::unexpected(located(decoded.error(), std::to_string(line_of(row))));
        document::BrailleLine line;
        line.reserve(decoded->size());
        for (std::size_t i = 0; i < decoded->size(); ++i) {
            const char32_t c = (*decoded)[i];
            // XML white space in a row is the file's layout (a row broken over
            // lines, indented), not cells: PEF readers skip it, and so does
            // Tactus. A blank cell is U+2800.
            if (c == U' ' || c == U'\n' || c == U'\r' || c == U'\t') continue;
            if (!document::Cell::is_unicode_braille(c)) {
                std::array<char, 64> what{};
                std::snprintf(what.data(), what.size(), "row character %zu is U+%04X", i + 1,
                              static_cast<unsigned>(c));
                return fail(ErrorKind::input, std::string(what.data()) +
                                ", not a braille cell (U+2800..U+28FF)",
                            std::to_string(line_of(row)));
            }
            line.push_back(document::Cell::from_unicode(c));
        }
        return line;
    }

    // PEF elements only: foreign-namespace extensions are allowed by the schema.
    static bool is_pef(const pugi::xml_node& n, std::string_view local) {
        return n.type() == pugi::node_element && local_name(n) == local && namespace_uri(n) == pef_ns;
    }
    static pugi::xml_node pef_child(const pugi::xml_node& parent, std::string_view local) {
        for (const auto& c : parent.children())
            if (is_pef(c, local)) return c;
        return {};
    }
    static std::vector<pugi::xml_node> pef_children(const pugi::xml_node& parent,
                                                    std::string_view local) {
        std::vector<pugi::xml_node> out;
        for (const auto& c : parent.children())
            if (is_pef(c, local)) out.push_back(c);
        return out;
    }

    int line_of(const pugi::xml_node& n) const {
        const auto offset = n.offset_debug();
        return offset < 0 ? 0 : lines_.line_at(static_cast<std::size_t>(offset));
    }

    LineIndex lines_;
    DocumentBuilder builder_;
    std::vector<document::BrailleSection> sections_;
    std::vector<document::MetadataItem> metadata_;
    int max_cols_ = 0, max_rows_ = 0;
};

}  // namespace

Result<document::Document> import_pef(std::string_view bytes) {
    pugi::xml_document xml;
    TACTUS_TRY_VOID(parse_xml(xml, bytes, ""));
    const auto root = xml.document_element();
    if (!root) return fail(ErrorKind::input, "no root element", "1");
    return PefReader(bytes).read(root);
}

}  // namespace tactus::import::detail
