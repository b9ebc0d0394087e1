// SPDX-License-Identifier: GPL-3.0-or-later
#include "estimate/ringing.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
#include <unordered_map>

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>

#include "estimate/simulate.hpp"
#include "machine/limits.hpp"
#include "motion/steps.hpp"

namespace tactus::estimate {
namespace {

constexpr int kSamples = 32;  // the dwell is sampled at kSamples + 1 instants, as MoveSimulator::residual_mm
constexpr int kBits = 32;     // exp(A 2^k ticks), k < kBits: rests up to 4660 s
using Mat4 = Eigen::Matrix4d;
using Vec4 = Eigen::Vector4d;
using Rows = Eigen::Matrix<double, kSamples + 1, 4>;
// The plant and a straight-line command u = p + v t as one system: state
// (x, u, u'), 4 + 2 padded states. exp of it over dt gives, in its top rows,
// x(dt) = Phi x + G0 p + G1 v.
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

// Every model padded to four states: the unused ones have no dynamics and stay 0.
struct Model {
    Mat4 a = Mat4::Zero();
    Eigen::RowVector4d c = Eigen::RowVector4d::Zero();
    Vec4 eq = Vec4::Zero();  // the resting state under a unit command
    Rows rows;               // c exp(A s_i), s_i = i dwell / kSamples: head error at each dwell instant
    Vec4 cmax, cmin;         // max_i and min_i of rows(i, j): bound the error (sample_bound)
    Mat4 dwell;              // exp(A dwell)
    std::array<Mat4, kBits> pow2;
    int n = 0;
    StateSpace space;
};

Mat4 expm(const Mat4& a, double t) { return (a * t).exp(); }

Model make_model(const StateSpace& s, double dwell_s) {
    Model m;
    m.n = s.n;
    m.space = s;
    Eigen::MatrixXd a(s.n, s.n);
    Eigen::VectorXd b(s.n);
    for (int i = 0; i < s.n; ++i) {
        b(i) = s.b[static_cast<std::size_t>(i)];
        m.c(i) = s.c[static_cast<std::size_t>(i)];
        for (int j = 0; j < s.n; ++j) a(i, j) = s.a[static_cast<std::size_t>(i * s.n + j)];
    }
    m.a.topLeftCorner(s.n, s.n) = a;
    // At rest under a constant command u: A x + B u = 0.
    m.eq.head(s.n) = -a.partialPivLu().solve(b);
    for (int i = 0; i <= kSamples; ++i) m.rows.row(i) = m.c * expm(m.a, dwell_s * i / kSamples);
    m.cmax = m.rows.colwise().maxCoeff().transpose();
    m.cmin = m.rows.colwise().minCoeff().transpose();
    m.dwell = expm(m.a, dwell_s);
    for (int k = 0; k < kBits; ++k) m.pow2[static_cast<std::size_t>(k)] = expm(m.a, std::ldexp(1.0, k) / machine::kTickHz);
    return m;
}

// Defined with the per-strike kernels (below): the largest |rows z + off| over
// the dwell samples, four rows per AVX2 instruction (two per SSE2 one in the
// baseline clone), every element computed by the same operations in the same
// order as the plain loop (one IEEE multiply or add at a time, no fused
// multiply-add, no reassociation): the same bits. `off` (mm) is where the
// command rests past the dot the hammer must hit (command minus dot): the
// error is then head minus dot, rows z + off.
double error_kernel(const double* c, const double* z, double off);

double error_um(const Model& m, const Vec4& z, double off = 0.0) { return error_kernel(m.rows.data(), z.data(), off); }

// A bound on error_um(m, z, off) / 1000 without sampling: every row's
// product rows(i) z lies between the sums of the columns' smallest and largest
// products with z; the error is that plus `off`.
double sample_bound(const Model& m, const Vec4& z, double off) {
    double hi = off, lo = off;
    for (int j = 0; j < 4; ++j) {
        const double a = z[j] * m.cmax[j], b = z[j] * m.cmin[j];
        hi += std::max(a, b);
        lo += std::min(a, b);
    }
    return std::max(std::fabs(hi), std::fabs(lo));
}

Vec4 after_ticks(const Model& m, Vec4 z, std::uint64_t ticks) {
    for (int k = 0; ticks != 0; ++k, ticks >>= 1)
        if (ticks & 1U) z = m.pow2[static_cast<std::size_t>(k)] * z;
    return z;
}

// The per-strike work across the models, element by element: the models'
// states side by side (z_soa[r * kPad + i], state r of model i), so one
// vector instruction handles four models, each lane computing exactly what
// the per-model code computes (the same IEEE multiplies and adds in the same
// order; no fused multiply-add: the AVX2 clone below does not enable FMA).
// Compiled twice (AVX2 and the baseline) and chosen at load time where the
// compiler supports it.
// band_variants' grid: damping x 5 values, natural frequency x 9.
constexpr int kDampingValues = 5, kFrequencyValues = 9;
// The models (the nominal one and the band's) rounded up to a multiple of 8.
constexpr std::size_t kPad = (1 + kDampingValues * kFrequencyValues + 7) / 8 * 8;
using V4 = double __attribute__((vector_size(32)));
using U4 = std::uint64_t __attribute__((vector_size(32)));

// Windows executables have no ifunc to pick a clone at load time.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(_WIN32)
#define TACTUS_SIMD_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define TACTUS_SIMD_CLONES
#endif

// z <- phi z + sign w, per model (Ringing::move).
TACTUS_SIMD_CLONES void move_kernel(double* z, const double* phi, const double* w, double sign, std::size_t n) {
    V4 sg;
    for (int l = 0; l < 4; ++l) sg[l] = sign;
    for (std::size_t i = 0; i < n; i += 4) {
        V4 z0, z1, z2, z3;
        __builtin_memcpy(&z0, z + 0 * kPad + i, sizeof(V4));
        __builtin_memcpy(&z1, z + 1 * kPad + i, sizeof(V4));
        __builtin_memcpy(&z2, z + 2 * kPad + i, sizeof(V4));
        __builtin_memcpy(&z3, z + 3 * kPad + i, sizeof(V4));
        for (std::size_t r = 0; r < 4; ++r) {
            V4 m0, m1, m2, m3, ww;
            __builtin_memcpy(&m0, phi + (0 * 4 + r) * kPad + i, sizeof(V4));
            __builtin_memcpy(&m1, phi + (1 * 4 + r) * kPad + i, sizeof(V4));
            __builtin_memcpy(&m2, phi + (2 * 4 + r) * kPad + i, sizeof(V4));
            __builtin_memcpy(&m3, phi + (3 * 4 + r) * kPad + i, sizeof(V4));
            __builtin_memcpy(&ww, w + r * kPad + i, sizeof(V4));
            V4 e = m0 * z0;
            e = e + m1 * z1;
            e = e + m2 * z2;
            e = e + m3 * z3;
            e = e + sg * ww;
            __builtin_memcpy(z + r * kPad + i, &e, sizeof(V4));
        }
    }
}

// sample_bound for every model at once (bound[i] for model i).
TACTUS_SIMD_CLONES void bound_kernel(const double* z, const double* cmax, const double* cmin, double off,
                                     double* bound, std::size_t n) {
    V4 o;
    for (int l = 0; l < 4; ++l) o[l] = off;
    U4 abs_mask;
    for (int l = 0; l < 4; ++l) abs_mask[l] = 0x7FFFFFFFFFFFFFFFULL;
    for (std::size_t i = 0; i < n; i += 4) {
        V4 hi = o, lo = o;
        for (std::size_t j = 0; j < 4; ++j) {
            V4 zj, mx, mn;
            __builtin_memcpy(&zj, z + j * kPad + i, sizeof(V4));
            __builtin_memcpy(&mx, cmax + j * kPad + i, sizeof(V4));
            __builtin_memcpy(&mn, cmin + j * kPad + i, sizeof(V4));
            const V4 a = zj * mx, b = zj * mn;
            hi = hi + (a < b ? b : a);  // std::max(a, b)
            lo = lo + (b < a ? b : a);  // std::min(a, b)
        }
        U4 uh, ul;  // |hi|, |lo|: the sign bit cleared, as std::fabs
        __builtin_memcpy(&uh, &hi, sizeof(V4));
        __builtin_memcpy(&ul, &lo, sizeof(V4));
        uh &= abs_mask;
        ul &= abs_mask;
        V4 ah, al;
        __builtin_memcpy(&ah, &uh, sizeof(V4));
        __builtin_memcpy(&al, &ul, sizeof(V4));
        const V4 r = ah < al ? al : ah;  // std::max(|hi|, |lo|)
        __builtin_memcpy(bound + i, &r, sizeof(V4));
    }
}

TACTUS_SIMD_CLONES double error_kernel(const double* c, const double* z, double off) {
    constexpr std::size_t n = kSamples + 1;  // rows, column-major
    V4 z0, z1, z2, z3, o, w;
    for (int l = 0; l < 4; ++l) z0[l] = z[0], z1[l] = z[1], z2[l] = z[2], z3[l] = z[3], o[l] = off, w[l] = 0.0;
    std::size_t r = 0;
    for (; r + 4 <= n; r += 4) {
        V4 c0, c1, c2, c3;
        __builtin_memcpy(&c0, c + r, sizeof(V4));
        __builtin_memcpy(&c1, c + n + r, sizeof(V4));
        __builtin_memcpy(&c2, c + 2 * n + r, sizeof(V4));
        __builtin_memcpy(&c3, c + 3 * n + r, sizeof(V4));
        V4 e = c0 * z0;
        e = e + c1 * z1;
        e = e + c2 * z2;
        e = e + c3 * z3;
        e = e + o;                    // + 0.0 leaves e as it was
        const V4 a = e < 0 ? -e : e;  // |e| (a zero's sign does not matter to the largest)
        w = w < a ? a : w;
    }
    double worst = std::max(std::max(w[0], w[1]), std::max(w[2], w[3]));
    for (; r < n; ++r)
        worst = std::max(worst,
                         std::fabs(c[r] * z[0] + c[n + r] * z[1] + c[2 * n + r] * z[2] + c[3 * n + r] * z[3] + off));
    return 1000.0 * worst;
}

}  // namespace

std::vector<ModelVariant> band_variants(const profile::Vibration& v) {
    std::vector<ModelVariant> out;
    constexpr int nd = kDampingValues, nf = kFrequencyValues;
    for (int i = 0; i < nd; ++i)
        for (int j = 0; j < nf; ++j)
            out.push_back({1 - v.damping_band + 2 * v.damping_band * i / (nd - 1),
                           1 - v.frequency_band + 2 * v.frequency_band * j / (nf - 1)});
    return out;
}

struct Ringing::Move {
    // Per model, while the move is made (emptied by lay_out_soa): exp(A T),
    // and the same after a dwell, exp(A T) exp(A dwell).
    std::vector<Mat4> phi, phi_d;
    std::vector<Vec4> w;  // per model
    // The same numbers laid out for Ringing::move (the hot loop): element by
    // element across the models, kPad models per element
    // (phi_soa[(c * 4 + r) * kPad + i] = phi[i](r, c); padding 0).
    std::vector<double> phi_soa, phi_d_soa, w_soa;
};

namespace {
// Model i's matrix from its element-by-element layout.
Mat4 matrix_of(const std::vector<double>& soa, std::size_t i) {
    Mat4 m;
    double* p = m.data();
    for (std::size_t e = 0; e < 16; ++e) p[e] = soa[e * kPad + i];
    return m;
}

// Fills a move's *_soa from its per-model numbers, and frees its per-model
// matrices (kept once: a tuned move is kept for the whole plan).
void lay_out_soa(Ringing::Move& mv) {
    mv.phi_soa.assign(16 * kPad, 0.0);
    mv.phi_d_soa.assign(16 * kPad, 0.0);
    mv.w_soa.assign(4 * kPad, 0.0);
    for (std::size_t i = 0; i < mv.phi.size(); ++i) {
        const double* p = mv.phi[i].data();  // column-major: p[c * 4 + r]
        const double* pd = mv.phi_d[i].data();
        for (std::size_t e = 0; e < 16; ++e) {
            mv.phi_soa[e * kPad + i] = p[e];
            mv.phi_d_soa[e * kPad + i] = pd[e];
        }
        for (std::size_t r = 0; r < 4; ++r) mv.w_soa[r * kPad + i] = mv.w[i][static_cast<Eigen::Index>(r)];
    }
    std::vector<Mat4>().swap(mv.phi);
    std::vector<Mat4>().swap(mv.phi_d);
}
}  // namespace

struct Ringing::Impl {
    std::vector<Model> models;  // [0] nominal, then the band
    mutable std::vector<MoveSimulator> sims;  // one per model: their matrix exponentials are cached
    // The head's error state of every model, element by element (z_soa[r *
    // kPad + i]: state r of model i; padding 0). z() and set_z() convert.
    std::vector<double> z_soa = std::vector<double>(4 * kPad, 0.0);
    std::vector<double> cmax_soa = std::vector<double>(4 * kPad, 0.0), cmin_soa = std::vector<double>(4 * kPad, 0.0);
    mutable std::vector<double> bounds = std::vector<double>(kPad, 0.0);
    bool dwell_pending = false;  // the last dwell not yet applied (folded into the next move)
    std::unordered_map<std::uint64_t, std::vector<Mat4>> rests;
    // prepare_step_train: per (kind of piece, interval in ticks, steps per mm),
    // per model, the piece's affine map raised to 1, 2, 4, ... (grown on demand).
    mutable std::map<std::tuple<int, std::int64_t, std::uint64_t>, std::vector<std::vector<Mat6>>> train_powers;
    mutable std::size_t first = 1;  // the band model that failed (or was worst) last: tried first
    mutable std::size_t worst_model = 1;

