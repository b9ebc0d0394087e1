// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/xml_util.hpp"

#include "common/nesting.hpp"

#include <charconv>
#include <string>

#include "import/text_position.hpp"

namespace tactus::import::detail {

Result<void> parse_xml(pugi::xml_document& doc, std::string_view bytes, std::string_view part) {
    // parse_ws_pcdata keeps <w:t xml:space="preserve"> </w:t>: a space is text.
    const auto result = doc.load_buffer(bytes.data(), bytes.size(),
                                        pugi::parse_default | pugi::parse_ws_pcdata,
                                        pugi::encoding_auto);
    if (result) {
        // Walked without recursion: the importers that read the tree next recurse.
        int depth = 0;
        for (auto n = doc.first_child(); n;) {
            if (n.type() == pugi::node_element && depth + 1 > max_nesting_depth) {
                const auto at = position_at(bytes, static_cast<std::size_t>(std::max<std::ptrdiff_t>(n.offset_debug(), 0)));
                return std::unexpected(too_deeply_nested(
                    "XML elements", part.empty() ? at.to_string() : std::string(part) + ":" + at.to_string()));
            }
            if (n.first_child()) {
                n = n.first_child();
                ++depth;
                continue;
            }
            while (n && !n.next_sibling()) {
                n = n.parent();
                --depth;
                if (n == doc) return {};
            }
            if (n) n = n.next_sibling();
        }
        return {};
    }
    const auto pos = position_at(bytes, static_cast<std::size_t>(std::max<std::ptrdiff_t>(result.offset, 0)));
    std::string where = part.empty() ? pos.to_string() : std::string(part) + ":" + pos.to_string();
    return fail(ErrorKind::input, std::string("invalid XML: ") + result.description(), std::move(where));
}

std::string_view local_name(const pugi::xml_node& node) {
    const std::string_view name = node.name();
    const auto colon = name.find(':');
    return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

std::string_view namespace_uri(const pugi::xml_node& node) {
    const std::string_view name = node.name();
    const auto colon = name.find(':');
    const std::string attr =
        colon == std::string_view::npos ? "xmlns" : "xmlns:" + std::string(name.substr(0, colon));
    for (auto n = node; n; n = n.parent()) {
        if (n.type() != pugi::node_element) break;
        if (const auto a = n.attribute(attr.c_str())) return a.value();
    }
    return {};
}

std::string_view attribute(const pugi::xml_node& node, std::string_view local) {
    for (const auto& a : node.attributes()) {
        const std::string_view name = a.name();
        const auto colon = name.find(':');
        if ((colon == std::string_view::npos ? name : name.substr(colon + 1)) == local)
            return a.value();
    }
    return {};
}

pugi::xml_node child(const pugi::xml_node& node, std::string_view local) {
    for (const auto& c : node.children())
        if (c.type() == pugi::node_element && local_name(c) == local) return c;
    return {};
}

int whole_number(std::string_view value, int fallback) {
    while (!value.empty() && (value.front() == ' ' || value.front() == '+')) value.remove_prefix(1);
    while (!value.empty() && value.back() == ' ') value.remove_suffix(1);
    int n = 0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
    return ec == std::errc{} && end == value.data() + value.size() && !value.empty() ? n : fallback;
}

}  // namespace tactus::import::detail
