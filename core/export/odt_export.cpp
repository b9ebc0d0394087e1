// SPDX-License-Identifier: GPL-3.0-or-later
// ODT: OpenDocument text in a ZIP package (mimetype first, stored), written
// for core's ODT importer (import/odt_import.cpp) to read back the same
// blocks, and for LibreOffice to show them as what they are: text:h
// headings in the "Heading N" styles, nested text:list lists (a number
// that does not follow on is an item's text:start-value), the "Quotations"
// style, tables with table:table-header-rows, text:note footnotes, boxes as
// text boxes (draw:text-box), pictures as frames of images in Pictures/
// with their descriptions (svg:desc), page breaks as paragraph styles
// breaking before, a passage's language in its automatic text style.
#include <algorithm>
#include <array>
#include <cctype>
#include <map>

#include "document/cell_paragraphs.hpp"
#include "document/main_language.hpp"
#include "document/placeholder_picture.hpp"
#include "export/office_common.hpp"
#include "export/office_export.hpp"
#include "export/zip_writer.hpp"

namespace tactus::exporter {
namespace odt_writer {

using document::Block;
using document::BlockKind;
using document::Span;
using office::escape;
using office::ListStyle;

constexpr std::string_view kMimeType = "application/vnd.oasis.opendocument.text";
constexpr std::string_view kXmlDeclaration = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
constexpr std::string_view kNamespaces =
    R"( xmlns:office="urn:oasis:names:tc:opendocument:xmlns:office:1.0")"
    R"( xmlns:style="urn:oasis:names:tc:opendocument:xmlns:style:1.0")"
    R"( xmlns:text="urn:oasis:names:tc:opendocument:xmlns:text:1.0")"
    R"( xmlns:table="urn:oasis:names:tc:opendocument:xmlns:table:1.0")"
    R"( xmlns:draw="urn:oasis:names:tc:opendocument:xmlns:drawing:1.0")"
    R"( xmlns:fo="urn:oasis:names:tc:opendocument:xmlns:xsl-fo-compatible:1.0")"
    R"( xmlns:xlink="http://www.w3.org/1999/xlink")"
    R"( xmlns:svg="urn:oasis:names:tc:opendocument:xmlns:svg-compatible:1.0")"
    R"( office:version="1.3")";

constexpr int kMaxListLevel = 10;  // text:list-level-style levels 1..10

// A list style is one kind of label per level, 1 to 10: 'b' bullet, 'd'
// "1.", 'p' "1)", 'n' none. LibreOffice draws every level of a list with the
// style of its outermost text:list, so a list's style holds the kind of each
// of its levels; a nested list whose items are another kind names its own.
using Signature = std::string;

constexpr char kind_char(ListStyle s) {
    switch (s) {
        case ListStyle::bullet: return 'b';
        case ListStyle::decimal_dot: return 'd';
        case ListStyle::decimal_paren: return 'p';
        case ListStyle::plain: return 'n';
    }
    return 'n';
}

constexpr ListStyle style_of(char kind) {
    return kind == 'b' ? ListStyle::bullet : kind == 'd' ? ListStyle::decimal_dot
                       : kind == 'p' ? ListStyle::decimal_paren : ListStyle::plain;
}

Signature uniform(ListStyle s) { return Signature(kMaxListLevel, kind_char(s)); }

class OdtWriter {
public:
    explicit OdtWriter(const document::Document& doc) : doc_(doc), notes_(doc) {}

