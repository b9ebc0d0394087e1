// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/steps.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace tactus::plan {

std::int32_t StepAxis::steps_for(double mm) const {
    return static_cast<std::int32_t>(std::llround(mm * steps_per_mm_));
}

std::vector<double> step_times_ticks(const MoveShape& shape, std::uint32_t steps,
                                     double steps_per_mm) {
    // Step targets ascend, and so does time: walk the pieces once, and inside a
    // piece bisect only to a small fraction of a tick.
    std::vector<double> t;
    t.reserve(steps);
    const auto& pcs = shape.pieces;
    std::size_t i = 0;
    for (std::uint32_t k = 1; k <= steps; ++k) {
        const double p = (k - 0.5) / steps_per_mm;
        while (i + 1 < pcs.size() && pcs[i + 1].d[0] < p) ++i;
        if (pcs.empty()) {
            t.push_back(0);
            continue;
        }
        const Piece& pc = pcs[i];
        double lo = 0, hi = pc.dt;
        while (hi - lo > 1e-4 / kTickHz) {
            const double mid = 0.5 * (lo + hi);
            if (advance_derivs(pc.d, mid)[0] < p) lo = mid;
            else hi = mid;
        }
        t.push_back((pc.t0 + hi) * kTickHz);
    }
    return t;
}

namespace {

constexpr std::int64_t kMaxInterval = std::numeric_limits<std::uint16_t>::max();

struct Fit {
    std::int64_t interval = 0;
    std::int64_t add = 0;
};

// Can steps [first, first+n) be one segment starting after `prev`? Tries every
// integer interval allowed by the first step and every integer add allowed by
// the last; the rest are checked one by one. Exhaustive over integers, so
// feasibility is monotone in n (more steps only add constraints).
bool fits(std::span<const double> t, std::size_t first, std::size_t n, std::int64_t prev,
          double tol, Fit& out) {
    const double t1 = t[first] - static_cast<double>(prev);
    const auto i_lo = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(t1 - tol)));
    const auto i_hi = std::min<std::int64_t>(kMaxInterval, static_cast<std::int64_t>(std::floor(t1 + tol)));
    const double tn = t[first + n - 1] - static_cast<double>(prev);
    const double tri = static_cast<double>(n) * static_cast<double>(n - 1) / 2.0;
    for (std::int64_t iv = i_lo; iv <= i_hi; ++iv) {
        std::int64_t a_lo = 0, a_hi = 0;
        if (n > 1) {
            const double base = static_cast<double>(n) * static_cast<double>(iv);
            a_lo = static_cast<std::int64_t>(std::ceil((tn - tol - base) / tri));
            a_hi = static_cast<std::int64_t>(std::floor((tn + tol - base) / tri));
            a_lo = std::max<std::int64_t>(a_lo, std::numeric_limits<std::int16_t>::min());
            a_hi = std::min<std::int64_t>(a_hi, std::numeric_limits<std::int16_t>::max());
        }
        for (std::int64_t add = a_lo; add <= a_hi; ++add) {
            // Every interval of the segment must be a positive 16-bit count.
            const std::int64_t last_iv = iv + add * static_cast<std::int64_t>(n - 1);
            if (last_iv < 1 || last_iv > kMaxInterval) continue;
            bool ok = true;
            std::int64_t r = prev, step_iv = iv;
            for (std::size_t k = 0; k < n && ok; ++k) {
                r += step_iv;
                step_iv += add;
                ok = std::fabs(static_cast<double>(r) - t[first + k]) <= tol;
            }
            if (ok) {
                out = {iv, add};
                return true;
            }
        }
    }
    return false;
}

}  // namespace

Result<std::vector<StepSegment>> compress_steps(std::span<const double> t, double tol) {
    std::vector<StepSegment> out;
    std::int64_t prev = 0;
    std::size_t first = 0;
    while (first < t.size()) {
        Fit fit;
        if (!fits(t, first, 1, prev, tol, fit))
            return fail("step " + std::to_string(first + 1) + " comes " +
                            std::to_string(static_cast<long long>(t[first]) - prev) +
                            " timer ticks after the previous one, more than the controller's "
                            "16-bit timer can count (65535)",
                        "steps");
        // Grow the segment by doubling, then bisect the first n that no longer fits.
        const std::size_t left = std::min<std::size_t>(t.size() - first, kMaxInterval);
        std::size_t good = 1, bad = 0;
        Fit best = fit;
        for (std::size_t n = 2;; n *= 2) {
            if (n > left) {
                if (good < left && fits(t, first, left, prev, tol, fit)) good = left, best = fit;
                else if (good < left) bad = left;
                break;
            }
            if (fits(t, first, n, prev, tol, fit)) {
                good = n, best = fit;
            } else {
                bad = n;
                break;
            }
        }
        while (bad > good + 1) {
            const std::size_t mid = (good + bad) / 2;
            if (fits(t, first, mid, prev, tol, fit)) good = mid, best = fit;
            else bad = mid;
        }
        out.push_back(StepSegment{static_cast<std::uint16_t>(best.interval),
                                  static_cast<std::uint16_t>(good),
                                  static_cast<std::int16_t>(best.add)});
        // Continue from the reconstructed (integer) time so errors never accumulate.
        const auto n = static_cast<std::int64_t>(good);
        prev += n * best.interval + best.add * n * (n - 1) / 2;
        first += good;
    }
    return out;
}

std::vector<std::int64_t> expand_steps(std::span<const StepSegment> segments) {
    std::vector<std::int64_t> t;
    std::int64_t now = 0;
    for (const auto& s : segments) {
        std::int64_t iv = s.interval;
        for (std::uint16_t k = 0; k < s.count; ++k) {
            now += iv;
            t.push_back(now);
            iv += s.add;
        }
    }
    return t;
}

Result<StepMove> encode_move(const MoveShape& shape, std::int32_t steps, double steps_per_mm) {
    StepMove m;
    m.steps = steps;
    m.duration_s = shape.duration;
    const auto n = static_cast<std::uint32_t>(std::abs(steps));
    if (n == 0) return m;
    const auto ticks = step_times_ticks(shape, n, steps_per_mm);
    auto seg = compress_steps(ticks);
    if (!seg) return std::unexpected(seg.error());
    m.segments = std::move(*seg);
    return m;
}

}  // namespace tactus::plan
