// SPDX-License-Identifier: GPL-3.0-or-later
// One walk for HTML, EPUB's content documents and DTBook (docs/import.md,
// "HTML, EPUB and DTBook"). Over 700 lines because the three vocabularies map
// onto one set of block rules, kept together so a rule (notes, page breaks,
// lists) is written once for all three.
#include "import/markup_walk.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "import/xml_util.hpp"
#include "common/try.hpp"

namespace tactus::import::detail {

using document::BlockKind;
namespace {

bool is_html_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

std::string_view trim_html_space(std::string_view s) {
    while (!s.empty() && is_html_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_html_space(s.back())) s.remove_suffix(1);
    return s;
}

bool has_token(std::string_view list, std::string_view token) {
    while (!list.empty()) {
        while (!list.empty() && is_html_space(list.front())) list.remove_prefix(1);
        const auto end = std::min(list.size(), static_cast<std::size_t>(std::find_if(list.begin(), list.end(), is_html_space) - list.begin()));
        auto word = list.substr(0, end);
        // "epub:footnote", "z3998:..." prefixes: the word after the colon counts.
        if (const auto colon = word.rfind(':'); colon != std::string_view::npos && token.find(':') == std::string_view::npos)
            word = word.substr(colon + 1);
        if (word == token) return true;
        list.remove_prefix(end);
    }
    return false;
}

// epub:type (any prefix bound to the OPS namespace; HTML parsers keep the
// name as written), and the ARIA role, which EPUB 3.3 recommends beside it.
std::string_view epub_type(const pugi::xml_node& n) {
    for (const auto& a : n.attributes()) {
        const std::string_view name = a.name();
        if (name.size() > 5 && name.ends_with(":type") && name != "xlink:type") return a.value();
    }
    return {};
}

bool semantic(const pugi::xml_node& n, std::string_view epub, std::string_view role) {
    return has_token(epub_type(n), epub) || has_token(n.attribute("role").value(), role);
}

std::string_view language_of(const pugi::xml_node& n) {
    if (const auto a = n.attribute("xml:lang")) return a.value();
    if (const auto a = n.attribute("lang")) return a.value();
    return {};
}

bool is_note_element(const pugi::xml_node& n) {
    const auto name = local_name(n);
    if (name == "note" || name == "annotation") return true;
    return semantic(n, "footnote", "doc-footnote") || semantic(n, "endnote", "doc-endnote") ||
           semantic(n, "rearnote", "doc-endnote") || has_token(epub_type(n), "note");
}

bool is_reference(const pugi::xml_node& n) {
    const auto name = local_name(n);
    return name == "noteref" || name == "annoref" || semantic(n, "noteref", "doc-noteref");
}

bool is_page_break(const pugi::xml_node& n) {
    return local_name(n) == "pagenum" || semantic(n, "pagebreak", "doc-pagebreak");
}

std::string percent_decoded(std::string_view s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const auto hex = [](char c) -> int {
            if (c >= '0' && c <= '9') return c - '0';
            if (c >= 'a' && c <= 'f') return c - 'a' + 10;
            if (c >= 'A' && c <= 'F') return c - 'A' + 10;
            return -1;
        };
        if (s[i] == '%' && i + 2 < s.size() && hex(s[i + 1]) >= 0 && hex(s[i + 2]) >= 0) {
            out += static_cast<char>(hex(s[i + 1]) * 16 + hex(s[i + 2]));
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

// Every element under `root`, in document order, without recursion.
template <typename F>
void for_each_element(const pugi::xml_node& root, F&& f) {
    std::vector<pugi::xml_node> stack{root};
    while (!stack.empty()) {
        const auto n = stack.back();
        stack.pop_back();
        if (n.type() == pugi::node_element) f(n);
        else if (n.type() != pugi::node_document) continue;
        for (auto c = n.last_child(); c; c = c.previous_sibling()) stack.push_back(c);
    }
}

// All the text under `n`, as written, in document order.
std::string all_text(const pugi::xml_node& n) {
    std::string out;
    std::vector<pugi::xml_node> stack{n};
    while (!stack.empty()) {
        const auto t = stack.back();
        stack.pop_back();
        if (t.type() == pugi::node_pcdata || t.type() == pugi::node_cdata) out += t.value();
        if (t.type() != pugi::node_element) continue;
        for (auto c = t.last_child(); c; c = c.previous_sibling()) stack.push_back(c);
    }
    return out;
}

std::string collapsed(std::string_view s) {
    std::string out;
    bool space = false;
    for (const char c : trim_html_space(s)) {
        if (is_html_space(c)) {
            space = true;
            continue;
        }
        if (space) out += ' ';
        space = false;
        out += c;
    }
    return out;
}

// MathML (3.0) as linear text, the way it is read aloud in print order:
// fractions as (a)/(b), scripts with ^ and _, roots as sqrt(...).
void linear_math(const pugi::xml_node& n, std::string& out, int depth) {
    if (depth <= 0) return;
    const auto add = [&out](std::string_view s) {
        s = trim_html_space(s);
        if (s.empty()) return;
        if (!out.empty() && out.back() != ' ' && out.back() != '(') out += ' ';
        out += s;
    };
    const auto group = [&](const pugi::xml_node& c) {
        std::string inner;
        linear_math(c, inner, depth - 1);
        const bool simple = inner.find(' ') == std::string::npos;
        add(simple ? inner : "(" + inner + ")");
    };
    const auto name = local_name(n);
    std::vector<pugi::xml_node> kids;
    for (const auto& c : n.children())
        if (c.type() == pugi::node_element) kids.push_back(c);
    if (name == "annotation" || name == "annotation-xml" || name == "none" || name == "mprescripts") return;
    if (name == "semantics") {
        if (!kids.empty()) linear_math(kids.front(), out, depth - 1);
        return;
    }
    if (name == "mfrac" && kids.size() == 2) {
        group(kids[0]);
        out += '/';
        std::string inner;
        linear_math(kids[1], inner, depth - 1);
        out += inner.find(' ') == std::string::npos ? inner : "(" + inner + ")";
        return;
    }
    if ((name == "msup" || name == "msub" || name == "munder" || name == "mover") && kids.size() == 2) {
        group(kids[0]);
        out += (name == "msup" || name == "mover") ? '^' : '_';
        std::string inner;
        linear_math(kids[1], inner, depth - 1);
        out += inner.find(' ') == std::string::npos ? inner : "(" + inner + ")";
        return;
    }
    if ((name == "msubsup" || name == "munderover") && kids.size() == 3) {
        group(kids[0]);
        for (int i = 1; i <= 2; ++i) {
            out += i == 1 ? '_' : '^';
            std::string inner;
            linear_math(kids[static_cast<std::size_t>(i)], inner, depth - 1);
            out += inner.find(' ') == std::string::npos ? inner : "(" + inner + ")";
        }
        return;
    }
    if (name == "msqrt" || (name == "mroot" && kids.size() == 2)) {
        std::string inner;
        if (name == "msqrt")
            for (const auto& c : kids) linear_math(c, inner, depth - 1);
        else
            linear_math(kids[0], inner, depth - 1);
        add(name == "msqrt" ? "sqrt(" + inner + ")" : "root(" + inner + ")");
        if (name == "mroot") {
            std::string index;
            linear_math(kids[1], index, depth - 1);
            out.pop_back();
            out += ", " + index + ")";
        }
        return;
    }
    if (name == "mfenced") {
        std::string inner;
        const std::string_view separator = n.attribute("separators") ? n.attribute("separators").value() : ",";
        for (std::size_t i = 0; i < kids.size(); ++i) {
            if (i > 0 && !separator.empty()) inner += std::string(1, separator[std::min(i - 1, separator.size() - 1)]) + " ";
            linear_math(kids[i], inner, depth - 1);
        }
        add((n.attribute("open") ? n.attribute("open").value() : "(") + inner +
            (n.attribute("close") ? n.attribute("close").value() : ")"));
        return;
    }
    if (kids.empty()) {
        add(n.text().get());
        return;
    }
    for (const auto& c : kids) {
        const bool row = local_name(c) == "mtr";
        if (row && !out.empty()) out += ';';
        linear_math(c, out, depth - 1);
    }
}

}  // namespace

std::string text_of(const pugi::xml_node& node) { return collapsed(all_text(node)); }

std::string resolve_path(std::string_view base_part, std::string_view relative) {
    const auto slash = base_part.rfind('/');
    const std::string path = (slash == std::string_view::npos ? std::string{} : std::string(base_part.substr(0, slash + 1))) +
                             percent_decoded(relative);
    std::vector<std::string> pieces;
    std::string piece;
    for (std::size_t i = 0; i <= path.size(); ++i) {
        if (i == path.size() || path[i] == '/') {
            if (piece == "..") {
                if (!pieces.empty()) pieces.pop_back();
            } else if (!piece.empty() && piece != ".") {
                pieces.push_back(piece);
            }
            piece.clear();
        } else {
            piece += path[i];
        }
    }
    std::string out;
    for (const auto& p : pieces) out += (out.empty() ? "" : "/") + p;
    return out;
}

MarkupWalk::MarkupWalk(std::vector<MarkupPart> parts) : parts_(std::move(parts)) {}

int MarkupWalk::line(const pugi::xml_node& node) const {
    const auto& part = parts_[part_];
    return part.line_of ? part.line_of(node) : 0;
}

std::string MarkupWalk::where(const pugi::xml_node& node) const {
    const auto& name = parts_[part_].name;
    const int l = line(node);
    std::string w = name;
    if (l > 0) w += (w.empty() ? "" : ":") + std::to_string(l);
    return w;
}

void MarkupWalk::warn(const pugi::xml_node& node, std::string what) {
    // One line per kind of thing left out: where it is first, and how many more.
    auto& count = warning_counts_[what];
    if (count++ == 0) {
        const auto w = where(node);
        warnings_.push_back((w.empty() ? std::string{} : w + ": ") + what);
    }
}

Result<document::Document> MarkupWalk::run() {
    for (std::size_t i = 0; i < parts_.size(); ++i)
        for_each_element(parts_[i].root, [&](const pugi::xml_node& e) {
            if (!is_note_element(e)) return;
            const auto id = e.attribute("id");
            if (id) notes_.emplace(parts_[i].name + "#" + id.value(), e);
        });
    for (part_ = 0; part_ < parts_.size(); ++part_) {
        TACTUS_TRY_VOID(walk(parts_[part_].root, Context{}, 0));
        close();
        flush_breaks();
        if (builder_.full()) break;
    }
    part_ = 0;
    auto doc = builder_.finish();
    if (!doc) return doc;
    for (auto& w : warnings_) {
        const auto what = w.substr(w.find(": ") == std::string::npos ? 0 : w.find(": ") + 2);
        if (const auto n = warning_counts_[what]; n > 1) w += " (and " + std::to_string(n - 1) + " more)";
        doc->warnings.push_back(std::move(w));
    }
    return doc;
}

void MarkupWalk::open(const Context& ctx) {
    if (builder_.is_open()) return;
    builder_.begin(ctx.kind, ctx.level, current_line_);
    block_fresh_ = true;
    space_pending_ = false;
    if (ctx.kind == BlockKind::list_item && !item_label_.empty()) builder_.add_text(item_label_);
    item_label_.clear();
}

void MarkupWalk::close() {
    if (note_depth_ > 0 || !builder_.is_open()) return;
    builder_.trim_end();
    builder_.end();
    block_fresh_ = true;
    space_pending_ = false;
}

void MarkupWalk::flush_breaks() {
    if (table_depth_ > 0 || note_depth_ > 0 || builder_.is_open()) return;
    for (auto& label : pending_breaks_) builder_.print_page_break(current_line_, std::move(label));
    pending_breaks_.clear();
}

void MarkupWalk::text(std::string_view raw, const Context& ctx) {
    // HTML white space: each run is one space, none at a block's start. The
    // space belongs to the text before it ("rain <em>falls</em>": the space
    // is not emphasised).
    std::string run;
    for (const char c : raw) {
        if (is_html_space(c)) {
            space_pending_ = true;
            continue;
        }
        if (!builder_.is_open()) open(ctx);  // run is empty here: nothing was open
        if (space_pending_ && !block_fresh_) {
            if (run.empty()) pending_space(ctx);
            else run += ' ';
        }
        space_pending_ = false;
        block_fresh_ = line_pending_ = after_label_ = false;
        run += c;
    }
    if (run.empty()) return;
    builder_.add_text(run, ctx.emphasis, document::Position::baseline, ctx.language);
    last_emphasis_ = ctx.emphasis;
    last_language_ = ctx.language;
}

void MarkupWalk::pending_space(const Context& ctx) {
    if (line_pending_) {
        // The cell's next paragraph: a line break, which no emphasis covers.
        builder_.add_text("\n", document::emphasis_none, document::Position::baseline, {});
        line_pending_ = false;
        return;
    }
    // A space between two runs is emphasised only as both are ("<b>clouds</b>
    // and": not bold), and in the language of the text before it.
    builder_.add_text(" ", static_cast<std::uint8_t>(last_emphasis_ & ctx.emphasis), document::Position::baseline, last_language_);
}

void MarkupWalk::cell_paragraph_break(const Context& ctx) {
    space_pending_ = true;
    // The item's own paragraph (<li><p>) goes on after its label.
    if (ctx.kind == BlockKind::table_cell && !after_label_) line_pending_ = true;
}

Result<void> MarkupWalk::walk_children(const pugi::xml_node& node, const Context& ctx, int depth) {
    for (const auto& c : node.children()) {
        if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
            text(c.value(), ctx);
        } else if (c.type() == pugi::node_element) {
            if (auto ok = walk(c, ctx, depth + 1); !ok) return ok;
        }
        if (builder_.full()) break;
    }
    return {};
}

Result<void> MarkupWalk::walk(const pugi::xml_node& node, const Context& parent, int depth) {
    if (node.type() == pugi::node_document) return walk_children(node, parent, depth);
    if (node.type() != pugi::node_element) return {};
    if (depth > max_markup_depth)
        return fail(ErrorKind::input, "elements nested more than " + std::to_string(max_markup_depth) + " deep (<" +
                        std::string(local_name(node)) + ">); the book cannot be read",
                    where(node));
    if (const int l = line(node); l > 0) current_line_ = l;
    Context ctx = parent;
    if (node.parent().type() == pugi::node_document) {
        // The root's language is the document's own: passages in it carry none.
        base_language_ = std::string(language_of(node));
    } else if (const auto lang = language_of(node); !lang.empty()) {
        ctx.language = lang == base_language_ ? std::string{} : std::string(lang);
    }
    const auto name = local_name(node);

    // Things that are not the book's text.
    if (name == "head" || name == "script" || name == "style" || name == "template" || name == "title" ||
        semantic(node, "backlink", "doc-backlink"))
        return {};
    if (name == "video" || name == "audio" || name == "iframe" || name == "object" || name == "embed" ||
        name == "canvas") {
        warn(node, "<" + std::string(name) + "> left out (only text and image descriptions are imported)");
        return {};
    }
    if (name == "svg") {
        if (const auto t = child(node, "title"); t && !trim_html_space(t.text().get()).empty()) image(node, ctx);
        else warn(node, "an SVG graphic with no <title> left out");
        return {};
    }
    if (is_page_break(node)) {
        page_break(node);
        // An HTML page break with its label in an attribute holds no text; when
        // XHTML's <span/> was read as HTML, what follows it is inside it.
        if (local_name(node) == "pagenum" || (!node.attribute("title") && !node.attribute("aria-label"))) return {};
        return walk_children(node, ctx, depth);
    }
    if (is_reference(node)) return reference(node, ctx, depth);
    if (is_note_element(node)) {
        if (notes_written_.contains(node.internal_object())) return {};
        notes_written_.insert(node.internal_object());
        return note(node, ctx, depth, std::to_string(++note_number_));
    }
    if (name == "math") {
        math(node, ctx);
        return {};
    }
    if (name == "img") {
        image(node, ctx);
        return {};
    }
    if (name == "br") {
        if (ctx.inline_only) cell_paragraph_break(ctx);
        else close();
        return {};
    }
    if (name == "hr") {
        if (ctx.inline_only) space_pending_ = true;
        else close();
        return {};
    }
    // Emphasis.
    if (name == "em" || name == "i" || name == "cite" || name == "dfn" || name == "var")
        ctx.emphasis |= document::emphasis_italic;
    else if (name == "strong" || name == "b")
        ctx.emphasis |= document::emphasis_bold;
    else if (name == "u" || name == "ins")
        ctx.emphasis |= document::emphasis_underline;

    if (name == "ul" || name == "ol" || name == "list") {
        const bool ordered = name == "ol" || (name == "list" && node.attribute("type").value() == std::string_view("ol"));
        return list(node, ctx, depth, ordered);
    }
    if (name == "table") return table(node, ctx, depth);
    if (name == "level" || name == "level1" || name == "level2" || name == "level3" || name == "level4" ||
        name == "level5" || name == "level6") {
        ctx.section_depth = name == "level" ? ctx.section_depth + 1 : name[5] - '0';
        return block(node, ctx, depth);
    }
    if (name.size() == 2 && name[0] == 'h' && name[1] >= '1' && name[1] <= '6') {
        ctx.kind = BlockKind::heading;
        ctx.level = name[1] - '0';
        return block(node, ctx, depth);
    }
    if (name == "hd" || name == "doctitle" || name == "bridgehead") {
        ctx.kind = BlockKind::heading;
        ctx.level = name == "doctitle" ? 1 : std::clamp(ctx.section_depth + (name == "bridgehead" ? 1 : 0), 1, 6);
        return block(node, ctx, depth);
    }
    if (name == "blockquote" || name == "epigraph") {
        ctx.quote_depth += 1;
        if (ctx.kind == BlockKind::paragraph || ctx.kind == BlockKind::quote) {
            ctx.kind = BlockKind::quote;
            ctx.level = ctx.quote_depth;
        }
        return block(node, ctx, depth);
    }
    if (name == "pre") {
        if (ctx.inline_only) return walk_children(node, ctx, depth);
        close();
        const auto whole = all_text(node);
        std::string_view all = whole;
        while (!all.empty()) {
            const auto nl = all.find('\n');
            const auto line_text = all.substr(0, nl);
            if (!trim_html_space(line_text).empty()) {
                builder_.begin(ctx.kind, ctx.level, current_line_);
                builder_.add_text(line_text, ctx.emphasis, document::Position::baseline, ctx.language);
                builder_.trim_end();
                builder_.end();
            }
            if (nl == std::string_view::npos) break;
            all.remove_prefix(nl + 1);
        }
        return {};
    }
    static constexpr std::array block_names{
        "html", "body", "section", "article", "nav", "aside", "header", "footer", "main", "div", "figure",
        "hgroup", "details", "summary", "address", "fieldset", "form", "center", "dtbook", "book",
        "frontmatter", "bodymatter", "rearmatter", "sidebar", "prodnote", "imggroup", "linegroup", "poem",
        "dl", "p", "dt", "dd", "figcaption", "caption", "legend", "line", "author", "byline", "dateline",
        "docauthor", "covertitle", "li", "noscript", "dateline", "signature", "lic"};
    if (std::find(block_names.begin(), block_names.end(), name) != block_names.end()) return block(node, ctx, depth);
    return walk_children(node, ctx, depth);  // inline: span, a, sent, w, abbr, q, sub, sup, ...
}

Result<void> MarkupWalk::block(const pugi::xml_node& node, Context ctx, int depth) {
    if (ctx.inline_only) {
        // A block inside a heading or a note runs on, a space apart; inside
        // a table cell it is a paragraph of the cell, a line break apart.
        cell_paragraph_break(ctx);
        auto ok = walk_children(node, ctx, depth);
        cell_paragraph_break(ctx);
        return ok;
    }
    close();
    flush_breaks();
    if (ctx.kind == BlockKind::heading) ctx.inline_only = true;
    auto ok = walk_children(node, ctx, depth);
    close();
    flush_breaks();
    return ok;
}

Result<void> MarkupWalk::list(const pugi::xml_node& node, const Context& parent, int depth, bool ordered) {
    const bool plain = node.attribute("type").value() == std::string_view("pl");
    int number = whole_number(node.attribute("start").value(), 1);
    if (parent.inline_only && parent.kind == BlockKind::table_cell) {
        // A list in a table cell: each item a paragraph of the cell, with its label.
        for (const auto& c : node.children()) {
            if (c.type() != pugi::node_element || local_name(c) != "li") {
                if (auto ok = c.type() == pugi::node_element ? walk(c, parent, depth + 1) : Result<void>{}; !ok) return ok;
                continue;
            }
            number = whole_number(c.attribute("value").value(), number);
            cell_paragraph_break(parent);
            if (!plain) {
                text(ordered ? std::to_string(number) + ". " : std::string("\u2022 "), parent);
                after_label_ = true;
            }
            ++number;
            if (auto ok = walk_children(c, parent, depth + 1); !ok) return ok;
            cell_paragraph_break(parent);
        }
        return {};
    }
    if (parent.inline_only) return walk_children(node, parent, depth);
    close();
    Context ctx = parent;
    ctx.list_depth += 1;
    for (const auto& c : node.children()) {
        if (c.type() == pugi::node_pcdata) {
            text(c.value(), ctx);
            continue;
        }
        if (c.type() != pugi::node_element) continue;
        if (local_name(c) != "li") {
            if (auto ok = walk(c, ctx, depth + 1); !ok) return ok;
            continue;
        }
        close();
        flush_breaks();
        number = whole_number(c.attribute("value").value(), number);
        Context item = ctx;
        if (const auto lang = language_of(c); !lang.empty())
            item.language = lang == base_language_ ? std::string{} : std::string(lang);
        item.kind = BlockKind::list_item;
        item.level = ctx.list_depth;
        item_label_ = plain ? std::string{} : ordered ? std::to_string(number) + ". " : std::string("\u2022 ");
        ++number;
        if (depth + 1 > max_markup_depth)
            return fail(ErrorKind::input, "elements nested more than " + std::to_string(max_markup_depth) + " deep (<li>)", where(c));
        if (const int l = line(c); l > 0) current_line_ = l;
        if (is_note_element(c)) {
            item_label_.clear();
            if (auto ok = walk(c, ctx, depth + 1); !ok) return ok;
            continue;
        }
        if (auto ok = walk_children(c, item, depth + 1); !ok) return ok;
        close();
        item_label_.clear();
        if (builder_.full()) break;
    }
    close();
    flush_breaks();
    return {};
}

Result<void> MarkupWalk::table(const pugi::xml_node& node, const Context& parent, int depth) {
    if (parent.inline_only || table_depth_ > 0) {
        // A table inside a cell, a heading or a note is read as its text.
        space_pending_ = true;
        Context ctx = parent;
        ctx.inline_only = true;
        auto ok = walk_children(node, ctx, depth);
        space_pending_ = true;
        return ok;
    }
    close();
    flush_breaks();
    // The caption first, as a paragraph; then the rows of thead, tbody, tfoot.
    for (const auto& c : node.children())
        if (c.type() == pugi::node_element && local_name(c) == "caption")
            if (auto ok = block(c, parent, depth + 1); !ok) return ok;
    std::vector<std::pair<pugi::xml_node, bool>> rows;
    for (const auto& c : node.children()) {
        if (c.type() != pugi::node_element) continue;
        const auto name = local_name(c);
        if (name == "tr") rows.emplace_back(c, false);
        else if (name == "thead" || name == "tbody" || name == "tfoot")
            for (const auto& r : c.children())
                if (r.type() == pugi::node_element && local_name(r) == "tr") rows.emplace_back(r, name == "thead");
    }
    ++table_depth_;
    bool any = false;
    for (const auto& [row, in_head] : rows) {
        bool all_th = true;
        bool cells = false;
        for (const auto& cell : row.children())
            if (cell.type() == pugi::node_element) {
                cells = true;
                if (local_name(cell) != "th") all_th = false;
            }
        if (!cells) continue;
        any = true;
        if (const int l = line(row); l > 0) current_line_ = l;
        builder_.table_row(in_head || all_th, current_line_);
        int column = 0;
        for (const auto& cell : row.children()) {
            if (cell.type() != pugi::node_element) continue;
            const auto name = local_name(cell);
            if (name != "td" && name != "th") {
                // A page number between cells waits for the table's end.
                if (auto ok = walk(cell, parent, depth + 2); !ok) {
                    --table_depth_;
                    return ok;
                }
                continue;
            }
            const int span = std::clamp(whole_number(cell.attribute("colspan").value(), 1), 1, 1000);
            if (const int l = line(cell); l > 0) current_line_ = l;
            builder_.begin_cell(column, current_line_, span);
            block_fresh_ = true;
            space_pending_ = line_pending_ = after_label_ = false;
            Context c = parent;
            if (const auto lang = language_of(cell); !lang.empty())
                c.language = lang == base_language_ ? std::string{} : std::string(lang);
            c.kind = BlockKind::table_cell;
            c.level = column;
            c.inline_only = true;
            if (name == "th") c.emphasis = parent.emphasis;
            if (auto ok = walk_children(cell, c, depth + 2); !ok) {
                --table_depth_;
                return ok;
            }
            builder_.trim_end();
            column += span;
        }
    }
    --table_depth_;
    if (any) builder_.end_table();
    block_fresh_ = true;
    space_pending_ = false;
    flush_breaks();
    return {};
}

Result<void> MarkupWalk::reference(const pugi::xml_node& node, const Context& ctx, int depth) {
    std::string target;
    std::string_view link = node.attribute("href").value();
    if (link.empty()) link = node.attribute("idref").value();
    if (!link.empty()) {
        const auto& base = parts_[part_].name;
        if (link.front() == '#' || local_name(node) == "noteref" || local_name(node) == "annoref") {
            target = base + "#" + std::string(link.front() == '#' ? link.substr(1) : link);
        } else if (const auto hash = link.find('#'); hash != std::string_view::npos) {
            // A path relative to this part's folder, "../Text/notes.xhtml#n1".
            target = resolve_path(base, link.substr(0, hash));
            target += "#" + std::string(link.substr(hash + 1));
        }
    }
    const auto found = notes_.find(target);
    if (found == notes_.end()) return walk_children(node, ctx, depth);  // not a link to a note: its text stays
    auto label = collapsed(all_text(node));
    while (!label.empty() && (label.front() == '[' || label.front() == '(')) label.erase(0, 1);
    while (!label.empty() && (label.back() == ']' || label.back() == ')')) label.pop_back();
    const bool written = notes_written_.contains(found->second.internal_object());
    if (label.empty() || label.size() > 8) label = std::to_string(written ? note_number_ : note_number_ + 1);
    if (!builder_.is_open()) open(ctx);
    if (space_pending_ && !block_fresh_) pending_space(ctx);
    space_pending_ = false;
    builder_.note_reference(label);
    block_fresh_ = line_pending_ = after_label_ = false;
    if (written) return {};
    ++note_number_;
    notes_written_.insert(found->second.internal_object());
    // The note's own part gives its lines and its links.
    const auto here = part_;
    const auto hash = target.rfind('#');
    for (std::size_t i = 0; i < parts_.size(); ++i)
        if (parts_[i].name == target.substr(0, hash)) part_ = i;
    auto ok = note(found->second, ctx, depth, label);
    part_ = here;
    return ok;
}

Result<void> MarkupWalk::note(const pugi::xml_node& node, const Context& parent, int depth, std::string label) {
    if (note_depth_ > 0) {
        // Notes do not nest: a note's note follows it (DocumentBuilder).
        space_pending_ = true;
    }
    const bool fresh = block_fresh_;
    const bool space = space_pending_;
    const bool line_break = line_pending_;
    if (note_depth_ == 0 && !builder_.is_open()) flush_breaks();
    builder_.begin_note(std::move(label), line(node));
    ++note_depth_;
    block_fresh_ = true;
    space_pending_ = false;
    Context ctx = parent;
    ctx.kind = BlockKind::note;
    ctx.level = 0;
    ctx.inline_only = true;
    auto ok = walk_children(node, ctx, depth);
    --note_depth_;
    builder_.end_note();
    block_fresh_ = fresh;
    space_pending_ = space;
    line_pending_ = line_break;
    if (!builder_.is_open()) flush_breaks();
    return ok;
}

void MarkupWalk::page_break(const pugi::xml_node& node) {
    std::string label;
    if (local_name(node) == "pagenum") label = collapsed(all_text(node));
    else if (const auto t = node.attribute("title"); t && !trim_html_space(t.value()).empty()) label = collapsed(t.value());
    else if (const auto a = node.attribute("aria-label"); a && !trim_html_space(a.value()).empty()) label = collapsed(a.value());
    else label = collapsed(all_text(node));
    // "Page 12": the number is the label.
    if (const auto space = label.rfind(' '); space != std::string::npos) label = label.substr(space + 1);
    if (table_depth_ > 0 || note_depth_ > 0) {
        pending_breaks_.push_back(std::move(label));
        return;
    }
    const bool was_open = builder_.is_open();
    builder_.trim_end();
    pending_breaks_.push_back(std::move(label));
    if (was_open) {
        builder_.end();
        block_fresh_ = true;
        space_pending_ = false;
    }
    flush_breaks();
}

void MarkupWalk::image(const pugi::xml_node& node, const Context& ctx) {
    std::string description;
    if (local_name(node) == "svg") description = collapsed(child(node, "title").text().get());
    else if (const auto alt = node.attribute("alt")) description = collapsed(alt.value());
    else {
        warn(node, "an image with no description (alt) left out");
        return;
    }
    if (description.empty()) return;  // alt="": decorative (HTML), nothing to read
    // A transcriber's note (BANA Braille Formats 2016, §3.3): the description
    // in place of the picture, in a paragraph of its own between blocks.
    const std::string note = "Image: " + description;
    if (ctx.inline_only || (builder_.is_open() && !block_fresh_)) {
        if (!builder_.is_open()) open(ctx);
        builder_.add_text(std::string(block_fresh_ ? "" : " ") + "[" + note + "]", ctx.emphasis, document::Position::baseline, ctx.language);
        attach_picture(node);
        block_fresh_ = line_pending_ = after_label_ = false;
        space_pending_ = true;
        return;
    }
    close();
    builder_.begin(BlockKind::paragraph, 0, line(node));
    builder_.add_text(note, document::emphasis_none, document::Position::baseline, ctx.language);
    attach_picture(node);
    builder_.end();
    block_fresh_ = true;
    space_pending_ = false;
}

void MarkupWalk::attach_picture(const pugi::xml_node& node) {
    if (!pictures_ || local_name(node) != "img") return;
    const std::string_view src = node.attribute("src").value();
    if (src.empty()) return;
    std::string why;
    if (auto picture = pictures_(parts_[part_].name, src, why))
        builder_.add_image(std::move(*picture));
    else if (!why.empty())
        warn(node, "picture " + std::string(src) + ": " + why + "; its description stays");
}

void MarkupWalk::math(const pugi::xml_node& node, const Context& ctx) {
    std::string linear;
    if (const auto alt = node.attribute("alttext"); alt && !trim_html_space(alt.value()).empty()) linear = collapsed(alt.value());
    else linear_math(node, linear, 64);
    if (linear.empty()) return;
    if (!builder_.is_open()) open(ctx);
    if (!block_fresh_ && space_pending_) pending_space(ctx);
    builder_.add_text(linear, ctx.emphasis, document::Position::baseline, ctx.language);
    last_emphasis_ = ctx.emphasis;
    last_language_ = ctx.language;
    block_fresh_ = line_pending_ = after_label_ = false;
    space_pending_ = false;
}

}  // namespace tactus::import::detail
