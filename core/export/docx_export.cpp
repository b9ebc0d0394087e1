// SPDX-License-Identifier: GPL-3.0-or-later
// DOCX: WordprocessingML in a ZIP package, written for core's DOCX importer
// (import/docx_import.cpp) to read back the same blocks, and for Word and
// LibreOffice to show them as what they are: headings in the "heading N"
// styles, list items numbered by word/numbering.xml, quotes in the "Quote"
// style, tables with header rows (w:tblHeader), notes in word/footnotes.xml,
// boxes as text boxes (wps:txbx), pictures as inline pictures in
// word/media with their descriptions (wp:docPr descr), page breaks as
// pageBreakBefore or w:br, a passage's language as w:lang.
#include <algorithm>
#include <array>
#include <map>

#include "document/cell_paragraphs.hpp"
#include "document/main_language.hpp"
#include "document/placeholder_picture.hpp"
#include "export/office_common.hpp"
#include "export/office_export.hpp"
#include "export/zip_writer.hpp"

namespace tactus::exporter {
namespace docx_writer {

using document::Block;
using document::BlockKind;
using document::Span;
using office::escape;
using office::ListStyle;

constexpr std::string_view kNamespaces =
    R"( xmlns:w="http://schemas.openxmlformats.org/wordprocessingml/2006/main")"
    R"( xmlns:r="http://schemas.openxmlformats.org/officeDocument/2006/relationships")"
    R"( xmlns:wp="http://schemas.openxmlformats.org/drawingml/2006/wordprocessingDrawing")"
    R"( xmlns:a="http://schemas.openxmlformats.org/drawingml/2006/main")"
    R"( xmlns:pic="http://schemas.openxmlformats.org/drawingml/2006/picture")"
    R"( xmlns:wps="http://schemas.microsoft.com/office/word/2010/wordprocessingShape")"
    R"( xmlns:mc="http://schemas.openxmlformats.org/markup-compatibility/2006")";

constexpr std::string_view kXmlDeclaration = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n";

// The numbering definitions (w:abstractNum) and their first w:num, one per
// list style; a list that starts at another number gets a w:num of its own
// with a w:startOverride.
constexpr int abstract_id(ListStyle s) {
    switch (s) {
        case ListStyle::bullet: return 1;
        case ListStyle::decimal_dot: return 2;
        case ListStyle::decimal_paren: return 3;
        case ListStyle::plain: return 4;
    }
    return 4;
}

constexpr int kMaxListLevel = 9;  // w:ilvl 0..8

class DocxWriter {
public:
    explicit DocxWriter(const document::Document& doc) : doc_(doc), notes_(doc) {}

    Result<OfficeFile> write() {
        std::string body;
        blocks(body, 0, doc_.blocks.size(), false);
        // Notes nothing refers to: in the notes part without a reference, where
        // the importer finds them (after the text).
        for (const auto& [label, index] : notes_.by_label)
            if (!notes_.referenced.contains(label)) footnote(doc_.blocks[index]);
        if (document::has_other_metadata(doc_)) losses_.add("the document's metadata (title, author) is not written", 0);
        if (dropped_controls_ > 0) losses_.add("control characters XML cannot hold are left out", 0);

        std::vector<ZipPart> parts;
        parts.push_back({"[Content_Types].xml", content_types(), false});
        parts.push_back({"_rels/.rels", package_rels(), false});
        parts.push_back({"word/document.xml", document_part(body), false});
        parts.push_back({"word/_rels/document.xml.rels", document_rels(), false});
        parts.push_back({"word/styles.xml", styles_part(document::main_language(doc_)), false});
        parts.push_back({"word/numbering.xml", numbering_part(), false});
        parts.push_back({"word/footnotes.xml", footnotes_part(), false});
        // A relationship belongs to its part: the notes' pictures name theirs
        // in the notes' own relationships, the same ids as the text's.
        if (const auto pictures = picture_rels(); !pictures.empty())
            parts.push_back({"word/_rels/footnotes.xml.rels",
                             std::string(kXmlDeclaration) +
                                 "<Relationships xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\">" +
                                 pictures + "</Relationships>",
                             false});
        parts.push_back({"word/settings.xml", settings_part(), false});
        if (pictures_ > 0) parts.push_back({"word/media/placeholder.png", std::string(document::placeholder_png()), false});
        for (const auto& m : media_) parts.push_back({"word/media/" + m.file, m.image->bytes, false});
        auto bytes = zip_package(parts);
        if (!bytes) return std::unexpected(bytes.error());
        return OfficeFile{std::move(*bytes), losses_.lines("DOCX")};
    }

private:
    // ---- Blocks ----