    [[nodiscard]] bool within(const std::vector<Vec4>& zs, std::uint64_t ticks, double target_um, double off) const {
        const std::size_t nb = models.size() - 1;
        const double target_mm = target_um / 1000.0;
        for (std::size_t k = 0, i = first; k < nb; ++k, i = i == nb ? 1 : i + 1) {
            const Model& m = models[i];
            const Vec4 zz = after_ticks(m, zs[i], ticks);
            if (sample_bound(m, zz, off) <= target_mm) continue;  // cannot exceed: no need to sample
            if (error_um(m, zz, off) > target_um) {
                first = i;
                return false;
            }
        }
        return true;
    }

    // Every band model of `zs` within target_um (the states as they are).
    [[nodiscard]] bool passes(const std::vector<Vec4>& zs, double target_um, double off) const {
        const std::size_t nb = models.size() - 1;
        const double target_mm = target_um / 1000.0;
        for (std::size_t k = 0, i = first; k < nb; ++k, i = i == nb ? 1 : i + 1) {
            const Model& m = models[i];
            if (sample_bound(m, zs[i], off) <= target_mm) continue;
            if (error_um(m, zs[i], off) > target_um) {
                first = i;
                return false;
            }
        }
        return true;
    }

    [[nodiscard]] std::vector<Vec4> advanced(const std::vector<Vec4>& zs, int k) const {
        std::vector<Vec4> out(zs.size());
        for (std::size_t i = 0; i < zs.size(); ++i) out[i] = models[i].pow2[static_cast<std::size_t>(k)] * zs[i];
        return out;
    }

