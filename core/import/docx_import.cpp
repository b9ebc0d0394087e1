// SPDX-License-Identifier: GPL-3.0-or-later
// DOCX (WordprocessingML in a ZIP package): paragraphs of the main document part,
// headings from styles (name "heading N"/"Title" or outline level), list items
// from numbering (label kept as text, bullets dropped), bold/italic/underline
// from direct formatting and styles, page breaks from <w:br w:type="page"/>,
// pageBreakBefore and section breaks. <w:lastRenderedPageBreak/> only records
// where the last layout happened to break, so it is not a break.
// Not imported: headers/footers, footnotes, comments, text boxes and images.
#include <pugixml.hpp>

#include "import/docx_styles.hpp"
#include "import/document_builder.hpp"
#include "import/import.hpp"
#include "import/importers.hpp"
#include "import/xml_util.hpp"
#include "import/zip_archive.hpp"

namespace tactus::import::detail {
namespace {

constexpr std::string_view default_main_part = "word/document.xml";

// Part names in relationships are relative to the source part's folder.
std::string resolve_target(std::string_view source_dir, std::string_view target) {
    if (target.starts_with('/')) return std::string(target.substr(1));
    std::string base(source_dir);
    while (target.starts_with("../")) {
        target.remove_prefix(3);
        const auto slash = base.find_last_of('/', base.empty() ? 0 : base.size() - 2);
        base = slash == std::string::npos ? std::string{} : base.substr(0, slash + 1);
    }
    return base + std::string(target);
}

std::string folder_of(std::string_view part) {
    const auto slash = part.rfind('/');
    return slash == std::string_view::npos ? std::string{} : std::string(part.substr(0, slash + 1));
}

std::string rels_of(std::string_view part) {
    const auto slash = part.rfind('/');
    const auto dir = slash == std::string_view::npos ? std::string_view{} : part.substr(0, slash + 1);
    const auto file = slash == std::string_view::npos ? part : part.substr(slash + 1);
    return std::string(dir) + "_rels/" + std::string(file) + ".rels";
}

class Package {
public:
    explicit Package(ZipArchive zip) : zip_(std::move(zip)) {}

    // Reads and parses a part; a missing optional part leaves `doc` empty.
    Result<bool> load(const std::string& part, pugi::xml_document& doc, std::string& storage,
                      bool required) {
        if (!zip_.contains(part)) {
            if (required) return fail("not a Word document: missing part " + part, part);
            return false;
        }
        auto bytes = zip_.read(part, max_import_bytes);
        if (!bytes) return std::unexpected(bytes.error());
        storage = std::move(*bytes);
        if (auto ok = parse_xml(doc, storage, part); !ok) return std::unexpected(ok.error());
        return true;
    }

    // Target of the first relationship of `source` whose type ends with `/kind`.
    Result<std::string> related(std::string_view source, std::string_view kind) {
        pugi::xml_document rels;
        std::string storage;
        auto found = load(rels_of(source), rels, storage, false);
        if (!found) return std::unexpected(found.error());
        if (!*found) return std::string{};
        for (const auto& r : rels.document_element().children()) {
            if (local_name(r) != "Relationship") continue;
            if (attribute(r, "TargetMode") == "External") continue;
            const auto type = attribute(r, "Type");
            if (type.size() > kind.size() && type.ends_with(kind) &&
                type[type.size() - kind.size() - 1] == '/')
                return resolve_target(folder_of(source), attribute(r, "Target"));
        }
        return std::string{};
    }

private:
    ZipArchive zip_;
};

class BodyReader {
public:
    BodyReader(const DocxStyles& styles, DocxNumbering& numbering)
        : styles_(styles), numbering_(numbering) {}

    void container(const pugi::xml_node& node) {
        for (const auto& c : node.children()) {
            if (builder_.full()) return;
            const auto name = local_name(c);
            if (name == "p")
                paragraph(c);
            else if (name == "tbl" || name == "tr" || name == "tc" || name == "sdt" ||
                     name == "sdtContent" || name == "customXml")
                container(c);  // table cells and content controls hold paragraphs
        }
    }