    [[nodiscard]] const Block* next_shown(std::size_t i, std::size_t end) const {
        return office::next_shown(doc_.blocks, i, end);
    }

    void blocks(std::string& out, std::size_t begin, std::size_t end, bool in_box) {
        bool break_before = false;
        for (std::size_t i = begin; i < end;) {
            const Block& b = doc_.blocks[i];
            if (b.box != 0 && !in_box) {
                std::size_t j = i;
                while (j < end && doc_.blocks[j].box == b.box) ++j;
                if (break_before) out += "<w:p><w:r><w:br w:type=\"page\"/></w:r></w:p>";
                break_before = false;
                text_box(out, i, j);
                i = j;
                continue;
            }
            switch (b.kind) {
                case BlockKind::print_page_break: {
                    if (!b.label_counted) losses_.add("a print page's own number is not kept (pages are counted)", i);
                    if (break_before) out += "<w:p><w:r><w:br w:type=\"page\"/></w:r></w:p>";
                    const Block* next = next_shown(i, end);
                    break_before = next && document::is_text_kind(next->kind) && next->kind != BlockKind::table_cell &&
                                   (in_box || next->box == 0);
                    if (!break_before) out += "<w:p><w:r><w:br w:type=\"page\"/></w:r></w:p>";
                    ++i;
                    continue;
                }
                case BlockKind::braille_page_break:
                    losses_.add("a braille page break is left out (DOCX has print pages only)", i);
                    ++i;
                    continue;
                case BlockKind::braille:
                    losses_.add("ready-made braille is left out (DOCX holds print text)", i);
                    ++i;
                    continue;
                case BlockKind::note:
                    ++i;  // with its reference
                    continue;
                case BlockKind::table_row:
                case BlockKind::table_cell: {
                    const auto j = office::table_end(doc_.blocks, i, end);
                    table(out, i, j);
                    i = j;
                    continue;
                }
                default:
                    paragraph(out, b, i, break_before);
                    break_before = false;
                    ++i;
            }
        }
        if (break_before) out += "<w:p><w:r><w:br w:type=\"page\"/></w:r></w:p>";
    }

    void paragraph(std::string& out, const Block& b, std::size_t index, bool break_before) {
        // CT_PPr's order: pStyle, then pageBreakBefore, then numPr.
        std::string ppr, numbering;
        std::vector<Span> spans = b.spans;
        switch (b.kind) {
            case BlockKind::heading:
                ppr += "<w:pStyle w:val=\"Heading" + std::to_string(std::clamp(b.level, 1, 6)) + "\"/>";
                break;
            case BlockKind::quote:
                ppr += "<w:pStyle w:val=\"Quote\"/>";
                if (b.level > 1) losses_.add("a quote in a quote is written as a quote of the first depth", index);
                break;
            case BlockKind::list_item: {
                const auto label = office::list_label(b);
                spans = office::without_label(b, label);
                int level = std::max(b.level, 1);
                if (level > kMaxListLevel) {
                    losses_.add("a list deeper than 9 levels is written at the 9th", index);
                    level = kMaxListLevel;
                }
                ppr += "<w:pStyle w:val=\"ListParagraph\"/>";
                numbering = "<w:numPr><w:ilvl w:val=\"" + std::to_string(level - 1) + "\"/><w:numId w:val=\"" +
                            std::to_string(num_for(label, level - 1)) + "\"/></w:numPr>";
                break;
            }
            default:
                break;
        }
        if (break_before) ppr += "<w:pageBreakBefore/>";
        ppr += numbering;
        out += "<w:p>";
        if (!ppr.empty()) out += "<w:pPr>" + ppr + "</w:pPr>";
        office::BlockPictures pictures(b);
        runs(out, spans, index, pictures);
        rest(out, pictures, index);
        out += "</w:p>";
    }

