// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Print page numbering, one rule for every importer, the editor's line dialect
// and the editor's live layout (docs/import.md, "Print pages"). A page break
// either carries the print page it starts (`<!-- pagebreak 10 -->`, a PEF or a
// DOCX field would give one) or continues from the page in effect before it.
#include <optional>
#include <string>
#include <string_view>

namespace tactus::document {

// The print page in effect before the first page break.
inline constexpr std::string_view first_print_page = "1";

// The print page an unlabelled page break starts, after page `current`:
// "10" -> "11", "A-9" -> "A-10" (the last run of digits counts on), "xii" ->
// "xiii" and "XII" -> "XIII" (roman numerals). A label that cannot be counted
// on ("preface", "") gives "": the reader then sees no number rather than a
// wrong one, until a break gives a label again.
std::string next_print_page(std::string_view current);

// The label a page break carries: its own when it has one, else the next page.
inline std::string print_page_label(std::string_view own, std::string_view current) {
    return own.empty() ? next_print_page(current) : std::string(own);
}

// The label of a page break in a document: print_page_label, except that an
// unlabelled break with nothing before it (no text, no earlier print page
// break: `started` false) starts no page and gives none. The importers drop
// such a break and the editor's dialect reads it as no block, alike.
inline std::optional<std::string> page_break_label(std::string_view own, std::string_view current, bool started) {
    if (own.empty() && !started) return std::nullopt;
    return print_page_label(own, current);
}

}  // namespace tactus::document
