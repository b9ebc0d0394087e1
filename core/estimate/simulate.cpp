// SPDX-License-Identifier: GPL-3.0-or-later
#include "estimate/simulate.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>

namespace tactus::estimate {
namespace {

Eigen::MatrixXd to_a(const StateSpace& s) {
    Eigen::MatrixXd a(s.n, s.n);
    for (int i = 0; i < s.n; ++i)
        for (int j = 0; j < s.n; ++j) a(i, j) = s.a[static_cast<std::size_t>(i * s.n + j)];
    return a;
}
Eigen::VectorXd to_vec(const std::vector<double>& v) {
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

}  // namespace

struct MoveSimulator::Impl {
    int n = 0;                // plant states
    Eigen::MatrixXd m;        // augmented generator: plant, command derivatives 0..4, crackle
    Eigen::RowVectorXd c;     // head position from the plant state
    std::unordered_map<std::uint64_t, Eigen::MatrixXd> phi_cache;

    explicit Impl(const StateSpace& s) : n(s.n) {
        const int na = n + 6;
        m = Eigen::MatrixXd::Zero(na, na);
        m.topLeftCorner(n, n) = to_a(s);
        m.block(0, n, n, 1) = to_vec(s.b);
        for (int k = 0; k < 5; ++k) m(n + k, n + k + 1) = 1.0;  // w_k' = w_{k+1}, w_4' = crackle
        c = to_vec(s.c).transpose();
    }

    // The last duration looked up: a step train's cruise repeats one interval.
    std::uint64_t last_key = 0;
    const Eigen::MatrixXd* last_phi = nullptr;

    const Eigen::MatrixXd& phi(double dt) {
        const auto key = std::bit_cast<std::uint64_t>(dt);
        if (last_phi && key == last_key) return *last_phi;
        auto it = phi_cache.find(key);
        if (it == phi_cache.end()) {
            if (phi_cache.size() > 4096) phi_cache.clear();  // bounded: durations repeat a lot
            it = phi_cache.emplace(key, (m * dt).exp()).first;
        }
        last_key = key;
        last_phi = &it->second;  // node-based map: stable until the next clear, which only a miss does
        return it->second;
    }