    // The w:num for an item, and the importer's count replayed
    // (import/docx_styles.cpp, DocxNumbering): a number that does not follow
    // on starts a w:num with its own start.
    int num_for(const office::ListLabel& label, int ilvl) {
        const auto i = static_cast<std::size_t>(ilvl);
        if (label.style != ListStyle::decimal_dot && label.style != ListStyle::decimal_paren)
            return abstract_id(label.style);
        auto& counters = counters_[abstract_id(label.style)];
        if (!counters_started_[abstract_id(label.style)]) {
            counters.fill(-1);
            counters_started_[abstract_id(label.style)] = true;
        }
        const int expected = counters[i] < 0 ? 1 : counters[i] + 1;
        int num = abstract_id(label.style);
        if (label.number != expected) {
            num = 5 + static_cast<int>(overrides_.size());
            overrides_.push_back({abstract_id(label.style), ilvl, label.number});
        }
        counters[i] = label.number;
        for (std::size_t deeper = i + 1; deeper < counters.size(); ++deeper) counters[deeper] = -1;
        return num;
    }

    void runs(std::string& out, const std::vector<Span>& spans, std::size_t index, office::BlockPictures& pictures) {
        for (const auto& s : spans) {
            if (s.note_reference) {
                reference(out, s, index, pictures);
                continue;
            }
            if (s.transcriber_note) {
                picture(out, s.text, pictures.next(), index);
                continue;
            }
            std::string rpr;
            if (s.emphasis & document::emphasis_bold) rpr += "<w:b/>";
            if (s.emphasis & document::emphasis_italic) rpr += "<w:i/>";
            if (s.emphasis & document::emphasis_underline) rpr += "<w:u w:val=\"single\"/>";
            if (s.position == document::Position::superscript) rpr += "<w:vertAlign w:val=\"superscript\"/>";
            if (s.position == document::Position::subscript) rpr += "<w:vertAlign w:val=\"subscript\"/>";
            // The passage's language for every script (Latin, East Asian,
            // complex): Word and the importer take one of the three by each
            // character's script, and the passage is in this language
            // whatever its characters are.
            rpr += language_element(s.language);
            out += "<w:r>";
            if (!rpr.empty()) out += "<w:rPr>" + rpr + "</w:rPr>";
            std::string text;
            const auto flush = [&] {
                if (text.empty()) return;
                out += "<w:t xml:space=\"preserve\">" + escape(text, &dropped_controls_) + "</w:t>";
                text.clear();
            };
            for (const char c : s.text) {
                if (c == '\t' || c == '\n') {
                    flush();
                    out += c == '\t' ? "<w:tab/>" : "<w:br/>";
                } else if (c != '\r') {
                    text += c;
                }
            }
            flush();
            out += "</w:r>";
        }
    }

    void reference(std::string& out, const Span& s, std::size_t index, office::BlockPictures& pictures) {
        const auto it = notes_.by_label.find(s.text);
        if (it == notes_.by_label.end()) {
            losses_.add("a note reference without its note is written as raised text", index);
            Span raised = s;
            raised.note_reference = false;
            raised.position = document::Position::superscript;
            runs(out, {raised}, index, pictures);
            return;
        }
        const int id = footnote(doc_.blocks[it->second]);
        out += "<w:r><w:rPr><w:rStyle w:val=\"FootnoteReference\"/></w:rPr><w:footnoteReference w:id=\"" +
               std::to_string(id) + "\"/></w:r>";
    }

    int footnote(const Block& note) {
        const int id = ++footnote_count_;
        const std::size_t index = static_cast<std::size_t>(&note - doc_.blocks.data());
        footnotes_ += "<w:footnote w:id=\"" + std::to_string(id) +
                      "\"><w:p><w:pPr><w:pStyle w:val=\"FootnoteText\"/></w:pPr><w:r><w:rPr><w:rStyle "
                      "w:val=\"FootnoteReference\"/></w:rPr><w:footnoteRef/></w:r><w:r><w:t xml:space=\"preserve\"> "
                      "</w:t></w:r>";
        std::string body;
        office::BlockPictures pictures(note);
        runs(body, office::note_body(note), index, pictures);
        rest(body, pictures, index);
        footnotes_ += body + "</w:p></w:footnote>";
        return id;
    }

