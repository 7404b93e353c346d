// SPDX-License-Identifier: BSD-3-Clause
// The pinned-base modes of the full-contact equations and the exact step of one mode, for the
// exact propagation (contact_propagator.hpp).
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>

#include "contact_propagator.hpp"

namespace flexrock::detail {

bool decompose_contact_matrix(const MatrixX& mu, const MatrixX& k, const MatrixX& c,
                              ContactModes& out) {
  const Eigen::Index n = mu.rows();
  if (n == 0 || !mu.allFinite() || !k.allFinite() || !c.allFinite()) return false;
  // K phi = omega^2 mu phi with phi^T mu phi = I: a mu-orthonormal basis, so the change of
  // coordinates is perfectly conditioned in the energy norm whatever the spread of frequencies
  Eigen::GeneralizedSelfAdjointEigenSolver<MatrixX> ges(k, mu);
  if (ges.info() != Eigen::Success) return false;
  const VectorX w2 = ges.eigenvalues();
  if (!(w2.minCoeff() > 0.0) || !w2.allFinite()) return false;
  out.from_modal = ges.eigenvectors();
  out.to_modal = out.from_modal.transpose() * mu;
  out.omega = w2.cwiseSqrt();
  // the damping must decouple the modes (Rayleigh and modal damping do, up to rounding): a
  // coupled damping matrix is left to the integrator
  const MatrixX d = out.from_modal.transpose() * c * out.from_modal;
  const double scale = std::max(d.cwiseAbs().maxCoeff(), 1e-300);
  out.damping = d.diagonal();
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      if (i != j && !(std::abs(d(i, j)) <= 1e-9 * scale)) return false;
    }
    if (!(out.damping(i) >= -1e-12 * scale)) return false;
    out.damping(i) = std::max(out.damping(i), 0.0);
  }
  // the largest |eigenvalue| of a mode's 2x2 matrix [0 w; -w -c]: w underdamped, else the fast
  // real root (c + sqrt(c^2 - 4 w^2)) / 2
  out.rate = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double w = out.omega(i), cd = out.damping(i);
    const double r = cd <= 2.0 * w ? w : 0.5 * (cd + std::sqrt(cd * cd - 4.0 * w * w));
    out.rate = std::max(out.rate, r);
  }
  return std::isfinite(out.rate) && out.rate > 0.0;
}

void mode_step(double omega, double damping, double tau, ModeStep& out) {
  // e^{X}, phi1(X) = sum X^k/(k+1)! and phi2(X) = sum X^k/(k+2)! of X = B t, t = tau / 2^s,
  // by their Taylor series where |X| <= 1/2 (every term positive in norm, no cancellation), then
  // doubled s times:  E(2t) = E(t)^2,  I1(2t) = (I + E(t)) I1(t),
  // I2(2t) = (I + E(t)) I2(t) + t I1(t)  for I1 = int_0^t e^{Bs} ds = t phi1 and
  // I2 = int_0^t e^{B(t-s)} s ds = t^2 phi2 (only their velocity columns: the forcing's).
  // Equal to Van Loan's exponential of [B t, I, 0; 0, 0, I; 0, 0, 0] in long double to 2e-15
  // for |B tau| up to the propagator's step cap (1.5), at a fraction of its cost.
  const double norm = tau * std::max(omega, omega + damping);  // >= |B tau| (inf-norm)
  int s = 0;
  if (norm > 0.5) s = std::max(0, static_cast<int>(std::ceil(std::log2(norm / 0.5))));
  const double t = std::ldexp(tau, -s);
  Eigen::Matrix2d x;
  x << 0.0, omega * t, -omega * t, -damping * t;
  // 1/k, 1/(k+1) and 1/((k+1)(k+2)): no division in the loop
  static constexpr int kTerms = 30;
  static constexpr auto inv = [] {
    std::array<std::array<double, 3>, kTerms> r{};
    for (int k = 1; k < kTerms; ++k) {
      const double kk = static_cast<double>(k);
      r[static_cast<std::size_t>(k)] = {1.0 / kk, 1.0 / (kk + 1.0),
                                        1.0 / ((kk + 1.0) * (kk + 2.0))};
    }
    return r;
  }();
  // only the velocity columns of phi1 and phi2 are needed (the forcing's)
  Eigen::Matrix2d term = Eigen::Matrix2d::Identity(), e = term;
  Eigen::Vector2d i1(0.0, 1.0), i2(0.0, 0.5);
  for (int k = 1; k < kTerms; ++k) {
    const auto& c = inv[static_cast<std::size_t>(k)];
    term = (term * x) * c[0];
    e += term;
    i1 += term.col(1) * c[1];
    i2 += term.col(1) * c[2];
    if (term.cwiseAbs().maxCoeff() < 1e-18) break;
  }
  i1 *= t;
  i2 *= t * t;
  double ti = t;
  for (int j = 0; j < s; ++j) {
    const Eigen::Vector2d i1_old = i1;
    i2 += e * i2 + ti * i1_old;
    i1 += e * i1_old;
    e = e * e;
    ti *= 2.0;
  }
  out.e = e;
  out.p1 = i1;
  out.p2 = i2;
}

}  // namespace flexrock::detail