    // State after the whole move; the command derivatives are re-seeded from the
    // move at each piece start (they are exact there, so nothing accumulates).
    Eigen::VectorXd run(const motion::MoveShape& move, Eigen::VectorXd z,
                        std::vector<double>* out = nullptr, std::span<const double> times = {}) {
        std::size_t ti = 0;
        auto seed = [&](const motion::Derivs& d) {
            for (int k = 0; k < 6; ++k) z(n + k) = d[static_cast<std::size_t>(k)];
        };
        // Samples inside [t0, t_end) are advanced from the seeded state at t0.
        auto emit = [&](double t0, double t_end) {
            for (; out && ti < times.size() && times[ti] < t_end; ++ti) {
                const Eigen::VectorXd zz = phi(std::max(0.0, times[ti] - t0)) * z;
                out->push_back(c * zz.head(n));
            }
        };
        // The product into a second vector, then a swap: `z = phi * z` would
        // allocate a temporary per piece (a step train has one piece per step).
        Eigen::VectorXd next(z.size());
        for (const auto& p : move.pieces) {
            seed(p.d);
            emit(p.t0, p.t0 + p.dt);
            next.noalias() = phi(p.dt) * z;
            z.swap(next);
        }
        seed(motion::Derivs{move.distance, 0, 0, 0, 0, 0});
        emit(move.duration, std::numeric_limits<double>::infinity());
        return z;
    }
};

MoveSimulator::MoveSimulator(const StateSpace& model) : impl_(std::make_unique<Impl>(model)) {}
MoveSimulator::~MoveSimulator() = default;
MoveSimulator::MoveSimulator(MoveSimulator&&) noexcept = default;
MoveSimulator& MoveSimulator::operator=(MoveSimulator&&) noexcept = default;

double MoveSimulator::residual_mm(const motion::MoveShape& move, double dwell_s, int samples) {
    auto& s = *impl_;
    Eigen::VectorXd z = Eigen::VectorXd::Zero(s.n + 6);
    z = s.run(move, z);
    // Free response at rest on the target: command derivatives all zero.
    for (int k = 0; k < 6; ++k) z(s.n + k) = k == 0 ? move.distance : 0.0;
    double worst = std::fabs(s.c * z.head(s.n) - move.distance);
    const Eigen::MatrixXd& step = s.phi(dwell_s / samples);
    for (int i = 0; i < samples; ++i) {
        z = step * z;
        worst = std::max(worst, std::fabs(s.c * z.head(s.n) - move.distance));
    }
    return worst;
}

std::vector<double> MoveSimulator::end_state(const motion::MoveShape& move) {
    auto& s = *impl_;
    const Eigen::VectorXd z = s.run(move, Eigen::VectorXd::Zero(s.n + 6));
    return {z.data(), z.data() + s.n};
}

std::vector<double> MoveSimulator::head_positions(const motion::MoveShape& move,
                                                  std::span<const double> times) {
    auto& s = *impl_;
    std::vector<double> out;
    out.reserve(times.size());
    s.run(move, Eigen::VectorXd::Zero(s.n + 6), &out, times);
    return out;
}

StepMetrics step_response(const StateSpace& model) {
    const Eigen::MatrixXd a = to_a(model);
    const Eigen::VectorXd b = to_vec(model.b);
    const Eigen::RowVectorXd c = to_vec(model.c).transpose();
    const Eigen::VectorXcd eig = a.eigenvalues();
    double fastest = 0, slowest_decay = std::numeric_limits<double>::infinity();
    for (const auto& l : eig) {
        fastest = std::max(fastest, std::abs(l));
        slowest_decay = std::min(slowest_decay, -l.real());
    }
    const double pi = std::acos(-1.0);
    const double dt = 2 * pi / (fastest * 2000);
    // Long enough for the slowest mode to decay far inside the 2 % band (or, undamped, 50 cycles).
    const double horizon = slowest_decay > 1e-9 ? 12.0 / slowest_decay : 100 * pi / fastest * 50;
    const auto steps = static_cast<long>(std::min(horizon / dt, 2e6));
    // Exact zero-order-hold discretisation: the step input is constant.
    const int n = model.n;
    Eigen::MatrixXd aug = Eigen::MatrixXd::Zero(n + 1, n + 1);
    aug.topLeftCorner(n, n) = a;
    aug.block(0, n, n, 1) = b;
    const Eigen::MatrixXd phi = (aug * dt).exp();
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n + 1);
    z(n) = 1.0;
    StepMetrics r;
    double peak = 0, prev = 0, t10 = -1, t90 = -1, last_out = 0;
    bool outside = true;
    for (long i = 1; i <= steps; ++i) {
        z = phi * z;
        const double y = c * z.head(n);
        const double t = static_cast<double>(i) * dt;
        auto cross = [&](double level) { return t - dt * (y - level) / (y - prev); };
        if (t10 < 0 && y >= 0.1) t10 = cross(0.1);
        if (t90 < 0 && y >= 0.9) t90 = cross(0.9);
        if (y > peak) peak = y, r.peak_time_s = t;
        const bool out = std::fabs(y - 1.0) > 0.02;
        if (!out && outside) {
            // Entered the band: interpolate the crossing of whichever edge it came through.
            const double edge = prev < 1.0 ? 0.98 : 1.02;
            last_out = t - dt * (y - edge) / (y - prev);
        }
        outside = out;
        prev = y;
    }
    r.overshoot_pct = std::max(0.0, (peak - 1.0) * 100.0);
    r.rise_time_s = t90 - t10;
    if (!outside) r.settling_time_s = last_out;
    return r;
}

std::vector<FrequencyPoint> frequency_response(const StateSpace& model, double f_lo, double f_hi,
                                               int points) {
    const Eigen::MatrixXcd a = to_a(model).cast<std::complex<double>>();
    const Eigen::VectorXcd b = to_vec(model.b).cast<std::complex<double>>();
    const Eigen::RowVectorXcd c = to_vec(model.c).transpose().cast<std::complex<double>>();
    const Eigen::MatrixXcd id = Eigen::MatrixXcd::Identity(model.n, model.n);
    const double pi = std::acos(-1.0);
    std::vector<FrequencyPoint> out;
    double prev_phase = 0;
    for (int i = 0; i < points; ++i) {
        const double f = points == 1 ? f_lo
                                     : f_lo * std::pow(f_hi / f_lo, static_cast<double>(i) / (points - 1));
        const std::complex<double> jw(0, 2 * pi * f);
        const std::complex<double> h = c * (jw * id - a).partialPivLu().solve(b);
        double phase = std::arg(h) * 180.0 / pi;
        if (!out.empty())  // unwrap: keep the curve continuous across +-180
            while (phase - prev_phase > 180) phase -= 360;
        if (!out.empty())
            while (phase - prev_phase < -180) phase += 360;
        prev_phase = phase;
        out.push_back({f, std::abs(h), 20 * std::log10(std::abs(h)), phase});
    }
    return out;
}

}  // namespace tactus::estimate
