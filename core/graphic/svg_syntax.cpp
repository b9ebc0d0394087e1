// SPDX-License-Identifier: GPL-3.0-or-later
#include "graphic/svg_syntax.hpp"
#include "common/try.hpp"

#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

namespace tactus::graphic {

double Affine::scale() const { return std::sqrt(std::abs(a * d - b * c)); }

}  // namespace tactus::graphic

namespace tactus::graphic::svg {

namespace {

bool is_ws(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Numbers, commas and white space, as SVG's attribute grammars write them.
struct Lexer {
    std::string_view s;
    std::size_t i = 0;

    void skip_ws() {
        while (i < s.size() && is_ws(s[i])) ++i;
    }
    void skip_comma_ws() {
        skip_ws();
        if (i < s.size() && s[i] == ',') {
            ++i;
            skip_ws();
        }
    }
    [[nodiscard]] bool at_end() const { return i >= s.size(); }
    [[nodiscard]] bool at_number() const {
        if (at_end()) return false;
        const char c = s[i];
        return is_digit(c) || c == '.' || c == '-' || c == '+';
    }
    [[nodiscard]] std::string here() const { return "character " + std::to_string(i + 1); }

    // sign? (digits ('.' digits?)? | '.' digits) (('e'|'E') sign? digits)?
    Result<double> number() {
        const std::size_t begin = i;
        if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
        std::size_t digits = 0;
        while (i < s.size() && is_digit(s[i])) ++i, ++digits;
        if (i < s.size() && s[i] == '.') {
            ++i;
            while (i < s.size() && is_digit(s[i])) ++i, ++digits;
        }
        if (digits == 0) {
            i = begin;
            return fail(ErrorKind::input, "a number was expected", here());
        }
        if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
            std::size_t j = i + 1;
            if (j < s.size() && (s[j] == '-' || s[j] == '+')) ++j;
            if (j < s.size() && is_digit(s[j])) {
                while (j < s.size() && is_digit(s[j])) ++j;
                i = j;
            }
        }
        std::size_t from = begin;
        if (s[from] == '+') ++from;  // from_chars takes no '+'
        double v = 0;
        const auto r = std::from_chars(s.data() + from, s.data() + i, v);
        if (r.ec != std::errc{} || !std::isfinite(v)) {
            i = begin;
            return fail(ErrorKind::input, "the number is out of range", here());
        }
        return v;
    }
    // An arc flag: one character, 0 or 1 (it may touch the next number).
    Result<bool> flag() {
        if (i < s.size() && (s[i] == '0' || s[i] == '1')) return s[i++] == '1';
        return fail(ErrorKind::input, "an arc flag (0 or 1) was expected", here());
    }
};

constexpr double kPi = std::numbers::pi;

Point lerp(Point a, Point b, double t) { return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}; }

Segment line_to(Point from, Point to) { return {{lerp(from, to, 1.0 / 3), lerp(from, to, 2.0 / 3), to}, true}; }

// The arc of the unit circle from t1 to t2 (at most 45°) as a cubic, through `map`.
template <typename Map>
Segment unit_arc(double t1, double t2, const Map& map) {
    const double k = 4.0 / 3.0 * std::tan((t2 - t1) / 4);
    const Point p1{std::cos(t1), std::sin(t1)}, p2{std::cos(t2), std::sin(t2)};
    return {{map(Point{p1.x - k * p1.y, p1.y + k * p1.x}), map(Point{p2.x + k * p2.y, p2.y - k * p2.x}), map(p2)}, false};
}

double vector_angle(double ux, double uy, double vx, double vy) {
    return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}

}  // namespace

