// SPDX-License-Identifier: GPL-3.0-or-later
// ODT (OpenDocument text, ISO/IEC 26300: content.xml in a ZIP package): the
// paragraphs of <office:text>, headings from <text:h text:outline-level>, list
// items from <text:list> (numbered levels get their label as text, bullets the
// bullet "•", as for DOCX), block quotes from the "Quotations" paragraph style,
// tables (rows, cells, header rows), notes (<text:note>, placed after the
// paragraph that refers to them), bold/italic/underline from the automatic and
// common text styles, and page breaks from paragraph styles with
// fo:break-before or fo:break-after="page". <text:soft-page-break/> only records
// where the last layout happened to break, so it is not a break (like DOCX's
// lastRenderedPageBreak). Sections are read paragraph by paragraph. The
// package and the paragraph walk are shared with DOCX (office_package.hpp).
// Not imported: headers and footers (in styles.xml, as for DOCX), annotations,
// frames (text boxes, images), change-tracked deletions.
#include <pugixml.hpp>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "import/docx_styles.hpp"
#include "import/import.hpp"
#include "import/importers.hpp"
#include "import/office_package.hpp"
#include "import/xml_util.hpp"

namespace tactus::import::detail {

using document::BlockKind;
using document::emphasis_bold;
using document::emphasis_italic;
using document::emphasis_none;
using document::emphasis_underline;
namespace {

// ODF 1.3 part 3, 6.1.2: in text content every run of spaces, tabs and line
// ends is one space; real tabs, breaks and runs of spaces are elements.
std::string collapse_white_space(std::string_view s) {
    std::string out;
    bool space = false;
    for (const char c : s) {
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
            space = true;
            continue;
        }
        if (space) out += ' ';
        space = false;
        out += c;
    }
    if (space) out += ' ';
    return out;
}

struct OdtStyle {
    std::string parent;
    std::uint8_t emphasis = emphasis_none;  // set bits
    std::uint8_t cleared = emphasis_none;   // bits the style turns off
    bool break_before = false;
    bool break_after = false;
    bool quote = false;  // "Quotations" (by name or display name)
};

// Paragraph and text styles by name (automatic styles in content.xml, common
// ones in styles.xml); a style inherits what its parent sets.
class OdtStyles {
public:
    void read(const pugi::xml_node& styles_parent) {
        for (const auto& s : styles_parent.children()) {
            if (local_name(s) != "style") continue;
            OdtStyle style;
            style.parent = std::string(attribute(s, "parent-style-name"));
            const auto text = child(s, "text-properties");
            const auto weight = attribute(text, "font-weight");
            if (weight == "bold" || (!weight.empty() && weight[0] >= '6' && weight[0] <= '9' && weight.size() == 3))
                style.emphasis |= emphasis_bold;
            else if (!weight.empty())
                style.cleared |= emphasis_bold;
            const auto italic = attribute(text, "font-style");
            if (italic == "italic" || italic == "oblique") style.emphasis |= emphasis_italic;
            else if (italic == "normal") style.cleared |= emphasis_italic;
            const auto underline = attribute(text, "text-underline-style");
            if (!underline.empty() && underline != "none") style.emphasis |= emphasis_underline;
            else if (underline == "none") style.cleared |= emphasis_underline;
            const auto para = child(s, "paragraph-properties");
            style.break_before = attribute(para, "break-before") == "page";
            style.break_after = attribute(para, "break-after") == "page";
            style.quote = is_quote_style_name(attribute(s, "name")) || is_quote_style_name(attribute(s, "display-name"));
            styles_[std::string(attribute(s, "name"))] = std::move(style);
        }
    }

    [[nodiscard]] std::uint8_t emphasis(std::string_view name) const {
        std::uint8_t e = emphasis_none;
        // Parent first, then each child's own settings override.
        std::vector<const OdtStyle*> chain;
        for (auto s = find(name); s && chain.size() < 16; s = find(s->parent)) chain.push_back(s);
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            e = static_cast<std::uint8_t>(e & ~(*it)->cleared);
            e |= (*it)->emphasis;
        }
        return e;
    }
    [[nodiscard]] bool break_before(std::string_view name) const {
        const auto* s = find(name);
        return s && s->break_before;
    }
    // A paragraph style that is, or is based on, a quotation style.
    [[nodiscard]] bool quote(std::string_view name) const {
        int depth = 0;
        for (auto s = find(name); s && depth < 16; s = find(s->parent), ++depth)
            if (s->quote) return true;
        return false;
    }
    [[nodiscard]] bool break_after(std::string_view name) const {
        const auto* s = find(name);
        return s && s->break_after;
    }

private:
    [[nodiscard]] const OdtStyle* find(std::string_view name) const {
        if (name.empty()) return nullptr;
        const auto it = styles_.find(std::string(name));
        return it == styles_.end() ? nullptr : &it->second;
    }
    std::map<std::string, OdtStyle> styles_;
};

