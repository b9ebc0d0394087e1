// SPDX-License-Identifier: GPL-3.0-or-later
// EPUB 3 and EPUB 2 (a ZIP package): META-INF/container.xml names the package
// document (OPF); its spine gives the reading order of the content documents
// (XHTML, or HTML when not well-formed; EPUB 2's DTBook), which are walked as
// one book (markup_walk.hpp), so a note reference in one chapter finds its note
// in the endnotes. The package's Dublin Core metadata (title, creator,
// publisher, date, language, ...) becomes the document's metadata, for the
// title page and the PEF head. Spine items of other types (images) are named
// in a warning. The navigation document and NCX are not read: the contents
// are generated from the headings.
#include <pugixml.hpp>

#include <algorithm>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "import/encoding.hpp"
#include "import/importers.hpp"
#include "import/markup_document.hpp"
#include "import/markup_walk.hpp"
#include "import/picture_part.hpp"
#include "import/xml_util.hpp"
#include "import/zip_archive.hpp"
#include "common/try.hpp"

namespace tactus::import::detail {
namespace {

// One content document unpacks to at most this; the whole book to at most
// twice the import limit (text compresses well, markup more so).
constexpr std::size_t max_part_bytes = std::size_t{64} << 20;
constexpr std::size_t max_book_bytes = std::size_t{512} << 20;

Result<std::unique_ptr<MarkupDocument>> read_xml(const ZipArchive& zip, const std::string& part) {
    TACTUS_TRY(bytes, zip.read(part, max_part_bytes));
    auto text = markup_text(bytes);
    if (!text) return std::unexpected(located(text.error(), part));
    return parse_xml_markup(std::move(*text), part);
}

struct ManifestItem {
    std::string path;
    std::string media_type;
};

}  // namespace

Result<document::Document> import_epub(std::string_view bytes, bool images) {
    auto zip = ZipArchive::open(bytes);
    if (!zip) return fail(ErrorKind::input, "not an EPUB: " + zip.error().message, zip.error().where);
    if (zip->contains("mimetype")) {
        auto type = zip->read("mimetype", 1024);
        if (type && type->find("application/epub+zip") == std::string::npos)
            return fail(ErrorKind::input, "not an EPUB: its mimetype is '" + *type + "'", "mimetype");
    }
    if (!zip->contains("META-INF/container.xml"))
        return fail(ErrorKind::input, "not an EPUB: missing part META-INF/container.xml", "META-INF/container.xml");
    TACTUS_TRY(container, read_xml(*zip, "META-INF/container.xml"));
    std::string opf_path;
    for (const auto& r : child(container->xml.document_element(), "rootfiles").children()) {
        if (local_name(r) != "rootfile") continue;
        const std::string_view type = r.attribute("media-type").value();
        if (type.empty() || type == "application/oebps-package+xml") {
            opf_path = r.attribute("full-path").value();
            break;
        }
    }
    if (opf_path.empty())
        return fail(ErrorKind::input, "not an EPUB: container.xml names no package document (rootfile full-path)", "META-INF/container.xml");
    opf_path = resolve_path("", opf_path);
    TACTUS_TRY(opf, read_xml(*zip, opf_path));
    const auto package = opf->xml.document_element();
    if (local_name(package) != "package")
        return fail(ErrorKind::input, "not an EPUB package document: the root element is <" + std::string(package.name()) + ">", opf_path);

    std::map<std::string, ManifestItem> manifest;
    for (const auto& item : child(package, "manifest").children()) {
        if (local_name(item) != "item") continue;
        manifest[item.attribute("id").value()] =
            ManifestItem{resolve_path(opf_path, item.attribute("href").value()), item.attribute("media-type").value()};
    }
    std::vector<std::string> warnings;
    std::vector<std::unique_ptr<MarkupDocument>> trees;
    std::vector<MarkupPart> parts;
    std::size_t total = 0;
    for (const auto& ref : child(package, "spine").children()) {
        if (local_name(ref) != "itemref") continue;
        const std::string idref = ref.attribute("idref").value();
        const auto found = manifest.find(idref);
        if (found == manifest.end()) {
            warnings.push_back(opf_path + ": the spine names '" + idref + "', which the manifest does not list; left out");
            continue;
        }
        const auto& [path, type] = found->second;
        const bool xhtml = type == "application/xhtml+xml" || type == "text/html";
        const bool dtbook = type == "application/x-dtbook+xml";
        if (!xhtml && !dtbook) {
            warnings.push_back(path + ": a spine item of type " + (type.empty() ? std::string("(none)") : type) +
                               " left out (only XHTML and DTBook are read)");
            continue;
        }
        TACTUS_TRY(raw, zip->read(path, max_part_bytes));
        total += raw.size();
        if (total > max_book_bytes)
            return fail(ErrorKind::input, "the book unpacks to more than " + std::to_string(max_book_bytes) + " bytes of text", path);
        auto text = markup_text(raw);
        if (!text) return std::unexpected(located(text.error(), path));
        TACTUS_TRY(tree, dtbook ? parse_xml_markup(std::move(*text), path) : parse_xhtml_or_html(std::move(*text), path));
        parts.push_back(MarkupPart{path, tree->xml, tree->lines()});
        trees.push_back(std::move(tree));
    }
    if (parts.empty()) return fail(ErrorKind::input, "the EPUB's spine lists no content document (XHTML)", opf_path);
    MarkupWalk walk(std::move(parts));
    if (images)
        walk.keep_pictures([&zip](std::string_view part, std::string_view src, std::string& why)
                               -> std::optional<document::Image> {
            const auto name = resolve_path(part, src);
            if (!zip->contains(name)) {
                why = "not in the EPUB";
                return std::nullopt;
            }
            auto picture = zip->read(name, max_import_bytes);
            if (!picture) {
                why = picture.error().message;
                return std::nullopt;
            }
            auto type = picture_media_type(*picture, name);
            if (type.empty()) {
                why = std::string(unsupported_picture_reason);
                return std::nullopt;
            }
            return document::Image{std::move(*picture), std::move(type), name};
        });
    auto doc = walk.run();
    if (!doc) return doc;
    doc->warnings.insert(doc->warnings.begin(), warnings.begin(), warnings.end());
    // Dublin Core, in the package's order; PEF names the same elements.
    static constexpr std::string_view kept[] = {"title", "creator", "contributor", "publisher", "date",
                                                "language", "identifier", "source", "rights", "subject", "description"};
    for (const auto& m : child(package, "metadata").children()) {
        const auto name = local_name(m);
        if (std::find(std::begin(kept), std::end(kept), name) == std::end(kept)) continue;
        const auto value = text_of(m);
        if (!value.empty()) doc->metadata.push_back({std::string(name), value});
    }
    return doc;
}

}  // namespace tactus::import::detail
