// SPDX-License-Identifier: BSD-3-Clause
// Test bodies built independently of the engine: parameters as sums over point masses (the paper's
// integral definitions) and the closed-form parameters of an oscillator on a rocking slab.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "flexrock/model/body.hpp"

namespace flexrock::test {

struct PointMass {
  double m;                  // [kg]
  double x, y;               // [m] position, base at y = 0
  std::vector<double> phix;  // [m] mode shapes, one per mode
  std::vector<double> phiy;
};

/// Paper's parameters of a point-mass body standing on tipping points (x1, 0) and (x2, 0), with
/// modal stiffness k (V = 1/2 k_ij q_i q_j, [J]).
inline BodyParameters lumped_body(const std::vector<PointMass>& pts, double x1, double x2,
                                  const MatrixX& k, double g = kStandardGravity) {
  const int n = static_cast<int>(k.rows());
  double M = 0, xc = 0, yc = 0;
  for (const auto& p : pts) {
    M += p.m;
    xc += p.m * p.x;
    yc += p.m * p.y;
  }
  xc /= M;
  yc /= M;
  BodyParameters b;
  b.mass = M;
  b.height = yc;
  b.b1 = xc - x1;
  b.b2 = x2 - xc;
  b.gravity = g;
  const double h = yc, mh2 = M * h * h;
  b.mu = MatrixX::Zero(n, n);
  b.gamma = MatrixX::Zero(n, n);
  b.psi_x = b.psi_y = b.delta = b.beta = VectorX::Zero(n);
  b.zeta2 = 0;
  for (const auto& p : pts) {
    const double rx = p.x - xc, ry = p.y - yc;
    b.zeta2 += p.m * (rx * rx + ry * ry) / mh2;
    for (int i = 0; i < n; ++i) {
      b.psi_x(i) += p.m * p.phix[i] / (M * h);
      b.psi_y(i) += p.m * p.phiy[i] / (M * h);
      b.delta(i) += p.m * (rx * p.phix[i] + ry * p.phiy[i]) / mh2;
      b.beta(i) += p.m * (rx * p.phiy[i] - ry * p.phix[i]) / mh2;
      for (int j = 0; j < n; ++j) {
        b.mu(i, j) += p.m * (p.phix[i] * p.phix[j] + p.phiy[i] * p.phiy[j]) / mh2;
        b.gamma(i, j) += p.m * (p.phix[i] * p.phiy[j] - p.phiy[i] * p.phix[j]) / mh2;
      }
    }
  }
  b.kappa = k / (M * g * h);
  return b;
}

/// A point-mass body with the data needed to check results mass by mass.
struct LumpedBody {
  std::vector<PointMass> pts;
  double x1 = 0, x2 = 0;  // [m] tipping points on the base line
  MatrixX k;              // [J] modal stiffness
  BodyParameters params() const { return lumped_body(pts, x1, x2, k); }
};

/// A random point-mass body with n modes: max(7, n) masses over a base [-b, b], heights up to ~2 m.
inline LumpedBody random_lumped(int n, unsigned seed, double stiffness_scale = 2e5,
                                double vertical_scale = 0.03) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  LumpedBody lb;
  const double half = 0.3 + 0.4 * u(rng);
  // enough masses for n independent planar modes
  const int masses = std::max(7, n);
  for (int k = 0; k < masses; ++k) {
    PointMass p;
    p.m = 50 + 200 * u(rng);
    p.x = half * (2 * u(rng) - 1) * 0.9;
    p.y = 0.1 + 1.9 * u(rng);
    for (int i = 0; i < n; ++i) {
      p.phix.push_back(0.1 * (2 * u(rng) - 1) * p.y);
      p.phiy.push_back(vertical_scale * (2 * u(rng) - 1) * p.y);
    }
    lb.pts.push_back(p);
  }
  MatrixX a(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) a(i, j) = 2 * u(rng) - 1;
  lb.k = stiffness_scale * (a * a.transpose() + n * MatrixX::Identity(n, n));
  lb.x1 = -half;
  lb.x2 = half;
  return lb;
}

inline BodyParameters random_lumped_body(int n, unsigned seed, double stiffness_scale = 2e5,
                                         double vertical_scale = 0.03) {
  return random_lumped(n, seed, stiffness_scale, vertical_scale).params();
}