    Result<OfficeFile> write() {
        std::string body;
        blocks(body, 0, doc_.blocks.size(), false);
        if (document::has_other_metadata(doc_)) losses_.add("the document's metadata (title, author) is not written", 0);
        if (dropped_controls_ > 0) losses_.add("control characters XML cannot hold are left out", 0);
        std::vector<ZipPart> parts;
        parts.push_back({"mimetype", std::string(kMimeType), true});
        parts.push_back({"content.xml", content_part(body), false});
        parts.push_back({"styles.xml", styles_part(document::main_language(doc_)), false});
        parts.push_back({"META-INF/manifest.xml", manifest(), false});
        if (pictures_ > 0) parts.push_back({"Pictures/placeholder.png", std::string(document::placeholder_png()), false});
        for (const auto& m : media_) parts.push_back({"Pictures/" + m.file, m.image->bytes, false});
        auto bytes = zip_package(parts);
        if (!bytes) return std::unexpected(bytes.error());
        return OfficeFile{std::move(*bytes), losses_.lines("ODT")};
    }

private:
    [[nodiscard]] const Block* next_shown(std::size_t i, std::size_t end) const {
        return office::next_shown(doc_.blocks, i, end);
    }

    static std::string break_paragraph() { return "<text:p text:style-name=\"P_break\"/>"; }

    void blocks(std::string& out, std::size_t begin, std::size_t end, bool in_box) {
        bool break_before = false;
        for (std::size_t i = begin; i < end;) {
            const Block& b = doc_.blocks[i];
            if (b.kind != BlockKind::list_item && b.kind != BlockKind::note &&
                !(b.kind == BlockKind::print_page_break && next_shown(i, end) &&
                  next_shown(i, end)->kind == BlockKind::list_item))
                close_lists(out);
            if (b.box != 0 && !in_box) {
                std::size_t j = i;
                while (j < end && doc_.blocks[j].box == b.box) ++j;
                close_lists(out);
                if (break_before) out += break_paragraph();
                break_before = false;
                text_box(out, i, j);
                i = j;
                continue;
            }
            switch (b.kind) {
                case BlockKind::print_page_break: {
                    if (!b.label_counted) losses_.add("a print page's own number is not kept (pages are counted)", i);
                    if (break_before) out += break_paragraph();
                    const Block* next = next_shown(i, end);
                    break_before = next && document::is_text_kind(next->kind) && next->kind != BlockKind::table_cell &&
                                   (in_box || next->box == 0);
                    if (!break_before) out += break_paragraph();
                    ++i;
                    continue;
                }
                case BlockKind::braille_page_break:
                    losses_.add("a braille page break is left out (ODT has print pages only)", i);
                    ++i;
                    continue;
                case BlockKind::braille:
                    losses_.add("ready-made braille is left out (ODT holds print text)", i);
                    ++i;
                    continue;
                case BlockKind::note:
                    if (!b.spans.empty() && b.spans.front().note_reference &&
                        !notes_.referenced.contains(b.spans.front().text)) {
                        // ODT's notes stand in the text: one nothing refers
                        // to gets a paragraph of its own.
                        losses_.add("a note nothing refers to is written in a paragraph of its own", i);
                        out += "<text:p>";
                        note(out, b, i);
                        out += "</text:p>";
                    }
                    ++i;
                    continue;
                case BlockKind::table_row:
                case BlockKind::table_cell: {
                    const auto j = office::table_end(doc_.blocks, i, end);
                    table(out, i, j);
                    i = j;
                    continue;
                }
                case BlockKind::list_item:
                    list_item(out, b, i, end, in_box, break_before);
                    break_before = false;
                    ++i;
                    continue;
                default:
                    paragraph(out, b, i, break_before);
                    break_before = false;
                    ++i;
            }
        }
        close_lists(out);
        if (break_before) out += break_paragraph();
    }

    // A paragraph style that breaks the page before, on top of `parent`.
    std::string breaking(const std::string& parent) {
        const auto [it, added] = breaking_.try_emplace(parent, "P_break_" + std::to_string(breaking_.size() + 1));
        return it->second;
    }