    [[nodiscard]] std::int64_t settle(const std::vector<Vec4>& zs, double target_um, std::uint64_t from,
                                      std::uint64_t max_ticks, double off) const {
        std::vector<Vec4> lo_z = zs;
        if (from > 0)
            for (std::size_t i = 0; i < lo_z.size(); ++i) lo_z[i] = after_ticks(models[i], zs[i], from);
        if (passes(lo_z, target_um, off)) return static_cast<std::int64_t>(from);
        // Rests grow by powers of two from the last that failed until one
        // passes; then the bits below it, from the highest, each kept when the
        // rest with it still fails: the first tick that passes after the last
        // that failed. One product per machine per trial.
        std::uint64_t lo = from;
        int k = 4;
        for (;; ++k) {
            if (k >= kBits || lo + (std::uint64_t{1} << k) > max_ticks) return -1;
            auto hi_z = advanced(lo_z, k);
            if (passes(hi_z, target_um, off)) break;
            lo += std::uint64_t{1} << k;
            lo_z = std::move(hi_z);
        }
        for (--k; k >= 0; --k) {
            auto try_z = advanced(lo_z, k);
            if (passes(try_z, target_um, off)) continue;
            lo += std::uint64_t{1} << k;
            lo_z = std::move(try_z);
        }
        return static_cast<std::int64_t>(lo + 1);
    }