/// A random point-mass body whose n modes are coupled and widely spread: every mode moves every
/// mass (horizontally and vertically), the modal mass m_ij = sum m phi_i.phi_j is full, and the
/// modal stiffness k = L Q diag(omega^2) Q^T L^T (m = L L^T, Q a random rotation) is full too, so
/// that the natural frequencies are exactly `hz` (ascending, [Hz]) and the eigenvectors of the
/// pinned-base problem are neither unit vectors nor orthogonal. `vertical_scale` sizes the vertical
/// shape components (a soft mode with a large vertical component sags g/omega^2 under gravity).
inline LumpedBody random_coupled(const std::vector<double>& hz, unsigned seed,
                                 double vertical_scale = 0.01) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = static_cast<int>(hz.size());
  LumpedBody lb;
  const double half = 0.3 + 0.4 * u(rng);
  const int masses = std::max(7, n);
  for (int k = 0; k < masses; ++k) {
    PointMass p;
    p.m = 50 + 200 * u(rng);
    p.x = half * (2 * u(rng) - 1) * 0.9;
    p.y = 0.1 + 1.9 * u(rng);
    for (int i = 0; i < n; ++i) {
      p.phix.push_back(0.1 * (2 * u(rng) - 1) * p.y);
      p.phiy.push_back(vertical_scale * (2 * u(rng) - 1) * p.y);
    }
    lb.pts.push_back(p);
  }
  MatrixX m = MatrixX::Zero(n, n);
  for (const auto& p : lb.pts)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) m(i, j) += p.m * (p.phix[i] * p.phix[j] + p.phiy[i] * p.phiy[j]);
  MatrixX r(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) r(i, j) = 2 * u(rng) - 1;
  const MatrixX q = Eigen::HouseholderQR<MatrixX>(r).householderQ();
  VectorX w2(n);
  for (int i = 0; i < n; ++i)
    w2(i) = std::pow(2 * 3.14159265358979323846 * hz[static_cast<std::size_t>(i)], 2);
  const MatrixX l = m.llt().matrixL();
  const MatrixX lq = l * q;
  lb.k = lq * w2.asDiagonal() * lq.transpose();
  lb.k = 0.5 * (lb.k + lb.k.transpose());
  lb.x1 = -half;
  lb.x2 = half;
  return lb;
}

/// n frequencies log-uniform over [lo, hi] Hz with both ends present (the widest spread),
/// ascending.
inline std::vector<double> spread_frequencies(int n, unsigned seed, double lo = 0.1,
                                              double hi = 1000.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> f;
  for (int i = 0; i < n; ++i) {
    const double s = n == 1 ? u(rng) : (i == 0 ? 0.0 : (i == n - 1 ? 1.0 : u(rng)));
    f.push_back(lo * std::pow(hi / lo, s));
  }
  std::sort(f.begin(), f.end());
  return f;
}

/// An elastic oscillator on a rocking base slab: top mass m at height H on a lateral spring k,
/// base slab of mass m0 and half-width b (uniform, thin, at the base). One mode: the top mass's
/// horizontal displacement u = h q.
struct Oscillator {
  double m = 1000, H = 2.0, m0 = 500, b = 0.5, k = 0, zeta = 0.05, g = kStandardGravity;
  double M() const { return m + m0; }
  double h() const { return m * H / M(); }
  double omega() const { return std::sqrt(k / m); }
  BodyParameters params() const {
    BodyParameters p;
    const double M_ = M(), h_ = h();
    p.mass = M_;
    p.height = h_;
    p.b1 = p.b2 = b;
    p.gravity = g;
    // slab: I = m0 (2b)^2/12 about its centre, a distance h_ below the c.g.
    p.zeta2 = (m * (H - h_) * (H - h_) + m0 * h_ * h_ + m0 * b * b / 3.0) / (M_ * h_ * h_);
    p.mu = MatrixX::Constant(1, 1, m / M_);
    p.kappa = MatrixX::Constant(1, 1, k * h_ / (M_ * g));
    p.gamma = MatrixX::Zero(1, 1);
    p.psi_x = VectorX::Constant(1, m / M_);
    p.psi_y = VectorX::Zero(1);
    p.delta = VectorX::Zero(1);
    p.beta = VectorX::Constant(1, -m * (H - h_) / (M_ * h_));
    p.damping.kind = DampingKind::kModal;
    p.damping.modal_ratios = VectorX::Constant(1, zeta);
    return p;
  }
};

}  // namespace flexrock::test
