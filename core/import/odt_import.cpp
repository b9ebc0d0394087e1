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
// Frames (draw:frame) are read where they stand: a text box
// (draw:text-box) is boxed material after its paragraph, an image's title
// or description (svg:title, svg:desc) a transcriber's note (an image
// without either is named in a warning), a formula object (draw:object) its
// StarMath annotation, else its MathML as linear text (office_math.hpp).
// Raised and lowered text from style:text-position; ruby (text:ruby) as for
// DOCX. A passage's language is the one its text, paragraph and default
// styles give each character's script (fo:language, style:language-asian,
// style:language-complex; office_language.hpp), kept only where it is not
// the document's own. List labels follow the list style's number format (1, i, I, a, A),
// start values (the level's text:start-value, an item's text:start-value)
// and continued numbering (text:continue-numbering, text:continue-list).
// Not imported: headers and footers (in styles.xml, as for DOCX), annotations,
// change-tracked deletions.
#include <pugixml.hpp>

#include <algorithm>
#include <array>
#include <memory>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <vector>

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
#include "import/trim.hpp"
#include "import/xml_util.hpp"
#include "common/try.hpp"

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
    document::Align align = document::Align::none;  // fo:text-align; start/left is the default
    document::Position position = document::Position::baseline;
    OfficeLanguages languages;
};

// fo:language and fo:country (Latin), style:language-asian and
// style:country-asian, style:language-complex and style:country-complex; a
// style:rfc-language-tag(-asian, -complex) names what a language and country
// cannot ("zh-Hant-TW") and wins.
OfficeLanguages read_languages(const pugi::xml_node& text_properties) {
    OfficeLanguages out;
    for (const auto& [suffix, tag] : {std::pair<std::string_view, std::optional<std::string>*>{"", &out.latin},
                                      {"-asian", &out.east_asian},
                                      {"-complex", &out.complex}}) {
        std::optional<std::string_view> language, country, rfc;
        for (const auto& a : text_properties.attributes()) {
            std::string_view name = a.name();
            if (const auto colon = name.find(':'); colon != std::string_view::npos) name.remove_prefix(colon + 1);
            if (!name.ends_with(suffix)) continue;
            name.remove_suffix(suffix.size());
            if (name == "language") language = a.value();
            if (name == "country") country = a.value();
            if (name == "rfc-language-tag") rfc = a.value();
        }
        if (rfc)
            *tag = language_tag(*rfc);
        else if (language)
            *tag = language_tag(*language, country.value_or(std::string_view{}));
    }
    return out;
}