    // `pictures`: a table cell's, shared by its paragraphs, the rest placed
    // in the last (`last`); else the block's own.
    void paragraph(std::string& out, const Block& b, std::size_t index, bool break_before,
                   office::BlockPictures* pictures = nullptr, bool last = true) {
        std::string style = "Standard";
        std::string element = "text:p";
        std::string attributes;
        if (b.kind == BlockKind::heading) {
            const auto level = std::to_string(std::clamp(b.level, 1, 6));
            style = "Heading_20_" + level;
            element = "text:h";
            attributes = " text:outline-level=\"" + level + "\"";
        } else if (b.kind == BlockKind::quote) {
            style = "Quotations";
            if (b.level > 1) losses_.add("a quote in a quote is written as a quote of the first depth", index);
        } else if (b.kind == BlockKind::table_cell) {
            style = b.align == document::Align::centre  ? "P_centre"
                    : b.align == document::Align::right ? "P_right"
                    : b.align == document::Align::left  ? "P_left"
                                                        : "Table_20_Contents";
        }
        if (break_before) style = breaking(style);
        out += "<" + element + " text:style-name=\"" + style + "\"" + attributes + ">";
        office::BlockPictures own(b);
        if (!pictures) pictures = &own;
        runs(out, b.spans, index, *pictures);
        if (last) rest(out, *pictures, index);
        out += "</" + element + ">";
    }

    // ---- Lists ----

    struct OpenList {
        ListStyle style;       // the kind of its items
        Signature signature;   // its list style, inherited by the lists in it
        bool item_open = false;
    };

    std::string list_style(const Signature& signature) {
        const auto [it, added] = list_styles_.try_emplace(signature, "L" + std::to_string(list_styles_.size() + 1));
        return it->second;
    }

    // The kinds of the levels of the list starting at `begin`: each level's
    // first item's, up to where the walk closes the list.
    [[nodiscard]] Signature list_signature(std::size_t begin, std::size_t end, bool in_box) const {
        Signature sig(kMaxListLevel, 'd');
        std::vector<bool> seen(kMaxListLevel, false);
        for (std::size_t j = begin; j < end; ++j) {
            const Block& b = doc_.blocks[j];
            if (!in_box && b.box != doc_.blocks[begin].box) break;
            if (b.kind == BlockKind::note) continue;
            if (b.kind == BlockKind::print_page_break) {
                const Block* next = next_shown(j, end);
                if (next && next->kind == BlockKind::list_item) continue;
                break;
            }
            if (b.kind != BlockKind::list_item) break;
            const auto level = static_cast<std::size_t>(std::clamp(b.level, 1, kMaxListLevel));
            const char kind = kind_char(office::list_label(b).style);
            if (level == 1 && seen[0] && sig[0] != kind) break;
            if (!seen[level - 1]) {
                sig[level - 1] = kind;
                seen[level - 1] = true;
            }
        }
        return sig;
    }

    void close_top(std::string& out) {
        if (lists_.back().item_open) out += "</text:list-item>";
        out += "</text:list>";
        lists_.pop_back();
    }

    void close_lists(std::string& out) {
        while (!lists_.empty()) close_top(out);
    }

