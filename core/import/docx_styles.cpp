// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/docx_styles.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "import/xml_util.hpp"

namespace tactus::import::detail {
namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::optional<int> to_int(std::string_view s) {
    int v = 0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc{} || p != s.data() + s.size()) return std::nullopt;
    return v;
}

// "heading 3" (the built-in name, any case) or "Title".
int heading_from_name(std::string_view name) {
    const auto n = lower(name);
    if (n == "title") return 1;
    if (n.size() == 9 && n.starts_with("heading ") && n[8] >= '1' && n[8] <= '9')
        return std::min(6, n[8] - '0');
    return 0;
}

}  // namespace

bool is_quote_style_name(std::string_view name) {
    const auto n = lower(name);
    return n == "quote" || n == "intense quote" || n == "quotations" || n == "block text";
}

namespace {

std::string roman(int n, bool upper) {
    static constexpr std::pair<int, std::string_view> table[] = {
        {1000, "m"}, {900, "cm"}, {500, "d"}, {400, "cd"}, {100, "c"}, {90, "xc"}, {50, "l"},
        {40, "xl"},  {10, "x"},   {9, "ix"},  {5, "v"},    {4, "iv"},  {1, "i"}};
    if (n <= 0 || n >= 4000) return std::to_string(n);
    std::string out;
    for (const auto& [value, digits] : table)
        for (; n >= value; n -= value) out += digits;
    if (upper)
        for (auto& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

// a..z, aa..zz, aaa.. as word processors count.
std::string letters(int n, bool upper) {
    if (n <= 0) return std::to_string(n);
    const char base = upper ? 'A' : 'a';
    const auto letter = static_cast<char>(base + (n - 1) % 26);
    return std::string(static_cast<std::size_t>((n - 1) / 26 + 1), letter);
}

std::string format_number(int n, const std::string& format) {
    if (format == "lowerLetter") return letters(n, false);
    if (format == "upperLetter") return letters(n, true);
    if (format == "lowerRoman") return roman(n, false);
    if (format == "upperRoman") return roman(n, true);
    if (format == "decimalZero" && n < 10) return "0" + std::to_string(n);
    return std::to_string(n);  // decimal and formats we do not render specially
}

}  // namespace

void RunFormat::apply(const RunFormat& over) {
    if (over.bold) bold = over.bold;
    if (over.italic) italic = over.italic;
    if (over.underline) underline = over.underline;
    languages.apply(over.languages);
}

std::uint8_t RunFormat::emphasis() const {
    return static_cast<std::uint8_t>((bold.value_or(false) ? document::emphasis_bold : 0) |
                                     (italic.value_or(false) ? document::emphasis_italic : 0) |
                                     (underline.value_or(false) ? document::emphasis_underline : 0));
}

std::optional<bool> read_toggle(const pugi::xml_node& element) {
    if (!element) return std::nullopt;
    const auto v = attribute(element, "val");
    return !(v == "0" || v == "false" || v == "off" || v == "none");
}

RunFormat read_run_format(const pugi::xml_node& rPr) {
    RunFormat f;
    if (!rPr) return f;
    f.bold = read_toggle(child(rPr, "b"));
    f.italic = read_toggle(child(rPr, "i"));
    f.underline = read_toggle(child(rPr, "u"));  // w:val="none" switches it off
    // <w:lang w:val="en-US" w:eastAsia="zh-TW" w:bidi="ar-SA"/>: an absent
    // attribute inherits, a present one sets its class's language.
    for (const auto& a : child(rPr, "lang").attributes()) {
        std::string_view name = a.name();
        name = name.substr(name.find(':') == std::string_view::npos ? 0 : name.find(':') + 1);
        if (name == "val") f.languages.latin = language_tag(a.value());
        if (name == "eastAsia") f.languages.east_asian = language_tag(a.value());
        if (name == "bidi") f.languages.complex = language_tag(a.value());
    }
    // Right-to-left or complex-script formatting: the run is complex script.
    const auto rtl = read_toggle(child(rPr, "rtl"));
    const auto cs = read_toggle(child(rPr, "cs"));
    if (rtl || cs) f.languages.complex_run = rtl.value_or(false) || cs.value_or(false);
    return f;
}

std::optional<NumberingRef> read_numbering_ref(const pugi::xml_node& pPr) {
    const auto numPr = child(pPr, "numPr");
    if (!numPr) return std::nullopt;
    NumberingRef ref;
    ref.num_id = std::string(attribute(child(numPr, "numId"), "val"));
    ref.ilvl = std::clamp(to_int(attribute(child(numPr, "ilvl"), "val")).value_or(0), 0, 8);
    if (ref.num_id.empty()) return std::nullopt;  // ilvl alone: level of a style's list
    return ref;
}

DocxStyles::DocxStyles(const pugi::xml_node& root) {
    defaults_ = read_run_format(child(child(child(root, "docDefaults"), "rPrDefault"), "rPr")).languages;
    for (const auto& s : root.children()) {
        if (local_name(s) != "style") continue;
        const std::string id(attribute(s, "styleId"));
        if (id.empty()) continue;
        Style style;
        style.name = attribute(child(s, "name"), "val");
        style.based_on = attribute(child(s, "basedOn"), "val");
        const auto pPr = child(s, "pPr");
        if (const auto lvl = to_int(attribute(child(pPr, "outlineLvl"), "val")))
            style.outline_level = *lvl;
        style.numbering = read_numbering_ref(pPr);
        style.page_break_before = read_toggle(child(pPr, "pageBreakBefore"));
        style.run = read_run_format(child(s, "rPr"));
        const auto is_default = attribute(s, "default");
        if (attribute(s, "type") == "paragraph" && (is_default == "1" || is_default == "true"))
            default_paragraph_ = id;
        styles_.emplace(id, std::move(style));
    }
}

const DocxStyles::Style* DocxStyles::find(std::string_view id) const {
    const auto it = styles_.find(std::string(id));
    return it == styles_.end() ? nullptr : &it->second;
}

const DocxStyles::Style* DocxStyles::find_paragraph(std::string_view id) const {
    const Style* s = find(id.empty() ? std::string_view(default_paragraph_) : id);
    return s ? s : find(default_paragraph_);
}

OfficeLanguages DocxStyles::paragraph_languages(std::string_view style_id, std::string_view table_style_id) const {
    // A style's languages over its ancestors' (the depth bound stops a
    // basedOn cycle in a hand-made file).
    const auto apply_chain = [this](const Style* s, OfficeLanguages& out) {
        std::vector<const Style*> chain;
        for (int depth = 0; s && depth < 32; ++depth, s = find(s->based_on)) chain.push_back(s);
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) out.apply((*it)->run.languages);
    };
    OfficeLanguages out = defaults_;
    if (!table_style_id.empty()) apply_chain(find(table_style_id), out);
    apply_chain(find_paragraph(style_id), out);
    return out;
}

ParagraphStyle DocxStyles::paragraph(std::string_view style_id) const {
    ParagraphStyle out;
    const Style* s = find_paragraph(style_id);
    // Walk from the style to its ancestors; the nearest definition wins. The
    // depth bound stops a basedOn cycle in a hand-made file.
    std::vector<const Style*> chain;
    for (int depth = 0; s && depth < 32; ++depth, s = find(s->based_on)) chain.push_back(s);
    std::optional<bool> page_break;
    for (const Style* st : chain) {
        if (out.heading_level == 0) {
            if (const int h = heading_from_name(st->name); h > 0)
                out.heading_level = h;
            else if (st->outline_level && *st->outline_level >= 0 && *st->outline_level < 9)
                out.heading_level = std::min(6, *st->outline_level + 1);
        }
        if (!out.numbering && st->numbering) out.numbering = st->numbering;
        out.quote = out.quote || is_quote_style_name(st->name);
        if (!page_break && st->page_break_before) page_break = st->page_break_before;
    }
    out.page_break_before = page_break.value_or(false);
    return out;
}

RunFormat DocxStyles::character(std::string_view style_id) const {
    std::vector<const Style*> chain;
    const Style* s = find(style_id);
    for (int depth = 0; s && depth < 32; ++depth, s = find(s->based_on)) chain.push_back(s);
    RunFormat out;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) out.apply((*it)->run);
    return out;
}