    // The pictures of a block that no description took, after its text.
    void rest(std::string& out, office::BlockPictures& pictures, std::size_t index) {
        for (const auto& image : pictures.rest()) picture(out, {}, &image, index);
    }

    // A picture in a run of its own, inline (wp:inline: in the text, where
    // the importer reads it back in order), its description on wp:docPr
    // descr, which the importer reads (else title). A description without a
    // picture stands on the placeholder (document/placeholder_picture.hpp).
    void picture(std::string& out, std::string_view description, const document::Image* image, std::size_t index) {
        std::string relationship = "rIdPicture";
        office::Extent extent{9525, 9525};  // the placeholder's one pixel
        std::string svg;
        if (image && !office::add_picture_file(media_, *image, index, losses_)) image = nullptr;
        if (image) {
            relationship = "rIdImage" + std::to_string(media_.size());
            extent = office::picture_extent(*image);
            // Word draws an SVG from its svgBlip extension (Office 2016
            // on); the blip itself names the SVG too, which LibreOffice
            // and the importer read (there is no PNG to fall back on).
            if (image->media_type == "image/svg+xml")
                svg = "<a:extLst><a:ext uri=\"{96DAC541-7B7A-43D3-8B79-37D633B846F1}\"><asvg:svgBlip "
                      "xmlns:asvg=\"http://schemas.microsoft.com/office/drawing/2016/SVG/main\" r:embed=\"" +
                      relationship + "\"/></a:ext></a:extLst>";
        }
        if (!image) {
            if (description.empty()) return;
            ++pictures_;
        }
        const auto id = std::to_string(++drawings_);
        const auto descr =
            description.empty() ? std::string() : " descr=\"" + escape(description, &dropped_controls_) + "\"";
        const auto size = "cx=\"" + std::to_string(extent.cx) + "\" cy=\"" + std::to_string(extent.cy) + "\"";
        out += "<w:r><w:drawing><wp:inline distT=\"0\" distB=\"0\" distL=\"0\" distR=\"0\"><wp:extent " + size +
               "/><wp:docPr id=\"" + id + "\" name=\"Picture " + id + "\"" + descr +
               "/><a:graphic><a:graphicData uri=\"http://schemas.openxmlformats.org/drawingml/2006/picture\">"
               "<pic:pic><pic:nvPicPr><pic:cNvPr id=\"" + id + "\" name=\"Picture " + id + "\"" + descr +
               "/><pic:cNvPicPr/></pic:nvPicPr><pic:blipFill><a:blip r:embed=\"" + relationship + "\">" + svg +
               "</a:blip><a:stretch><a:fillRect/></a:stretch></pic:blipFill><pic:spPr><a:xfrm><a:off x=\"0\" "
               "y=\"0\"/><a:ext " + size + "/></a:xfrm><a:prstGeom prst=\"rect\"><a:avLst/></a:prstGeom></pic:spPr>"
               "</pic:pic></a:graphicData></a:graphic></wp:inline></w:drawing></w:r>";
    }

    // A box: a text box in a paragraph of its own, its blocks inside.
    void text_box(std::string& out, std::size_t begin, std::size_t end) {
        const auto id = std::to_string(++drawings_);
        std::string content;
        blocks(content, begin, end, true);
        if (content.empty()) content = "<w:p/>";
        out += "<w:p><w:r><mc:AlternateContent><mc:Choice Requires=\"wps\"><w:drawing><wp:inline distT=\"0\" "
               "distB=\"0\" distL=\"0\" distR=\"0\"><wp:extent cx=\"5486400\" cy=\"914400\"/><wp:docPr id=\"" + id +
               "\" name=\"Text Box " + id + "\"/><a:graphic><a:graphicData "
               "uri=\"http://schemas.microsoft.com/office/word/2010/wordprocessingShape\"><wps:wsp><wps:cNvSpPr "
               "txBox=\"1\"/><wps:spPr><a:xfrm><a:off x=\"0\" y=\"0\"/><a:ext cx=\"5486400\" cy=\"914400\"/></a:xfrm>"
               "<a:prstGeom prst=\"rect\"><a:avLst/></a:prstGeom><a:noFill/><a:ln w=\"9525\"><a:solidFill><a:srgbClr "
               "val=\"000000\"/></a:solidFill></a:ln></wps:spPr><wps:txbx><w:txbxContent>" + content +
               "</w:txbxContent></wps:txbx><wps:bodyPr><a:spAutoFit/></wps:bodyPr></wps:wsp></a:graphicData>"
               "</a:graphic></wp:inline></w:drawing></mc:Choice></mc:AlternateContent></w:r></w:p>";
    }