    // Lists nest as the items' levels say; a change of list style at a level
    // starts another list there. The importer's count is replayed (its
    // counters are the top list's, shared by the lists nested in it): a
    // number that does not follow on is written as the item's start value.
    void list_item(std::string& out, const Block& b, std::size_t index, std::size_t end, bool in_box,
                   bool break_before) {
        const auto label = office::list_label(b);
        int level = std::max(b.level, 1);
        if (level > kMaxListLevel) {
            losses_.add("a list deeper than 10 levels is written at the 10th", index);
            level = kMaxListLevel;
        }
        const auto depth = static_cast<std::size_t>(level);
        while (lists_.size() > depth) close_top(out);
        if (lists_.size() == depth && lists_.back().style != label.style) close_top(out);
        if (lists_.size() == depth && lists_.back().item_open) {
            out += "</text:list-item>";
            lists_.back().item_open = false;
        }
        while (lists_.size() < depth) {
            if (lists_.empty()) counters_.fill(0);  // a list of its own: counted anew
            if (!lists_.empty() && !lists_.back().item_open) {
                out += "<text:list-item>";
                lists_.back().item_open = true;
            }
            const auto at = lists_.size();  // the new list's level, 0-based
            const bool items_here = at + 1 == depth;
            if (lists_.empty()) {
                const auto sig = list_signature(index, end, in_box);
                out += "<text:list text:style-name=\"" + list_style(sig) + "\">";
                lists_.push_back({style_of(sig[at]), sig, false});
                continue;
            }
            const auto& inherited = lists_.back().signature;
            if (!items_here || inherited[at] == kind_char(label.style)) {
                out += "<text:list>";
                lists_.push_back({style_of(inherited[at]), inherited, false});
            } else {
                const auto own = uniform(label.style);
                out += "<text:list text:style-name=\"" + list_style(own) + "\">";
                lists_.push_back({label.style, own, false});
            }
        }
        auto& number = counters_[depth];
        const int expected = number == 0 ? 1 : number + 1;
        out += "<text:list-item";
        if (label.number > 0 && label.number != expected)
            out += " text:start-value=\"" + std::to_string(label.number) + "\"";
        out += ">";
        number = label.number > 0 ? label.number : expected;
        std::fill(counters_.begin() + static_cast<std::ptrdiff_t>(depth) + 1, counters_.end(), 0);
        lists_.back().item_open = true;
        out += "<text:p text:style-name=\"" + (break_before ? breaking("List_20_Paragraph") : "List_20_Paragraph") + "\">";
        office::BlockPictures pictures(b);
        runs(out, office::without_label(b, label), index, pictures);
        rest(out, pictures, index);
        out += "</text:p>";
    }

    // ---- Text ----

    // The automatic text style for a span's emphasis and position.
    std::string text_style(const Span& s) {
        std::string key;
        if (s.emphasis & document::emphasis_bold) key += "b";
        if (s.emphasis & document::emphasis_italic) key += "i";
        if (s.emphasis & document::emphasis_underline) key += "u";
        if (s.position == document::Position::superscript) key += "sup";
        if (s.position == document::Position::subscript) key += "sub";
        if (!s.language.empty()) key += "_" + s.language;
        if (key.empty()) return {};
        const auto [it, added] = text_styles_.try_emplace(key, std::make_pair("T" + std::to_string(text_styles_.size() + 1), s));
        return it->second.first;
    }

    // Text with ODF's white space rules (ODF 1.3 part 3, 6.1.2): a single
    // space between two characters is itself, every other run of spaces is
    // text:s, a tab text:tab and a line end text:line-break.
    void text(std::string& out, std::string_view t) {
        std::string chunk;
        for (std::size_t i = 0; i < t.size();) {
            const char c = t[i];
            if (c == '\t' || c == '\n') {
                out += escape(chunk, &dropped_controls_);
                chunk.clear();
                out += c == '\t' ? "<text:tab/>" : "<text:line-break/>";
                ++i;
            } else if (c == ' ') {
                std::size_t j = i;
                while (j < t.size() && t[j] == ' ') ++j;
                const bool inside = !chunk.empty() && j < t.size() && t[j] != '\t' && t[j] != '\n';
                if (j - i == 1 && inside) {
                    chunk += ' ';
                } else {
                    out += escape(chunk, &dropped_controls_);
                    chunk.clear();
                    out += j - i == 1 ? "<text:s/>" : "<text:s text:c=\"" + std::to_string(j - i) + "\"/>";
                }
                i = j;
            } else {
                if (c != '\r') chunk += c;
                ++i;
            }
        }
        out += escape(chunk, &dropped_controls_);
    }

    void runs(std::string& out, const std::vector<Span>& spans, std::size_t index, office::BlockPictures& pictures) {
        for (const auto& s : spans) {
            if (s.note_reference) {
                const auto it = notes_.by_label.find(s.text);
                if (it != notes_.by_label.end()) {
                    note(out, doc_.blocks[it->second], index);
                    continue;
                }
                losses_.add("a note reference without its note is written as raised text", index);
                Span raised = s;
                raised.note_reference = false;
                raised.position = document::Position::superscript;
                runs(out, {raised}, index, pictures);
                continue;
            }
            if (s.transcriber_note) {
                picture(out, s.text, pictures.next(), index);
                continue;
            }
            const auto style = text_style(s);
            if (!style.empty()) out += "<text:span text:style-name=\"" + style + "\">";
            text(out, s.text);
            if (!style.empty()) out += "</text:span>";
        }
    }