// Which list levels are numbered, per list style (text:list-style).
class OdtListStyles {
public:
    void read(const pugi::xml_node& styles_parent) {
        for (const auto& s : styles_parent.children()) {
            if (local_name(s) != "list-style") continue;
            auto& levels = lists_[std::string(attribute(s, "name"))];
            for (const auto& l : s.children()) {
                const auto name = local_name(l);
                const auto level = std::atoi(std::string(attribute(l, "level")).c_str());
                if (level < 1 || level > 10) continue;
                if (name == "list-level-style-number")
                    levels[level] = {std::string(attribute(l, "num-prefix")), std::string(attribute(l, "num-suffix")), false};
                else if (name == "list-level-style-bullet")
                    levels[level] = {{}, {}, true};
            }
        }
    }
    // The label of item `number` at this level: prefix, number and suffix
    // ("3."), the UEB bullet sign "•" for a bullet level (whatever glyph the
    // style draws), or nothing for a level the style leaves unnumbered.
    [[nodiscard]] std::string label(std::string_view style, int level, int number) const {
        const auto it = lists_.find(std::string(style));
        if (it == lists_.end()) return {};
        const auto l = it->second.find(level);
        if (l == it->second.end()) return {};
        if (l->second.bullet) return "\u2022";
        return l->second.prefix + std::to_string(number) + l->second.suffix;
    }

private:
    struct Level {
        std::string prefix, suffix;
        bool bullet = false;
    };
    std::map<std::string, std::map<int, Level>> lists_;
};

class OdtReader {
public:
    OdtReader(const OdtStyles& styles, const OdtListStyles& lists) : styles_(styles), lists_(lists) {}

    void container(const pugi::xml_node& node) {
        for (const auto& c : node.children()) {
            if (out_.full()) return;
            if (c.type() != pugi::node_element) continue;
            const auto name = local_name(c);
            if (name == "p" || name == "h")
                paragraph(c, name == "h", 0, {});
            else if (name == "list")
                list(c, 1, std::string(attribute(c, "style-name")));
            else if (name == "table")
                table(c);
            else if (name == "section" || name == "index-body")
                container(c);
        }
    }

    Result<document::Document> finish() { return out_.finish(); }

private:
    // Rows in <table:table-header-rows> are header rows; covered cells (the
    // places a spanned cell covers) hold nothing of their own.
    void table(const pugi::xml_node& t) {
        out_.begin_table();
        rows(t, false);
        out_.end_table();
    }

    void rows(const pugi::xml_node& node, bool header) {
        for (const auto& r : node.children()) {
            const auto name = local_name(r);
            if (name == "table-header-rows")
                rows(r, true);
            else if (name == "table-rows" || name == "table-row-group")
                rows(r, header);
            else if (name == "table-row") {
                out_.begin_row(header);
                for (const auto& cell : r.children()) {
                    // A cell merged across columns has table:number-columns-spanned;
                    // the columns it (or a cell merged down from the row above)
                    // covers are <table:covered-table-cell>s, which hold no cell
                    // of their own: the next cell keeps its column.
                    const auto kind = local_name(cell);
                    if (kind == "covered-table-cell") {
                        out_.skip_columns(repeated(cell));
                        continue;
                    }
                    if (kind != "table-cell") continue;
                    // table:number-columns-repeated: the same cell in as many
                    // columns (LibreOffice writes a run of empty cells so).
                    for (int n = repeated(cell); n > 0; --n) {
                        out_.begin_cell(whole_number(attribute(cell, "number-columns-spanned"), 1));
                        container(cell);
                        out_.end_cell();
                    }
                }
            }
        }
    }

    // How many columns a cell stands for (table:number-columns-repeated), at
    // most as many as a table may have.
    static int repeated(const pugi::xml_node& cell) {
        return std::clamp(whole_number(attribute(cell, "number-columns-repeated"), 1), 1, 1024);
    }

    void list(const pugi::xml_node& l, int level, std::string style) {
        if (const auto own = attribute(l, "style-name"); !own.empty()) style = own;
        int number = 0;
        if (const auto start = attribute(l, "start-value"); !start.empty()) number = std::atoi(std::string(start).c_str()) - 1;
        for (const auto& item : l.children()) {
            const auto name = local_name(item);
            if (name != "list-item" && name != "list-header") continue;
            ++number;
            bool first = true;
            for (const auto& c : item.children()) {
                if (out_.full()) return;
                const auto cname = local_name(c);
                if (cname == "list") {
                    list(c, level + 1, style);
                } else if (cname == "p" || cname == "h") {
                    const bool labelled = first && name == "list-item";
                    paragraph(c, cname == "h", level, labelled ? lists_.label(style, level, number) : std::string{});
                    first = false;
                }
            }
        }
    }

