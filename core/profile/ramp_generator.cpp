// SPDX-License-Identifier: GPL-3.0-or-later
// The reference firmware's motion tables from a printer profile: the one copy
// of the rule (firmware/tools/gen-ramp.cpp writes the firmware's build files
// with it; the simulated controller and the host's planner call it directly).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

#include "machine/limits.hpp"
#include "profile/firmware_tables.hpp"
#include "common/try.hpp"

namespace tactus::profile {
namespace {

constexpr double kTick = machine::kTickHz;
using machine::kFastMaxTicks;
using machine::kMaxFastEntries;
using machine::kMaxRampSeconds;
using machine::kMinCruiseTicks;
using machine::kMinSlowTicks;
using machine::kStartGapTicks;

// v with `digits` decimals, or %g (digits < 0).
std::string fmt(double v, int digits) {
    char buf[64];
    if (digits < 0) std::snprintf(buf, sizeof buf, "%g", v);
    else std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}
std::string num_repr(double v) { return fmt(v, -1); }

// Python's round(): to the nearest, ties to even (the default rounding mode).
long round_even(double v) { return static_cast<long>(std::nearbyint(v)); }

// pow() through the C library, as gen-ramp.py's `tau**2` was: the compiler
// must not turn pow(x, 2) into x * x, whose rounding may differ.
double libm_pow(double x, double y) {
    static double (*volatile p)(double, double) = [](double a, double b) { return std::pow(a, b); };
    return p(x, y);
}

struct Ramp {
    std::vector<std::uint16_t> intervals;  // T[0..R]; T[R] the cruise interval
    long cruise = 0;
};

Result<Ramp> s_curve_table(const Axis& axis, const std::string& name) {
    const double spm = axis.steps_per_mm;
    const double v = axis.v_max_mm_s;
    const double a = axis.a_max_mm_s2;
    const double j = axis.j_max_mm_s3;
    if (!(spm > 0)) return fail(ErrorKind::input, "must be positive", "field " + name + ".steps_per_mm");
    if (!(v > 0)) return fail(ErrorKind::input, "must be positive", "field " + name + ".v_max_mm_s");
    if (!(a > 0)) return fail(ErrorKind::input, "must be positive", "field " + name + ".a_max_mm_s2");
    if (!(j > 0)) return fail(ErrorKind::input, "must be positive", "field " + name + ".j_max_mm_s3");
    // Peak acceleration alpha, ramp half-time dta: alpha * dta = v and the
    // peak jerk 1.5 alpha / dta within j.
    const double alpha = std::min(a, std::sqrt(v * j / 1.5));
    const double dta = v / alpha;
    const double total = 2 * dta;
    // The tables are walked from flash; a ramp this long would not fit in it
    // (and would take minutes to integrate).
    if (total > kMaxRampSeconds)
        return fail(ErrorKind::input, "the ramp from rest to " + num_repr(v) + " mm/s takes " + fmt(total, 2) +
                        " s; the firmware's tables hold ramps of at most " + num_repr(kMaxRampSeconds) +
                        " s (raise " + name + ".a_max_mm_s2 or " + name + ".j_max_mm_s3, or lower " + name +
                        ".v_max_mm_s)",
                    "field " + name + ".a_max_mm_s2");
    // Position over the ramp, integrated finely (1/64 tick). Every operation
    // is the one gen-ramp.py made, in its order: the tables are the same bits.
    const double dt = 1 / kTick / 64;
    double t = 0, x = 0, vel = 0;
    std::vector<double> times;
    double target = 0.5 / spm;
    while (t < total) {
        const double tau = t / dta;
        double acc = 0;
        if (tau <= 1) {
            acc = alpha * (3 * libm_pow(tau, 2) - 2 * libm_pow(tau, 3));
        } else {
            const double u = tau - 1;
            acc = alpha * (1 - (3 * libm_pow(u, 2) - 2 * libm_pow(u, 3)));
        }
        vel += acc * dt;
        x += vel * dt;
        t += dt;
        while (x >= target) {
            times.push_back(t * kTick);
            target += 1 / spm;
        }
    }
    Ramp r;
    r.cruise = round_even(kTick / (v * spm));
    if (times.empty() || r.cruise > 65535)
        return fail(ErrorKind::input, "a step interval exceeds the 16-bit timer",
                    "field " + name + ".v_max_mm_s or " + name + ".a_max_mm_s2");
    std::vector<long> ticks;
    ticks.reserve(times.size());
    for (double tt : times) ticks.push_back(round_even(tt));
    std::vector<long> intervals{ticks[0]};
    for (std::size_t i = 1; i < ticks.size(); ++i) intervals.push_back(ticks[i] - ticks[i - 1]);
    // Near the top the ramp's intervals must not undercut the cruise interval.
    for (auto& i : intervals) i = std::max(i, r.cruise);
    if (intervals[0] > 65535)
        return fail(ErrorKind::input, "a step interval exceeds the 16-bit timer",
                    "field " + name + ".v_max_mm_s or " + name + ".a_max_mm_s2");
    for (long i : intervals) r.intervals.push_back(static_cast<std::uint16_t>(i));
    r.intervals.push_back(static_cast<std::uint16_t>(r.cruise));
    return r;
}

struct GridValue {
    double mm;
    const char* field;
};

// The largest step count every distance is a whole multiple of.
Result<std::uint32_t> grid_steps(const std::vector<GridValue>& values, double spm, const char* axis) {
    long g = 0;
    for (const auto& [v, field] : values) {
        const double s = v * spm;
        const long r = round_even(s);
        if (std::fabs(s - static_cast<double>(r)) > 1e-6)
            return fail(ErrorKind::input, "is " + num_repr(v) + " mm, not a whole number of " + std::string(axis) + " steps (" +
                            fmt(s, 3) + "); the firmware moves on a grid of whole steps",
                        std::string("field ") + field);
        if (r != 0) g = std::gcd(g, std::labs(r));
    }
    if (g == 0) return fail(ErrorKind::input, std::string("no distance of the ") + axis + " is a whole step", "field geometry");
    if (g > 255) return fail(ErrorKind::input, "the dot grid is over 255 steps", "field geometry");
    return static_cast<std::uint32_t>(g);
}

// CRC-32 (IEEE 802.3, zlib's crc32) of the tables' text.
std::uint32_t crc32(std::string_view s) {
    static const auto table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t i = 0; i < 256; ++i) {
            std::uint32_t c = i;
            for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320U ^ (c >> 1) : c >> 1;
            t[i] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xFFFFFFFFU;
    for (const char ch : s) c = table[(c ^ static_cast<std::uint8_t>(ch)) & 0xFF] ^ (c >> 8);
    return c ^ 0xFFFFFFFFU;
}

std::string list(const std::vector<std::uint16_t>& v) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v[i]);
    return s + "]";
}

}  // namespace

