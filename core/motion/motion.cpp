// SPDX-License-Identifier: GPL-3.0-or-later
#include "motion/motion.hpp"

#include <algorithm>
#include <cmath>

namespace tactus::motion {
namespace {

// Builds a move from a list of (duration, crackle-or-lower-order-input) pieces by
// integrating forward exactly from rest; `kick` sets a derivative at a piece start
// (used for the discontinuous acceleration of the trapezoid and jerk of the 7-segment move).
struct Builder {
    MoveShape m;
    Derivs cur{};
    double t = 0;
    // A piece where derivative `order` (2 = accel, 3 = jerk) is held at `value`
    // and the higher ones are zero, or, for the S-curve, an explicit start state.
    void hold(double dt, int order, double value) {
        if (dt <= 0) return;
        for (int k = order; k < 6; ++k) cur[static_cast<std::size_t>(k)] = 0;
        cur[static_cast<std::size_t>(order)] = value;
        push(dt);
    }
    void push(double dt) {
        m.pieces.push_back(Piece{t, dt, cur});
        cur = advance_derivs(cur, dt);
        t += dt;
    }
    MoveShape done(double distance) {
        m.duration = t;
        m.distance = distance;
        return std::move(m);
    }
};

}  // namespace

Derivs advance_derivs(const Derivs& d, double tau) {
    Derivs r{};
    for (std::size_t k = 0; k < 6; ++k) {
        double term = 1, sum = 0;
        for (std::size_t i = k; i < 6; ++i) {
            sum += d[i] * term;
            term *= tau / static_cast<double>(i - k + 1);
        }
        r[k] = sum;
    }
    return r;
}

Derivs MoveShape::at(double t) const {
    if (pieces.empty() || t >= duration) return Derivs{distance, 0, 0, 0, 0, 0};
    if (t <= 0) return Derivs{};
    // Pieces are contiguous and sorted: binary search for the one holding t.
    auto it = std::upper_bound(pieces.begin(), pieces.end(), t,
                               [](double x, const Piece& p) { return x < p.t0; });
    const Piece& p = *(it - 1);
    return advance_derivs(p.d, t - p.t0);
}

double MoveShape::time_at(double p) const {
    if (p <= 0) return 0;
    if (p >= distance) {
        // The last instant the position is still below the end (end of motion).
        return duration;
    }
    // Find the piece whose end position passes p, then bisect inside it.
    std::size_t i = 0;
    for (; i < pieces.size(); ++i) {
        const double end = i + 1 < pieces.size() ? pieces[i + 1].d[0] : distance;
        if (end >= p) break;
    }
    if (i == pieces.size()) return duration;
    const Piece& pc = pieces[i];
    double lo = 0, hi = pc.dt;
    for (int it = 0; it < 60 && hi - lo > 1e-12; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (advance_derivs(pc.d, mid)[0] < p) lo = mid;
        else hi = mid;
    }
    return pc.t0 + hi;
}

MoveShape trapezoid_move(double distance, const Limits& lim) {
    Builder b;
    if (distance <= 0) return b.done(0);
    double ta = lim.v / lim.a;
    double vp = lim.v;
    if (distance < vp * ta) {  // never reaches v: a triangle
        ta = std::sqrt(distance / lim.a);
        vp = lim.a * ta;
    }
    const double tc = (distance - vp * ta) / vp;
    b.hold(ta, 2, lim.a);
    b.hold(tc, 2, 0);
    b.hold(ta, 2, -lim.a);
    return b.done(distance);
}

MoveShape scurve_move(double alpha_d, double dt_a, double dt_c) {
    Builder b;
    // Acceleration alpha_d * s(tau), s = 3u^2 - 2u^3 rising, then 1 - s falling:
    // a cubic in time, so its derivatives at the piece start fix it exactly.
    const double c = 12.0 * alpha_d / (dt_a * dt_a * dt_a);  // |a'''| of the smoothstep
    auto rise = [&](double sign) {  // a goes 0 -> sign*alpha_d
        b.cur[2] = 0, b.cur[3] = 0, b.cur[4] = sign * 6.0 * alpha_d / (dt_a * dt_a), b.cur[5] = -sign * c;
        b.push(dt_a);
    };
    auto fall = [&](double sign) {  // a goes sign*alpha_d -> 0
        b.cur[2] = sign * alpha_d, b.cur[3] = 0, b.cur[4] = -sign * 6.0 * alpha_d / (dt_a * dt_a),
        b.cur[5] = sign * c;
        b.push(dt_a);
    };
    rise(+1);
    fall(+1);
    if (dt_c > 0) b.hold(dt_c, 2, 0);
    rise(-1);
    fall(-1);
    const double vp = alpha_d * dt_a;
    return b.done(vp * (2 * dt_a + dt_c));
}

MoveShape scurve_move(double distance, const Limits& lim) {
    if (distance <= 0) return Builder{}.done(0);
    // Peak jerk of the smoothstep is 1.5 alpha_d / dt_a; peak velocity alpha_d dt_a.
    double dt = std::max(lim.v / lim.a, 1.5 * lim.a / lim.j);
    double alpha = std::min({lim.a, lim.j * dt / 1.5, lim.v / dt});
    if (lim.v / lim.a < 1.5 * lim.a / lim.j) {  // jerk binds before a is reached
        dt = std::sqrt(1.5 * lim.v / lim.j);
        alpha = lim.v / dt;
    }
    if (distance < 2 * alpha * dt * dt) {  // too short to reach the cruise speed
        dt = std::sqrt(distance / (2 * lim.a));
        alpha = lim.a;
        if (dt < 1.5 * lim.a / lim.j) {
            dt = std::cbrt(3 * distance / (4 * lim.j));
            alpha = lim.j * dt / 1.5;
        }
    }
    const double dtc = std::max(0.0, (distance - 2 * alpha * dt * dt) / (alpha * dt));
    MoveShape m = scurve_move(alpha, dt, dtc);
    m.distance = distance;  // exact by construction; avoids a rounding residue
    return m;
}

namespace {
struct JerkTimes {
    double tj, ta, tc, jerk;
};
JerkTimes jerk_times(double d, const Limits& lim) {
    double tj = lim.a / lim.j;
    double ta = 0;
    double vp = lim.v;
    if (lim.v < lim.a * tj) {  // the velocity limit is hit before full acceleration
        tj = std::sqrt(lim.v / lim.j);
    } else {
        ta = lim.v / lim.a - tj;
    }
    const double d_v = vp * (2 * tj + ta);
    if (d >= d_v) return {tj, ta, (d - d_v) / vp, lim.j};
    const double tj_a = lim.a / lim.j;
    if (lim.v >= lim.a * tj_a && d >= 2 * lim.a * tj_a * tj_a) {
        // Full acceleration reached, cruise speed not: solve the quadratic for ta.
        const double tau = 0.5 * (-3 * tj_a + std::sqrt(tj_a * tj_a + 4 * d / lim.a));
        return {tj_a, std::max(0.0, tau), 0, lim.j};
    }
    return {std::cbrt(d / (2 * lim.j)), 0, 0, lim.j};
}
}  // namespace

double jerk_min_time(double distance, const Limits& lim) {
    if (distance <= 0) return 0;
    const auto t = jerk_times(distance, lim);
    return 4 * t.tj + 2 * t.ta + t.tc;
}

MoveShape jerk_move(double distance, const Limits& lim) {
    Builder b;
    if (distance <= 0) return b.done(0);
    const auto t = jerk_times(distance, lim);
    b.hold(t.tj, 3, t.jerk);
    if (t.ta > 0) b.hold(t.ta, 3, 0);
    b.hold(t.tj, 3, -t.jerk);
    if (t.tc > 0) b.hold(t.tc, 3, 0);
    b.hold(t.tj, 3, -t.jerk);
    if (t.ta > 0) b.hold(t.ta, 3, 0);
    b.hold(t.tj, 3, t.jerk);
    MoveShape m = b.done(distance);
    return m;
}

MoveShape make_move(profile::ProfileShape shape, double distance, const Limits& lim) {
    switch (shape) {
        case profile::ProfileShape::trapezoid: return trapezoid_move(distance, lim);
        case profile::ProfileShape::scurve: return scurve_move(distance, lim);
        case profile::ProfileShape::jerk:
        case profile::ProfileShape::automatic: break;
    }
    return jerk_move(distance, lim);
}

}  // namespace tactus::motion
