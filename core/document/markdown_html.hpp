// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What Markdown has no mark for, as the HTML core's Markdown writer writes and
// its importer reads back (one place, so they never disagree; docs/import.md,
// "Markdown"). A Markdown reader shows the inline tags as underline, raised
// and lowered text (md4c passes them on as raw HTML), and does not show the
// box lines, HTML comments as the page break's: the boxed blocks read as the
// rest.
#include <optional>
#include <string>
#include <string_view>

#include "document/document.hpp"

namespace tactus::document::markdown_html {

inline constexpr std::string_view kUnderlineOpen = "<u>";
inline constexpr std::string_view kUnderlineClose = "</u>";
inline constexpr std::string_view kSuperscriptOpen = "<sup>";
inline constexpr std::string_view kSuperscriptClose = "</sup>";
inline constexpr std::string_view kSubscriptOpen = "<sub>";
inline constexpr std::string_view kSubscriptClose = "</sub>";
// `<span lang="de">` ... `</span>`: a passage's language (Span::language).
inline constexpr std::string_view kSpanClose = "</span>";

// Boxed material (Block::box): a line of its own before a box's first block
// and one after its last.
inline constexpr std::string_view kBoxStart = "<!-- box -->";
inline constexpr std::string_view kBoxEnd = "<!-- /box -->";
// The comments' bodies, as the importer reads a comment.
inline constexpr std::string_view kBoxStartBody = "box";
inline constexpr std::string_view kBoxEndBody = "/box";

// The tags written around a span's text, outermost first, and their closing
// tags in the order they are written; both empty for a span Markdown marks
// itself (bold, italic) or not at all.
inline std::string open_tags(const Span& s) {
    std::string out;
    if (!s.language.empty()) out += "<span lang=\"" + s.language + "\">";
    if (s.emphasis & emphasis_underline) out += kUnderlineOpen;
    if (s.position == Position::superscript) out += kSuperscriptOpen;
    if (s.position == Position::subscript) out += kSubscriptOpen;
    return out;
}
inline std::string close_tags(const Span& s) {
    std::string out;
    if (s.position == Position::subscript) out += kSubscriptClose;
    if (s.position == Position::superscript) out += kSuperscriptClose;
    if (s.emphasis & emphasis_underline) out += kUnderlineClose;
    if (!s.language.empty()) out += kSpanClose;
    return out;
}

// What one inline tag does, as the importer reads it; nothing for any other tag.
struct Tag {
    enum class What { underline, superscript, subscript, language } what;
    bool closing = false;
    std::string language;  // an opening language tag's
};
inline std::optional<Tag> read_tag(std::string_view html) {
    if (html == kUnderlineOpen) return Tag{Tag::What::underline, false, {}};
    if (html == kUnderlineClose) return Tag{Tag::What::underline, true, {}};
    if (html == kSuperscriptOpen) return Tag{Tag::What::superscript, false, {}};
    if (html == kSuperscriptClose) return Tag{Tag::What::superscript, true, {}};
    if (html == kSubscriptOpen) return Tag{Tag::What::subscript, false, {}};
    if (html == kSubscriptClose) return Tag{Tag::What::subscript, true, {}};
    if (html == kSpanClose) return Tag{Tag::What::language, true, {}};
    constexpr std::string_view open = "<span lang=\"";
    if (html.starts_with(open) && html.ends_with("\">")) {
        const auto lang = html.substr(open.size(), html.size() - open.size() - 2);
        if (lang.find_first_of("\"<>") == std::string_view::npos) return Tag{Tag::What::language, false, std::string(lang)};
    }
    // Any other <span ...> opens a span that sets nothing, closed by </span> as well.
    if (html.starts_with("<span") && html.ends_with(">")) return Tag{Tag::What::language, false, {}};
    return std::nullopt;
}

}  // namespace tactus::document::markdown_html
