// SPDX-License-Identifier: GPL-3.0-or-later
#include "motion/steps.hpp"
#include "common/try.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace tactus::motion {

std::int32_t StepAxis::steps_for(double mm) const {
    return static_cast<std::int32_t>(std::llround(mm * steps_per_mm_));
}

std::vector<double> step_times_ticks(const MoveShape& shape, std::uint32_t steps,
                                     double steps_per_mm) {
    // Step targets ascend, and so does time: walk the pieces once, and inside a
    // piece solve to a small fraction of a tick.
    std::vector<double> t;
    t.reserve(steps);
    const auto& pcs = shape.pieces;
    std::size_t i = 0;
    std::size_t last_piece = pcs.size();
    double last_tau = 0;
    for (std::uint32_t k = 1; k <= steps; ++k) {
        const double p = (k - 0.5) / steps_per_mm;
        while (i + 1 < pcs.size() && pcs[i + 1].d[0] < p) ++i;
        if (pcs.empty()) {
            t.push_back(0);
            continue;
        }
        const Piece& pc = pcs[i];
        // Newton on the piece's polynomial (position and velocity by Horner),
        // safeguarded by a bracket that halves when a step would leave it; it
        // starts from the previous step's time in the same piece.
        const auto& d = pc.d;
        const auto pos = [&](double x) {
            return d[0] + x * (d[1] + x * (d[2] / 2 + x * (d[3] / 6 + x * (d[4] / 24 + x * d[5] / 120))));
        };
        const auto vel = [&](double x) { return d[1] + x * (d[2] + x * (d[3] / 2 + x * (d[4] / 6 + x * d[5] / 24))); };
        constexpr double eps = 1e-4 / machine::kTickHz;
        double lo = i == last_piece ? last_tau : 0.0, hi = pc.dt;
        double x = lo;
        for (int it = 0; it < 200; ++it) {
            const double f = pos(x) - p;
            if (f < 0) lo = x;
            else hi = x;
            if (hi - lo <= eps) {
                x = hi;
                break;
            }
            const double v = vel(x);
            double next = v > 0 ? x - f / v : 0.5 * (lo + hi);
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (std::fabs(next - x) <= 1e-3 * eps) {
                x = next;
                break;
            }
            x = next;
        }
        last_piece = i;
        last_tau = std::min(x, lo);
        t.push_back((pc.t0 + x) * machine::kTickHz);
    }
    return t;
}

namespace {

constexpr std::int64_t kOne = std::int64_t{1} << machine::kStepFractionBits;
constexpr std::int64_t kMaxIntervalQ = (std::int64_t{0xFFFF} << machine::kStepFractionBits) | 0xFFFF;

// Firing times relative to the segment start, computed as the controller does.
template <typename Fn>
bool replay(std::int64_t iv, std::int64_t add, std::size_t n, Fn&& on_step) {
    std::int64_t now = 0;   // whole ticks
    std::int64_t frac = 0;  // fraction accumulator, < kOne
    for (std::size_t k = 0; k < n; ++k) {
        if (iv < kOne || iv > kMaxIntervalQ) return false;
        frac += iv & (kOne - 1);
        now += (iv >> machine::kStepFractionBits) + (frac >> machine::kStepFractionBits);
        frac &= kOne - 1;
        if (!on_step(k, now)) return false;
        iv += add;
    }
    return true;
}

struct Fit {
    std::int64_t interval = 0;
    std::int64_t add = 0;
};

// Can steps [first, first+n) be one segment starting at integer tick `prev`,
// with its interval and add on a grid of 2^shift Q16.16 units (the coarser the
// grid, the fewer bytes on the line: encode/stream.cpp)? The reconstruction
// x_k = k*iv + add*k(k-1)/2 is fitted by least squares to the ideal times,
// `add` quantised first (over hundreds of steps one unit of its last bit moves
// the last step by several ticks) and `iv` refitted for it; then the candidate
// is replayed with the controller's exact arithmetic. The fit aims at the ideal
// times, then half a tick later (the controller truncates to whole ticks).
bool fits(std::span<const double> t, std::span<const double> tols, std::size_t first, std::size_t n,
          std::int64_t prev, int shift, Fit& out) {
    const auto one = static_cast<double>(kOne);
    const std::int64_t grid = std::int64_t{1} << shift;
    const auto on_grid = [&](double v, std::int64_t nudge) {
        return (static_cast<std::int64_t>(std::llround(v / static_cast<double>(grid))) + nudge) * grid;
    };
    for (const double offset : {0.0, 0.5}) {
        double saa = 0, sab = 0, sbb = 0, say = 0, sby = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const double k = static_cast<double>(i + 1);
            const double a = k, b = k * (k - 1) / 2;
            const double y = t[first + i] - static_cast<double>(prev) + offset;
            saa += a * a, sab += a * b, sbb += b * b, say += a * y, sby += b * y;
        }
        const double det = saa * sbb - sab * sab;
        const double add = (n == 1 || det <= 0) ? 0.0 : (saa * sby - sab * say) / det;
        const double add_scaled = add * one;
        if (std::fabs(add_scaled) > static_cast<double>(std::numeric_limits<std::int32_t>::max())) continue;
        for (const std::int64_t add_nudge : {0, -1, 1}) {
            const std::int64_t add_q = n == 1 ? 0 : on_grid(add_scaled, add_nudge);
            if (n == 1 && add_nudge != 0) break;
            const double iv = (say - static_cast<double>(add_q) / one * sab) / saa;
            for (const std::int64_t iv_nudge : {0, -1, 1}) {
                if (shift == 0 && iv_nudge != 0) break;
                const std::int64_t iv_q = on_grid(iv * one, iv_nudge);
                const bool ok = replay(iv_q, add_q, n, [&](std::size_t k, std::int64_t now) {
                    return std::fabs(static_cast<double>(prev + now) - t[first + k]) <= tols[first + k];
                });
                if (ok) {
                    out = {iv_q, add_q};
                    return true;
                }
            }
        }
    }
    return false;
}

}  // namespace