    void note(std::string& out, const Block& b, std::size_t index) {
        const auto id = std::to_string(++notes_written_);
        out += "<text:note text:id=\"ftn" + id + "\" text:note-class=\"footnote\"><text:note-citation>" + id +
               "</text:note-citation><text:note-body><text:p text:style-name=\"Footnote\">";
        office::BlockPictures pictures(b);
        runs(out, office::note_body(b), index, pictures);
        rest(out, pictures, index);
        out += "</text:p></text:note-body></text:note>";
    }

    // The pictures of a block that no description took, after its text.
    void rest(std::string& out, office::BlockPictures& pictures, std::size_t index) {
        for (const auto& image : pictures.rest()) picture(out, {}, &image, index);
    }

    // A picture in a frame anchored as a character (in the text, where the
    // importer reads it back in order), its description in svg:desc, which
    // the importer reads (else svg:title). A description without a picture
    // stands on the placeholder (document/placeholder_picture.hpp).
    void picture(std::string& out, std::string_view description, const document::Image* image, std::size_t index) {
        std::string href = "Pictures/placeholder.png", type = "image/png";
        office::Extent extent{9525, 9525};  // the placeholder's one pixel
        if (image && !office::add_picture_file(media_, *image, index, losses_)) image = nullptr;
        if (image) {
            href = "Pictures/" + media_.back().file;
            type = image->media_type;
            extent = office::picture_extent(*image);
        }
        if (!image) {
            if (description.empty()) return;
            ++pictures_;
        }
        out += "<draw:frame draw:name=\"Picture " + std::to_string(++frames_) +
               "\" text:anchor-type=\"as-char\" svg:width=\"" + office::odf_length(extent.cx) + "\" svg:height=\"" +
               office::odf_length(extent.cy) + "\" draw:z-index=\"0\"><draw:image xlink:href=\"" + href +
               "\" xlink:type=\"simple\" xlink:show=\"embed\" xlink:actuate=\"onLoad\" draw:mime-type=\"" + type +
               "\"/>";
        if (!description.empty()) out += "<svg:desc>" + escape(description, &dropped_controls_) + "</svg:desc>";
        out += "</draw:frame>";
    }

    void text_box(std::string& out, std::size_t begin, std::size_t end) {
        std::string content;
        auto outer = std::move(lists_);
        auto counters = counters_;
        lists_.clear();
        blocks(content, begin, end, true);
        lists_ = std::move(outer);
        counters_ = counters;
        out += "<text:p text:style-name=\"Standard\"><draw:frame draw:style-name=\"Box\" draw:name=\"Box " +
               std::to_string(++frames_) +
               "\" text:anchor-type=\"as-char\" svg:width=\"15cm\" draw:z-index=\"0\"><draw:text-box "
               "fo:min-height=\"0.5cm\">" + content + "</draw:text-box></draw:frame></text:p>";
    }