std::uint32_t table_identity(const machine::FirmwareTables& t) {
    // The text Python's json.dumps gave [c_tab, f_tab, c_grid, f_grid, c_back, f_back].
    const std::string blob = "[" + list(t.carriage.intervals) + ", " + list(t.feed.intervals) + ", " +
                             std::to_string(t.carriage.grid_steps) + ", " + std::to_string(t.feed.grid_steps) +
                             ", " + std::to_string(t.carriage.backlash_steps) + ", " +
                             std::to_string(t.feed.backlash_steps) + "]";
    return crc32(blob);
}

std::uint32_t fast_from(const machine::FirmwareTables& t) {
    const auto& c = t.carriage.intervals;
    const auto it = std::find_if(c.begin(), c.end(), [](std::uint16_t v) { return v <= kFastMaxTicks; });
    return std::max<std::uint32_t>(2, static_cast<std::uint32_t>(it - c.begin()));
}

Result<machine::FirmwareTables> make_firmware_tables(const PrinterProfile& p) {
    auto rate_error = [](const Axis& a, const char* axis, long cruise, std::uint32_t min) -> Result<void> {
        if (cruise >= static_cast<long>(min)) return {};
        const std::string field = std::string(axis) + ".v_max_mm_s";
        if (std::string_view(axis) == "carriage")
            return fail(ErrorKind::input, num_repr(a.v_max_mm_s) + " mm/s x " + num_repr(a.steps_per_mm) + " steps/mm = " +
                            fmt(kTick / static_cast<double>(cruise), 0) +
                            " steps/s; the 89C52 step interrupt sustains at most " +
                            fmt(kTick / min, 0) + " steps/s",
                        "field " + field);
        return fail(ErrorKind::input, num_repr(a.v_max_mm_s) + " mm/s x " + num_repr(a.steps_per_mm) + " steps/mm exceeds the " +
                        fmt(kTick / min, 0) + " steps/s the feed's interrupt path sustains",
                    "field " + field);
    };
    // The step rates first: they need no integration.
    for (const auto& [axis, a, min] : {std::tuple{"carriage", &p.carriage, kMinCruiseTicks},
                                       std::tuple{"feed", &p.feed, kMinSlowTicks}}) {
        if (a->steps_per_mm > 0 && a->v_max_mm_s > 0)
            if (auto r = rate_error(*a, axis, round_even(kTick / (a->v_max_mm_s * a->steps_per_mm)), min); !r)
                return std::unexpected(r.error());
    }
    TACTUS_TRY(c, s_curve_table(p.carriage, "carriage"));
    TACTUS_TRY(f, s_curve_table(p.feed, "feed"));
    machine::FirmwareTables t;
    t.carriage.intervals = std::move(c.intervals);
    t.feed.intervals = std::move(f.intervals);
    // The carriage cruises on the fast path: its interval must fit one reload byte.
    if (c.cruise > static_cast<long>(kFastMaxTicks))
        return fail(ErrorKind::input, num_repr(p.carriage.v_max_mm_s) + " mm/s x " + num_repr(p.carriage.steps_per_mm) + " steps/mm = " +
                        fmt(kTick / static_cast<double>(c.cruise), 0) +
                        " steps/s; the firmware's carriage cruises at " + fmt(kTick / kFastMaxTicks, 0) +
                        " steps/s or faster",
                    "field carriage.v_max_mm_s");
    const std::uint32_t k = fast_from(t);
    const std::size_t fast = t.carriage.intervals.size() - k;
    if (fast > kMaxFastEntries)
        return fail(ErrorKind::input, "the ramp needs " + std::to_string(fast) + " table entries above 3600 steps/s; the firmware holds " +
                        std::to_string(kMaxFastEntries),
                    "field carriage.a_max_mm_s2 / carriage.j_max_mm_s3");
    const auto& g = p.geometry;
    const auto& pa = p.paper;
    auto cg = grid_steps({{g.cell_pitch_mm, "geometry.cell_pitch_mm"},
                          {g.dot_pitch_mm, "geometry.dot_pitch_mm"},
                          {g.back_offset_x_mm, "geometry.back_offset_x_mm"},
                          {p.head.concave_offset_mm, "head.concave_offset_mm"},
                          {pa.margin_left_mm, "paper.margin_left_mm"},
                          {pa.width_mm, "paper.width_mm"}},
                         p.carriage.steps_per_mm, "carriage");
    if (!cg) return std::unexpected(cg.error());
    auto fg = grid_steps({{g.line_pitch_mm, "geometry.line_pitch_mm"},
                          {g.dot_pitch_mm, "geometry.dot_pitch_mm"},
                          {g.back_offset_y_mm, "geometry.back_offset_y_mm"},
                          {pa.margin_top_mm, "paper.margin_top_mm"}},
                         p.feed.steps_per_mm, "feed");
    if (!fg) return std::unexpected(fg.error());
    t.carriage.grid_steps = *cg;
    t.feed.grid_steps = *fg;
    t.carriage.backlash_steps = static_cast<std::uint32_t>(round_even(p.carriage.backlash_mm * p.carriage.steps_per_mm));
    t.feed.backlash_steps = static_cast<std::uint32_t>(round_even(p.feed.backlash_mm * p.feed.steps_per_mm));
    t.start_gap_ticks = kStartGapTicks;
    t.table_id = table_identity(t);
    return t;
}

}  // namespace tactus::profile