Result<double> parse_length_mm(std::string_view text, double percent_of) {
    Lexer lx{text};
    lx.skip_ws();
    auto v = lx.number();
    if (!v) return v;
    const std::size_t unit_at = lx.i;
    std::size_t end = text.size();
    while (end > unit_at && is_ws(text[end - 1])) --end;
    const std::string_view unit = text.substr(unit_at, end - unit_at);
    double mm_per_unit = 0;
    if (unit.empty() || unit == "px") mm_per_unit = kMmPerPx;
    else if (unit == "mm") mm_per_unit = 1;
    else if (unit == "cm") mm_per_unit = 10;
    else if (unit == "in") mm_per_unit = 25.4;
    else if (unit == "pt") mm_per_unit = 25.4 / 72;
    else if (unit == "pc") mm_per_unit = 25.4 / 6;
    else if (unit == "%" && percent_of > 0) return *v * percent_of / 100;
    else if (unit == "%") return fail(ErrorKind::input, "a percentage needs a size to be a part of, and there is none here", "");
    else
        return fail(ErrorKind::input, "unknown unit '" + std::string(unit) + "' (px, mm, cm, in, pt or pc)",
                    "character " + std::to_string(unit_at + 1));
    return *v * mm_per_unit;
}

Result<std::vector<double>> parse_numbers(std::string_view text) {
    Lexer lx{text};
    std::vector<double> out;
    lx.skip_ws();
    while (!lx.at_end()) {
        TACTUS_TRY(v, lx.number());
        out.push_back(v);
        lx.skip_comma_ws();
    }
    return out;
}

Result<Affine> parse_transform(std::string_view text) {
    Lexer lx{text};
    Affine total;
    lx.skip_ws();
    while (!lx.at_end()) {
        const std::size_t name_at = lx.i;
        while (!lx.at_end() && ((text[lx.i] >= 'a' && text[lx.i] <= 'z') || (text[lx.i] >= 'A' && text[lx.i] <= 'Z')))
            ++lx.i;
        const std::string_view name = text.substr(name_at, lx.i - name_at);
        lx.skip_ws();
        if (lx.at_end() || text[lx.i] != '(')
            return fail(ErrorKind::input, name.empty() ? "a transform (matrix, translate, scale, rotate, skewX, skewY) was expected"
                                     : "'(' was expected after '" + std::string(name) + "'",
                        lx.here());
        ++lx.i;
        lx.skip_ws();
        std::vector<double> args;
        while (!lx.at_end() && text[lx.i] != ')') {
            TACTUS_TRY(v, lx.number());
            args.push_back(v);
            lx.skip_comma_ws();
        }
        if (lx.at_end()) return fail(ErrorKind::input, "')' was expected", lx.here());
        ++lx.i;
        const auto n = args.size();
        const auto count_error = [&](const char* want) {
            return fail(ErrorKind::input, std::string(name) + " takes " + want + " numbers, not " + std::to_string(n),
                        "character " + std::to_string(name_at + 1));
        };
        Affine t;
        constexpr double kDeg = kPi / 180;
        if (name == "matrix") {
            if (n != 6) return count_error("6");
            t = {args[0], args[1], args[2], args[3], args[4], args[5]};
        } else if (name == "translate") {
            if (n != 1 && n != 2) return count_error("1 or 2");
            t.e = args[0];
            t.f = n == 2 ? args[1] : 0;
        } else if (name == "scale") {
            if (n != 1 && n != 2) return count_error("1 or 2");
            t.a = args[0];
            t.d = n == 2 ? args[1] : args[0];
        } else if (name == "rotate") {
            if (n != 1 && n != 3) return count_error("1 or 3");
            const double r = args[0] * kDeg, cs = std::cos(r), sn = std::sin(r);
            const Affine rot{cs, sn, -sn, cs, 0, 0};
            if (n == 3) {
                const Affine to{1, 0, 0, 1, args[1], args[2]}, back{1, 0, 0, 1, -args[1], -args[2]};
                t = to.then_after(rot).then_after(back);
            } else {
                t = rot;
            }
        } else if (name == "skewX") {
            if (n != 1) return count_error("1");
            t.c = std::tan(args[0] * kDeg);
        } else if (name == "skewY") {
            if (n != 1) return count_error("1");
            t.b = std::tan(args[0] * kDeg);
        } else {
            return fail(ErrorKind::input, "unknown transform '" + std::string(name) + "'", "character " + std::to_string(name_at + 1));
        }
        total = total.then_after(t);
        lx.skip_comma_ws();
    }
    return total;
}