    // Header rows first, in table:table-header-rows (ODF has one run of
    // them); a cell covering columns has table:number-columns-spanned and
    // covered cells after it, and a column no cell starts in a covered cell.
    void table(std::string& out, std::size_t begin, std::size_t end) {
        const int columns = office::table_columns(doc_.blocks, begin, end);
        out += "<table:table table:name=\"Table" + std::to_string(++tables_) +
               "\"><table:table-column table:number-columns-repeated=\"" + std::to_string(columns) + "\"/>";
        std::size_t i = begin;
        bool headers_open = false, body_started = false;
        while (i < end) {
            const bool header = doc_.blocks[i].kind == BlockKind::table_row && doc_.blocks[i].level == 1;
            if (doc_.blocks[i].kind == BlockKind::table_row) ++i;
            std::size_t j = i;
            while (j < end && doc_.blocks[j].kind == BlockKind::table_cell) ++j;
            if (header && !body_started && !headers_open) {
                out += "<table:table-header-rows>";
                headers_open = true;
            } else if (!header || body_started) {
                if (header) losses_.add("a header row after the table's first rows is written as a row", i);
                if (headers_open) out += "</table:table-header-rows>";
                headers_open = false;
                body_started = true;
            }
            out += "<table:table-row>";
            int column = 0;
            for (std::size_t k = i; k < j; ++k) {
                const Block& cell = doc_.blocks[k];
                for (; column < cell.level; ++column) out += "<table:covered-table-cell/>";
                const int span = std::max(cell.span, 1);
                out += "<table:table-cell office:value-type=\"string\"";
                if (span > 1) out += " table:number-columns-spanned=\"" + std::to_string(span) + "\"";
                out += ">";
                if (cell.align == document::Align::left)
                    losses_.add("a column aligned left comes back as not aligned (left is ODT's default)", k);
                // Each of the cell's paragraphs a text:p of its own (document/cell_paragraphs.hpp).
                // Its pictures no description took in the last.
                office::BlockPictures pictures(cell);
                auto paragraphs = document::cell_paragraphs(cell.spans);
                for (std::size_t p = 0; p < paragraphs.size(); ++p) {
                    Block piece = cell;
                    piece.spans = std::move(paragraphs[p]);
                    paragraph(out, piece, k, false, &pictures, p + 1 == paragraphs.size());
                }
                out += "</table:table-cell>";
                for (int c = 1; c < span; ++c) out += "<table:covered-table-cell/>";
                column = std::max(column, cell.level) + span;
            }
            if (j == i) {
                // A row holds at least one cell (ODF): it comes back with an empty one.
                losses_.add("a table row without cells gets an empty cell", i);
                out += "<table:table-cell/>";
            }
            out += "</table:table-row>";
            i = j;
        }
        if (headers_open) out += "</table:table-header-rows>";
        out += "</table:table>";
    }

    // A passage's language for every script (Latin, Asian, complex: the
    // importer and LibreOffice take one of the three by each character's
    // script, and the passage is in this language whatever its characters
    // are): language and country, and the whole tag as
    // style:rfc-language-tag when it says more ("zh-Hant-TW", "sr-Latn").
    [[nodiscard]] static std::string language_attributes(const std::string& tag) {
        const auto dash = tag.find('-');
        const std::string language = tag.substr(0, dash);
        const std::string rest = dash == std::string::npos ? std::string{} : tag.substr(dash + 1);
        const bool region = (rest.size() == 2 && std::isalpha(static_cast<unsigned char>(rest[0])) &&
                             std::isalpha(static_cast<unsigned char>(rest[1]))) ||
                            (rest.size() == 3 && std::all_of(rest.begin(), rest.end(), [](char c) { return c >= '0' && c <= '9'; }));
        std::string out;
        for (const std::string_view suffix : {"", "-asian", "-complex"}) {
            const std::string prefix = suffix.empty() ? "fo:" : "style:";
            out += " " + prefix + "language" + std::string(suffix) + "=\"" + escape(language) + "\"";
            if (region) out += " " + prefix + "country" + std::string(suffix) + "=\"" + escape(rest) + "\"";
            if (!rest.empty() && !region)
                out += " style:rfc-language-tag" + std::string(suffix) + "=\"" + escape(tag) + "\"";
        }
        return out;
    }

    // ---- Parts ----

