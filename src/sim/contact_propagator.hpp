// SPDX-License-Identifier: BSD-3-Clause
// Exact propagation of a flexible body in full contact under a sampled record. Internal header.
//
// In full contact the modal equations are linear with constant coefficients (docs/theory.md,
// "Exact propagation in full contact"):
//   y' = A y + f(t),   y = (q, q_dot),   A = [0 I; -mu^-1 K  -mu^-1 C],
//   f = (0, -(g/h) mu^-1 (psi_x Xdd/g + psi_y (1 + Ydd/g))),
// and a sampled record is linear between samples, so f = f0 + f1 tau on each step. With the
// particular solution c0 + c1 tau (c1 = -A^-1 f1, c0 = A^-1 (c1 - f0)) the step is exact:
//   y(t0 + tau) = e^{A tau} (y0 - c0) + c0 + c1 tau,
// which is the Nigam-Jennings idea of response-spectrum codes. e^{A tau} = V e^{Lambda tau} V^-1
// from the eigenvectors of A, computed once per run; a body whose A is defective or nearly so
// (a mode damped exactly critically) is left to the integrator. The input work and the damping
// loss are Gauss-Legendre quadratures of their exact integrands.
//
// Hand-written: no packaged propagator takes piecewise-linear forcing with a dense output at
// arbitrary times, and Eigen's matrix exponential (unsupported/MatrixFunctions) costs a Pade
// approximant and a scaling-and-squaring per call, where this costs one complex exponential per
// eigenvalue and reuses those of the usual step length.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <vector>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/integrate/dopri5.hpp"
#include "flexrock/model/dynamics.hpp"

namespace flexrock::detail {

// The modes of the full-contact state matrix A, found once per run on dynamic sizes (one
// instantiation of the eigensolver for every body size keeps the build short).
struct ContactModes {
  Eigen::MatrixXcd v, v_inv;  // eigenvectors of A and their inverse
  Eigen::VectorXcd lambda;    // eigenvalues of A
  MatrixX a_inv;              // A^-1
  Eigen::VectorXcd scratch;   // e^{lambda tau}
  Eigen::MatrixXcd product;   // V e^{Lambda tau}
  Eigen::MatrixXcd full;      // V e^{Lambda tau} V^-1
  MatrixX transition;         // e^{A tau}, real
};

/// Decomposes A = V Lambda V^-1; false when A is (nearly) defective or singular, where the
/// body is integrated instead. (src/sim/contact_modes.cpp)
bool decompose_contact_matrix(const MatrixX& a, ContactModes& out);
/// out.transition = e^{A tau}; allocates nothing after the decomposition.
void contact_transition(ContactModes& modes, double tau);

template <int N, int MaxN, class State>
class ContactPropagator {
 public:
  static constexpr int Y = N == Eigen::Dynamic ? Eigen::Dynamic : 2 * N;
  static constexpr int MaxY = MaxN == Eigen::Dynamic ? Eigen::Dynamic : 2 * MaxN;
  using Real = Eigen::Matrix<double, Y, 1, Eigen::ColMajor, MaxY, 1>;
  using RealMat = Eigen::Matrix<double, Y, Y, Eigen::ColMajor, MaxY, MaxY>;
  using Cplx = Eigen::Matrix<std::complex<double>, Y, 1, Eigen::ColMajor, MaxY, 1>;
  using CplxMat = Eigen::Matrix<std::complex<double>, Y, Y, Eigen::ColMajor, MaxY, MaxY>;
  using Dyn = Dynamics<N, MaxN>;
  using Vec = typename Dyn::Vec;

  // the largest |lambda| tau of a step: keeps the event samples a fraction of the fastest
  // period apart and the 8-point Gauss-Legendre quadrature of the energies near round-off
  static constexpr double kMaxPhase = 1.5;
  static constexpr int kNodes = 8;

