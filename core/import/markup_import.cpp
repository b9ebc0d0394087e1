// SPDX-License-Identifier: GPL-3.0-or-later
// HTML and DTBook (DAISY 3, NIMAS) files: one content document each, parsed
// (markup_document.hpp) and walked into blocks (markup_walk.hpp); the book's
// title, author and language become the document's metadata, as an EPUB's
// package metadata does (epub_import.cpp).
#include <algorithm>
#include <string>

#include "common/utf8.hpp"
#include "import/encoding.hpp"
#include "import/importers.hpp"
#include "import/markup_document.hpp"
#include "import/markup_walk.hpp"
#include "import/picture_part.hpp"
#include "import/xml_util.hpp"
#include "common/try.hpp"

namespace tactus::import::detail {

Result<std::string> markup_text(std::string_view bytes) {
    // Valid UTF-8 is taken as it is (XML allows C1 controls, which the text
    // importers refuse); anything else is detected and converted.
    auto body = bytes.starts_with("\xEF\xBB\xBF") ? bytes.substr(3) : bytes;
    if (find_invalid_utf8(body) == std::string_view::npos && body.find('\0') == std::string_view::npos)
        return std::string(body);
    TACTUS_TRY(decoded, decode_text(bytes, {}));
    return std::string(decoded.text(bytes));
}

namespace {

void add_metadata(document::Document& doc, std::string name, std::string_view value) {
    std::string v;
    bool space = false;
    for (const char c : value) {
        if (c == ' ' || c == '\n' || c == '\t' || c == '\r') {
            space = !v.empty();
            continue;
        }
        if (space) v += ' ';
        space = false;
        v += c;
    }
    if (v.empty()) return;
    for (const auto& m : doc.metadata)
        if (m.name == name && m.value == v) return;
    doc.metadata.push_back({std::move(name), std::move(v)});
}

}  // namespace

Result<document::Document> import_html(std::string_view bytes, const std::filesystem::path* image_folder) {
    TACTUS_TRY(text, markup_text(bytes));
    auto parsed = parse_xhtml_or_html(std::move(text), {});
    if (!parsed) return std::unexpected(parsed.error());
    const auto& tree = **parsed;
    MarkupWalk walk({MarkupPart{{}, tree.xml, tree.lines()}});
    if (image_folder)
        walk.keep_pictures([folder = *image_folder](std::string_view, std::string_view src, std::string& why) {
            return picture_file(folder, src, why);
        });
    auto doc = walk.run();
    if (!doc) return doc;
    const auto html = tree.xml.document_element();
    const auto head = child(html, "head");
    add_metadata(*doc, "title", text_of(child(head, "title")));
    for (const auto& meta : head.children()) {
        if (local_name(meta) != "meta") continue;
        const std::string_view name = meta.attribute("name").value();
        if (name == "author" || name == "dc.creator" || name == "DC.creator") add_metadata(*doc, "creator", meta.attribute("content").value());
    }
    std::string_view lang = html.attribute("lang").value();
    if (lang.empty()) lang = html.attribute("xml:lang").value();
    add_metadata(*doc, "language", lang);
    return doc;
}

Result<document::Document> import_dtbook(std::string_view bytes) {
    TACTUS_TRY(text, markup_text(bytes));
    auto parsed = parse_xml_markup(std::move(text), {});
    if (!parsed) return std::unexpected(parsed.error());
    const auto& tree = **parsed;
    const auto root = tree.xml.document_element();
    if (local_name(root) != "dtbook")
        return fail(ErrorKind::input, "not a DTBook document: the root element is <" + std::string(root.name()) + ">, not <dtbook>");
    auto doc = MarkupWalk({MarkupPart{{}, tree.xml, tree.lines()}}).run();
    if (!doc) return doc;
    // <meta name="dc:Title" content="...">: Dublin Core, named in lower case as PEF names it.
    for (const auto& meta : child(root, "head").children()) {
        std::string name = meta.attribute("name").value();
        if (local_name(meta) != "meta" || !name.starts_with("dc:")) continue;
        name = name.substr(3);
        for (auto& c : name) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
        add_metadata(*doc, name, meta.attribute("content").value());
    }
    const auto book = child(root, "book");
    const auto front = child(book, "frontmatter");
    if (std::none_of(doc->metadata.begin(), doc->metadata.end(), [](const auto& m) { return m.name == "title"; }))
        add_metadata(*doc, "title", text_of(child(front, "doctitle")));
    return doc;
}

}  // namespace tactus::import::detail
