// SPDX-License-Identifier: GPL-3.0-or-later
// PEF 2008-1: every <page> becomes one verbatim braille block (its <row>s), with
// a braille page break between pages. Volume and section boundaries start a new
// page in PEF anyway, so they become page breaks too.
#include <array>
#include <cstdio>

#include "common/utf8.hpp"
#include "import/document_builder.hpp"
#include "import/importers.hpp"
#include "import/text_position.hpp"
#include "import/xml_util.hpp"

namespace tactus::import::detail {
namespace {

constexpr std::string_view pef_ns = "http://www.daisy.org/ns/2008/pef";

class PefReader {
public:
    explicit PefReader(std::string_view bytes) : lines_(bytes) {}

    Result<document::Document> read(const pugi::xml_node& root) {
        if (local_name(root) != "pef" || namespace_uri(root) != pef_ns)
            return fail("not a PEF 2008-1 document: root element is <" +
                            std::string(root.name()) + "> in namespace '" +
                            std::string(namespace_uri(root)) + "', expected <pef> in '" +
                            std::string(pef_ns) + "'",
                        std::to_string(line_of(root)));
        const auto body = pef_child(root, "body");
        if (!body) return fail("PEF has no <body>", std::to_string(line_of(root)));
        bool any_volume = false;
        for (const auto& volume : pef_children(body, "volume")) {
            any_volume = true;
            for (const auto& section : pef_children(volume, "section"))
                for (const auto& page : pef_children(section, "page"))
                    if (auto ok = read_page(page); !ok) return std::unexpected(ok.error());
        }
        if (!any_volume) return fail("PEF <body> has no <volume>", std::to_string(line_of(body)));
        return builder_.finish();
    }

private:
    Result<void> read_page(const pugi::xml_node& page) {
        if (builder_.full()) return {};
        builder_.braille_page_break(line_of(page));
        std::vector<document::BrailleLine> rows;
        for (const auto& row : pef_children(page, "row")) {
            auto line = read_row(row);
            if (!line) return std::unexpected(line.error());
            rows.push_back(std::move(*line));
        }
        builder_.braille_block(std::move(rows), line_of(page));
        return {};
    }

    Result<document::BrailleLine> read_row(const pugi::xml_node& row) {
        const auto decoded = utf8_to_utf32(row.child_value());
        if (!decoded) return std::unexpected(located(decoded.error(), std::to_string(line_of(row))));
        document::BrailleLine line;
        line.reserve(decoded->size());
        for (std::size_t i = 0; i < decoded->size(); ++i) {
            const char32_t c = (*decoded)[i];
            if (!document::Cell::is_unicode_braille(c)) {
                std::array<char, 64> what{};
                std::snprintf(what.data(), what.size(), "row character %zu is U+%04X", i + 1,
                              static_cast<unsigned>(c));
                return fail(std::string(what.data()) +
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
};

}  // namespace

Result<document::Document> import_pef(std::string_view bytes) {
    pugi::xml_document xml;
    if (auto ok = parse_xml(xml, bytes, ""); !ok) return std::unexpected(ok.error());
    const auto root = xml.document_element();
    if (!root) return fail("no root element", "1");
    return PefReader(bytes).read(root);
}

}  // namespace tactus::import::detail