  ContactPropagator(const Dyn& dyn, const GroundMotion& motion, int samples, double max_step,
                    bool enabled)
      : dyn_(dyn), motion_(motion), n_(dyn.modes()), samples_(samples), max_step_(max_step) {
    if (!enabled || n_ == 0 || !motion.is_sampled()) return;
    const int m = 2 * n_;
    MatrixX a = MatrixX::Zero(m, m);
    a.topRightCorner(n_, n_).setIdentity();
    a.bottomLeftCorner(n_, n_) = -(dyn.mu_inverse() * dyn.stiffness());
    a.bottomRightCorner(n_, n_) = -(dyn.mu_inverse() * dyn.damping());
    if (!decompose_contact_matrix(a, modes_)) return;
    v_ = modes_.v;
    v_inv_ = modes_.v_inv;
    lambda_ = modes_.lambda;
    a_inv_ = modes_.a_inv;
    a_ = a;
    h_cap_ = kMaxPhase / lambda_.cwiseAbs().maxCoeff();
    gx_ = -dyn.g_over_h() * (dyn.mu_inverse() * dyn.psi_x()) / dyn.g();
    gy_ = -dyn.g_over_h() * (dyn.mu_inverse() * dyn.psi_y());
    for (Real* v : {&c0_, &c1_, &z_, &az_, &f_, &yt_, &yd_, &zd_}) v->setZero(m);
    ex_.setZero(m);
    w_.setZero(m);
    cache_.assign(static_cast<std::size_t>(samples_ + 1 + kNodes), RealMat::Zero(m, m));
    q_.setZero(n_);
    qd_.setZero(n_);
    available_ = true;
  }

  bool available() const { return available_; }

  void start(double t, const State& x) {
    t0_ = t1_ = t;
    x0_ = x;
    x1_ = x;
    xn_ = x;
  }

  /// One step from t1() to min(t_stop, t1() + max_step, the phase cap); never fails.
  template <class System>
  typename Dopri5<State>::Status step(System&& /*sys*/, double t_stop) {
    // equal steps across the rest of the interval, so that a uniform record's steps all have
    // one length and reuse one cache
    const double t = t1_;
    const double rest = t_stop - t, h_max = std::min(max_step_, h_cap_);
    const double pieces = std::max(1.0, std::ceil(rest / h_max - 1e-9));
    const double h = pieces == 1.0 ? rest : rest / pieces;
    propagate(t, x1_, h, xn_);
    t0_ = t;
    t1_ = t + h;
    x0_ = x1_;
    x1_ = xn_;
    return Dopri5<State>::Status::kAccepted;
  }

  /// Replaces the last step by one from its start to t_target (an event time within it).
  template <class System>
  void restep_to(System&& /*sys*/, double t_target) {
    propagate(t0_, x0_, t_target - t0_, xn_);
    t1_ = t_target;
    x1_ = xn_;
  }

  template <class System>
  void refresh_derivative(System&& /*sys*/, double /*t*/) {}

  /// The exact state at t in [t0(), t1()]; the input work and damping loss between the step's
  /// ends are cubic Hermite in their values and rates there (exact at the ends).
  void dense(double t, State& out) const {
    const double tau = t - t0_;
    at(tau, yd_);
    out = x0_;
    out.segment(1, n_) = yd_.head(n_);
    out.segment(n_ + 2, n_) = yd_.tail(n_);
    const double s = h_ > 0.0 ? tau / h_ : 0.0, s2 = s * s, s3 = s2 * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2,
                 h11 = s3 - s2;
    const int iw = 2 * n_ + 2, id = 2 * n_ + 3;
    out(iw) = h00 * x0_(iw) + h01 * x1_(iw) + h_ * (h10 * p0_ + h11 * p1_);
    out(id) = h00 * x0_(id) + h01 * x1_(id) + h_ * (h10 * d0_ + h11 * d1_);
  }

  double t0() const { return t0_; }
  double t1() const { return t1_; }
  const State& x0() const { return x0_; }
  const State& x1() const { return x1_; }

 private:
  // the base acceleration on [t, t + h] as a0 + slope tau, from two interior points: exact for
  // the linear pieces of a record, and blind to the jump where a record starts late or ends
  void forcing(double t, double h) {
    GroundMotion::Cursor& c = cursor_;
    const BaseAcceleration l = motion_.at(t + h / 3.0, c), r = motion_.at(t + 2.0 * h / 3.0, c);
    slope_ = {3.0 * (r.x - l.x) / h, 3.0 * (r.y - l.y) / h};
    a0_ = {l.x - slope_.x * h / 3.0, l.y - slope_.y * h / 3.0};
  }

