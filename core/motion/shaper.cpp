// SPDX-License-Identifier: GPL-3.0-or-later
#include "motion/shaper.hpp"

#include <algorithm>
#include <cmath>

namespace tactus::motion {

Shaper design_shaper(profile::ShaperKind kind, double frequency_hz, double zeta) {
    using profile::ShaperKind;
    Shaper s;
    s.kind = kind;
    const double df = std::sqrt(1.0 - zeta * zeta);
    const double td = 1.0 / (frequency_hz * df);  // damped period
    const double pi = std::acos(-1.0);
    std::vector<double> a, t;
    switch (kind) {
        case ShaperKind::none:
        case ShaperKind::automatic:
            s.kind = ShaperKind::none;
            return s;
        case ShaperKind::zv: {
            const double k = std::exp(-zeta * pi / df);
            a = {1.0, k};
            t = {0.0, 0.5 * td};
            break;
        }
        case ShaperKind::mzv: {
            const double k = std::exp(-0.75 * zeta * pi / df);
            const double a1 = 1.0 - 1.0 / std::sqrt(2.0);
            a = {a1, (std::sqrt(2.0) - 1.0) * k, a1 * k * k};
            t = {0.0, 0.375 * td, 0.75 * td};
            break;
        }
        case ShaperKind::zvd: {
            const double k = std::exp(-zeta * pi / df);
            a = {1.0, 2.0 * k, k * k};
            t = {0.0, 0.5 * td, td};
            break;
        }
        case ShaperKind::ei: {
            const double v = kEiVibrationTolerance;
            const double k = std::exp(-zeta * pi / df);
            const double a1 = 0.25 * (1.0 + v);
            a = {a1, 0.5 * (1.0 - v) * k, a1 * k * k};
            t = {0.0, 0.5 * td, td};
            break;
        }
    }
    double sum = 0;
    for (double x : a) sum += x;
    s.impulses.clear();
    for (std::size_t i = 0; i < a.size(); ++i) s.impulses.push_back({t[i], a[i] / sum});
    return s;
}

MoveShape shape_move(const MoveShape& base, const Shaper& shaper) {
    if (shaper.impulses.size() <= 1) return base;
    // Every breakpoint of every shifted copy starts a piece of the sum; within a
    // piece each copy is one polynomial, so the sum is exact.
    std::vector<double> cuts;
    for (const auto& imp : shaper.impulses) {
        for (const auto& p : base.pieces) cuts.push_back(imp.t + p.t0);
        cuts.push_back(imp.t + base.duration);
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end(),
                           [](double x, double y) { return std::fabs(x - y) < 1e-12; }),
               cuts.end());
    MoveShape m;
    m.distance = base.distance;
    m.duration = base.duration + shaper.duration();
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double t0 = cuts[i];
        const double mid = 0.5 * (cuts[i] + cuts[i + 1]);
        Derivs sum{};
        for (const auto& imp : shaper.impulses) {
            // Evaluate the copy at t0 with the polynomial of the piece that holds `mid`,
            // so a discontinuous derivative is taken from the right side.
            const double local = mid - imp.t;
            Derivs d{};
            if (local >= base.duration) {
                d[0] = base.distance;
            } else if (local > 0) {
                auto it = std::upper_bound(base.pieces.begin(), base.pieces.end(), local,
                                           [](double x, const Piece& p) { return x < p.t0; });
                const Piece& p = *(it - 1);
                d = advance_derivs(p.d, t0 - imp.t - p.t0);
            }
            for (std::size_t k = 0; k < 6; ++k) sum[k] += imp.a * d[k];
        }
        m.pieces.push_back(Piece{t0, cuts[i + 1] - t0, sum});
    }
    return m;
}

}  // namespace tactus::motion
