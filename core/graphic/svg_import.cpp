// SPDX-License-Identifier: GPL-3.0-or-later
#include "graphic/svg_import.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "common/file_io.hpp"
#include "common/nesting.hpp"
#include "graphic/svg_syntax.hpp"
#include "common/try.hpp"

namespace tactus::graphic {

namespace {

using svg::kMmPerPx;

// More path segments than this in one file is not a drawing a finger can read;
// refusing it keeps a hostile file from taking the memory of millions.
constexpr std::size_t kMaxSegments = 200000;

std::string trim(std::string_view s) {
    const auto b = s.find_first_not_of(" \t\r\n\f");
    if (b == std::string_view::npos) return {};
    const auto e = s.find_last_not_of(" \t\r\n\f");
    return std::string(s.substr(b, e - b + 1));
}

std::string lower(std::string s) {
    for (char& c : s)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return s;
}

// The element's name without a namespace prefix (svg:path is path).
std::string_view local_name(const pugi::xml_node& n) {
    const std::string_view name = n.name();
    const auto colon = name.find(':');
    return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

// What a child inherits from its ancestors (SVG's inherited properties) and
// what each element carries itself.
struct Style {
    std::string fill = "black";
    std::string stroke = "none";
    std::string stroke_width = "1";
    std::string dasharray = "none";
    std::string fill_rule = "nonzero";
    std::string font_size = "16";
    std::string display = "inline";      // not inherited, but `none` hides the subtree
    std::string visibility = "visible";
    std::string fill_opacity = "1";
    std::string stroke_opacity = "1";
};

class Reader {
public:
    explicit Reader(std::string_view bytes) : bytes_(bytes) {}

    Result<Drawing> read();

private:
    int line_of(const pugi::xml_node& n) const {
        const auto off = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, n.offset_debug()));
        return 1 + static_cast<int>(std::count(bytes_.begin(), bytes_.begin() + static_cast<std::ptrdiff_t>(std::min(off, bytes_.size())), '\n'));
    }
    std::string where(const pugi::xml_node& n) const { return "line " + std::to_string(line_of(n)); }
    std::string where(const pugi::xml_node& n, std::string_view attribute, const std::string& inner) const {
        return where(n) + ": attribute " + std::string(attribute) + (inner.empty() ? "" : ", " + inner);
    }
    void warn(const pugi::xml_node& n, const std::string& why) { drawing_.warnings.push_back(where(n) + ": " + why); }

    Result<void> walk(const pugi::xml_node& n, Style style, const Affine& ctm, int depth);
    Result<void> apply_style(const pugi::xml_node& n, Style& s);
    Result<double> number_attr(const pugi::xml_node& n, const char* name, double fallback);
    Result<void> add_shape(const pugi::xml_node& n, const Style& s, const Affine& ctm, std::vector<Subpath> paths,
                           bool can_fill);
    Result<void> add_text(const pugi::xml_node& n, const Style& s, const Affine& ctm);

