// SPDX-License-Identifier: GPL-3.0-or-later
// DOCX (WordprocessingML in a ZIP package): paragraphs of the main document part,
// headings from styles (name "heading N"/"Title" or outline level), list items
// from numbering (label kept as text, a bullet as "•"), block quotes from the
// "Quote" styles, tables (rows, cells, <w:tblHeader/> header rows), footnotes
// and endnotes (placed after the paragraph that refers to them),
// bold/italic/underline from direct formatting and styles, page breaks from
// <w:br w:type="page"/>, pageBreakBefore and section breaks.
// <w:lastRenderedPageBreak/> only records where the last layout happened to
// break, so it is not a break.
// Content controls (w:sdt) around blocks, rows, cells and runs are read
// through, placeholder text included ("Choose an item."). Text boxes
// (wps:txbx, or v:textbox in the VML fallback; one of the two, never both)
// are boxed material after the paragraph they are anchored in; a picture's
// description (wp:docPr descr, else title) is a transcriber's note where the
// picture is, and a picture without one is named in a warning. Ruby
// (w:ruby) keeps its base and, by choice, its guide as a transcriber's note;
// w:vertAlign raises and lowers runs; equations (m:oMath) are linear text
// (office_math.hpp). A passage's language is w:lang's for each character's
// script (office_language.hpp), from direct formatting, character and
// paragraph styles and the document defaults; only a language other than
// the document's own for that script is kept on the text.
// Not imported, deliberately: headers and footers (braille pages carry their
// own numbers, and a running head repeated on every print page is not text),
// comments.
#include <pugixml.hpp>

#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "import/docx_styles.hpp"
#include "import/import.hpp"
#include "import/importers.hpp"
#include "import/office_language.hpp"
#include "import/office_math.hpp"
#include "import/office_package.hpp"
#include "document/main_language.hpp"
#include "document/placeholder_picture.hpp"
#include "import/picture_part.hpp"
#include "import/text_position.hpp"
#include "import/xml_util.hpp"
#include "common/try.hpp"

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

// The relationships of a part: the target of the first one of a kind.
Result<std::string> related(const XmlPackage& package, std::string_view source, std::string_view kind) {
    XmlPart rels;
    TACTUS_TRY(found, package.load(rels_of(source), rels, false));
    if (!found) return std::string{};
    for (const auto& r : rels.root().children()) {
        if (local_name(r) != "Relationship") continue;
        if (attribute(r, "TargetMode") == "External") continue;
        const auto type = attribute(r, "Type");
        if (type.size() > kind.size() && type.ends_with(kind) && type[type.size() - kind.size() - 1] == '/')
            return resolve_target(folder_of(source), attribute(r, "Target"));
    }
    return std::string{};
}

// Footnotes or endnotes by id (<w:footnote w:id="2">).
std::unordered_map<std::string, pugi::xml_node> notes_by_id(const pugi::xml_node& root) {
    std::unordered_map<std::string, pugi::xml_node> out;
    for (const auto& n : root.children())
        if (const auto name = local_name(n); name == "footnote" || name == "endnote")
            out.emplace(std::string(attribute(n, "id")), n);
    return out;
}

class BodyReader {
public:
    BodyReader(const DocxStyles& styles, DocxNumbering& numbering, const pugi::xml_node& footnotes,
               const pugi::xml_node& endnotes, RubyGuide ruby, std::string_view part, std::string_view bytes)
        : styles_(styles), numbering_(numbering), footnotes_(notes_by_id(footnotes)),
          endnotes_(notes_by_id(endnotes)), footnotes_root_(footnotes), endnotes_root_(endnotes),
          ruby_(ruby), part_(part), bytes_(bytes), document_languages_(styles.document_languages()),
          paragraph_languages_(document_languages_) {}

    void container(const pugi::xml_node& node) {
        for (const auto& c : node.children()) {
            if (out_.full()) return;
            const auto name = local_name(c);
            if (name == "p")
                paragraph(c);
            else if (name == "tbl")
                table(c);
            else if (name == "sdt" || name == "sdtContent" || name == "customXml")
                container(c);  // content controls hold paragraphs
        }
    }