    // Rows and cells; a cell covering columns has w:gridSpan, columns before a
    // row's first cell are w:gridBefore.
    void table(std::string& out, std::size_t begin, std::size_t end) {
        const int columns = office::table_columns(doc_.blocks, begin, end);
        const int width = 9000 / columns;
        out += "<w:tbl><w:tblPr><w:tblStyle w:val=\"TableGrid\"/><w:tblW w:w=\"0\" w:type=\"auto\"/></w:tblPr>"
               "<w:tblGrid>";
        for (int c = 0; c < columns; ++c) out += "<w:gridCol w:w=\"" + std::to_string(width) + "\"/>";
        out += "</w:tblGrid>";
        std::size_t i = begin;
        if (doc_.blocks[i].kind == BlockKind::table_cell) {
            losses_.add("table cells before the first row are written as a row", i);
        }
        while (i < end) {
            const bool header = doc_.blocks[i].kind == BlockKind::table_row && doc_.blocks[i].level == 1;
            if (doc_.blocks[i].kind == BlockKind::table_row) ++i;
            std::size_t j = i;
            while (j < end && doc_.blocks[j].kind == BlockKind::table_cell) ++j;
            if (j == i) {
                losses_.add("a table row without cells is left out", i);
                continue;
            }
            std::string trpr;
            if (header) trpr += "<w:tblHeader/>";
            int column = 0;
            if (const int first = doc_.blocks[i].level; first > 0) {
                trpr += "<w:gridBefore w:val=\"" + std::to_string(first) + "\"/>";
                column = first;
            }
            out += "<w:tr>";
            if (!trpr.empty()) out += "<w:trPr>" + trpr + "</w:trPr>";
            for (std::size_t k = i; k < j; ++k) {
                const Block& cell = doc_.blocks[k];
                for (; column < cell.level; ++column) {
                    losses_.add("a column no cell starts in (a cell merged down) is written as an empty cell", k);
                    out += "<w:tc><w:p/></w:tc>";
                }
                const int span = std::max(cell.span, 1);
                out += "<w:tc><w:tcPr><w:tcW w:w=\"" + std::to_string(width * span) + "\" w:type=\"dxa\"/>";
                if (span > 1) out += "<w:gridSpan w:val=\"" + std::to_string(span) + "\"/>";
                out += "</w:tcPr>";
                std::string ppr;
                if (cell.align == document::Align::centre) ppr = "<w:pPr><w:jc w:val=\"center\"/></w:pPr>";
                if (cell.align == document::Align::right) ppr = "<w:pPr><w:jc w:val=\"right\"/></w:pPr>";
                if (cell.align == document::Align::left) {
                    ppr = "<w:pPr><w:jc w:val=\"left\"/></w:pPr>";
                    losses_.add("a column aligned left comes back as not aligned (left is DOCX's default)", k);
                }
                // Each of the cell's paragraphs a w:p of its own
                // (document/cell_paragraphs.hpp), its pictures no
                // description took in the last.
                office::BlockPictures pictures(cell);
                const auto paragraphs = document::cell_paragraphs(cell.spans);
                for (std::size_t p = 0; p < paragraphs.size(); ++p) {
                    out += "<w:p>" + ppr;
                    runs(out, paragraphs[p], k, pictures);
                    if (p + 1 == paragraphs.size()) rest(out, pictures, k);
                    out += "</w:p>";
                }
                out += "</w:tc>";
                column = std::max(column, cell.level) + span;
            }
            out += "</w:tr>";
            i = j;
        }
        out += "</w:tbl>";
    }

    // ---- Parts ----