DocxNumbering::DocxNumbering(const pugi::xml_node& root) {
    for (const auto& n : root.children()) {
        if (local_name(n) == "abstractNum") {
            Levels levels;
            for (const auto& lvl : n.children()) {
                if (local_name(lvl) != "lvl") continue;
                const auto i = to_int(attribute(lvl, "ilvl")).value_or(-1);
                if (i < 0 || i > 8) continue;
                auto& level = levels[static_cast<std::size_t>(i)];
                if (const auto f = attribute(child(lvl, "numFmt"), "val"); !f.empty())
                    level.format = f;
                level.text = attribute(child(lvl, "lvlText"), "val");
                level.start = to_int(attribute(child(lvl, "start"), "val")).value_or(1);
            }
            abstracts_[std::string(attribute(n, "abstractNumId"))] = std::move(levels);
        } else if (local_name(n) == "num") {
            const std::string id(attribute(n, "numId"));
            abstract_of_num_[id] = attribute(child(n, "abstractNumId"), "val");
            // <w:lvlOverride w:ilvl="0"><w:startOverride w:val="4"/>: this
            // list restarts the shared counter at 4 where it begins.
            for (const auto& o : n.children()) {
                if (local_name(o) != "lvlOverride") continue;
                const auto i = to_int(attribute(o, "ilvl")).value_or(-1);
                const auto start = to_int(attribute(child(o, "startOverride"), "val"));
                if (i >= 0 && i <= 8 && start) start_overrides_[id][static_cast<std::size_t>(i)] = *start;
            }
        }
    }
}