    [[nodiscard]] Vec4 z_of(std::size_t i) const {
        return {z_soa[i], z_soa[kPad + i], z_soa[2 * kPad + i], z_soa[3 * kPad + i]};
    }
    void set_z(std::size_t i, const Vec4& v) {
        for (std::size_t r = 0; r < 4; ++r) z_soa[r * kPad + i] = v[static_cast<Eigen::Index>(r)];
    }
    [[nodiscard]] std::vector<Vec4> z() const {
        std::vector<Vec4> out(models.size());
        for (std::size_t i = 0; i < models.size(); ++i) out[i] = z_of(i);
        return out;
    }

    void apply_dwell() {
        if (!dwell_pending) return;
        for (std::size_t i = 0; i < models.size(); ++i) set_z(i, models[i].dwell * z_of(i));
        dwell_pending = false;
    }

    // residual() on the state as it is, the band's bounds computed for every model at once.
    [[nodiscard]] Residual residual_here(double off) const {
        Residual r;
        r.nominal_um = error_um(models[0], z_of(0), off);
        bound_kernel(z_soa.data(), cmax_soa.data(), cmin_soa.data(), off, bounds.data(), kPad);
        const std::size_t nb = models.size() - 1;
        // The one that was worst last, first (then on, wrapping round).
        for (std::size_t k = 0, i = first; k < nb; ++k, i = i == nb ? 1 : i + 1) {
            if (1000.0 * bounds[i] <= r.worst_um) continue;  // cannot be the worst
            const double e = error_um(models[i], z_of(i), off);
            if (e > r.worst_um) r.worst_um = e, worst_model = i;
        }
        first = worst_model;
        return r;
    }