    [[nodiscard]] std::string content_types() const {
        std::string out(kXmlDeclaration);
        out += "<Types xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\">"
               "<Default Extension=\"rels\" ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/>"
               "<Default Extension=\"xml\" ContentType=\"application/xml\"/>"
               "<Default Extension=\"png\" ContentType=\"image/png\"/>";
        for (const auto& [extension, type] : {std::pair<std::string_view, std::string_view>{".jpeg", "image/jpeg"},
                                              {".svg", "image/svg+xml"}})
            if (std::ranges::any_of(media_, [&](const office::PictureFile& m) { return m.file.ends_with(extension); }))
                out += "<Default Extension=\"" + std::string(extension.substr(1)) + "\" ContentType=\"" +
                       std::string(type) + "\"/>";
        out += "<Override PartName=\"/word/document.xml\" "
               "ContentType=\"application/vnd.openxmlformats-officedocument.wordprocessingml.document.main+xml\"/>"
               "<Override PartName=\"/word/styles.xml\" "
               "ContentType=\"application/vnd.openxmlformats-officedocument.wordprocessingml.styles+xml\"/>"
               "<Override PartName=\"/word/numbering.xml\" "
               "ContentType=\"application/vnd.openxmlformats-officedocument.wordprocessingml.numbering+xml\"/>"
               "<Override PartName=\"/word/footnotes.xml\" "
               "ContentType=\"application/vnd.openxmlformats-officedocument.wordprocessingml.footnotes+xml\"/>"
               "<Override PartName=\"/word/settings.xml\" "
               "ContentType=\"application/vnd.openxmlformats-officedocument.wordprocessingml.settings+xml\"/>"
               "</Types>";
        return out;
    }

    [[nodiscard]] static std::string package_rels() {
        std::string out(kXmlDeclaration);
        out += "<Relationships xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\">"
               "<Relationship Id=\"rId1\" "
               "Type=\"http://schemas.openxmlformats.org/officeDocument/2006/relationships/officeDocument\" "
               "Target=\"word/document.xml\"/></Relationships>";
        return out;
    }

    [[nodiscard]] std::string document_rels() const {
        std::string out(kXmlDeclaration);
        const std::string base = "http://schemas.openxmlformats.org/officeDocument/2006/relationships/";
        out += "<Relationships xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\">";
        for (const auto& [id, type, target] :
             std::array<std::array<std::string_view, 3>, 4>{{{"rIdStyles", "styles", "styles.xml"},
                                                             {"rIdNumbering", "numbering", "numbering.xml"},
                                                             {"rIdFootnotes", "footnotes", "footnotes.xml"},
                                                             {"rIdSettings", "settings", "settings.xml"}}})
            out += "<Relationship Id=\"" + std::string(id) + "\" Type=\"" + base + std::string(type) +
                   "\" Target=\"" + std::string(target) + "\"/>";
        out += picture_rels() + "</Relationships>";
        return out;
    }

    // The relationships of the pictures (rIdPicture the placeholder's,
    // rIdImageN each picture's), for document.xml and footnotes.xml alike.
    [[nodiscard]] std::string picture_rels() const {
        const std::string type = "http://schemas.openxmlformats.org/officeDocument/2006/relationships/image";
        std::string out;
        if (pictures_ > 0) out += "<Relationship Id=\"rIdPicture\" Type=\"" + type + "\" Target=\"media/placeholder.png\"/>";
        for (std::size_t k = 0; k < media_.size(); ++k)
            out += "<Relationship Id=\"rIdImage" + std::to_string(k + 1) + "\" Type=\"" + type +
                   "\" Target=\"media/" + media_[k].file + "\"/>";
        return out;
    }

    [[nodiscard]] static std::string document_part(const std::string& body) {
        std::string out(kXmlDeclaration);
        out += "<w:document";
        out += kNamespaces;
        out += "><w:body>" + body +
               "<w:sectPr><w:pgSz w:w=\"11906\" w:h=\"16838\"/><w:pgMar w:top=\"1440\" w:right=\"1440\" "
               "w:bottom=\"1440\" w:left=\"1440\" w:header=\"708\" w:footer=\"708\" w:gutter=\"0\"/></w:sectPr>"
               "</w:body></w:document>";
        return out;
    }

