// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// pugixml helpers shared by the DOCX and PEF importers: parsing with errors that
// name line:column, and namespace-aware names (pugixml itself ignores namespaces).
#include <pugixml.hpp>

#include <string_view>

#include "common/result.hpp"

namespace tactus::import::detail {

// Parses `bytes` (kept alive by the caller: offsets refer to it). On failure the
// error's `where` is "part:line:column" (or "line:column" when `part` is empty).
Result<void> parse_xml(pugi::xml_document& doc, std::string_view bytes, std::string_view part);

// "w:p" -> "p".
std::string_view local_name(const pugi::xml_node& node);
// The namespace URI of an element, from the xmlns declarations around it.
std::string_view namespace_uri(const pugi::xml_node& node);
// The attribute with this local name, whatever its prefix ("" if absent).
std::string_view attribute(const pugi::xml_node& node, std::string_view local);
// The first child element with this local name.
pugi::xml_node child(const pugi::xml_node& node, std::string_view local);
// An attribute's value as a whole number ("3"), `fallback` when it is absent
// or not one ("", "x", "2.5", out of int's range).
int whole_number(std::string_view value, int fallback);

}  // namespace tactus::import::detail