    [[nodiscard]] Residual residual(const std::vector<Vec4>& zs, double off) const {
        Residual r;
        r.nominal_um = error_um(models[0], zs[0], off);
        const std::size_t nb = models.size() - 1;
        // The one that was worst last, first (then on, wrapping round).
        for (std::size_t k = 0, i = first; k < nb; ++k, i = i == nb ? 1 : i + 1) {
            const Model& m = models[i];
            if (1000.0 * sample_bound(m, zs[i], off) <= r.worst_um) continue;  // cannot be the worst
            const double e = error_um(m, zs[i], off);
            if (e > r.worst_um) r.worst_um = e, worst_model = i;
        }
        first = worst_model;
        return r;
    }
};

Ringing::Ringing(const profile::PrinterProfile& p) : impl_(std::make_unique<Impl>()) {
    impl_->models.push_back(make_model(build_model(p.dynamics), p.head.dwell_s));
    for (const auto& v : band_variants(p.vibration))
        impl_->models.push_back(make_model(build_model(p.dynamics, v), p.head.dwell_s));
    for (const auto& m : impl_->models) impl_->sims.emplace_back(m.space);
    for (std::size_t i = 0; i < impl_->models.size(); ++i)
        for (std::size_t j = 0; j < 4; ++j) {
            impl_->cmax_soa[j * kPad + i] = impl_->models[i].cmax[static_cast<Eigen::Index>(j)];
            impl_->cmin_soa[j * kPad + i] = impl_->models[i].cmin[static_cast<Eigen::Index>(j)];
        }
    reset();
}
Ringing::~Ringing() = default;
Ringing::Ringing(Ringing&&) noexcept = default;
Ringing& Ringing::operator=(Ringing&&) noexcept = default;

std::size_t Ringing::models() const { return impl_->models.size(); }

std::shared_ptr<const Ringing::Move> Ringing::prepare(const motion::MoveShape& shape) const {
    auto mv = std::make_shared<Move>();
    for (std::size_t k = 0; k < impl_->models.size(); ++k) {
        const Model& m = impl_->models[k];
        const auto end = impl_->sims[k].end_state(shape);
        Vec4 w = -m.eq * shape.distance;
        for (int i = 0; i < m.n; ++i) w(i) += end[static_cast<std::size_t>(i)];
        mv->w.push_back(w);
        mv->phi.push_back(expm(m.a, shape.duration));
        mv->phi_d.push_back(mv->phi.back() * m.dwell);
    }
    lay_out_soa(*mv);
    return mv;
}

namespace {

Mat6 line_generator(const Model& m) {
    Mat6 g = Mat6::Zero();
    g.topLeftCorner<4, 4>() = m.a;
    for (int i = 0; i < m.n; ++i) g(i, 4) = m.space.b[static_cast<std::size_t>(i)];
    g(4, 5) = 1.0;
    return g;
}

// The affine map of one straight piece lasting dt (s) at velocity v on
// X = (x, p, 1): x <- Phi x + G0 p + G1 v, p <- p + v dt.
Mat6 piece_map(const Mat6& e, double v, double dp) {
    Mat6 mm = Mat6::Zero();
    mm.topLeftCorner<4, 4>() = e.topLeftCorner<4, 4>();
    mm.block<4, 1>(0, 4) = e.block<4, 1>(0, 4);
    mm.block<4, 1>(0, 5) = e.block<4, 1>(0, 5) * v;
    mm(4, 4) = 1.0;
    mm(4, 5) = dp;
    mm(5, 5) = 1.0;
    return mm;
}

}  // namespace

std::shared_ptr<const Ringing::Move> Ringing::prepare_step_train(std::span<const motion::StepSegment> segments,
                                                                 double steps_per_mm, double duration_s) const {
    const auto ticks = motion::expand_steps(segments);
    const double f = machine::kTickHz;
    const double step = 1.0 / steps_per_mm;
    const double distance = static_cast<double>(ticks.size()) / steps_per_mm;
    // The pieces of step_train_shape: from rest at 0 to the middle of the first
    // step at its tick; between steps, one step in each interval (runs of equal
    // intervals together); the last half step as long as half the interval
    // before it; then at rest on the end until the duration.
    struct Run {
        double dt;       // s
        double v;        // mm/s
        double dp;       // mm per piece
        std::size_t n;   // pieces
        std::int64_t key;  // the interval in ticks (cached exponentials), or -1
    };
    std::vector<Run> runs;
    double t = 0, p = 0;
    if (!ticks.empty()) {
        const double t0 = static_cast<double>(ticks[0]) / f;
        if (t0 > t) runs.push_back({t0, (0.5 * step) / t0, 0.5 * step, 1, ticks[0]});
        t = t0;
        p = 0.5 * step;
        for (std::size_t k = 1; k < ticks.size();) {
            const std::int64_t iv = ticks[k] - ticks[k - 1];
            std::size_t e = k + 1;
            while (e < ticks.size() && ticks[e] - ticks[e - 1] == iv) ++e;
            const double dt = static_cast<double>(iv) / f;
            runs.push_back({dt, step / dt, step, e - k, iv});
            t = static_cast<double>(ticks[e - 1]) / f;
            p += step * static_cast<double>(e - k);
            k = e;
        }
        const double last = ticks.size() > 1 ? static_cast<double>(ticks.back() - ticks[ticks.size() - 2]) / f : 1e-3;
        const double dt = 0.5 * last;
        runs.push_back({dt, (distance - p) / dt, distance - p, 1, -1});
        t += dt;
    }
    const double duration = std::max(duration_s, t);
    if (duration > t) runs.push_back({duration - t, 0.0, 0.0, 1, -1});

    auto& s = *impl_;
    if (s.train_powers.size() > 4096) s.train_powers.clear();  // bounded: a table has a few hundred intervals
    // The powers of each run's map, per model: cached for the pieces between
    // steps and the first (the same for every move of a table), computed for
    // the last half step and the rest.
    std::vector<std::vector<std::vector<Mat6>>*> powers(runs.size(), nullptr);
    std::vector<std::vector<std::vector<Mat6>>> own(runs.size());
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const auto& r = runs[i];
        if (r.key >= 0) {
            const std::tuple key{i == 0 ? 0 : 1, r.key, std::bit_cast<std::uint64_t>(steps_per_mm)};
            powers[i] = &s.train_powers[key];
        } else {
            powers[i] = &own[i];
        }
        if (powers[i]->empty()) {
            for (const auto& m : s.models)
                powers[i]->push_back({piece_map(Mat6((line_generator(m) * r.dt).exp()), r.v, r.dp)});
        }
    }
    auto mv = std::make_shared<Move>();
    for (std::size_t k = 0; k < s.models.size(); ++k) {
        const Model& m = s.models[k];
        Vec6 x = Vec6::Zero();
        x(5) = 1.0;  // X = (x, p, 1), p = 0 at the start
        for (std::size_t i = 0; i < runs.size(); ++i) {
            auto& pw = (*powers[i])[k];
            std::size_t j = 0;
            for (std::size_t n = runs[i].n; n != 0; n >>= 1, ++j) {
                if (pw.size() <= j) pw.push_back(pw.back() * pw.back());
                if (n & 1U) x = pw[j] * x;
            }
        }
        Vec4 w = -m.eq * distance;
        w += x.head<4>();
        mv->w.push_back(w);
        mv->phi.push_back(expm(m.a, duration));
        mv->phi_d.push_back(mv->phi.back() * m.dwell);
    }
    lay_out_soa(*mv);
    return mv;
}

