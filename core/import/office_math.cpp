// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/office_math.hpp"

#include <string>
#include <vector>

#include "import/xml_util.hpp"

namespace tactus::import::detail {
namespace {

using document::Position;

// Math nests as deep as the XML does; a hostile file cannot nest deeper
// than this (the rest of a deeper formula is read flat).
constexpr int kMaxDepth = 64;

// A part of a formula collected before it is written: its text and position.
struct Piece {
    std::string text;
    Position position = Position::baseline;
};
using Pieces = std::vector<Piece>;

void put(Pieces& out, std::string_view text, Position p) {
    if (text.empty()) return;
    if (!out.empty() && out.back().position == p)
        out.back().text.append(text);
    else
        out.push_back({std::string(text), p});
}

std::size_t code_points(const Pieces& ps) {
    std::size_t n = 0;
    for (const auto& p : ps)
        for (const char c : p.text) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80 ? 1u : 0u;
    return n;
}

void append(Pieces& out, const Pieces& in) {
    for (const auto& p : in) put(out, p.text, p.position);
}

// A side of a fraction or a root's radicand: in parentheses unless it is one
// character, so the linear text reads as the formula did.
void grouped(Pieces& out, const Pieces& in, Position p) {
    const bool parens = code_points(in) > 1;
    if (parens) put(out, "(", p);
    append(out, in);
    if (parens) put(out, ")", p);
}

// A raised or lowered part: on the line already raised or lowered, it is
// written with "^" or "_" (a second level the document model has no mark for).
Position shifted(Position at, Position to, Pieces& out, std::string_view mark) {
    if (at == Position::baseline) return to;
    put(out, mark, at);
    return at;
}

class Omml {
public:
    explicit Omml(Pieces& out) : out_(out) {}

    void walk(const pugi::xml_node& n, Position p, int depth) {
        for (const auto& c : n.children()) node(c, p, depth + 1);
    }

private:
    Pieces part(const pugi::xml_node& n, Position p, int depth) {
        Pieces saved;
        std::swap(saved, out_);
        if (n) walk(n, p, depth);
        std::swap(saved, out_);
        return saved;
    }

    void node(const pugi::xml_node& c, Position p, int depth) {
        if (c.type() != pugi::node_element) return;
        const auto name = local_name(c);
        if (name.ends_with("Pr") || name == "rPr") return;  // properties
        if (name == "t") {
            put(out_, c.child_value(), p);
            return;
        }
        if (depth > kMaxDepth) {
            walk(c, p, depth);
            return;
        }
        if (name == "f") {
            grouped(out_, part(child(c, "num"), p, depth), p);
            put(out_, "/", p);
            grouped(out_, part(child(c, "den"), p, depth), p);
        } else if (name == "sSup" || name == "sSub" || name == "sSubSup" || name == "sPre") {
            const bool pre = name == "sPre";
            if (!pre) walk(child(c, "e"), p, depth);
            if (const auto sub = child(c, "sub")) walk(sub, shifted(p, Position::subscript, out_, "_"), depth);
            if (const auto sup = child(c, "sup")) walk(sup, shifted(p, Position::superscript, out_, "^"), depth);
            if (pre) walk(child(c, "e"), p, depth);
        } else if (name == "rad") {
            const auto degree = part(child(c, "deg"), p, depth);
            if (!degree.empty()) {
                put(out_, "(", p);
                append(out_, degree);
                put(out_, ")", p);
            }
            put(out_, "\u221A", p);
            grouped(out_, part(child(c, "e"), p, depth), p);
        } else if (name == "d") {
            // Delimiters: "(" and ")" unless the properties name others; the
            // separator between the parts "|" unless named.
            const auto pr = child(c, "dPr");
            const auto chr = [&](std::string_view el, std::string_view fallback) -> std::string {
                const auto e = child(pr, el);
                return e ? std::string(attribute(e, "val")) : std::string(fallback);
            };
            put(out_, chr("begChr", "("), p);
            bool first = true;
            for (const auto& e : c.children()) {
                if (local_name(e) != "e") continue;
                if (!first) put(out_, chr("sepChr", "|"), p);
                walk(e, p, depth);
                first = false;
            }
            put(out_, chr("endChr", ")"), p);
        } else if (name == "nary") {
            const auto pr = child(c, "naryPr");
            const auto sign = child(pr, "chr");
            put(out_, sign ? attribute(sign, "val") : std::string_view("\u222B"), p);
            if (const auto sub = child(c, "sub")) walk(sub, shifted(p, Position::subscript, out_, "_"), depth);
            if (const auto sup = child(c, "sup")) walk(sup, shifted(p, Position::superscript, out_, "^"), depth);
            put(out_, " ", p);
            walk(child(c, "e"), p, depth);
        } else if (name == "func") {
            walk(child(c, "fName"), p, depth);
            put(out_, " ", p);
            walk(child(c, "e"), p, depth);
        } else if (name == "mr" || name == "eqArr") {
            // Matrix rows and lines of an equation array: a space apart.
            walk(c, p, depth);
            put(out_, " ", p);
        } else if (name == "oMath" && local_name(c.previous_sibling()) == "oMath") {
            put(out_, " ", p);  // equations of one paragraph, a space apart
            walk(c, p, depth);
        } else {
            walk(c, p, depth);  // m:r, m:e, m:acc, m:bar, m:box, m:groupChr, m:lim*, m:m ...
        }
    }

