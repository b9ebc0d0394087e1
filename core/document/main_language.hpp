// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The document's main language: the first Dublin Core "language" of its
// metadata (BCP 47), as EPUB's dc:language, HTML's lang, a Markdown front
// matter's lang and the office formats' default languages give it. A passage
// in another language is a Span::language; text without one is in this.
#include <algorithm>
#include <string>
#include <string_view>

#include "document/document.hpp"

namespace tactus::document {

inline constexpr std::string_view kLanguageItem = "language";

// "" when the document names none.
inline std::string main_language(const Document& doc) {
    const auto it = std::ranges::find_if(doc.metadata, [](const MetadataItem& m) { return m.name == kLanguageItem; });
    return it == doc.metadata.end() ? std::string() : it->value;
}

// Sets (or, with "", takes away) the main language, in the place the first
// one stood; any further language items stay.
inline void set_main_language(Document& doc, std::string_view tag) {
    const auto it = std::ranges::find_if(doc.metadata, [](const MetadataItem& m) { return m.name == kLanguageItem; });
    if (tag.empty()) {
        if (it != doc.metadata.end()) doc.metadata.erase(it);
    } else if (it != doc.metadata.end()) {
        it->value = std::string(tag);
    } else {
        doc.metadata.push_back({std::string(kLanguageItem), std::string(tag)});
    }
}

// Metadata besides the main language (a title, an author): what the office
// writers do not write.
inline bool has_other_metadata(const Document& doc) {
    bool seen_language = false;
    return std::ranges::any_of(doc.metadata, [&](const MetadataItem& m) {
        if (m.name == kLanguageItem && !seen_language) return !(seen_language = true);
        return true;
    });
}

}  // namespace tactus::document