  // f's lower half for a base acceleration
  Vec lower(BaseAcceleration a) const { return gx_ * a.x + gy_ * (1.0 + a.y / dyn_.g()); }

  void transition(double tau, RealMat& e) {
    contact_transition(modes_, tau);
    e = modes_.transition;
  }

  // the usual step length (a record interval, or a part of it): e^{A tau} at its event-sample
  // fractions and quadrature nodes, kept. Steps of a uniform record differ from it by rounding
  // (a few ulp of t); e^{A (tau + d)} z = e^{A tau} (z + d A z) + O((|lambda| d)^2) corrects that
  // to ~1e-20.
  bool usual(double h) const { return std::abs(h - cache_h_) <= 1e-9 * h; }
  void fill_cache(double h) {
    cache_h_ = h;
    for (int k = 0; k <= samples_; ++k)
      transition(h * k / samples_, cache_[static_cast<std::size_t>(k)]);
    for (int j = 0; j < kNodes; ++j)
      transition(h * kGaussX[j], cache_[static_cast<std::size_t>(samples_ + 1 + j)]);
  }

  // y(tau) in the current step: from the cache at the usual fractions, else from the modes
  void at(double tau, Real& y) const {
    if (cached_) {
      const double k = tau * samples_ / h_;
      const double kr = std::round(k);
      if (std::abs(k - kr) <= 1e-9 && kr >= 0 && kr <= samples_) {
        zd_ = z_ + (tau - kr * cache_h_ / samples_) * az_;
        y.noalias() = cache_[static_cast<std::size_t>(kr)] * zd_;
        y += c0_ + c1_ * tau;
        return;
      }
    }
    from_modes(tau, y);
  }

  // y(tau) = Re(V e^{Lambda tau} V^-1 z) + c0 + c1 tau, with V^-1 z formed once per step
  void from_modes(double tau, Real& y) const {
    if (!modal_ready_) {
      w_.noalias() = v_inv_ * z_.template cast<std::complex<double>>();
      modal_ready_ = true;
    }
    for (int i = 0; i < 2 * n_; ++i) ex_(i) = std::exp(lambda_(i) * tau) * w_(i);
    y.noalias() = (v_ * ex_).real();
    y += c0_ + c1_ * tau;
  }

  // input power and damping power at y and base acceleration a [W]
  void powers(const Real& y, BaseAcceleration a, double& p, double& d) {
    q_ = y.head(n_);
    qd_ = y.tail(n_);
    p = dyn_.input_power(0.0, 0.0, q_, 0.0, qd_, a);
    d = dyn_.damping_power(qd_);
  }

  void propagate(double t, const State& x, double h, State& out) {
    forcing(t, h);
    yt_.head(n_) = x.segment(1, n_);
    yt_.tail(n_) = x.segment(n_ + 2, n_);
    // particular solution c0 + c1 tau of y' = A y + f0 + f1 tau
    f_.head(n_).setZero();
    f_.tail(n_) = lower(slope_) - gy_;  // f1: the slope carries no gravity
    c1_.noalias() = -(a_inv_ * f_);
    f_.tail(n_) = lower(a0_);
    f_ = c1_ - f_;
    c0_.noalias() = a_inv_ * f_;
    z_ = yt_ - c0_;
    modal_ready_ = false;
    h_ = h;
    // the usual step fills the cache; a short one after an event computes its own
    if (!usual(h) && h >= 0.5 * std::min(max_step_, h_cap_)) fill_cache(h);
    cached_ = usual(h);
    if (cached_) az_.noalias() = a_ * z_;
    const int iw = 2 * n_ + 2, id = 2 * n_ + 3;
    powers(yt_, a0_, p0_, d0_);
    at(h, yd_);
    out = x;
    out.segment(1, n_) = yd_.head(n_);
    out.segment(n_ + 2, n_) = yd_.tail(n_);
    powers(yd_, {a0_.x + slope_.x * h, a0_.y + slope_.y * h}, p1_, d1_);
    // the energies by 8-point Gauss-Legendre on the exact integrands
    double work = 0.0, loss = 0.0;
    for (int j = 0; j < kNodes; ++j) {
      const double tau = h * kGaussX[j];
      if (cached_) {
        zd_ = z_ + (h - cache_h_) * kGaussX[j] * az_;
        yt_.noalias() = cache_[static_cast<std::size_t>(samples_ + 1 + j)] * zd_;
        yt_ += c0_ + c1_ * tau;
      } else {
        from_modes(tau, yt_);
      }
      double p = 0.0, d = 0.0;
      powers(yt_, {a0_.x + slope_.x * tau, a0_.y + slope_.y * tau}, p, d);
      work += kGaussW[j] * p;
      loss += kGaussW[j] * d;
    }
    out(iw) = x(iw) + h * work;
    out(id) = x(id) + h * loss;
  }