    // w:lang for every script class, "" for no language.
    [[nodiscard]] static std::string language_element(const std::string& language) {
        if (language.empty()) return {};
        const auto tag = escape(language);
        return "<w:lang w:val=\"" + tag + "\" w:eastAsia=\"" + tag + "\" w:bidi=\"" + tag + "\"/>";
    }

    // The document's main language is the defaults' for every script, as a
    // passage's is its run's (the importer reads it back from there).
    [[nodiscard]] static std::string styles_part(const std::string& language) {
        std::string out(kXmlDeclaration);
        out += "<w:styles xmlns:w=\"http://schemas.openxmlformats.org/wordprocessingml/2006/main\">"
               "<w:docDefaults><w:rPrDefault><w:rPr><w:sz w:val=\"24\"/>";
        out += language_element(language);
        out += "</w:rPr></w:rPrDefault>"
               "<w:pPrDefault><w:pPr><w:spacing w:after=\"120\"/></w:pPr></w:pPrDefault></w:docDefaults>"
               "<w:style w:type=\"paragraph\" w:default=\"1\" w:styleId=\"Normal\"><w:name w:val=\"Normal\"/>"
               "<w:qFormat/></w:style>";
        // Word's built-in names ("heading 1"), which it shows as Heading 1
        // and puts in the navigation pane; the outline level says it again.
        for (int level = 1; level <= 6; ++level) {
            const auto n = std::to_string(level);
            out += "<w:style w:type=\"paragraph\" w:styleId=\"Heading" + n + "\"><w:name w:val=\"heading " + n +
                   "\"/><w:basedOn w:val=\"Normal\"/><w:next w:val=\"Normal\"/><w:uiPriority w:val=\"9\"/><w:qFormat/>"
                   "<w:pPr><w:keepNext/><w:spacing w:before=\"240\" w:after=\"120\"/><w:outlineLvl w:val=\"" +
                   std::to_string(level - 1) + "\"/></w:pPr><w:rPr><w:b/><w:sz w:val=\"" +
                   std::to_string(40 - 3 * level) + "\"/></w:rPr></w:style>";
        }
        out += "<w:style w:type=\"paragraph\" w:styleId=\"Quote\"><w:name w:val=\"Quote\"/><w:basedOn "
               "w:val=\"Normal\"/><w:next w:val=\"Normal\"/><w:qFormat/><w:pPr><w:ind w:left=\"720\" "
               "w:right=\"720\"/></w:pPr><w:rPr><w:i/></w:rPr></w:style>"
               "<w:style w:type=\"paragraph\" w:styleId=\"ListParagraph\"><w:name w:val=\"List Paragraph\"/>"
               "<w:basedOn w:val=\"Normal\"/><w:qFormat/></w:style>"
               "<w:style w:type=\"paragraph\" w:styleId=\"FootnoteText\"><w:name w:val=\"footnote text\"/>"
               "<w:basedOn w:val=\"Normal\"/><w:rPr><w:sz w:val=\"20\"/></w:rPr></w:style>"
               "<w:style w:type=\"character\" w:styleId=\"FootnoteReference\"><w:name w:val=\"footnote reference\"/>"
               "<w:rPr><w:vertAlign w:val=\"superscript\"/></w:rPr></w:style>"
               "<w:style w:type=\"table\" w:styleId=\"TableGrid\"><w:name w:val=\"Table Grid\"/><w:tblPr><w:tblBorders>"
               "<w:top w:val=\"single\" w:sz=\"4\" w:space=\"0\" w:color=\"auto\"/>"
               "<w:left w:val=\"single\" w:sz=\"4\" w:space=\"0\" w:color=\"auto\"/>"
               "<w:bottom w:val=\"single\" w:sz=\"4\" w:space=\"0\" w:color=\"auto\"/>"
               "<w:right w:val=\"single\" w:sz=\"4\" w:space=\"0\" w:color=\"auto\"/>"
               "<w:insideH w:val=\"single\" w:sz=\"4\" w:space=\"0\" w:color=\"auto\"/>"
               "<w:insideV w:val=\"single\" w:sz=\"4\" w:space=\"0\" w:color=\"auto\"/>"
               "</w:tblBorders></w:tblPr></w:style></w:styles>";
        return out;
    }