    Pieces& out_;
};

class MathMl {
public:
    explicit MathMl(Pieces& out) : out_(out) {}

    void walk(const pugi::xml_node& n, Position p, int depth) {
        for (const auto& c : n.children()) node(c, p, depth + 1);
    }

private:
    // The element children of a script or fraction: base, then its parts.
    static std::vector<pugi::xml_node> args(const pugi::xml_node& n) {
        std::vector<pugi::xml_node> out;
        for (const auto& c : n.children())
            if (c.type() == pugi::node_element) out.push_back(c);
        return out;
    }

    Pieces part(const pugi::xml_node& n, Position p, int depth) {
        Pieces saved;
        std::swap(saved, out_);
        if (n) node(n, p, depth + 1);
        std::swap(saved, out_);
        return saved;
    }

    void node(const pugi::xml_node& c, Position p, int depth) {
        if (c.type() == pugi::node_pcdata) {
            std::string t = c.value();
            const auto first = t.find_first_not_of(" \t\r\n");
            if (first == std::string::npos) return;
            t = t.substr(first, t.find_last_not_of(" \t\r\n") - first + 1);
            put(out_, t, p);
            return;
        }
        if (c.type() != pugi::node_element) return;
        const auto name = local_name(c);
        if (name == "annotation" || name == "annotation-xml") return;
        if (depth > kMaxDepth) {
            walk(c, p, depth);
            return;
        }
        const auto a = args(c);
        if (name == "mfrac" && a.size() == 2) {
            grouped(out_, part(a[0], p, depth), p);
            put(out_, "/", p);
            grouped(out_, part(a[1], p, depth), p);
        } else if ((name == "msup" || name == "msub" || name == "mover" || name == "munder") && a.size() == 2) {
            node(a[0], p, depth + 1);
            const bool up = name == "msup" || name == "mover";
            node(a[1], shifted(p, up ? Position::superscript : Position::subscript, out_, up ? "^" : "_"),
                 depth + 1);
        } else if ((name == "msubsup" || name == "munderover") && a.size() == 3) {
            node(a[0], p, depth + 1);
            node(a[1], shifted(p, Position::subscript, out_, "_"), depth + 1);
            node(a[2], shifted(p, Position::superscript, out_, "^"), depth + 1);
        } else if (name == "msqrt") {
            put(out_, "\u221A", p);
            grouped(out_, part_of_children(c, p, depth), p);
        } else if (name == "mroot" && a.size() == 2) {
            put(out_, "(", p);
            node(a[1], p, depth + 1);
            put(out_, ")\u221A", p);
            grouped(out_, part(a[0], p, depth), p);
        } else if (name == "mfenced") {
            const auto open = attribute(c, "open");
            const auto close = attribute(c, "close");
            put(out_, c.attribute("open") ? open : std::string_view("("), p);
            walk(c, p, depth);
            put(out_, c.attribute("close") ? close : std::string_view(")"), p);
        } else if (name == "mtr") {
            walk(c, p, depth);
            put(out_, " ", p);
        } else if (name == "mtd" || name == "mspace") {
            walk(c, p, depth);
            put(out_, " ", p);
        } else {
            walk(c, p, depth);  // math, semantics, mrow, mi, mn, mo, mtext, mstyle, mtable ...
        }
    }

    Pieces part_of_children(const pugi::xml_node& n, Position p, int depth) {
        Pieces saved;
        std::swap(saved, out_);
        walk(n, p, depth);
        std::swap(saved, out_);
        return saved;
    }

    Pieces& out_;
};

void emit(const Pieces& pieces, const MathSink& out) {
    for (const auto& p : pieces) out(p.text, p.position);
}

}  // namespace

void omml_linear(const pugi::xml_node& math, const MathSink& out) {
    Pieces pieces;
    Omml(pieces).walk(math, Position::baseline, 0);
    emit(pieces, out);
}

void mathml_linear(const pugi::xml_node& math, const MathSink& out) {
    Pieces pieces;
    MathMl(pieces).walk(math, Position::baseline, 0);
    emit(pieces, out);
}

}  // namespace tactus::import::detail