    Result<document::Document> finish() { return builder_.finish(); }

private:
    void paragraph(const pugi::xml_node& p) {
        const auto pPr = child(p, "pPr");
        const auto style = styles_.paragraph(attribute(child(pPr, "pStyle"), "val"));
        int heading = style.heading_level;
        if (const auto lvl = attribute(child(pPr, "outlineLvl"), "val"); !lvl.empty()) {
            const int v = lvl[0] - '0';
            if (lvl.size() == 1 && v >= 0 && v < 9) heading = std::min(6, v + 1);
        }
        auto numbering = style.numbering;
        if (auto direct = read_numbering_ref(pPr)) numbering = direct;
        if (numbering && numbering->num_id == "0") numbering.reset();
        const auto break_before = read_toggle(child(pPr, "pageBreakBefore"));

        if (break_before.value_or(style.page_break_before)) builder_.print_page_break(0);
        kind_ = heading > 0 ? document::BlockKind::heading
                : numbering ? document::BlockKind::list_item
                            : document::BlockKind::paragraph;
        level_ = heading > 0 ? heading : numbering ? numbering->ilvl + 1 : 0;
        label_.clear();
        if (numbering) {
            label_ = numbering_.next_label(*numbering);
            if (!label_.empty()) label_ += ' ';
        }
        builder_.begin(kind_, level_, 0);
        inline_content(p);
        builder_.end();

        // A section break in the paragraph properties ends the section here; all
        // kinds except "continuous" (and column breaks) start a new page.
        if (const auto sect = child(pPr, "sectPr")) {
            const auto type = attribute(child(sect, "type"), "val");
            if (type != "continuous" && type != "nextColumn") builder_.print_page_break(0);
        }
    }

    void inline_content(const pugi::xml_node& node) {
        for (const auto& c : node.children()) {
            if (c.type() != pugi::node_element) continue;
            const auto name = local_name(c);
            if (name == "r")
                run(c);
            else if (name == "pPr" || name == "rPr" || name == "del" || name == "moveFrom" ||
                     name == "AlternateContent" || name == "drawing" || name == "pict" ||
                     name == "object")
                continue;  // properties, deleted text, graphics
            else
                inline_content(c);  // hyperlink, ins, smartTag, fldSimple, sdt, math...
        }
    }

    void run(const pugi::xml_node& r) {
        const auto rPr = child(r, "rPr");
        // Only character styles and direct formatting are emphasis: the bold of a
        // heading style or the italic of a quote style is the paragraph's typeface.
        RunFormat format;
        format.apply(styles_.character(attribute(child(rPr, "rStyle"), "val")));
        format.apply(read_run_format(rPr));
        const auto emphasis = format.emphasis();
        for (const auto& c : r.children()) {
            if (c.type() != pugi::node_element) continue;
            const auto name = local_name(c);
            if (name == "t")
                text(c.child_value(), emphasis);
            else if (name == "tab")
                text("\t", emphasis);
            else if (name == "cr")
                text("\n", emphasis);
            else if (name == "noBreakHyphen")
                text("\xE2\x80\x91", emphasis);  // U+2011 non-breaking hyphen
            else if (name == "br") {
                const auto type = attribute(c, "type");
                if (type == "page")
                    page_break_inside();
                else if (type != "column")
                    text("\n", emphasis);
            }
        }
    }

    void text(std::string_view s, std::uint8_t emphasis) {
        if (s.empty()) return;
        if (!builder_.is_open()) builder_.begin(kind_, level_, 0);
        if (!label_.empty()) {
            builder_.add_text(label_);
            label_.clear();
        }
        builder_.add_text(s, emphasis);
    }

    // The paragraph goes on after the break as a block of the same kind.
    void page_break_inside() {
        builder_.print_page_break(0);
        builder_.begin(kind_, level_, 0);
    }

    const DocxStyles& styles_;
    DocxNumbering& numbering_;
    DocumentBuilder builder_;
    document::BlockKind kind_ = document::BlockKind::paragraph;
    int level_ = 0;
    std::string label_;  // list label not yet written (waits for the first text)
};

}  // namespace

Result<document::Document> import_docx(std::string_view bytes) {
    auto zip = ZipArchive::open(bytes);
    if (!zip) return std::unexpected(zip.error());
    Package package(std::move(*zip));

    auto main_part = package.related("", "officeDocument");
    if (!main_part) return std::unexpected(main_part.error());
    if (main_part->empty()) *main_part = default_main_part;

    pugi::xml_document styles_xml, numbering_xml, document_xml;
    std::string styles_bytes, numbering_bytes, document_bytes;
    auto styles_part = package.related(*main_part, "styles");
    if (!styles_part) return std::unexpected(styles_part.error());
    if (!styles_part->empty()) {
        if (auto ok = package.load(*styles_part, styles_xml, styles_bytes, false); !ok)
            return std::unexpected(ok.error());
    }
    auto numbering_part = package.related(*main_part, "numbering");
    if (!numbering_part) return std::unexpected(numbering_part.error());
    if (!numbering_part->empty()) {
        if (auto ok = package.load(*numbering_part, numbering_xml, numbering_bytes, false); !ok)
            return std::unexpected(ok.error());
    }
    if (auto ok = package.load(*main_part, document_xml, document_bytes, true); !ok)
        return std::unexpected(ok.error());

    const DocxStyles styles(styles_xml.document_element());
    DocxNumbering numbering(numbering_xml.document_element());
    const auto body = child(document_xml.document_element(), "body");
    if (local_name(document_xml.document_element()) != "document" || !body)
        return fail("not a Word document: no <w:document>/<w:body>", *main_part);
    BodyReader reader(styles, numbering);
    reader.container(body);
    return reader.finish();
}

}  // namespace tactus::import::detail