    std::string_view bytes_;
    Drawing drawing_;
    std::size_t segments_ = 0;
};

Result<double> Reader::number_attr(const pugi::xml_node& n, const char* name, double fallback) {
    const auto a = n.attribute(name);
    if (!a) return fallback;
    auto v = svg::parse_length_mm(a.value());
    if (!v) return fail(ErrorKind::input, v.error().message, where(n, name, v.error().where));
    return *v / kMmPerPx;  // in user units: a unit on a coordinate is rare and means px-relative
}

Result<void> Reader::apply_style(const pugi::xml_node& n, Style& s) {
    // Presentation attributes first, then the style attribute's declarations over them.
    const std::pair<const char*, std::string*> props[] = {
        {"fill", &s.fill},           {"stroke", &s.stroke},         {"stroke-width", &s.stroke_width},
        {"stroke-dasharray", &s.dasharray}, {"fill-rule", &s.fill_rule}, {"font-size", &s.font_size},
        {"display", &s.display},     {"visibility", &s.visibility}, {"fill-opacity", &s.fill_opacity},
        {"stroke-opacity", &s.stroke_opacity}};
    s.display = "inline";
    for (const auto& [name, field] : props)
        if (const auto a = n.attribute(name)) *field = trim(a.value());
    if (const auto st = n.attribute("style")) {
        const std::string_view css = st.value();
        std::size_t i = 0;
        while (i < css.size()) {
            auto semi = css.find(';', i);
            if (semi == std::string_view::npos) semi = css.size();
            const auto decl = css.substr(i, semi - i);
            i = semi + 1;
            const auto colon = decl.find(':');
            if (colon == std::string_view::npos) {
                if (!trim(decl).empty()) warn(n, "style declaration '" + trim(decl) + "' has no ':' and is ignored");
                continue;
            }
            const auto key = lower(trim(decl.substr(0, colon)));
            auto value = trim(decl.substr(colon + 1));
            if (const auto imp = value.find("!important"); imp != std::string::npos) value = trim(value.substr(0, imp));
            bool known = false;
            for (const auto& [name, field] : props)
                if (key == name) {
                    *field = value;
                    known = true;
                }
            (void)known;  // colours, fonts and the like change nothing a finger feels
        }
    }
    return {};
}

bool paint_is_none(const std::string& paint, const std::string& opacity) {
    const auto p = lower(paint);
    if (p.empty() || p == "none" || p == "transparent") return true;
    if (!opacity.empty()) {
        char* end = nullptr;
        const double o = std::strtod(opacity.c_str(), &end);
        if (end != opacity.c_str() && o <= 0) return true;
    }
    return false;
}

// White paint is the paper's colour: nothing to feel.
bool paint_is_white(const std::string& paint) {
    const auto p = lower(paint);
    return p == "white" || p == "#fff" || p == "#ffffff" || p == "rgb(255,255,255)" || p == "rgb(255, 255, 255)";
}

Result<void> Reader::add_shape(const pugi::xml_node& n, const Style& s, const Affine& ctm, std::vector<Subpath> paths,
                               bool can_fill) {
    Shape shape;
    shape.element = std::string(local_name(n));
    shape.line = line_of(n);
    shape.stroked = !paint_is_none(s.stroke, s.stroke_opacity);
    const double scale = ctm.scale();
    if (shape.stroked) {
        auto w = svg::parse_length_mm(s.stroke_width);
        if (!w) return fail(ErrorKind::input, w.error().message, where(n, "stroke-width", w.error().where));
        shape.stroke_width_mm = *w / kMmPerPx * scale;
        if (shape.stroke_width_mm <= 0) shape.stroked = false;
    }
    if (shape.stroked && lower(s.dasharray) != "none" && !s.dasharray.empty()) {
        auto d = svg::parse_numbers(s.dasharray);
        if (!d) return fail(ErrorKind::input, d.error().message, where(n, "stroke-dasharray", d.error().where));
        double sum = 0, longest_dash = 0;
        bool negative = false;
        for (std::size_t i = 0; i < d->size(); ++i) {
            negative = negative || (*d)[i] < 0;
            sum += (*d)[i];
            // An odd count repeats the list, so every entry is a dash once.
            if (i % 2 == 0 || d->size() % 2 == 1) longest_dash = std::max(longest_dash, (*d)[i]);
        }
        if (negative) return fail(ErrorKind::input, "a dash length is negative", where(n, "stroke-dasharray", ""));
        if (sum > 0) {
            // Dashes no longer than the stroke is wide (or half a millimetre) look like dots.
            const double dash_mm = longest_dash * scale;
            shape.style = dash_mm <= std::max(shape.stroke_width_mm, 0.5) ? LineStyle::dotted : LineStyle::dashed;
        }
    }
    shape.filled = can_fill && !paint_is_none(s.fill, s.fill_opacity) && !paint_is_white(s.fill);
    shape.even_odd = lower(s.fill_rule) == "evenodd";
    shape.fill_paint = lower(s.fill);
    if (!shape.stroked && !shape.filled) return {};
    for (auto& sp : paths) {
        sp.start = ctm.apply(sp.start);
        for (auto& seg : sp.segments)
            for (auto& p : seg.p) p = ctm.apply(p);
        segments_ += sp.segments.size();
    }
    if (segments_ > kMaxSegments)
        return fail(ErrorKind::input,
                    "the drawing has more than " + std::to_string(kMaxSegments) +
                        " path segments, far more than a tactile graphic can show: simplify it",
                    where(n));
    shape.subpaths = std::move(paths);
    drawing_.shapes.push_back(std::move(shape));
    return {};
}

void append_text(const pugi::xml_node& n, std::string& out) {
    for (const auto& c : n.children()) {
        if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) out += c.value();
        else if (c.type() == pugi::node_element && local_name(c) != "title" && local_name(c) != "desc") append_text(c, out);
    }
}