  // Gauss-Legendre nodes on [0, 1] and weights summing to 1
  static constexpr std::array<double, kNodes> kGaussX = {
      0.5 - 0.5 * 0.9602898564975363, 0.5 - 0.5 * 0.7966664774136267,
      0.5 - 0.5 * 0.5255324099163290, 0.5 - 0.5 * 0.1834346424956498,
      0.5 + 0.5 * 0.1834346424956498, 0.5 + 0.5 * 0.5255324099163290,
      0.5 + 0.5 * 0.7966664774136267, 0.5 + 0.5 * 0.9602898564975363};
  static constexpr std::array<double, kNodes> kGaussW = {
      0.5 * 0.1012285362903763, 0.5 * 0.2223810344533745, 0.5 * 0.3137066458778873,
      0.5 * 0.3626837833783620, 0.5 * 0.3626837833783620, 0.5 * 0.3137066458778873,
      0.5 * 0.2223810344533745, 0.5 * 0.1012285362903763};

  const Dyn& dyn_;
  const GroundMotion& motion_;
  int n_ = 0;
  int samples_ = 4;
  double max_step_ = 0.01;
  double h_cap_ = 0.0;
  bool available_ = false;
  ContactModes modes_;
  CplxMat v_, v_inv_;
  Cplx lambda_;
  mutable Cplx ex_;
  RealMat a_, a_inv_;
  mutable Cplx w_;  // V^-1 z of this step
  mutable bool modal_ready_ = false;
  std::vector<RealMat> cache_;  // e^{A tau} of the usual step: sample fractions, then nodes
  double cache_h_ = -1.0;
  bool cached_ = false;  // this step has the usual length
  Vec gx_, gy_, q_, qd_;
  Real c0_, c1_, z_, az_, f_, yt_;
  mutable Real yd_, zd_;
  GroundMotion::Cursor cursor_;
  BaseAcceleration a0_, slope_;
  double h_ = 0.0;
  double p0_ = 0.0, p1_ = 0.0, d0_ = 0.0, d1_ = 0.0;  // input and damping power at the ends [W]
  double t0_ = 0.0, t1_ = 0.0;
  State x0_, x1_, xn_;
};

// a rigid body has no modes: nothing to propagate (it is not integrated in full contact at all)
template <int MaxN, class State>
class ContactPropagator<0, MaxN, State> {
 public:
  template <class Dyn>
  ContactPropagator(const Dyn&, const GroundMotion&, int, double, bool) {}
  bool available() const { return false; }
  void start(double, const State&) {}
  template <class System>
  typename Dopri5<State>::Status step(System&&, double) {
    return Dopri5<State>::Status::kStepCollapsed;
  }
  template <class System>
  void restep_to(System&&, double) {}
  template <class System>
  void refresh_derivative(System&&, double) {}
  void dense(double, State&) const {}
  double t0() const { return 0.0; }
  double t1() const { return 0.0; }
  const State& x0() const { return x_; }
  const State& x1() const { return x_; }

 private:
  State x_;
};

}  // namespace flexrock::detail