std::shared_ptr<const Ringing::Move> Ringing::then_rest(const Move& mv, std::uint64_t ticks) const {
    auto out = std::make_shared<Move>();
    out->w = mv.w;
    for (std::size_t i = 0; i < impl_->models.size(); ++i) {
        Mat4 e = Mat4::Identity();
        for (std::uint64_t t = ticks, k = 0; t != 0; ++k, t >>= 1)
            if (t & 1U) e = impl_->models[i].pow2[k] * e;
        out->phi.push_back(e * matrix_of(mv.phi_soa, i));
        out->phi_d.push_back(e * matrix_of(mv.phi_d_soa, i));
        out->w[i] = e * mv.w[i];
    }
    lay_out_soa(*out);
    return out;
}

void Ringing::reset() {
    std::fill(impl_->z_soa.begin(), impl_->z_soa.end(), 0.0);
    impl_->dwell_pending = false;
}

void Ringing::move(const Move& mv, int dir) {
    auto& s = *impl_;
    // The hot loop of planning, on every model at once (move_kernel).
    move_kernel(s.z_soa.data(), s.dwell_pending ? mv.phi_d_soa.data() : mv.phi_soa.data(), mv.w_soa.data(),
                static_cast<double>(dir), kPad);
    s.dwell_pending = false;
}