Result<void> Reader::add_text(const pugi::xml_node& n, const Style& s, const Affine& ctm) {
    Label label;
    label.line = line_of(n);
    std::string raw;
    append_text(n, raw);
    // White space collapsed, as SVG's default xml:space does.
    bool space = true;
    for (char c : raw) {
        const bool ws = c == ' ' || c == '\t' || c == '\n' || c == '\r';
        if (ws) {
            if (!space) label.text += ' ';
            space = true;
        } else {
            label.text += c;
            space = false;
        }
    }
    while (!label.text.empty() && label.text.back() == ' ') label.text.pop_back();
    if (label.text.empty()) return {};
    Point at;
    for (const auto& [name, field] : {std::pair{"x", &at.x}, std::pair{"y", &at.y}}) {
        const auto a = n.attribute(name);
        if (!a) continue;
        auto v = svg::parse_numbers(a.value());
        if (!v) return fail(ErrorKind::input, v.error().message, where(n, name, v.error().where));
        if (!v->empty()) *field = v->front();
    }
    auto fs = svg::parse_length_mm(s.font_size);
    label.font_size_mm = fs ? *fs / kMmPerPx * ctm.scale() : 0;
    label.anchor = ctm.apply(at);
    drawing_.labels.push_back(std::move(label));
    return {};
}