    // Footnotes, then endnotes, that nothing in the text refers to (kept, so
    // no text of the file is lost): at the end of the document, in their
    // part's order, as notes without a reference. Word's own notes (the
    // separator lines, w:type="separator" and the like) are not notes.
    Result<document::Document> finish() {
        for (const auto* root : {&footnotes_root_, &endnotes_root_})
            for (const auto& n : root->children()) {
                const auto name = local_name(n);
                if ((name != "footnote" && name != "endnote") || out_.full()) continue;
                if (const auto type = attribute(n, "type"); !type.empty() && type != "normal") continue;
                if (referenced_.contains(std::string(name) + ":" + std::string(attribute(n, "id")))) continue;
                out_.begin_unreferenced_note();
                note_text(n);
                out_.end_note();
            }
        return out_.finish();
    }

private:
    // Rows and cells; a row with <w:tblHeader/> is a header row. A cell merged
    // across columns (<w:gridSpan w:val="n"/>) covers n columns, and a row's
    // <w:gridBefore> columns hold no cell, so every cell keeps its column. A
    // cell merged down (<w:vMerge/>) is the cells the file has: the first holds
    // the text, the ones under it are empty.
    // The children of a table or row, with content controls (w:sdt around
    // rows or cells) and custom XML read through.
    static void controlled(const pugi::xml_node& node, std::string_view want, std::vector<pugi::xml_node>& out,
                           int depth = 0) {
        for (const auto& c : node.children()) {
            const auto name = local_name(c);
            if (name == want)
                out.push_back(c);
            else if ((name == "sdt" || name == "sdtContent" || name == "customXml") && depth < 64)
                controlled(c, want, out, depth + 1);
        }
    }

    void table(const pugi::xml_node& tbl) {
        // The table's style gives its text's languages (a table in another
        // language); a table inside it has its own.
        const auto outer_style =
            std::exchange(table_style_, std::string(attribute(child(child(tbl, "tblPr"), "tblStyle"), "val")));
        out_.begin_table();
        std::vector<pugi::xml_node> rows;
        controlled(tbl, "tr", rows);
        for (const auto& row : rows) {
            const auto trPr = child(row, "trPr");
            out_.begin_row(read_toggle(child(trPr, "tblHeader")).value_or(false));
            out_.skip_columns(whole_number(attribute(child(trPr, "gridBefore"), "val"), 0));
            std::vector<pugi::xml_node> cells;
            controlled(row, "tc", cells);
            for (const auto& cell : cells) {
                // The alignment of the cell's first paragraph (<w:jc w:val="center"/>);
                // left is the default (LibreOffice writes it in every cell), so none.
                const auto jc = attribute(child(child(child(cell, "p"), "pPr"), "jc"), "val");
                const auto align = jc == "center"                 ? document::Align::centre
                                   : jc == "right" || jc == "end" ? document::Align::right
                                                                  : document::Align::none;
                out_.begin_cell(whole_number(attribute(child(child(cell, "tcPr"), "gridSpan"), "val"), 1), align);
                container(cell);
                out_.end_cell();
            }
        }
        out_.end_table();
        table_style_ = outer_style;
    }

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

        if (break_before.value_or(style.page_break_before)) out_.page_break();
        const auto kind = heading > 0  ? document::BlockKind::heading
                          : numbering  ? document::BlockKind::list_item
                          : style.quote ? document::BlockKind::quote
                                       : document::BlockKind::paragraph;
        const int level = heading > 0 ? heading : numbering ? numbering->ilvl + 1 : style.quote ? 1 : 0;
        out_.begin_paragraph(kind, level, numbering ? numbering_.next_label(*numbering) : std::string{});
        std::vector<pugi::xml_node> boxes;
        std::swap(boxes, boxes_);
        {
            const ParagraphLanguages languages(*this, p);
            inline_content(p);
        }
        out_.end_paragraph();
        std::swap(boxes, boxes_);
        text_boxes(boxes);

