// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One parsed markup document as a pugixml tree: XHTML, DTBook and the EPUB
// package files by pugixml; HTML (and XHTML that is not well-formed XML) by
// the HTML5 parser Gumbo, its tree copied into pugixml so that one walk reads
// both (markup_walk.hpp). Each element keeps its source line.
#include <pugixml.hpp>

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>

#include "common/result.hpp"
#include "import/text_position.hpp"

namespace tactus::import::detail {

struct MarkupDocument {
    std::string text;  // the UTF-8 text parsed; XML offsets refer to it
    pugi::xml_document xml;
    bool html = false;  // parsed by the HTML parser
    std::unordered_map<const void*, int> html_lines;  // HTML: element -> line
    std::unique_ptr<LineIndex> xml_lines;             // XML: offset -> line

    [[nodiscard]] int line_of(const pugi::xml_node& node) const;
    [[nodiscard]] std::function<int(const pugi::xml_node&)> lines() const {
        return [this](const pugi::xml_node& n) { return line_of(n); };
    }
};

// A markup file's bytes as UTF-8: valid UTF-8 as it is (less a byte-order
// mark), else decoded from the encoding detected (import/encoding.hpp).
Result<std::string> markup_text(std::string_view bytes);

// Parses `text` (UTF-8) as XML; `part` names it in errors.
Result<std::unique_ptr<MarkupDocument>> parse_xml_markup(std::string text, std::string_view part);
// Parses `text` (UTF-8) as HTML5: never fails on tag soup (the HTML5
// algorithm repairs it), only on nesting deeper than the walk allows.
Result<std::unique_ptr<MarkupDocument>> parse_html_markup(std::string text, std::string_view part);
// XHTML when it is well-formed XML, else HTML.
Result<std::unique_ptr<MarkupDocument>> parse_xhtml_or_html(std::string text, std::string_view part);

}  // namespace tactus::import::detail
