// SPDX-License-Identifier: GPL-3.0-or-later
#include "estimate/dynamics.hpp"

#include <cmath>

#include <Eigen/Dense>

namespace tactus::estimate {
namespace {

bool two_inertia(const profile::Dynamics& d) {
    return d.rotor_inertia_kg_m2 > 0 && d.pulley_radius_m > 0 && d.motor_stiffness_nm_rad > 0;
}

// Mass and stiffness matrices of the two-inertia chain (rotor, head), rotor
// quantities reflected to the belt line through the pulley radius.
void two_inertia_mk(const profile::Dynamics& d, Eigen::Matrix2d& m, Eigen::Matrix2d& k, double& k_motor) {
    const double r2 = d.pulley_radius_m * d.pulley_radius_m;
    const double m_rotor = d.rotor_inertia_kg_m2 / r2;
    k_motor = d.motor_stiffness_nm_rad / r2;
    const double kb = d.belt_stiffness_n_m;
    m << m_rotor, 0, 0, d.head_mass_kg;
    k << k_motor + kb, -kb, -kb, kb;
}

}  // namespace

StateSpace build_model(const profile::Dynamics& d, ModelVariant v) {
    StateSpace s;
    const double zeta = d.damping_ratio * v.damping_scale;
    const double f2 = v.frequency_scale * v.frequency_scale;
    if (!two_inertia(d)) {
        const double w = std::sqrt(d.belt_stiffness_n_m / d.head_mass_kg) * v.frequency_scale;
        s.n = 2;
        s.a = {0, 1, -w * w, -2 * zeta * w};
        s.b = {0, w * w};
        s.c = {1, 0};
        return s;
    }
    Eigen::Matrix2d m, k;
    double k_motor = 0;
    two_inertia_mk(d, m, k, k_motor);
    k *= f2;
    k_motor *= f2;
    // Mass-normalised modes: phi^T M phi = I, phi^T K phi = diag(w^2).
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> es(k, m);
    const Eigen::Matrix2d phi = es.eigenvectors();
    const Eigen::Vector2d w = es.eigenvalues().cwiseSqrt();
    const Eigen::Matrix2d c = m * phi * (2 * zeta * w).asDiagonal() * phi.transpose() * m;
    const Eigen::Matrix2d minv = m.inverse();
    // State: rotor position, head position, rotor velocity, head velocity.
    Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
    a.block<2, 2>(0, 2) = Eigen::Matrix2d::Identity();
    a.block<2, 2>(2, 0) = -minv * k;
    a.block<2, 2>(2, 2) = -minv * c;
    Eigen::Vector4d b = Eigen::Vector4d::Zero();
    b.segment<2>(2) = minv * Eigen::Vector2d(k_motor, 0);
    s.n = 4;
    s.a.resize(16);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) s.a[static_cast<std::size_t>(i * 4 + j)] = a(i, j);
    s.b = {b(0), b(1), b(2), b(3)};
    s.c = {0, 1, 0, 0};
    return s;
}

std::vector<double> natural_frequencies_hz(const profile::Dynamics& d) {
    const double two_pi = 2 * std::acos(-1.0);
    if (!two_inertia(d)) return {sqrt_k_over_m(d) / two_pi};
    Eigen::Matrix2d m, k;
    double k_motor = 0;
    two_inertia_mk(d, m, k, k_motor);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> es(k, m);
    return {std::sqrt(es.eigenvalues()(0)) / two_pi, std::sqrt(es.eigenvalues()(1)) / two_pi};
}

double sqrt_k_over_m(const profile::Dynamics& d) {
    return std::sqrt(d.belt_stiffness_n_m / d.head_mass_kg);
}

double dominant_frequency_hz(const profile::Dynamics& d) { return natural_frequencies_hz(d).front(); }

}  // namespace tactus::estimate