    [[nodiscard]] std::string content_part(const std::string& body) const {
        std::string out(kXmlDeclaration);
        out += "<office:document-content";
        out += kNamespaces;
        out += "><office:automatic-styles>";
        for (const auto& [parent, name] : breaking_)
            out += "<style:style style:name=\"" + name + "\" style:family=\"paragraph\" style:parent-style-name=\"" +
                   parent + "\"><style:paragraph-properties fo:break-before=\"page\"/></style:style>";
        for (const auto& [key, style] : text_styles_) {
            const auto& [name, s] = style;
            out += "<style:style style:name=\"" + name + "\" style:family=\"text\"><style:text-properties";
            if (s.emphasis & document::emphasis_bold) out += " fo:font-weight=\"bold\"";
            if (s.emphasis & document::emphasis_italic) out += " fo:font-style=\"italic\"";
            if (s.emphasis & document::emphasis_underline)
                out += " style:text-underline-style=\"solid\" style:text-underline-width=\"auto\" "
                       "style:text-underline-color=\"font-color\"";
            if (s.position == document::Position::superscript) out += " style:text-position=\"super 58%\"";
            if (s.position == document::Position::subscript) out += " style:text-position=\"sub 58%\"";
            if (!s.language.empty()) out += language_attributes(s.language);
            out += "/></style:style>";
        }
        for (const auto& [name, align] : {std::pair<std::string_view, std::string_view>{"P_centre", "center"},
                                          {"P_right", "end"},
                                          {"P_left", "start"}})
            out += "<style:style style:name=\"" + std::string(name) +
                   "\" style:family=\"paragraph\" style:parent-style-name=\"Table_20_Contents\">"
                   "<style:paragraph-properties fo:text-align=\"" + std::string(align) + "\"/></style:style>";
        out += "<style:style style:name=\"P_break\" style:family=\"paragraph\" style:parent-style-name=\"Standard\">"
               "<style:paragraph-properties fo:break-before=\"page\"/></style:style>"
               "<style:style style:name=\"Box\" style:family=\"graphic\"><style:graphic-properties "
               "fo:border=\"0.06pt solid #000000\" fo:padding=\"0.1cm\"/></style:style>";
        for (const auto& [sig, name] : list_styles_) {
            out += "<text:list-style style:name=\"" + name + "\">";
            for (int l = 1; l <= kMaxListLevel; ++l) {
                const auto level = std::to_string(l);
                const char kind = sig[static_cast<std::size_t>(l - 1)];
                const std::string properties =
                    "<style:list-level-properties text:list-level-position-and-space-mode=\"label-alignment\">"
                    "<style:list-level-label-alignment text:label-followed-by=\"listtab\" fo:margin-left=\"" +
                    std::to_string(l * 0.635).substr(0, 5) + "cm\" fo:text-indent=\"-0.635cm\"/>"
                    "</style:list-level-properties>";
                if (kind == 'b')
                    out += "<text:list-level-style-bullet text:level=\"" + level + "\" text:bullet-char=\"\u2022\">" +
                           properties + "</text:list-level-style-bullet>";
                else
                    out += "<text:list-level-style-number text:level=\"" + level + "\" style:num-format=\"" +
                           (kind == 'n' ? "" : "1") + "\"" +
                           (kind == 'd' ? " style:num-suffix=\".\"" : kind == 'p' ? " style:num-suffix=\")\"" : "") +
                           ">" + properties + "</text:list-level-style-number>";
            }
            out += "</text:list-style>";
        }
        out += "</office:automatic-styles><office:body><office:text>" + body +
               "</office:text></office:body></office:document-content>";
        return out;
    }