    [[nodiscard]] std::string numbering_part() const {
        std::string out(kXmlDeclaration);
        out += "<w:numbering xmlns:w=\"http://schemas.openxmlformats.org/wordprocessingml/2006/main\">";
        for (const auto style : {ListStyle::bullet, ListStyle::decimal_dot, ListStyle::decimal_paren, ListStyle::plain}) {
            out += "<w:abstractNum w:abstractNumId=\"" + std::to_string(abstract_id(style)) +
                   "\"><w:multiLevelType w:val=\"hybridMultilevel\"/>";
            for (int l = 0; l < kMaxListLevel; ++l) {
                const auto n = std::to_string(l + 1);
                std::string format = "decimal", text;
                switch (style) {
                    case ListStyle::bullet: format = "bullet"; text = "\u2022"; break;
                    case ListStyle::decimal_dot: text = "%" + n + "."; break;
                    case ListStyle::decimal_paren: text = "%" + n + ")"; break;
                    case ListStyle::plain: format = "none"; break;
                }
                out += "<w:lvl w:ilvl=\"" + std::to_string(l) + "\"><w:start w:val=\"1\"/><w:numFmt w:val=\"" + format +
                       "\"/><w:lvlText w:val=\"" + text + "\"/><w:lvlJc w:val=\"left\"/><w:pPr><w:ind w:left=\"" +
                       std::to_string(720 * (l + 1)) + "\" w:hanging=\"360\"/></w:pPr></w:lvl>";
            }
            out += "</w:abstractNum>";
        }
        for (const auto style : {ListStyle::bullet, ListStyle::decimal_dot, ListStyle::decimal_paren, ListStyle::plain})
            out += "<w:num w:numId=\"" + std::to_string(abstract_id(style)) + "\"><w:abstractNumId w:val=\"" +
                   std::to_string(abstract_id(style)) + "\"/></w:num>";
        for (std::size_t k = 0; k < overrides_.size(); ++k) {
            const auto& o = overrides_[k];
            out += "<w:num w:numId=\"" + std::to_string(5 + k) + "\"><w:abstractNumId w:val=\"" +
                   std::to_string(o.abstract) + "\"/><w:lvlOverride w:ilvl=\"" + std::to_string(o.ilvl) +
                   "\"><w:startOverride w:val=\"" + std::to_string(o.start) + "\"/></w:lvlOverride></w:num>";
        }
        out += "</w:numbering>";
        return out;
    }

    [[nodiscard]] std::string footnotes_part() const {
        std::string out(kXmlDeclaration);
        out += "<w:footnotes";
        out += kNamespaces;
        out += "><w:footnote w:type=\"separator\" w:id=\"-1\"><w:p><w:r><w:separator/></w:r></w:p></w:footnote>"
               "<w:footnote w:type=\"continuationSeparator\" w:id=\"0\"><w:p><w:r><w:continuationSeparator/></w:r>"
               "</w:p></w:footnote>" +
               footnotes_ + "</w:footnotes>";
        return out;
    }

    [[nodiscard]] static std::string settings_part() {
        std::string out(kXmlDeclaration);
        out += "<w:settings xmlns:w=\"http://schemas.openxmlformats.org/wordprocessingml/2006/main\">"
               "<w:footnotePr><w:footnote w:id=\"-1\"/><w:footnote w:id=\"0\"/></w:footnotePr></w:settings>";
        return out;
    }

    // A picture stored in word/media, in the order written.
    struct Override {
        int abstract;
        int ilvl;
        int start;
    };

    const document::Document& doc_;
    office::Notes notes_;
    office::Losses losses_;
    std::string footnotes_;
    int footnote_count_ = 0;
    int drawings_ = 0;
    int pictures_ = 0;  // descriptions on the placeholder
    std::vector<office::PictureFile> media_;
    std::size_t dropped_controls_ = 0;
    std::map<int, std::array<int, kMaxListLevel>> counters_;  // per w:abstractNum, as the importer counts
    std::map<int, bool> counters_started_;
    std::vector<Override> overrides_;
};

}  // namespace docx_writer

Result<OfficeFile> to_docx(const document::Document& document) { return docx_writer::DocxWriter(document).write(); }

}  // namespace tactus::exporter