std::string DocxNumbering::next_label(const NumberingRef& ref) {
    const auto a = abstract_of_num_.find(ref.num_id);
    if (a == abstract_of_num_.end()) return {};
    const auto l = abstracts_.find(a->second);
    if (l == abstracts_.end()) return {};
    const Levels& levels = l->second;
    const auto ilvl = static_cast<std::size_t>(ref.ilvl);
    const auto& level = levels[ilvl];
    // Word draws its bullets from symbol fonts (U+F0B7 in Symbol): whatever the
    // glyph, a bullet is the UEB bullet sign (U+2022).
    if (level.format == "bullet") return "\u2022";
    if (level.format == "none") return {};

    constexpr int unset = -1;  // level not used since its parent last advanced
    auto [it, fresh] = counters_.try_emplace(a->second);
    auto& counters = it->second;
    if (fresh) counters.fill(unset);
    const auto over = start_overrides_.find(ref.num_id);
    if (over != start_overrides_.end() && over->second[ilvl] && overridden_.insert(ref.num_id + ":" + std::to_string(ilvl)).second)
        counters[ilvl] = *over->second[ilvl];
    else
        counters[ilvl] = counters[ilvl] == unset ? levels[ilvl].start : counters[ilvl] + 1;
    for (std::size_t deeper = ilvl + 1; deeper < counters.size(); ++deeper) counters[deeper] = unset;

    std::string label;
    const std::string& text = level.text;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '%' && i + 1 < text.size() && text[i + 1] >= '1' && text[i + 1] <= '9') {
            const auto k = static_cast<std::size_t>(text[i + 1] - '1');
            const int value = counters[k] == unset ? levels[k].start : counters[k];
            label += format_number(value, levels[k].format);
            ++i;
        } else {
            label += text[i];
        }
    }
    return label;
}

}  // namespace tactus::import::detail
