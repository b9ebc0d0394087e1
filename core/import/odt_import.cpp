// SPDX-License-Identifier: GPL-3.0-or-later
// ODT (OpenDocument text, ISO/IEC 26300: content.xml in a ZIP package): the
// paragraphs of <office:text>, headings from <text:h text:outline-level>, list
// items from <text:list> (numbered levels get their label as text, bullets are
// dropped, as for DOCX), bold/italic/underline from the automatic and common
// text styles, and page breaks from paragraph styles with fo:break-before or
// fo:break-after="page". <text:soft-page-break/> only records where the last
// layout happened to break, so it is not a break (like DOCX's
// lastRenderedPageBreak). Tables and sections are read cell by cell.
// Not imported: notes, annotations, frames (text boxes, images), change-tracked
// deletions.
#include <pugixml.hpp>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "import/document_builder.hpp"
#include "import/import.hpp"
#include "import/importers.hpp"
#include "import/xml_util.hpp"
#include "import/zip_archive.hpp"

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
                if (local_name(l) != "list-level-style-number") continue;
                const auto level = std::atoi(std::string(attribute(l, "level")).c_str());
                if (level >= 1 && level <= 10)
                    levels[level] = {std::string(attribute(l, "num-prefix")), std::string(attribute(l, "num-suffix"))};
            }
        }
    }
    // Prefix and suffix around the number, or nullptr for a bullet level.
    [[nodiscard]] const std::pair<std::string, std::string>* numbered(std::string_view style, int level) const {
        const auto it = lists_.find(std::string(style));
        if (it == lists_.end()) return nullptr;
        const auto l = it->second.find(level);
        return l == it->second.end() ? nullptr : &l->second;
    }

private:
    std::map<std::string, std::map<int, std::pair<std::string, std::string>>> lists_;
};

class OdtReader {
public:
    OdtReader(const OdtStyles& styles, const OdtListStyles& lists) : styles_(styles), lists_(lists) {}

    void container(const pugi::xml_node& node) {
        for (const auto& c : node.children()) {
            if (builder_.full()) return;
            if (c.type() != pugi::node_element) continue;
            const auto name = local_name(c);
            if (name == "p" || name == "h")
                paragraph(c, name == "h");
            else if (name == "list")
                list(c, 1, std::string(attribute(c, "style-name")));
            else if (name == "table" || name == "table-row" || name == "table-cell" || name == "table-header-rows" ||
                     name == "table-rows" || name == "section" || name == "index-body")
                container(c);
        }
    }

    Result<document::Document> finish() { return builder_.finish(); }

private:
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
                if (builder_.full()) return;
                const auto cname = local_name(c);
                if (cname == "list") {
                    list(c, level + 1, style);
                } else if (cname == "p" || cname == "h") {
                    label_.clear();
                    if (first && name == "list-item")
                        if (const auto* fix = lists_.numbered(style, level))
                            label_ = fix->first + std::to_string(number) + fix->second + " ";
                    list_level_ = level;
                    paragraph(c, cname == "h");
                    list_level_ = 0;
                    first = false;
                }
            }
        }
    }

    void paragraph(const pugi::xml_node& p, bool heading) {
        const auto style = attribute(p, "style-name");
        if (styles_.break_before(style)) builder_.print_page_break(0);
        int level = 0;
        if (heading) {
            level = std::atoi(std::string(attribute(p, "outline-level")).c_str());
            level = std::clamp(level == 0 ? 1 : level, 1, 6);
        }
        kind_ = heading ? BlockKind::heading : list_level_ ? BlockKind::list_item : BlockKind::paragraph;
        level_ = heading ? level : list_level_;
        builder_.begin(kind_, level_, 0);
        // Only text (span) styles are emphasis: a paragraph style's bold is the
        // paragraph's typeface (a heading, a quote), as for DOCX.
        inline_content(p, emphasis_none);
        builder_.end();
        label_.clear();
        if (styles_.break_after(style)) builder_.print_page_break(0);
    }

    void inline_content(const pugi::xml_node& node, std::uint8_t emphasis) {
        for (const auto& c : node.children()) {
            if (c.type() == pugi::node_pcdata) {
                text(collapse_white_space(c.value()), emphasis);
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
                text(std::string(static_cast<std::size_t>(count), ' '), emphasis);
            } else if (name == "tab") {
                text("\t", emphasis);
            } else if (name == "line-break") {
                text("\n", emphasis);
            } else if (name == "note" || name == "annotation" || name == "frame" || name == "tracked-changes" ||
                       name == "soft-page-break" || name == "bookmark" || name == "bookmark-start" ||
                       name == "bookmark-end" || name == "reference-mark") {
                continue;
            } else {
                inline_content(c, emphasis);  // text:a (links), fields, ruby, meta
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

    const OdtStyles& styles_;
    const OdtListStyles& lists_;
    DocumentBuilder builder_;
    BlockKind kind_ = BlockKind::paragraph;
    int level_ = 0;
    int list_level_ = 0;
    std::string label_;
};

Result<bool> load(ZipArchive& zip, const std::string& part, pugi::xml_document& doc, std::string& storage,
                  bool required) {
    if (!zip.contains(part)) {
        if (required) return fail("not an OpenDocument text: missing part " + part, part);
        return false;
    }
    auto bytes = zip.read(part, max_import_bytes);
    if (!bytes) return std::unexpected(bytes.error());
    storage = std::move(*bytes);
    if (auto ok = parse_xml(doc, storage, part); !ok) return std::unexpected(ok.error());
    return true;
}

}  // namespace

Result<document::Document> import_odt(std::string_view bytes) {
    auto zip = ZipArchive::open(bytes);
    if (!zip) return std::unexpected(zip.error());
    if (zip->contains("mimetype")) {
        auto type = zip->read("mimetype", 256);
        if (type && *type != "application/vnd.oasis.opendocument.text")
            return fail("not an OpenDocument text but " + *type + " (only text documents are read)", "mimetype");
    }
    pugi::xml_document styles_xml, content_xml;
    std::string styles_bytes, content_bytes;
    if (auto ok = load(*zip, "styles.xml", styles_xml, styles_bytes, false); !ok) return std::unexpected(ok.error());
    if (auto ok = load(*zip, "content.xml", content_xml, content_bytes, true); !ok) return std::unexpected(ok.error());

    OdtStyles styles;
    OdtListStyles lists;
    for (const auto* root : {&styles_xml, &content_xml}) {
        const auto top = root->document_element();
        for (const char* part : {"styles", "automatic-styles"}) {
            styles.read(child(top, part));
            lists.read(child(top, part));
        }
    }
    const auto top = content_xml.document_element();
    const auto text = child(child(top, "body"), "text");
    if (local_name(top) != "document-content" || !text)
        return fail("not an OpenDocument text: no <office:body>/<office:text>", "content.xml");
    OdtReader reader(styles, lists);
    reader.container(text);
    return reader.finish();
}

}  // namespace tactus::import::detail