Result<void> Reader::walk(const pugi::xml_node& n, Style style, const Affine& parent, int depth) {
    if (depth > max_nesting_depth) return std::unexpected(too_deeply_nested("SVG elements", where(n)));
    if (auto r = apply_style(n, style); !r) return r;
    if (style.display == "none") return {};
    Affine ctm = parent;
    if (const auto t = n.attribute("transform")) {
        auto a = svg::parse_transform(t.value());
        if (!a) return fail(ErrorKind::input, a.error().message, where(n, "transform", a.error().where));
        ctm = parent.then_after(*a);
    }
    const bool visible = style.visibility != "hidden" && style.visibility != "collapse";
    for (const auto& c : n.children()) {
        if (c.type() != pugi::node_element) continue;
        const auto name = local_name(c);
        if (name == "g" || name == "a" || name == "switch") {
            if (auto r = walk(c, style, ctm, depth + 1); !r) return r;
            continue;
        }
        if (name == "title" || name == "desc") {
            if (n == n.root().first_child() || depth == 0) {
                std::string text;
                append_text(c, text);
                (name == "title" ? drawing_.title : drawing_.description) = trim(text);
            }
            continue;
        }
        // Not drawn by SVG itself: definitions are drawn only where <use>d.
        if (name == "defs" || name == "metadata" || name == "symbol" || name == "clipPath" || name == "mask" ||
            name == "marker" || name == "linearGradient" || name == "radialGradient" || name == "pattern" ||
            name == "filter" || name == "script" || name == "sodipodi:namedview" || name == "namedview")
            continue;
        Style s = style;
        if (auto r = apply_style(c, s); !r) return r;
        if (s.display == "none") continue;
        Affine m = ctm;
        if (const auto t = c.attribute("transform")) {
            auto a = svg::parse_transform(t.value());
            if (!a) return fail(ErrorKind::input, a.error().message, where(c, "transform", a.error().where));
            m = ctm.then_after(*a);
        }
        const bool shown = s.visibility != "hidden" && s.visibility != "collapse";
        const auto num = [&](const char* attr, double fallback = 0) { return number_attr(c, attr, fallback); };
        std::vector<Subpath> paths;
        bool can_fill = true;
        if (name == "line") {
            auto x1 = num("x1"), y1 = num("y1"), x2 = num("x2"), y2 = num("y2");
            for (auto* v : {&x1, &y1, &x2, &y2})
                if (!*v) return std::unexpected(v->error());
            Subpath sp{{*x1, *y1}, {}, false};
            std::vector<Segment> seg;
            svg::append_arc(seg, sp.start, 0, 0, 0, false, false, {*x2, *y2});
            sp.segments = std::move(seg);
            if (!sp.segments.empty()) paths.push_back(std::move(sp));
            can_fill = false;
        } else if (name == "polyline" || name == "polygon") {
            auto pts = svg::parse_numbers(c.attribute("points").value());
            if (!pts) return fail(ErrorKind::input, pts.error().message, where(c, "points", pts.error().where));
            if (pts->size() % 2 == 1) {
                warn(c, "the points list has an odd count of numbers; the last one is left out");
                pts->pop_back();
            }
            if (pts->size() >= 4) {
                Subpath sp{{(*pts)[0], (*pts)[1]}, {}, name == "polygon"};
                Point cur = sp.start;
                for (std::size_t i = 2; i + 1 < pts->size(); i += 2) {
                    const Point p{(*pts)[i], (*pts)[i + 1]};
                    svg::append_arc(sp.segments, cur, 0, 0, 0, false, false, p);
                    cur = p;
                }
                if (sp.closed && !(cur == sp.start)) svg::append_arc(sp.segments, cur, 0, 0, 0, false, false, sp.start);
                if (!sp.segments.empty()) paths.push_back(std::move(sp));
            }
        } else if (name == "rect") {
            auto x = num("x"), y = num("y"), w = num("width"), h = num("height"), rx = num("rx", -1), ry = num("ry", -1);
            for (auto* v : {&x, &y, &w, &h, &rx, &ry})
                if (!*v) return std::unexpected(v->error());
            if (*w < 0 || *h < 0) return fail(ErrorKind::input, "a rectangle's width and height cannot be negative", where(c));
            double r1 = *rx, r2 = *ry;
            if (r1 < 0 && r2 < 0) r1 = r2 = 0;
            else if (r1 < 0) r1 = r2;
            else if (r2 < 0) r2 = r1;
            r1 = std::min(r1, *w / 2);
            r2 = std::min(r2, *h / 2);
            if (*w > 0 && *h > 0) {
                const double x0 = *x, y0 = *y, x1 = *x + *w, y1 = *y + *h;
                Subpath sp{{x0 + r1, y0}, {}, true};
                auto& sg = sp.segments;
                const auto to = [&](Point from, Point p) { svg::append_arc(sg, from, 0, 0, 0, false, false, p); };
                const auto arc = [&](Point from, Point p) { svg::append_arc(sg, from, r1, r2, 0, false, true, p); };
                to({x0 + r1, y0}, {x1 - r1, y0});
                arc({x1 - r1, y0}, {x1, y0 + r2});
                to({x1, y0 + r2}, {x1, y1 - r2});
                arc({x1, y1 - r2}, {x1 - r1, y1});
                to({x1 - r1, y1}, {x0 + r1, y1});
                arc({x0 + r1, y1}, {x0, y1 - r2});
                to({x0, y1 - r2}, {x0, y0 + r2});
                arc({x0, y0 + r2}, {x0 + r1, y0});
                paths.push_back(std::move(sp));
            }
        } else if (name == "circle" || name == "ellipse") {
            auto cx = num("cx"), cy = num("cy");
            auto rx = name == "circle" ? num("r") : num("rx", -1);
            auto ry = name == "circle" ? num("r") : num("ry", -1);
            for (auto* v : {&cx, &cy, &rx, &ry})
                if (!*v) return std::unexpected(v->error());
            double a = *rx, b = *ry;
            if (a < 0 && b >= 0) a = b;  // SVG 2: an auto radius takes the other
            if (b < 0 && a >= 0) b = a;
            if (a > 0 && b > 0) paths.push_back(svg::ellipse({*cx, *cy}, a, b));
        } else if (name == "path") {
            auto p = svg::parse_path(c.attribute("d").value());
            if (!p) return fail(ErrorKind::input, p.error().message, where(c, "d", p.error().where));
            paths = std::move(*p);
        } else if (name == "text") {
            if (visible && shown)
                if (auto r = add_text(c, s, m); !r) return r;
            continue;
        } else if (name == "svg") {
            warn(c, "a nested <svg> is not embossed (only the outer drawing is read)");
            continue;
        } else {
            warn(c, "<" + std::string(name) + "> is not embossed (Tactus reads lines, polylines, polygons, "
                    "rectangles, circles, ellipses, paths and text)");
            continue;
        }
        if (visible && shown)
            if (auto r = add_shape(c, s, m, std::move(paths), can_fill); !r) return r;
    }
    (void)visible;
    return {};
}