        // A section break in the paragraph properties ends the section here; all
        // kinds except "continuous" (and column breaks) start a new page.
        if (const auto sect = child(pPr, "sectPr")) {
            const auto type = attribute(child(sect, "type"), "val");
            if (type != "continuous" && type != "nextColumn") out_.page_break();
        }
    }

    // The text boxes anchored in a paragraph, after it, each a box.
    void text_boxes(const std::vector<pugi::xml_node>& boxes) {
        for (const auto& content : boxes) {
            if (out_.full()) return;
            out_.begin_box();
            if (++box_depth_ < 16) container(content);  // a box in a box in ... is read flat
            --box_depth_;
            out_.end_box();
        }
    }

    [[nodiscard]] std::string where(const pugi::xml_node& n) const {
        return std::string(part_) + ":" +
               position_at(bytes_, static_cast<std::size_t>(std::max<std::ptrdiff_t>(n.offset_debug(), 0))).to_string();
    }

    void inline_content(const pugi::xml_node& node, int depth = 0) {
        for (const auto& c : node.children()) {
            if (c.type() != pugi::node_element) continue;
            const auto name = local_name(c);
            if (name == "r")
                run(c);
            else if (name == "pPr" || name == "rPr" || name == "del" || name == "moveFrom" || name == "object")
                continue;  // properties, deleted text, embedded objects
            else if (name == "AlternateContent")
                alternate(c);
            else if (name == "drawing")
                drawing(c);
            else if (name == "pict")
                vml(c);
            else if (name == "oMath" || name == "oMathPara")
                math(c);
            else if (name == "ruby")
                ruby(c);
            else if (name == "hyperlink" && depth < 64) {
                ++in_hyperlink_;
                inline_content(c, depth + 1);
                --in_hyperlink_;
            } else if (depth < 64)
                inline_content(c, depth + 1);  // ins, smartTag, fldSimple, sdt...
        }
    }

    void math(const pugi::xml_node& m) {
        omml_linear(m, [&](std::string_view t, document::Position p) { out_.text(t, document::emphasis_none, p); });
    }

    // Word's Phonetic Guide: the base always, the guide after it by choice.
    void ruby(const pugi::xml_node& r) {
        inline_content(child(r, "rubyBase"));
        if (ruby_ == RubyGuide::omit) return;
        std::string guide;
        for (const auto& t : child(r, "rt").select_nodes(".//*[local-name()='t']")) guide += t.node().child_value();
        out_.transcriber_note(guide);
    }

    // Markup compatibility: the first choice this reader knows (DrawingML
    // text boxes and pictures, wps:), else the fallback (VML), never both.
    void alternate(const pugi::xml_node& ac) {
        for (const auto& c : ac.children())
            if (local_name(c) == "Choice") {
                inline_content(c);
                return;
            }
        inline_content(child(ac, "Fallback"));
    }

    // A DrawingML object: a text box (its w:txbxContent) or a picture (its
    // description). A group holds several.
    void drawing(const pugi::xml_node& d) {
        for (const auto& anchor : d.children()) {
            const auto docPr = child(anchor, "docPr");
            if (!docPr) continue;
            const auto boxes = anchor.select_nodes(".//*[local-name()='txbxContent']");
            for (const auto& b : boxes) boxes_.push_back(b.node());
            if (!boxes.empty()) continue;
            const auto blip = anchor.select_node(".//*[local-name()='blip']").node();
            picture(attribute(docPr, "descr"), attribute(docPr, "title"), anchor, attribute(blip, "embed"));
        }
    }

    // VML (Word 2007's, and the fallback of later files): v:textbox, or an
    // image (v:imagedata o:title, the shape's alt).
    void vml(const pugi::xml_node& pict) {
        const auto boxes = pict.select_nodes(".//*[local-name()='txbxContent']");
        for (const auto& b : boxes) boxes_.push_back(b.node());
        if (!boxes.empty()) return;
        for (const auto& shape : pict.children()) {
            if (shape.type() != pugi::node_element) continue;
            const auto image = shape.select_node(".//*[local-name()='imagedata']").node();
            if (!image) continue;
            picture(attribute(shape, "alt"), attribute(image, "title"), shape, attribute(image, "id"));
        }
    }

    void picture(std::string_view description, std::string_view title, const pugi::xml_node& where_node,
                 std::string_view relationship) {
        const auto text = description.find_first_not_of(" \t\r\n") != std::string_view::npos ? description : title;
        const bool described = text.find_first_not_of(" \t\r\n") != std::string_view::npos;
        auto image = picture_bytes(relationship);
        if (described) out_.transcriber_note(text);
        if (image)
            out_.image(std::move(*image), described, where(where_node));
        else if (!described)
            out_.picture_without_description(where(where_node));
    }

    // The picture a relationship names, when pictures are kept and the
    // graphic stage can read its type (else a warning naming it).
    std::optional<document::Image> picture_bytes(std::string_view relationship) {
        if (!package_ || relationship.empty()) return std::nullopt;
        const auto target = image_targets_.find(std::string(relationship));
        if (target == image_targets_.end()) return std::nullopt;
        auto bytes = package_->read(target->second, max_import_bytes);
        if (!bytes) {
            out_.warn("picture " + target->second + ": " + bytes.error().message + "; its description stays");
            return std::nullopt;
        }
        // The writers' stand-in for a description with no picture: the
        // description is the picture (document/placeholder_picture.hpp).
        if (*bytes == document::placeholder_png()) return std::nullopt;
        auto type = picture_media_type(*bytes, target->second);
        if (type.empty()) {
            out_.warn(unsupported_picture_warning(target->second));
            return std::nullopt;
        }
        return document::Image{std::move(*bytes), std::move(type), target->second};
    }