// Paragraph and text styles by name (automatic styles in content.xml, common
// ones in styles.xml); a style inherits what its parent sets.
class OdtStyles {
public:
    void read(const pugi::xml_node& styles_parent) {
        for (const auto& s : styles_parent.children()) {
            // The paragraph family's default style: what every paragraph
            // style starts from (LibreOffice keeps the document's languages there).
            if (local_name(s) == "default-style" && attribute(s, "family") == "paragraph")
                default_languages_.apply(read_languages(child(s, "text-properties")));
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
            // style:text-position: "super", "sub", or a percentage raised
            // (positive) or lowered (negative), then the font size.
            if (const auto pos = attribute(text, "text-position"); !pos.empty()) {
                if (pos.starts_with("super") || (pos[0] >= '1' && pos[0] <= '9'))
                    style.position = document::Position::superscript;
                else if (pos.starts_with("sub") || pos.starts_with("-"))
                    style.position = document::Position::subscript;
            }
            style.languages = read_languages(text);
            const auto underline = attribute(text, "text-underline-style");
            if (!underline.empty() && underline != "none") style.emphasis |= emphasis_underline;
            else if (underline == "none") style.cleared |= emphasis_underline;
            const auto para = child(s, "paragraph-properties");
            style.break_before = attribute(para, "break-before") == "page";
            style.break_after = attribute(para, "break-after") == "page";
            if (const auto a = attribute(para, "text-align"); a == "center")
                style.align = document::Align::centre;
            else if (a == "end" || a == "right")
                style.align = document::Align::right;
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
    // The nearest position a style or its parents set; baseline when none.
    [[nodiscard]] document::Position position(std::string_view name) const {
        int depth = 0;
        for (auto s = find(name); s && depth < 16; s = find(s->parent), ++depth)
            if (s->position != document::Position::baseline) return s->position;
        return document::Position::baseline;
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
    // The nearest alignment a paragraph style or its parents set.
    [[nodiscard]] document::Align align(std::string_view name) const {
        int depth = 0;
        for (auto s = find(name); s && depth < 16; s = find(s->parent), ++depth)
            if (s->align != document::Align::none) return s->align;
        return document::Align::none;
    }
    [[nodiscard]] bool break_after(std::string_view name) const {
        const auto* s = find(name);
        return s && s->break_after;
    }
    // A text style's languages (with its parents') over `languages`.
    void apply_languages(std::string_view name, OfficeLanguages& languages) const {
        std::vector<const OdtStyle*> chain;
        for (auto s = find(name); s && chain.size() < 16; s = find(s->parent)) chain.push_back(s);
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) languages.apply((*it)->languages);
    }
    // The languages of a paragraph's text before its spans': the default
    // style's, then the paragraph style's chain.
    [[nodiscard]] OfficeLanguages paragraph_languages(std::string_view name) const {
        auto out = default_languages_;
        apply_languages(name, out);
        return out;
    }
    // The document's own: those of LibreOffice's default paragraph style,
    // "Standard", which the other paragraph styles are based on.
    [[nodiscard]] OfficeLanguages document_languages() const { return paragraph_languages("Standard"); }

private:
    [[nodiscard]] const OdtStyle* find(std::string_view name) const {
        if (name.empty()) return nullptr;
        const auto it = styles_.find(std::string(name));
        return it == styles_.end() ? nullptr : &it->second;
    }
    std::map<std::string, OdtStyle> styles_;
    OfficeLanguages default_languages_;
};

// A number in a list style's format (style:num-format): "1" decimal, "i"/"I"
// roman, "a"/"A" letters (a..z, aa..zz, as word processors count on).
std::string format_number(std::string_view format, int n) {
    if (n < 1 || format.empty() || format == "1") return std::to_string(n);
    if (format == "i" || format == "I") {
        if (n >= 4000) return std::to_string(n);
        static constexpr std::pair<int, const char*> numerals[] = {{1000, "m"}, {900, "cm"}, {500, "d"}, {400, "cd"},
                                                                   {100, "c"},  {90, "xc"},  {50, "l"},  {40, "xl"},
                                                                   {10, "x"},   {9, "ix"},   {5, "v"},   {4, "iv"},
                                                                   {1, "i"}};
        std::string out;
        for (const auto& [value, text] : numerals)
            for (; n >= value; n -= value) out += text;
        if (format == "I")
            for (auto& c : out) c = static_cast<char>(c - 'a' + 'A');
        return out;
    }
    if (format == "a" || format == "A") {
        const char base = format == "A" ? 'A' : 'a';
        return std::string(static_cast<std::size_t>((n - 1) / 26 + 1), static_cast<char>(base + (n - 1) % 26));
    }
    return std::to_string(n);
}

// List styles (text:list-style): per level, numbered (format, prefix,
// suffix, start value) or a bullet.
class OdtListStyles {
public:
    void read(const pugi::xml_node& styles_parent) {
        for (const auto& s : styles_parent.children()) {
            if (local_name(s) != "list-style") continue;
            auto& levels = lists_[std::string(attribute(s, "name"))];
            for (const auto& l : s.children()) {
                const auto name = local_name(l);
                const auto level = whole_number(attribute(l, "level"), 0);
                if (level < 1 || level > 10) continue;
                if (name == "list-level-style-number")
                    levels[level] = {std::string(attribute(l, "num-prefix")), std::string(attribute(l, "num-suffix")),
                                     l.attribute("style:num-format") ? std::string(attribute(l, "num-format")) : "1",
                                     whole_number(attribute(l, "start-value"), 1), false};
                else if (name == "list-level-style-bullet")
                    levels[level] = {{}, {}, {}, 1, true};
            }
        }
    }
    // The label of item `number` at this level: prefix, number in the
    // level's format and suffix ("iii)"), the UEB bullet sign "•" for a
    // bullet level (whatever glyph the style draws), or nothing for a level
    // the style leaves unnumbered (num-format empty) or does not define.
    [[nodiscard]] std::string label(std::string_view style, int level, int number) const {
        const auto* l = find(style, level);
        if (!l) return {};
        if (l->bullet) return "\u2022";
        if (l->format.empty()) return l->prefix + l->suffix;  // num-format="": no number
        return l->prefix + format_number(l->format, number) + l->suffix;
    }
    // The number a level starts at (text:start-value, 1 by default).
    [[nodiscard]] int start(std::string_view style, int level) const {
        const auto* l = find(style, level);
        return l ? l->start : 1;
    }

private:
    struct Level {
        std::string prefix, suffix, format;
        int start = 1;
        bool bullet = false;
    };
    [[nodiscard]] const Level* find(std::string_view style, int level) const {
        const auto it = lists_.find(std::string(style));
        if (it == lists_.end()) return nullptr;
        const auto l = it->second.find(level);
        return l == it->second.end() ? nullptr : &l->second;
    }
    std::map<std::string, std::map<int, Level>> lists_;
};

class OdtReader {
public:
    OdtReader(const OdtStyles& styles, const OdtListStyles& lists, const XmlPackage& package, RubyGuide ruby,
              std::string_view content)
        : styles_(styles), lists_(lists), package_(package), ruby_(ruby), content_(content),
          document_languages_(styles.document_languages()) {}

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
            else if (name == "frame") {  // anchored to the page
                frame(c);
                text_boxes();
            }
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
                int spanned = 0;  // covered cells that belong to the last cell's span
                for (const auto& cell : r.children()) {
                    // A cell merged across columns has table:number-columns-spanned;
                    // the columns it (or a cell merged down from the row above)
                    // covers are <table:covered-table-cell>s, which hold no cell
                    // of their own: the next cell keeps its column.
                    const auto kind = local_name(cell);
                    // The covered cells right after a spanned cell are its
                    // own columns, which begin_cell has counted already.
                    if (kind == "covered-table-cell") {
                        const int n = repeated(cell);
                        const int own = std::min(n, spanned);
                        spanned -= own;
                        if (n > own) out_.skip_columns(n - own);
                        continue;
                    }
                    if (kind != "table-cell") continue;
                    const int span = std::clamp(whole_number(attribute(cell, "number-columns-spanned"), 1), 1, 1024);
                    spanned = span - 1;
                    // The alignment of the cell's first paragraph, as for DOCX.
                    const auto align = styles_.align(attribute(child(cell, "p"), "style-name"));
                    // table:number-columns-repeated: the same cell in as many
                    // columns (LibreOffice writes a run of empty cells so).
                    for (int n = repeated(cell); n > 0; --n) {
                        out_.begin_cell(span, align);
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

    // A list's item numbers, per level; nested lists share their top
    // list's, and a list that continues another (text:continue-numbering,
    // text:continue-list) shares that one's.
    struct Counters {
        std::array<int, 12> at{};
    };

    // text:continue-numbering continues the last list of the same list
    // style (as LibreOffice reads it); text:continue-list the list with that
    // xml:id.
    std::shared_ptr<Counters> counters_for(const pugi::xml_node& l, const std::string& style) {
        std::shared_ptr<Counters> c;
        if (const auto id = attribute(l, "continue-list"); !id.empty()) {
            if (const auto it = lists_by_id_.find(std::string(id)); it != lists_by_id_.end()) c = it->second;
        } else if (attribute(l, "continue-numbering") == "true") {
            if (const auto it = last_of_style_.find(style); it != last_of_style_.end()) c = it->second;
        }
        if (!c) c = std::make_shared<Counters>();
        if (const auto id = l.attribute("xml:id"); id) lists_by_id_[id.value()] = c;
        last_of_style_[style] = c;
        return c;
    }

    void list(const pugi::xml_node& l, int level, std::string style, std::shared_ptr<Counters> counters = {}) {
        if (const auto own = attribute(l, "style-name"); !own.empty()) style = own;
        if (!counters) counters = counters_for(l, style);
        const auto at = static_cast<std::size_t>(std::clamp(level, 1, 11));
        for (const auto& item : l.children()) {
            const auto name = local_name(item);
            if (name != "list-item" && name != "list-header") continue;
            const bool has_text = child(item, "p") || child(item, "h");
            int& number = counters->at[at];
            if (name == "list-item" && has_text) {
                if (const auto start = whole_number(attribute(item, "start-value"), 0); start > 0)
                    number = start;
                else
                    number = number == 0 ? lists_.start(style, level) : number + 1;
                std::fill(counters->at.begin() + static_cast<std::ptrdiff_t>(at) + 1, counters->at.end(), 0);
            }
            bool first = true;
            for (const auto& c : item.children()) {
                if (out_.full()) return;
                const auto cname = local_name(c);
                if (cname == "list") {
                    list(c, level + 1, style, counters);
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
        std::vector<pugi::xml_node> boxes;
        std::swap(boxes, boxes_);
        inline_content(p, emphasis_none, styles_.paragraph_languages(style));
        out_.end_paragraph();
        std::swap(boxes, boxes_);
        text_boxes(std::move(boxes));
        if (styles_.break_after(style)) out_.page_break();
    }

    // The text boxes met in a paragraph, after it, each a box.
    void text_boxes(std::vector<pugi::xml_node> boxes = {}) {
        if (boxes.empty()) std::swap(boxes, boxes_);
        for (const auto& b : boxes) {
            if (out_.full()) return;
            out_.begin_box();
            if (++box_depth_ < 16) container(b);  // a box in a box in ... is read flat
            --box_depth_;
            out_.end_box();
        }
    }

    [[nodiscard]] std::string where(const pugi::xml_node& n) const {
        return "content.xml:" +
               position_at(content_, static_cast<std::size_t>(std::max<std::ptrdiff_t>(n.offset_debug(), 0))).to_string();
    }

    // draw:frame: a text box, a formula object or an image.
    void frame(const pugi::xml_node& f) {
        if (const auto box = child(f, "text-box")) {
            boxes_.push_back(box);
            return;
        }
        if (const auto object = child(f, "object"); object && formula(object)) return;
        if (!child(f, "image") && !child(f, "object") && !child(f, "object-ole")) return;
        std::string description = child(f, "desc").child_value();
        if (description.find_first_not_of(" \t\r\n") == std::string::npos) description = child(f, "title").child_value();
        const bool described = description.find_first_not_of(" \t\r\n") != std::string::npos;
        auto image = picture_bytes(child(f, "image"));
        if (described) out_.transcriber_note(collapse_white_space(description));
        if (image)
            out_.image(std::move(*image), described, where(f));
        else if (!described)
            out_.picture_without_description(where(f));
    }

    // A draw:image's picture (its xlink:href part of the package), when
    // pictures are kept and the graphic stage can read its type (else a
    // warning naming it). An image stored inline (office:binary-data) or
    // outside the package is left to its description.
    std::optional<document::Image> picture_bytes(const pugi::xml_node& image) {
        if (!images_ || !image) return std::nullopt;
        std::string href(attribute(image, "href"));
        if (href.starts_with("./")) href.erase(0, 2);
        if (href.empty() || !package_.contains(href)) {
            if (!href.empty()) out_.warn("picture " + href + ": not in the package; its description stays");
            return std::nullopt;
        }
        auto bytes = package_.read(href, max_import_bytes);
        if (!bytes) {
            out_.warn("picture " + href + ": " + bytes.error().message + "; its description stays");
            return std::nullopt;
        }
        // The writers' stand-in for a description with no picture: the
        // description is the picture (document/placeholder_picture.hpp).
        if (*bytes == document::placeholder_png()) return std::nullopt;
        auto type = picture_media_type(*bytes, href);
        if (type.empty()) {
            out_.warn(unsupported_picture_warning(href));
            return std::nullopt;
        }
        return document::Image{std::move(*bytes), std::move(type), href};
    }

public:
    void keep_images() { images_ = true; }

private:

    // A formula object (LibreOffice Math): its MathML as linear text, else
    // its StarMath annotation. The object is inline in a flat ODT, else its
    // own part ("./Object 1" -> "Object 1/content.xml"). False when it holds
    // no formula.
    bool formula(const pugi::xml_node& object) {
        XmlPart part;
        auto math = child(object, "math");
        if (!math) {
            std::string href(attribute(object, "href"));
            if (href.starts_with("./")) href.erase(0, 2);
            if (href.empty() || href.find("..") != std::string::npos) return false;
            auto loaded = package_.load(href + "/content.xml", part, false);
            if (!loaded || !*loaded) return false;
            math = part.root();
            if (local_name(math) != "math") return false;
        }
        std::vector<std::pair<std::string, document::Position>> pieces;
        mathml_linear(math, [&](std::string_view t, document::Position p) { pieces.emplace_back(std::string(t), p); });
        if (pieces.empty()) {
            const std::string annotation = math.select_node(".//*[local-name()='annotation']").node().child_value();
            if (annotation.find_first_not_of(" \t\r\n") == std::string::npos) return false;
            pieces.emplace_back(collapse_white_space(annotation), document::Position::baseline);
        }
        for (const auto& [t, p] : pieces) out_.text(t, emphasis_none, p);
        return true;
    }

    // Text in pieces of one language each (office_language.hpp): each
    // character in the language its script takes, marked only where that is
    // not the document's own. A span is cut where its script changes class,
    // as LibreOffice shows it: the Latin words of a span set in Chinese for
    // Asian text stay in the Latin language.
    void text(std::string_view t, std::uint8_t emphasis, document::Position position,
              const OfficeLanguages& languages) {
        for (const auto& piece : language_pieces(t, languages, document_languages_))
            out_.text(piece.text, emphasis, position, piece.language);
    }

    void inline_content(const pugi::xml_node& node, std::uint8_t emphasis, const OfficeLanguages& languages,
                        document::Position position = document::Position::baseline, int depth = 0) {
        for (const auto& c : node.children()) {
            if (c.type() == pugi::node_pcdata) {
                text(collapse_white_space(c.value()), emphasis, position, languages);
                continue;
            }
            if (c.type() != pugi::node_element) continue;
            const auto name = local_name(c);
            if (depth > 64) continue;  // a hostile nesting of spans
            if (name == "span") {
                const auto own = styles_.emphasis(attribute(c, "style-name"));
                const auto raised = styles_.position(attribute(c, "style-name"));
                auto inner = languages;
                styles_.apply_languages(attribute(c, "style-name"), inner);
                inline_content(c, static_cast<std::uint8_t>(emphasis | own), inner,
                               raised == document::Position::baseline ? position : raised, depth + 1);
            } else if (name == "frame") {
                frame(c);
            } else if (name == "ruby") {
                inline_content(child(c, "ruby-base"), emphasis, languages, position, depth + 1);
                if (ruby_ == RubyGuide::after) out_.transcriber_note(collapse_white_space(child(c, "ruby-text").child_value()));
            } else if (name == "s") {
                const auto n = attribute(c, "c");
                const int count = n.empty() ? 1 : std::clamp(std::atoi(std::string(n).c_str()), 1, 1000);
                text(std::string(static_cast<std::size_t>(count), ' '), emphasis, document::Position::baseline, languages);
            } else if (name == "tab") {
                text("\t", emphasis, document::Position::baseline, languages);
            } else if (name == "line-break") {
                text("\n", emphasis, document::Position::baseline, languages);
            } else if (name == "note") {
                note(c);
            } else if (name == "annotation" || name == "tracked-changes" ||
                       name == "soft-page-break" || name == "bookmark" || name == "bookmark-start" ||
                       name == "bookmark-end" || name == "reference-mark") {
                continue;
            } else {
                inline_content(c, emphasis, languages, position, depth + 1);  // text:a, draw:a (links), fields, meta
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
                inline_content(p, emphasis_none, styles_.paragraph_languages(attribute(p, "style-name")));
                out_.end_paragraph();
            }
        }
        out_.end_note();
    }

    const OdtStyles& styles_;
    const OdtListStyles& lists_;
    const XmlPackage& package_;
    RubyGuide ruby_;
    bool images_ = false;
    std::string_view content_;  // content.xml, for the places warnings name
    std::vector<pugi::xml_node> boxes_;  // text boxes met in the paragraph being read
    int box_depth_ = 0;
    std::map<std::string, std::shared_ptr<Counters>> lists_by_id_;
    std::map<std::string, std::shared_ptr<Counters>> last_of_style_;
    OfficeText out_;
    const OfficeLanguages document_languages_;  // the default style's and "Standard"'s
};

}  // namespace

Result<document::Document> import_odt(std::string_view bytes, RubyGuide ruby, bool images) {
    TACTUS_TRY(package, XmlPackage::open(bytes, "an OpenDocument text"));
    if (package.contains("mimetype")) {
        auto type = package.read("mimetype", 256);
        if (type && *type != "application/vnd.oasis.opendocument.text")
            return fail(ErrorKind::input, "not an OpenDocument text but " + *type + " (only text documents are read)", "mimetype");
    }
    XmlPart styles_xml, content_xml;
    TACTUS_TRY_VOID(package.load("styles.xml", styles_xml, false));
    TACTUS_TRY_VOID(package.load("content.xml", content_xml, true));

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
        return fail(ErrorKind::input, "not an OpenDocument text: no <office:body>/<office:text>", "content.xml");
    OdtReader reader(styles, lists, package, ruby, content_xml.bytes);
    if (images) reader.keep_images();
    reader.container(text);
    auto doc = reader.finish();
    if (!doc) return doc;
    // The main language is the default style's (what LibreOffice edits as
    // the document's languages); meta.xml's dc:language names it for a
    // document whose styles do not.
    auto language = main_language(styles.document_languages(), *doc);
    if (language.empty()) {
        XmlPart meta_xml;
        TACTUS_TRY(found, package.load("meta.xml", meta_xml, false));
        if (found) language = language_tag(trim(child(child(meta_xml.root(), "meta"), "language").child_value()));
    }
    document::set_main_language(*doc, language);
    return doc;
}

}  // namespace tactus::import::detail