    void paragraph(const pugi::xml_node& p, bool heading, int list_level, std::string label) {
        const auto style = attribute(p, "style-name");
        if (styles_.break_before(style)) out_.page_break();
        int level = 0;
        if (heading) {
            level = std::atoi(std::string(attribute(p, "outline-level")).c_str());
            level = std::clamp(level == 0 ? 1 : level, 1, 6);
        }
        const bool quote = !heading && list_level == 0 && styles_.quote(style);
        const auto kind = heading ? BlockKind::heading
                          : list_level ? BlockKind::list_item
                          : quote      ? BlockKind::quote
                                       : BlockKind::paragraph;
        out_.begin_paragraph(kind, heading ? level : list_level ? list_level : quote ? 1 : 0, std::move(label));
        // Only text (span) styles are emphasis: a paragraph style's bold is the
        // paragraph's typeface (a heading, a quote), as for DOCX.
        inline_content(p, emphasis_none);
        out_.end_paragraph();
        if (styles_.break_after(style)) out_.page_break();
    }

    void inline_content(const pugi::xml_node& node, std::uint8_t emphasis) {
        for (const auto& c : node.children()) {
            if (c.type() == pugi::node_pcdata) {
                out_.text(collapse_white_space(c.value()), emphasis);
                continue;
            }
            if (c.type() != pugi::node_element) continue;
            const auto name = local_name(c);
            if (name == "span") {
                const auto own = styles_.emphasis(attribute(c, "style-name"));
                inline_content(c, static_cast<std::uint8_t>(emphasis | own));
            } else if (name == "s") {
                const auto n = attribute(c, "c");
                const int count = n.empty() ? 1 : std::clamp(std::atoi(std::string(n).c_str()), 1, 1000);
                out_.text(std::string(static_cast<std::size_t>(count), ' '), emphasis);
            } else if (name == "tab") {
                out_.text("\t", emphasis);
            } else if (name == "line-break") {
                out_.text("\n", emphasis);
            } else if (name == "note") {
                note(c);
            } else if (name == "annotation" || name == "frame" || name == "tracked-changes" ||
                       name == "soft-page-break" || name == "bookmark" || name == "bookmark-start" ||
                       name == "bookmark-end" || name == "reference-mark") {
                continue;
            } else {
                inline_content(c, emphasis);  // text:a (links), fields, ruby, meta
            }
        }
    }

    // <text:note>: the citation is print's mark (ours is numbered by OfficeText);
    // the body's paragraphs are the note's text.
    void note(const pugi::xml_node& n) {
        out_.begin_note();
        for (const auto& p : child(n, "note-body").children()) {
            const auto name = local_name(p);
            if (name == "p" || name == "h") {
                out_.begin_paragraph(BlockKind::paragraph, 0, {});
                inline_content(p, emphasis_none);
                out_.end_paragraph();
            }
        }
        out_.end_note();
    }

    const OdtStyles& styles_;
    const OdtListStyles& lists_;
    OfficeText out_;
};

}  // namespace

Result<document::Document> import_odt(std::string_view bytes) {
    auto package = XmlPackage::open(bytes, "an OpenDocument text");
    if (!package) return std::unexpected(package.error());
    if (package->contains("mimetype")) {
        auto type = package->read("mimetype", 256);
        if (type && *type != "application/vnd.oasis.opendocument.text")
            return fail("not an OpenDocument text but " + *type + " (only text documents are read)", "mimetype");
    }
    XmlPart styles_xml, content_xml;
    if (auto ok = package->load("styles.xml", styles_xml, false); !ok) return std::unexpected(ok.error());
    if (auto ok = package->load("content.xml", content_xml, true); !ok) return std::unexpected(ok.error());

    OdtStyles styles;
    OdtListStyles lists;
    for (const auto* part : {&styles_xml, &content_xml}) {
        const auto top = part->root();
        for (const char* name : {"styles", "automatic-styles"}) {
            styles.read(child(top, name));
            lists.read(child(top, name));
        }
    }
    const auto top = content_xml.root();
    const auto text = child(child(top, "body"), "text");
    if (local_name(top) != "document-content" || !text)
        return fail("not an OpenDocument text: no <office:body>/<office:text>", "content.xml");
    OdtReader reader(styles, lists);
    reader.container(text);
    return reader.finish();
}

}  // namespace tactus::import::detail