public:
    // Keep pictures' bytes (ImportOptions::images): `targets` maps the main
    // part's relationship ids to the parts they name.
    void keep_images(const XmlPackage& package, std::unordered_map<std::string, std::string> targets) {
        package_ = &package;
        image_targets_ = std::move(targets);
    }

private:

    void run(const pugi::xml_node& r) {
        const auto rPr = child(r, "rPr");
        const auto align = attribute(child(rPr, "vertAlign"), "val");
        const auto position = align == "superscript" ? document::Position::superscript
                              : align == "subscript" ? document::Position::subscript
                                                     : document::Position::baseline;
        // Only character styles and direct formatting are emphasis: the bold of a
        // heading style or the italic of a quote style is the paragraph's typeface.
        RunFormat format;
        format.apply(styles_.character(attribute(child(rPr, "rStyle"), "val")));
        format.apply(read_run_format(rPr));
        auto emphasis = format.emphasis();
        // A link's underline is print's way of showing a link, not emphasis
        // the author chose: BANA's guidance is not to show it in braille (a
        // typeform indicator there would tell the reader of emphasis that is not).
        if (in_hyperlink_ > 0 || attribute(child(rPr, "rStyle"), "val") == "Hyperlink")
            emphasis = static_cast<std::uint8_t>(emphasis & ~document::emphasis_underline);
        auto languages = paragraph_languages_;
        languages.apply(format.languages);
        const auto baseline = document::Position::baseline;
        for (const auto& c : r.children()) {
            if (c.type() != pugi::node_element) continue;
            const auto name = local_name(c);
            if (name == "t")
                text(c.child_value(), emphasis, position, languages);
            else if (name == "drawing")
                drawing(c);
            else if (name == "pict")
                vml(c);
            else if (name == "AlternateContent")
                alternate(c);
            else if (name == "ruby")
                ruby(c);
            else if (name == "tab")
                text("\t", emphasis, baseline, languages);
            else if (name == "cr")
                text("\n", emphasis, baseline, languages);
            else if (name == "noBreakHyphen")
                text("\xE2\x80\x91", emphasis, baseline, languages);  // U+2011 non-breaking hyphen
            else if (name == "footnoteReference")
                note(footnotes_, attribute(c, "id"));
            else if (name == "endnoteReference")
                note(endnotes_, attribute(c, "id"));
            else if (name == "br") {
                const auto type = attribute(c, "type");
                if (type == "page")
                    out_.page_break_inside();
                else if (type != "column")
                    text("\n", emphasis, baseline, languages);
            }
        }
    }

    // A footnote or endnote: its paragraphs as the note's text. Word's own
    // reference mark at the start of the note (<w:footnoteRef/>) is ours to
    // write, so it is not text; an id the part lacks leaves the reference out.
    void note(const std::unordered_map<std::string, pugi::xml_node>& notes, std::string_view id) {
        const auto it = notes.find(std::string(id));
        if (it == notes.end()) return;
        referenced_.insert(std::string(local_name(it->second)) + ":" + std::string(id));
        out_.begin_note();
        note_text(it->second);
        out_.end_note();
    }

    void note_text(const pugi::xml_node& note) {
        for (const auto& p : note.children())
            if (local_name(p) == "p") {
                out_.begin_paragraph(document::BlockKind::paragraph, 0, {});
                const ParagraphLanguages languages(*this, p);
                inline_content(p);
                out_.end_paragraph();
            }
    }

    // The languages of a paragraph's text while it is read; the paragraph
    // around it (a note's reference stands in one) has its own again after.
    class ParagraphLanguages {
    public:
        ParagraphLanguages(BodyReader& reader, const pugi::xml_node& p)
            : reader_(reader), outer_(std::move(reader.paragraph_languages_)) {
            reader_.paragraph_languages_ =
                reader_.styles_.paragraph_languages(attribute(child(child(p, "pPr"), "pStyle"), "val"),
                                                    reader_.table_style_);
        }
        ~ParagraphLanguages() { reader_.paragraph_languages_ = std::move(outer_); }
        ParagraphLanguages(const ParagraphLanguages&) = delete;
        ParagraphLanguages& operator=(const ParagraphLanguages&) = delete;

    private:
        BodyReader& reader_;
        OfficeLanguages outer_;
    };

    // A run's text in pieces of one language each (office_language.hpp): the
    // run's characters decide which of its three languages applies, as in
    // Word, so a run is cut where its script changes class, and only a
    // language other than the document's own is marked. Cutting (rather than
    // one language per run) keeps the Latin words of a run marked Chinese
    // for its East Asian text in the Latin language, as Word shows them.
    void text(std::string_view t, std::uint8_t emphasis, document::Position position, const OfficeLanguages& languages) {
        for (const auto& piece : language_pieces(t, languages, document_languages_))
            out_.text(piece.text, emphasis, position, piece.language);
    }

    const DocxStyles& styles_;
    DocxNumbering& numbering_;
    std::unordered_map<std::string, pugi::xml_node> footnotes_, endnotes_;
    pugi::xml_node footnotes_root_, endnotes_root_;
    std::unordered_set<std::string> referenced_;  // "footnote:2", "endnote:1"
    RubyGuide ruby_;
    const XmlPackage* package_ = nullptr;
    std::unordered_map<std::string, std::string> image_targets_;
    std::string_view part_, bytes_;     // the main part, for the places warnings name
    std::vector<pugi::xml_node> boxes_;  // text boxes met in the paragraph being read
    int box_depth_ = 0;
    OfficeText out_;
    int in_hyperlink_ = 0;  // inside w:hyperlink (nested ones count)
    const OfficeLanguages document_languages_;  // the defaults' and the default paragraph style's
    OfficeLanguages paragraph_languages_;       // the paragraph being read: defaults, then its style
    std::string table_style_;                   // the w:tblStyle of the table being read
};