void append_arc(std::vector<Segment>& out, Point from, double rx, double ry, double x_axis_rotation_deg,
                bool large_arc, bool sweep, Point to) {
    if (from == to) return;  // F.6.2: no arc at all
    rx = std::abs(rx);
    ry = std::abs(ry);
    if (rx == 0 || ry == 0) {
        out.push_back(line_to(from, to));
        return;
    }
    const double phi = std::fmod(x_axis_rotation_deg, 360.0) * kPi / 180;
    const double cs = std::cos(phi), sn = std::sin(phi);
    // F.6.5 step 1: the start point in the ellipse's axes, midway to the end.
    const double dx = (from.x - to.x) / 2, dy = (from.y - to.y) / 2;
    const double x1 = cs * dx + sn * dy, y1 = -sn * dx + cs * dy;
    // F.6.6: radii too small for the end points grow until they reach.
    const double lambda = x1 * x1 / (rx * rx) + y1 * y1 / (ry * ry);
    if (lambda > 1) {
        rx *= std::sqrt(lambda);
        ry *= std::sqrt(lambda);
    }
    // Step 2: the centre in those axes.
    const double num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
    const double den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
    double coef = den > 0 ? std::sqrt(std::max(0.0, num / den)) : 0;
    if (large_arc == sweep) coef = -coef;
    const double cxp = coef * rx * y1 / ry, cyp = -coef * ry * x1 / rx;
    // Step 3: the centre on the page.
    const double cx = cs * cxp - sn * cyp + (from.x + to.x) / 2, cy = sn * cxp + cs * cyp + (from.y + to.y) / 2;
    // Step 4: the start angle and the sweep.
    const double ux = (x1 - cxp) / rx, uy = (y1 - cyp) / ry, vx = (-x1 - cxp) / rx, vy = (-y1 - cyp) / ry;
    const double theta1 = vector_angle(1, 0, ux, uy);
    double delta = vector_angle(ux, uy, vx, vy);
    if (!sweep && delta > 0) delta -= 2 * kPi;
    if (sweep && delta < 0) delta += 2 * kPi;
    const auto map = [&](Point u) {
        return Point{cx + rx * cs * u.x - ry * sn * u.y, cy + rx * sn * u.x + ry * cs * u.y};
    };
    const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(delta) / (kPi / 4) - 1e-9)));
    for (int k = 0; k < pieces; ++k) {
        const double t1 = theta1 + delta * k / pieces, t2 = theta1 + delta * (k + 1) / pieces;
        out.push_back(unit_arc(t1, t2, map));
    }
    out.back().p[2] = to;  // the end point exactly, not as cos/sin left it
}

Subpath ellipse(Point c, double rx, double ry) {
    Subpath sp;
    sp.start = {c.x + rx, c.y};
    sp.closed = true;
    const auto map = [&](Point u) { return Point{c.x + rx * u.x, c.y + ry * u.y}; };
    for (int k = 0; k < 8; ++k) sp.segments.push_back(unit_arc(k * kPi / 4, (k + 1) * kPi / 4, map));
    sp.segments.back().p[2] = sp.start;
    return sp;
}