void Ringing::rest(double seconds) {
    if (seconds <= 0) return;
    auto& s = *impl_;
    s.apply_dwell();
    const auto key = std::bit_cast<std::uint64_t>(seconds);
    auto it = s.rests.find(key);
    if (it == s.rests.end()) {
        if (s.rests.size() > 4096) s.rests.clear();  // bounded: rests repeat a lot
        std::vector<Mat4> e;
        for (const auto& m : s.models) e.push_back(expm(m.a, seconds));
        it = s.rests.emplace(key, std::move(e)).first;
    }
    for (std::size_t i = 0; i < s.models.size(); ++i) s.set_z(i, it->second[i] * s.z_of(i));
}

void Ringing::rest_ticks(std::uint64_t ticks) {
    auto& s = *impl_;
    s.apply_dwell();
    for (std::size_t i = 0; i < s.models.size(); ++i) s.set_z(i, after_ticks(s.models[i], s.z_of(i), ticks));
}

void Ringing::dwell() {
    impl_->apply_dwell();
    impl_->dwell_pending = true;  // applied by the next move (one product) or whatever comes first
}

Ringing::Residual Ringing::residual(double offset_mm) {
    impl_->apply_dwell();
    return impl_->residual_here(offset_mm);
}

bool Ringing::within_after(std::uint64_t ticks, double target_um, double offset_mm) {
    impl_->apply_dwell();
    return impl_->within(impl_->z(), ticks, target_um, offset_mm);
}

std::int64_t Ringing::settle_ticks(double target_um, std::uint64_t from, std::uint64_t max_ticks, double offset_mm) {
    impl_->apply_dwell();
    return impl_->settle(impl_->z(), target_um, from, max_ticks, offset_mm);
}

std::int64_t Ringing::settle_after(const Move& mv, double target_um, std::uint64_t max_ticks, double offset_mm) const {
    return impl_->settle(mv.w, target_um, 0, max_ticks, offset_mm);
}

Ringing::Residual Ringing::from_rest(const Move& mv, double rest_s, double offset_mm) const {
    const auto& s = *impl_;
    std::vector<Vec4> z(mv.w.begin(), mv.w.end());
    if (rest_s > 0)
        for (std::size_t i = 0; i < z.size(); ++i) z[i] = expm(s.models[i].a, rest_s) * z[i];
    return s.residual(z, offset_mm);
}

}  // namespace tactus::estimate