// The main part's relationships by id, their targets as part names.
Result<std::unordered_map<std::string, std::string>> relationship_targets(const XmlPackage& package,
                                                                          std::string_view source) {
    std::unordered_map<std::string, std::string> out;
    XmlPart rels;
    TACTUS_TRY(found, package.load(rels_of(source), rels, false));
    if (!found) return out;
    for (const auto& r : rels.root().children())
        if (local_name(r) == "Relationship" && attribute(r, "TargetMode") != "External")
            out.emplace(std::string(attribute(r, "Id")), resolve_target(folder_of(source), attribute(r, "Target")));
    return out;
}

}  // namespace

Result<document::Document> import_docx(std::string_view bytes, RubyGuide ruby, bool images) {
    TACTUS_TRY(package, XmlPackage::open(bytes, "a Word document"));

    auto main_part = related(package, "", "officeDocument");
    if (!main_part) return std::unexpected(main_part.error());
    if (main_part->empty()) *main_part = default_main_part;

    // The main part's optional companions, each found through its relationship.
    XmlPart styles_xml, numbering_xml, footnotes_xml, endnotes_xml, document_xml;
    for (const auto& [kind, part] : {std::pair<std::string_view, XmlPart*>{"styles", &styles_xml},
                                     {"numbering", &numbering_xml},
                                     {"footnotes", &footnotes_xml},
                                     {"endnotes", &endnotes_xml}}) {
        TACTUS_TRY(name, related(package, *main_part, kind));
        if (name.empty()) continue;
        TACTUS_TRY_VOID(package.load(name, *part, false));
    }
    TACTUS_TRY_VOID(package.load(*main_part, document_xml, true));

    const DocxStyles styles(styles_xml.root());
    DocxNumbering numbering(numbering_xml.root());
    const auto body = child(document_xml.root(), "body");
    if (local_name(document_xml.root()) != "document" || !body)
        return fail(ErrorKind::input, "not a Word document: no <w:document>/<w:body>", *main_part);
    BodyReader reader(styles, numbering, footnotes_xml.root(), endnotes_xml.root(), ruby, *main_part,
                      document_xml.bytes);
    if (images) {
        TACTUS_TRY(targets, relationship_targets(package, *main_part));
        reader.keep_images(package, std::move(targets));
    }
    reader.container(body);
    auto doc = reader.finish();
    if (doc) document::set_main_language(*doc, main_language(styles.document_languages(), *doc));
    return doc;
}

}  // namespace tactus::import::detail
