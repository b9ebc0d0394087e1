// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/markdown_front_matter.hpp"

#include <algorithm>
#include <string>

namespace tactus::import::detail {
namespace {

std::string_view trim_blanks(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// A scalar without its quotes ("A title", 'A title').
std::string_view unquote(std::string_view v) {
    v = trim_blanks(v);
    if (v.size() >= 2 && (v.front() == '"' || v.front() == '\'') && v.back() == v.front())
        return v.substr(1, v.size() - 2);
    return v;
}

// The Dublin Core element of a front-matter key ("" for one Tactus does not keep).
std::string_view dublin_core(std::string_view key) {
    if (key == "title") return "title";
    if (key == "author" || key == "authors" || key == "creator") return "creator";
    if (key == "date") return "date";
    if (key == "lang" || key == "language") return "language";
    if (key == "description" || key == "abstract" || key == "subtitle") return "description";
    if (key == "subject" || key == "keywords") return "subject";
    return {};
}

}  // namespace

std::optional<FrontMatter> front_matter(std::string_view markdown) {
    const auto first_end = markdown.find('\n');
    if (first_end == std::string_view::npos || trim_blanks(markdown.substr(0, first_end)) != "---") return std::nullopt;
    // As pandoc: the opening line is not followed by a blank line (that is a
    // thematic break and a paragraph).
    if (first_end + 1 >= markdown.size() || trim_blanks(markdown.substr(first_end + 1, markdown.find('\n', first_end + 1) - first_end - 1)).empty())
        return std::nullopt;
    FrontMatter fm;
    fm.lines = 1;
    std::string_view key;  // the key whose `- item` list is being read
    std::size_t at = first_end + 1;
    while (at < markdown.size()) {
        const auto end = std::min(markdown.find('\n', at), markdown.size());
        const auto line = markdown.substr(at, end - at);
        at = std::min(end + 1, markdown.size());
        ++fm.lines;
        const auto t = trim_blanks(line);
        if (t == "---" || t == "...") {
            fm.length = at;
            return fm;
        }
        if (t.starts_with("- ") || t == "-") {
            if (key.empty()) continue;
            if (const auto v = unquote(t.substr(1)); !v.empty())
                fm.metadata.push_back({std::string(dublin_core(key)), std::string(v)});
            continue;
        }
        key = {};
        if (line.empty() || line.front() == ' ' || line.front() == '\t' || t.starts_with('#')) continue;
        const auto colon = t.find(':');
        if (colon == std::string_view::npos) return std::nullopt;  // not YAML: Markdown after a rule
        const auto name = dublin_core(trim_blanks(t.substr(0, colon)));
        if (name.empty()) continue;
        auto value = unquote(t.substr(colon + 1));
        if (value.empty()) {
            key = trim_blanks(t.substr(0, colon));  // a list may follow
            continue;
        }
        if (value.front() == '[' && value.back() == ']') {  // [a, b]
            value = value.substr(1, value.size() - 2);
            for (std::size_t from = 0; from <= value.size();) {
                const auto comma = std::min(value.find(',', from), value.size());
                if (const auto v = unquote(value.substr(from, comma - from)); !v.empty())
                    fm.metadata.push_back({std::string(name), std::string(v)});
                from = comma + 1;
            }
            continue;
        }
        if (value == "|" || value == ">" || value.starts_with("|-") || value.starts_with(">-")) continue;
        fm.metadata.push_back({std::string(name), std::string(value)});
    }
    return std::nullopt;  // no closing line: a thematic break, not front matter
}

}  // namespace tactus::import::detail
