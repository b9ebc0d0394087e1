// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// WordprocessingML styles (word/styles.xml) and list numbering (word/numbering.xml),
// resolved to what the document model needs: heading level, list membership,
// page-break-before, bold/italic/underline and the languages of the text.
#include <pugixml.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "document/document.hpp"
#include "import/office_language.hpp"

namespace tactus::import::detail {

// Toggle properties and w:lang; unset = inherit.
struct RunFormat {
    std::optional<bool> bold, italic, underline;
    OfficeLanguages languages;  // w:lang w:val, w:eastAsia, w:bidi; w:rtl, w:cs
    void apply(const RunFormat& over);
    [[nodiscard]] std::uint8_t emphasis() const;
};
RunFormat read_run_format(const pugi::xml_node& rPr);

struct NumberingRef {
    std::string num_id;  // "0" means "no numbering" (used to switch a style's list off)
    int ilvl = 0;
};
std::optional<NumberingRef> read_numbering_ref(const pugi::xml_node& pPr);
// <w:b/>, <w:b w:val="true"/>, <w:b w:val="0"/>: unset when the element is absent.
std::optional<bool> read_toggle(const pugi::xml_node& element);

struct ParagraphStyle {
    int heading_level = 0;  // 1..6, 0 = not a heading
    std::optional<NumberingRef> numbering;
    bool page_break_before = false;
    bool quote = false;  // a block quote style ("Quote", "Intense Quote", "Quotations")
};

// Word's "Quote" and "Intense Quote" and LibreOffice's "Quotations": the style
// names of a block quote (compared without case).
bool is_quote_style_name(std::string_view name);

class DocxStyles {
public:
    DocxStyles() = default;
    explicit DocxStyles(const pugi::xml_node& styles_root);
    // Empty id = the default paragraph style. Unknown ids resolve like the default.
    [[nodiscard]] ParagraphStyle paragraph(std::string_view style_id) const;
    [[nodiscard]] RunFormat character(std::string_view style_id) const;
    // The languages of a paragraph's text before its runs' own: the
    // document defaults (w:docDefaults), then, in a table, its table style's
    // chain (w:tblStyle's run properties), then the paragraph style's chain
    // (empty id = the default paragraph style): Word's order (ECMA-376 Part 1,
    // 17.7.2, "Style hierarchy"). Unlike bold or italic, a paragraph style's
    // language is the text's.
    [[nodiscard]] OfficeLanguages paragraph_languages(std::string_view style_id,
                                                      std::string_view table_style_id = {}) const;
    // The document's own languages: those of a paragraph in the default
    // paragraph style with no language of its own.
    [[nodiscard]] OfficeLanguages document_languages() const { return paragraph_languages({}); }

private:
    struct Style {
        std::string name;
        std::string based_on;
        std::optional<int> outline_level;  // 0-based, as in w:outlineLvl
        std::optional<NumberingRef> numbering;
        std::optional<bool> page_break_before;
        RunFormat run;
    };
    [[nodiscard]] const Style* find(std::string_view id) const;
    [[nodiscard]] const Style* find_paragraph(std::string_view id) const;
    std::unordered_map<std::string, Style> styles_;
    OfficeLanguages defaults_;  // w:docDefaults/w:rPrDefault
    std::string default_paragraph_;
};

class DocxNumbering {
public:
    DocxNumbering() = default;
    explicit DocxNumbering(const pugi::xml_node& numbering_root);
    // The label of the next item of this list at this level ("3.", "b)", "1.2.");
    // "•" for bullets. Deeper levels restart, as in a word processor.
    std::string next_label(const NumberingRef& ref);

private:
    struct Level {
        std::string format = "decimal";
        std::string text;  // lvlText, e.g. "%1." or "%1.%2"
        int start = 1;
    };
    using Levels = std::array<Level, 9>;
    std::unordered_map<std::string, std::string> abstract_of_num_;
    std::unordered_map<std::string, Levels> abstracts_;
    std::unordered_map<std::string, std::array<int, 9>> counters_;  // per abstract list
    // w:num's startOverride per level, and the (num, level) pairs already restarted.
    std::unordered_map<std::string, std::array<std::optional<int>, 9>> start_overrides_;
    std::unordered_set<std::string> overridden_;
};

}  // namespace tactus::import::detail