Result<std::vector<Subpath>> parse_path(std::string_view d) {
    Lexer lx{d};
    std::vector<Subpath> out;
    Point cur, start;
    Point last_control;  // the second control point of the last C/S, or the control of the last Q/T
    char last = 0;       // the last command, upper case
    char cmd = 0;
    lx.skip_ws();
    const auto need = [&](double& v) -> Result<void> {
        TACTUS_TRY(n, lx.number());
        v = n;
        lx.skip_comma_ws();
        return {};
    };
    while (!lx.at_end()) {
        const char c = d[lx.i];
        if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')) {
            cmd = c;
            ++lx.i;
            lx.skip_ws();
        } else if (!lx.at_number() || cmd == 0 || cmd == 'z' || cmd == 'Z') {
            return fail(ErrorKind::input, cmd == 0 ? "path data must start with a moveto (M or m)"
                                 : "a path command was expected",
                        lx.here());
        }
        // else: the previous command again (a moveto's extra pairs are linetos)
        const bool rel = cmd >= 'a' && cmd <= 'z';
        const char up = static_cast<char>(rel ? cmd - 'a' + 'A' : cmd);
        if (out.empty() && up != 'M') return fail(ErrorKind::input, "path data must start with a moveto (M or m)", lx.here());
        const Point base = rel ? cur : Point{};
        Result<void> r;
        switch (up) {
            case 'M': {
                Point p;
                if (r = need(p.x); r) r = need(p.y);
                if (!r) return std::unexpected(r.error());
                cur = start = {base.x + p.x, base.y + p.y};
                out.push_back({cur, {}, false});
                cmd = rel ? 'l' : 'L';  // F: "subsequent pairs are implicit lineto commands"
                break;
            }
            case 'Z': {
                if (!out.back().segments.empty() || !(cur == start)) {
                    if (!(cur == start)) out.back().segments.push_back(line_to(cur, start));
                }
                out.back().closed = true;
                cur = start;
                // A command after Z without a moveto starts a new subpath at the same point.
                out.push_back({cur, {}, false});
                break;
            }
            case 'L': case 'H': case 'V': {
                Point p = cur;
                if (up == 'L') {
                    if (r = need(p.x); r) r = need(p.y);
                    p = {base.x + p.x, base.y + p.y};
                } else if (up == 'H') {
                    r = need(p.x);
                    if (rel) p.x += cur.x;
                } else {
                    r = need(p.y);
                    if (rel) p.y += cur.y;
                }
                if (!r) return std::unexpected(r.error());
                out.back().segments.push_back(line_to(cur, p));
                cur = p;
                break;
            }
            case 'C': case 'S': {
                Point c1, c2, p;
                if (up == 'C') {
                    if (r = need(c1.x); r) r = need(c1.y);
                    if (r) c1 = {base.x + c1.x, base.y + c1.y};
                } else {
                    c1 = (last == 'C' || last == 'S') ? Point{2 * cur.x - last_control.x, 2 * cur.y - last_control.y}
                                                      : cur;
                }
                if (r) r = need(c2.x);
                if (r) r = need(c2.y);
                if (r) r = need(p.x);
                if (r) r = need(p.y);
                if (!r) return std::unexpected(r.error());
                c2 = {base.x + c2.x, base.y + c2.y};
                p = {base.x + p.x, base.y + p.y};
                out.back().segments.push_back({{c1, c2, p}, false});
                last_control = c2;
                cur = p;
                break;
            }
            case 'Q': case 'T': {
                Point q, p;
                if (up == 'Q') {
                    if (r = need(q.x); r) r = need(q.y);
                    if (r) q = {base.x + q.x, base.y + q.y};
                } else {
                    q = (last == 'Q' || last == 'T') ? Point{2 * cur.x - last_control.x, 2 * cur.y - last_control.y}
                                                     : cur;
                }
                if (r) r = need(p.x);
                if (r) r = need(p.y);
                if (!r) return std::unexpected(r.error());
                p = {base.x + p.x, base.y + p.y};
                // The cubic a quadratic is: its controls two thirds of the way to q.
                out.back().segments.push_back({{lerp(cur, q, 2.0 / 3), lerp(p, q, 2.0 / 3), p}, false});
                last_control = q;
                cur = p;
                break;
            }
            case 'A': {
                double rx = 0, ry = 0, rot = 0;
                bool large = false, sweep = false;
                Point p;
                if (r = need(rx); r) r = need(ry);
                if (r) r = need(rot);
                if (r) {
                    auto f = lx.flag();
                    if (!f) return std::unexpected(f.error());
                    large = *f;
                    lx.skip_comma_ws();
                    f = lx.flag();
                    if (!f) return std::unexpected(f.error());
                    sweep = *f;
                    lx.skip_comma_ws();
                }
                if (r) r = need(p.x);
                if (r) r = need(p.y);
                if (!r) return std::unexpected(r.error());
                p = {base.x + p.x, base.y + p.y};
                append_arc(out.back().segments, cur, rx, ry, rot, large, sweep, p);
                cur = p;
                break;
            }
            default:
                return fail(ErrorKind::input, std::string("unknown path command '") + cmd + "'", "character " + std::to_string(lx.i));
        }
        last = up;
        if (up == 'M') last = 'M';
    }
    // Subpaths that are only a moveto draw nothing.
    std::erase_if(out, [](const Subpath& s) { return s.segments.empty(); });
    return out;
}

}  // namespace tactus::graphic::svg
