// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/markup_document.hpp"

// Without gumbo (TACTUS_WITH_GUMBO off) HTML that is not well-formed XHTML is refused.
#if TACTUS_HAVE_GUMBO
#include <gumbo.h>
#else
#include "common/unavailable.hpp"
#endif

#include <algorithm>
#include <array>
#include <cctype>
#include <vector>

#include "common/nesting.hpp"
#include "import/markup_walk.hpp"
#include "import/xml_util.hpp"
#include "common/try.hpp"

namespace tactus::import::detail {
namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

// An upper bound of how deep the tags in `text` nest, from the tags alone:
// Gumbo frees its tree recursively, so a tower of a million <div>s is refused
// before it is parsed. Void elements and those whose end tag may be left out
// do not count; a self-closed tag does not either.
std::size_t tag_depth_bound(std::string_view text) {
    static constexpr std::array no_depth{"area", "base", "br", "col", "embed", "hr", "img", "input", "link",
                                         "meta", "source", "track", "wbr", "p", "li", "dt", "dd", "tr",
                                         "td", "th", "option", "param", "keygen"};
    std::size_t depth = 0;
    std::size_t most = 0;
    for (std::size_t at = text.find('<'); at != std::string_view::npos && at + 1 < text.size();
         at = text.find('<', at + 1)) {
        const char next = text[at + 1];
        if (next == '/') {
            if (depth > 0) --depth;
            continue;
        }
        if (!std::isalpha(static_cast<unsigned char>(next))) continue;
        std::size_t end = at + 1;
        while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '-' || text[end] == ':'))
            ++end;
        const auto name = lower(text.substr(at + 1, end - at - 1));
        const auto close = text.find('>', end);
        if (close != std::string_view::npos && close > 0 && text[close - 1] == '/') continue;
        if (std::find(no_depth.begin(), no_depth.end(), name) != no_depth.end()) continue;
        most = std::max(most, ++depth);
    }
    return most;
}

#if TACTUS_HAVE_GUMBO
std::string tag_name(const GumboNode* node) {
    const auto& e = node->v.element;
    if (e.tag != GUMBO_TAG_UNKNOWN) return gumbo_normalized_tagname(e.tag);
    GumboStringPiece piece = e.original_tag;
    gumbo_tag_from_original_text(&piece);
    if (e.tag_namespace == GUMBO_NAMESPACE_SVG)
        if (const char* svg = gumbo_normalize_svg_tagname(&piece)) return svg;
    std::string name(piece.data ? piece.data : "", piece.data ? piece.length : 0);
    const auto end = name.find_first_of(" \t\r\n/>");
    return lower(name.substr(0, end));
}
#endif

}  // namespace

int MarkupDocument::line_of(const pugi::xml_node& node) const {
    if (html) {
        const auto it = html_lines.find(node.internal_object());
        return it == html_lines.end() ? 0 : it->second;
    }
    if (!xml_lines) return 0;
    const auto offset = node.offset_debug();
    return offset < 0 ? 0 : xml_lines->line_at(static_cast<std::size_t>(offset));
}

Result<std::unique_ptr<MarkupDocument>> parse_xml_markup(std::string text, std::string_view part) {
    auto doc = std::make_unique<MarkupDocument>();
    doc->text = std::move(text);
    TACTUS_TRY_VOID(parse_xml(doc->xml, doc->text, part));
    doc->xml_lines = std::make_unique<LineIndex>(doc->text);
    return doc;
}

Result<std::unique_ptr<MarkupDocument>> parse_html_markup(std::string text, std::string_view part) {
    if (tag_depth_bound(text) > 20000)
        return fail(ErrorKind::input, "elements nested more than 20000 deep; the document cannot be read", std::string(part));
    auto doc = std::make_unique<MarkupDocument>();
    doc->text = std::move(text);
    doc->html = true;
#if !TACTUS_HAVE_GUMBO
    return unavailable("reading HTML that is not well-formed XHTML", "gumbo", std::string(part));
#else
    GumboOutput* output = gumbo_parse_with_options(&kGumboDefaultOptions, doc->text.data(), doc->text.size());
    if (!output) return fail(ErrorKind::input, "the HTML parser gave up on this document", std::string(part));
    // Copy the tree without recursion; the walk bounds the depth it reads.
    struct Item {
        const GumboNode* node;
        pugi::xml_node parent;
        int depth;
    };
    std::vector<Item> stack{{output->root, pugi::xml_node(doc->xml), 0}};
    std::string error;
    while (!stack.empty()) {
        auto [node, parent, depth] = stack.back();
        stack.pop_back();
        switch (node->type) {
            case GUMBO_NODE_TEXT:
            case GUMBO_NODE_WHITESPACE:
            case GUMBO_NODE_CDATA:
                parent.append_child(pugi::node_pcdata).set_value(node->v.text.text);
                break;
            case GUMBO_NODE_ELEMENT:
            case GUMBO_NODE_TEMPLATE: {
                if (depth > max_markup_depth) {
                    error = "elements nested more than " + std::to_string(max_markup_depth) + " deep (<" +
                            tag_name(node) + ">); the document cannot be read";
                    stack.clear();
                    break;
                }
                auto e = parent.append_child(tag_name(node).c_str());
                doc->html_lines.emplace(e.internal_object(), static_cast<int>(node->v.element.start_pos.line));
                const auto& attrs = node->v.element.attributes;
                for (unsigned i = 0; i < attrs.length; ++i) {
                    const auto* a = static_cast<const GumboAttribute*>(attrs.data[i]);
                    if (!e.attribute(a->name)) e.append_attribute(a->name).set_value(a->value);
                }
                const auto& kids = node->v.element.children;
                for (unsigned i = kids.length; i > 0; --i)
                    stack.push_back({static_cast<const GumboNode*>(kids.data[i - 1]), e, depth + 1});
                break;
            }
            default: break;  // comments, the doctype
        }
    }
    gumbo_destroy_output(&kGumboDefaultOptions, output);
    if (!error.empty()) return fail(ErrorKind::input, error, std::string(part));
    return doc;
#endif
}

namespace {

// An entity reference XML does not define ("&nbsp;"): pugixml would keep it
// as text, so such a file is read as HTML, whose parser knows them all.
bool has_html_entity(std::string_view text) {
    for (std::size_t at = text.find('&'); at != std::string_view::npos; at = text.find('&', at + 1)) {
        const auto end = text.find_first_of("; \t\r\n<&", at + 1);
        if (end == std::string_view::npos || text[end] != ';') continue;
        const auto name = text.substr(at + 1, end - at - 1);
        if (name.empty() || name[0] == '#' || name == "amp" || name == "lt" || name == "gt" || name == "quot" ||
            name == "apos")
            continue;
        return true;
    }
    return false;
}

}  // namespace

Result<std::unique_ptr<MarkupDocument>> parse_xhtml_or_html(std::string text, std::string_view part) {
    if (!has_html_entity(text)) {
        auto xml = parse_xml_markup(text, part);
        if (xml || is_too_deeply_nested(xml.error())) return xml;
    }
    return parse_html_markup(std::move(text), part);
}

}  // namespace tactus::import::detail