Result<std::vector<StepSegment>> compress_steps(std::span<const double> t, double tol) {
    const std::vector<double> tols(t.size(), tol);
    return compress_steps(t, tols);
}

Result<std::vector<StepSegment>> compress_steps(std::span<const double> t,
                                                std::span<const double> tols) {
    if (tols.size() != t.size()) return fail(ErrorKind::internal, "one tolerance per step expected", "steps");
    std::vector<StepSegment> out;
    std::int64_t prev = 0;
    std::size_t first = 0;
    while (first < t.size()) {
        Fit fit;
        if (!fits(t, tols, first, 1, prev, 0, fit))
            return fail(ErrorKind::input, "step " + std::to_string(first + 1) + " comes " +
                            std::to_string(static_cast<long long>(t[first]) - prev) +
                            " timer ticks after the previous one, more than the controller's "
                            "16-bit timer can count (65535)",
                        "steps");
        // Grow the segment by doubling, then bisect the first n that no longer fits.
        const std::size_t left = std::min<std::size_t>(t.size() - first, 0xFFFF);
        std::size_t good = 1, bad = 0;
        Fit best = fit;
        for (std::size_t n = 2;; n *= 2) {
            if (n > left) {
                if (good < left && fits(t, tols, first, left, prev, 0, fit)) good = left, best = fit;
                else if (good < left) bad = left;
                break;
            }
            if (fits(t, tols, first, n, prev, 0, fit)) {
                good = n, best = fit;
            } else {
                bad = n;
                break;
            }
        }
        while (bad > good + 1) {
            const std::size_t mid = (good + bad) / 2;
            if (fits(t, tols, first, mid, prev, 0, fit)) good = mid, best = fit;
            else bad = mid;
        }
        // The coarsest grid that still fits these steps: fewer bytes to send.
        for (int shift = static_cast<int>(machine::kMaxGridShift); shift > 0; --shift)
            if (fits(t, tols, first, good, prev, shift, fit)) {
                best = fit;
                break;
            }
        out.push_back(StepSegment{static_cast<std::uint32_t>(best.interval),
                                  static_cast<std::uint16_t>(good),
                                  static_cast<std::int32_t>(best.add)});
        // The next segment starts from the integer time of this one's last step.
        std::int64_t last = 0;
        replay(best.interval, best.add, good, [&](std::size_t, std::int64_t now) {
            last = now;
            return true;
        });
        prev += last;
        first += good;
    }
    return out;
}

std::vector<std::int64_t> expand_steps(std::span<const StepSegment> segments) {
    std::vector<std::int64_t> t;
    std::int64_t start = 0;
    for (const auto& s : segments) {
        std::int64_t last = 0;
        replay(s.interval_q16, s.add_q16, s.count, [&](std::size_t, std::int64_t now) {
            t.push_back(start + now);
            last = now;
            return true;
        });
        start += last;
    }
    return t;
}

std::vector<double> step_tolerances(std::span<const double> t, double fraction) {
    std::vector<double> tol(t.size(), 1.0);
    if (fraction <= 0) return tol;
    for (std::size_t k = 0; k + 1 < t.size(); ++k) {
        // The shorter of the intervals on either side of the step: a step may
        // move by that fraction without coming near its neighbours.
        double iv = t[k + 1] - t[k];
        iv = std::min(iv, k == 0 ? t[0] : t[k] - t[k - 1]);
        tol[k] = std::max(1.0, fraction * iv);
    }
    // The last step stays within a tick: the move ends, and the settle before
    // the strike starts, exactly when planned.
    return tol;
}

Result<StepMove> encode_move(const MoveShape& shape, std::int32_t steps, double steps_per_mm,
                             double tolerance_fraction) {
    StepMove m;
    m.steps = steps;
    m.duration_s = shape.duration;
    const auto n = static_cast<std::uint32_t>(std::abs(steps));
    if (n == 0) return m;
    const auto ticks = step_times_ticks(shape, n, steps_per_mm);
    TACTUS_TRY(seg, compress_steps(ticks, step_tolerances(ticks, tolerance_fraction)));
    m.segments = std::move(seg);
    const auto fired = expand_steps(m.segments);
    const auto end = std::llround(shape.duration * machine::kTickHz);
    if (!fired.empty() && end > fired.back())
        m.settle_ticks = static_cast<std::uint32_t>(std::min<std::int64_t>(end - fired.back(), 0xFFFFFFFF));
    return m;
}

}  // namespace tactus::motion