Result<Drawing> Reader::read() {
    pugi::xml_document doc;
    const auto parsed = doc.load_buffer(bytes_.data(), bytes_.size(), pugi::parse_default | pugi::parse_ws_pcdata);
    if (!parsed) {
        const auto off = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, parsed.offset));
        const int line = 1 + static_cast<int>(std::count(bytes_.begin(), bytes_.begin() + static_cast<std::ptrdiff_t>(std::min(off, bytes_.size())), '\n'));
        return fail(ErrorKind::input, std::string("not well-formed XML: ") + parsed.description(),
                    "line " + std::to_string(line));
    }
    const auto root = doc.document_element();
    if (!root || local_name(root) != "svg")
        return fail(ErrorKind::input,
                    "not an SVG drawing: the root element is <" + std::string(root ? root.name() : "") + ">, not <svg>",
                    root ? where(root) : "line 1");
    // The viewport in mm and the map from user units to it (SVG 1.1 §7.7, xMidYMid meet).
    std::vector<double> vb;
    if (const auto a = root.attribute("viewBox")) {
        auto v = svg::parse_numbers(a.value());
        if (!v) return fail(ErrorKind::input, v.error().message, where(root, "viewBox", v.error().where));
        if (v->size() != 4) return fail(ErrorKind::input, "a viewBox is four numbers: min-x min-y width height", where(root, "viewBox", ""));
        if ((*v)[2] <= 0 || (*v)[3] <= 0) return fail(ErrorKind::input, "a viewBox's width and height must be positive", where(root, "viewBox", ""));
        vb = *v;
    }
    double w = 0, h = 0;
    for (const auto& [name, out, from_vb] : {std::tuple{"width", &w, 2}, std::tuple{"height", &h, 3}}) {
        const auto a = root.attribute(name);
        const std::string value = a ? trim(a.value()) : std::string{};
        if (value.empty() || value == "auto" || value == "100%") {
            if (vb.empty())
                return fail(ErrorKind::input, "the drawing has no size: give <svg> a width and height, or a viewBox",
                            where(root));
            *out = vb[static_cast<std::size_t>(from_vb)] * kMmPerPx;
            continue;
        }
        auto v = svg::parse_length_mm(value);
        if (!v) return fail(ErrorKind::input, v.error().message, where(root, name, v.error().where));
        if (*v <= 0) return fail(ErrorKind::input, "must be positive", where(root, name, ""));
        *out = *v;
    }
    drawing_.width_mm = w;
    drawing_.height_mm = h;
    Affine ctm{kMmPerPx, 0, 0, kMmPerPx, 0, 0};
    if (!vb.empty()) {
        const double s = std::min(w / vb[2], h / vb[3]);
        const double tx = (w - vb[2] * s) / 2 - vb[0] * s, ty = (h - vb[3] * s) / 2 - vb[1] * s;
        ctm = {s, 0, 0, s, tx, ty};
        if (const auto par = root.attribute("preserveAspectRatio"); par && trim(par.value()) != "xMidYMid meet" &&
                                                                    trim(par.value()) != "xMidYMid")
            warn(root, "preserveAspectRatio=\"" + trim(par.value()) + "\" is read as xMidYMid meet");
    }
    TACTUS_TRY_VOID(walk(root, Style{}, ctm, 0));
    return std::move(drawing_);
}

}  // namespace

Result<Drawing> read_svg(std::string_view bytes) { return Reader(bytes).read(); }

Result<Drawing> load_svg(const std::filesystem::path& path) {
    TACTUS_TRY(bytes, read_file(path, std::size_t{64} << 20));
    auto d = read_svg(bytes);
    if (!d) return std::unexpected(located(d.error(), path.string()));
    return d;
}

bool is_svg_path(const std::filesystem::path& path) { return lower(path.extension().string()) == ".svg"; }

}  // namespace tactus::graphic