    // The document's main language is the default style's for every script,
    // where LibreOffice keeps it and the importer reads it back.
    [[nodiscard]] static std::string styles_part(const std::string& language) {
        std::string out(kXmlDeclaration);
        out += "<office:document-styles";
        out += kNamespaces;
        out += "><office:styles>"
               "<style:default-style style:family=\"paragraph\"><style:text-properties fo:font-size=\"12pt\"";
        if (!language.empty()) out += language_attributes(language);
        out += "/></style:default-style>"
               "<style:style style:name=\"Standard\" style:family=\"paragraph\" style:class=\"text\"/>"
               "<style:style style:name=\"Heading\" style:family=\"paragraph\" style:parent-style-name=\"Standard\" "
               "style:next-style-name=\"Standard\" style:class=\"text\"><style:paragraph-properties "
               "fo:margin-top=\"0.42cm\" fo:margin-bottom=\"0.21cm\" fo:keep-with-next=\"always\"/>"
               "<style:text-properties fo:font-weight=\"bold\"/></style:style>";
        for (int level = 1; level <= 6; ++level) {
            const auto n = std::to_string(level);
            out += "<style:style style:name=\"Heading_20_" + n + "\" style:display-name=\"Heading " + n +
                   "\" style:family=\"paragraph\" style:parent-style-name=\"Heading\" style:next-style-name=\"Standard\" "
                   "style:default-outline-level=\"" + n + "\" style:class=\"text\"><style:text-properties "
                   "fo:font-size=\"" + std::to_string(20 - 2 * level) + "pt\"/></style:style>";
        }
        out += "<style:style style:name=\"Quotations\" style:family=\"paragraph\" style:parent-style-name=\"Standard\" "
               "style:class=\"html\"><style:paragraph-properties fo:margin-left=\"1cm\" fo:margin-right=\"1cm\"/>"
               "</style:style>"
               "<style:style style:name=\"List_20_Paragraph\" style:display-name=\"List Paragraph\" "
               "style:family=\"paragraph\" style:parent-style-name=\"Standard\" style:class=\"list\"/>"
               "<style:style style:name=\"Footnote\" style:family=\"paragraph\" style:parent-style-name=\"Standard\" "
               "style:class=\"extra\"><style:text-properties fo:font-size=\"10pt\"/></style:style>"
               "<style:style style:name=\"Table_20_Contents\" style:display-name=\"Table Contents\" "
               "style:family=\"paragraph\" style:parent-style-name=\"Standard\" style:class=\"extra\"/>"
               "</office:styles></office:document-styles>";
        return out;
    }

    [[nodiscard]] std::string manifest() const {
        std::string out(kXmlDeclaration);
        out += "<manifest:manifest xmlns:manifest=\"urn:oasis:names:tc:opendocument:xmlns:manifest:1.0\" "
               "manifest:version=\"1.3\">"
               "<manifest:file-entry manifest:full-path=\"/\" manifest:version=\"1.3\" manifest:media-type=\"" +
               std::string(kMimeType) + "\"/>"
               "<manifest:file-entry manifest:full-path=\"content.xml\" manifest:media-type=\"text/xml\"/>"
               "<manifest:file-entry manifest:full-path=\"styles.xml\" manifest:media-type=\"text/xml\"/>";
        if (pictures_ > 0)
            out += "<manifest:file-entry manifest:full-path=\"Pictures/placeholder.png\" "
                   "manifest:media-type=\"image/png\"/>";
        for (const auto& m : media_)
            out += "<manifest:file-entry manifest:full-path=\"Pictures/" + m.file + "\" manifest:media-type=\"" +
                   m.image->media_type + "\"/>";
        out += "</manifest:manifest>";
        return out;
    }

    // A picture stored in Pictures/, in the order written.
    const document::Document& doc_;
    office::Notes notes_;
    office::Losses losses_;
    std::vector<OpenList> lists_;
    std::array<int, kMaxListLevel + 2> counters_{};  // the importer's, per level (1-based)
    std::map<std::string, std::string> breaking_;     // parent style -> breaking style
    std::map<Signature, std::string> list_styles_;    // list style -> its name
    std::map<std::string, std::pair<std::string, Span>> text_styles_;
    int notes_written_ = 0;
    int pictures_ = 0;  // descriptions on the placeholder
    std::vector<office::PictureFile> media_;
    int frames_ = 0;
    int tables_ = 0;
    std::size_t dropped_controls_ = 0;
};

}  // namespace odt_writer

Result<OfficeFile> to_odt(const document::Document& document) { return odt_writer::OdtWriter(document).write(); }

}  // namespace tactus::exporter
