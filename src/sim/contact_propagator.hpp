// SPDX-License-Identifier: BSD-3-Clause
// Exact propagation of a flexible body in full contact under a sampled record. Internal header.
//
// In full contact the modal equations are linear with constant coefficients (docs/theory.md,
// "Exact propagation in full contact"):
//   mu q'' + C q' + K q = -(g/h) (psi_x Xdd/g + psi_y (1 + Ydd/g)),
// and a sampled record is linear between samples. In the pinned-base modes (K phi = w^2 mu phi,
// phi^T mu phi = I; C decouples them) each mode is a 2x2 system in energy coordinates
//   s = (w (eta - eta_static), eta'),   s' = [0 w; -w -c] s + (0, g0 + g1 tau),
// whose exact step s(tau) = e^{B tau} s0 + tau phi1(B tau) (0, g0) + tau^2 phi2(B tau) (0, g1)
// comes from the Taylor series of e^X, phi1 and phi2 at |X| <= 1/2 and doubling (mode_step; equal
// to Van Loan's 6x6 exponential to 2e-15 for |B tau| up to the step cap). Nothing is inverted or
// cancelled: the change of coordinates is orthonormal in the energy norm and |e^{B tau}| <= 1, so
// the rounding of a step is a few ulp of the state's energy however far apart the frequencies
// are. (The former V e^{Lambda tau} V^-1 (y0 - c0) + c0 + c1 tau on the first-order system lost
// digits twice: cond(V) ~ 1e4-1e5 on coupled, widely spread modes, times a particular solution
// c0 ~ 1e4 times the state.) The input work and the damping loss are Gauss-Legendre quadratures
// of their exact integrands.
//
// Hand-written: no packaged propagator takes piecewise-linear forcing with a dense output at
// arbitrary times; the usual step's exponentials are computed once and kept.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/integrate/dopri5.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/model/dynamics.hpp"

namespace flexrock::detail {

// The pinned-base modes of the full-contact equations, found once per run on dynamic sizes.
struct ContactModes {
  MatrixX from_modal;  // phi: q = phi eta
  MatrixX to_modal;    // phi^T mu: eta = phi^T mu q
  VectorX omega;       // [rad/s] pinned-base frequencies
  VectorX damping;     // [1/s] c_i = phi_i^T C phi_i
  double rate = 0.0;   // [1/s] the largest |eigenvalue| of the full-contact equations
};

// The exact step of one mode over tau: e^{B tau}, and the velocity columns of tau phi1(B tau)
// and tau^2 phi2(B tau) (s = (w (eta - eta_static), eta'))
struct ModeStep {
  Eigen::Matrix2d e = Eigen::Matrix2d::Zero();
  Eigen::Vector2d p1 = Eigen::Vector2d::Zero();
  Eigen::Vector2d p2 = Eigen::Vector2d::Zero();
};

/// The mu-orthonormal pinned-base modes of (mu, K, C); false when they cannot be found or C does
/// not decouple them, where the body is integrated instead. (src/sim/contact_modes.cpp)
bool decompose_contact_matrix(const MatrixX& mu, const MatrixX& k, const MatrixX& c,
                              ContactModes& out);
/// The exact step of the mode (omega, damping) over tau; allocates nothing.
void mode_step(double omega, double damping, double tau, ModeStep& out);
/// e^{B tau} of the mode (omega, damping) in closed form (one sincos or sinh/cosh and one exp):
/// with B = [0 w; -w -c] and k^2 = w^2 - c^2/4,
///   e^{B tau} = e^{-c tau/2} (C(tau) I + S(tau) (B + c/2 I)),
/// C = cos k tau, S = sin(k tau)/k (cosh, sinh(|k| tau)/|k| where k^2 < 0; 1, tau at k = 0).
inline Eigen::Matrix2d mode_exponential(double omega, double damping, double tau) {
  const double half = 0.5 * damping, k2 = omega * omega - half * half;
  double cs = 1.0, sn = tau;
  if (k2 > 0.0) {
    const double k = std::sqrt(k2);
    cs = std::cos(k * tau);
    sn = std::sin(k * tau) / k;
  } else if (k2 < 0.0) {
    const double k = std::sqrt(-k2);
    cs = std::cosh(k * tau);
    sn = std::sinh(k * tau) / k;
  }
  const double decay = std::exp(-half * tau);
  Eigen::Matrix2d e;
  e << decay * (cs + sn * half), decay * sn * omega, -decay * sn * omega, decay * (cs - sn * half);
  return e;
}

template <int N, int MaxN, class State>
class ContactPropagator {
 public:
  using Dyn = Dynamics<N, MaxN>;
  using Vec = typename Dyn::Vec;
  using Mat = typename Dyn::Mat;

  // the largest |lambda| tau of a step: keeps the event samples a fraction of the fastest
  // period apart and the 8-point Gauss-Legendre quadrature of the energies near round-off
  static constexpr double kMaxPhase = 1.5;
  static constexpr int kNodes = 8;

  ContactPropagator(const Dyn& dyn, const GroundMotion& motion, int samples, double max_step,
                    bool enabled)
      : dyn_(dyn), motion_(motion), n_(dyn.modes()), samples_(samples), max_step_(max_step) {
    if (!enabled || n_ == 0 || !motion.is_sampled()) return;
    ContactModes modes;
    if (!decompose_contact_matrix(dyn.mu(), dyn.stiffness(), dyn.damping(), modes)) return;
    from_modal_ = modes.from_modal;
    to_modal_ = modes.to_modal;
    user_from_modal_ = from_modal_;
    omega_ = modes.omega;
    damp_ = modes.damping;
    h_cap_ = kMaxPhase / modes.rate;
    rate_ = modes.rate;
    // the modal forcing per unit base acceleration, and gravity's static part
    gxm_ = -dyn.g_over_h() * (from_modal_.transpose() * dyn.psi_x()) / dyn.g();
    gym_ = -dyn.g_over_h() * (from_modal_.transpose() * dyn.psi_y());
    // the static state of these very equations, K q_s = -(g/h) psi_y, solved to a few ulp: the
    // soft modes' w^2 from the eigensolver are off by ~ulp(w_max^2), and their gym / w^2 would
    // put the equilibrium of a 0.1 Hz mode beside a 1 kHz one 1e-8 of its sag away, where the
    // body at rest would start to swing
    const VectorX q_static = solve_refined(dyn.stiffness(), VectorX(-dyn.g_over_h() * dyn.psi_y()));
    eta_static_ = to_modal_ * q_static;
    inv_omega_ = omega_.cwiseInverse();
    // the input and damping powers in the modes: -M h a.(psi . q_dot) and M h^2 sum c_i eta_i'^2
    pxm_ = from_modal_.transpose() * dyn.psi_x();
    pym_ = from_modal_.transpose() * dyn.psi_y();
    mh_ = dyn.mass() * dyn.height();
    mh2_ = mh_ * dyn.height();
    for (Vec* v : {&g0_, &g1_, &sd0_, &sv0_, &eta_, &etad_, &q_, &qd_, &qo_, &qdo_}) v->setZero(n_);
    const auto cells =
        static_cast<std::size_t>(samples_ + 1 + kNodes) * static_cast<std::size_t>(n_);
    cache_.assign(cells, ModeStep{});
    scratch_.assign(static_cast<std::size_t>(n_), ModeStep{});
    // the walk's modal coupling and its storage, sized once (a run allocates nothing)
    betam_ = from_modal_.transpose() * dyn.beta();
    gamma_norm_ = (from_modal_.transpose() * dyn.gamma() * from_modal_).norm();
    for (Vec* v : {&wd_, &wv_, &bm_, &hom_, &acc_hom_, &dev2_, &p0d_, &p0v_, &hd_, &hv_})
      v->setZero(n_);
    for (Vec& b : bound_) b.setZero(n_);
    for (Vec& j : jet_) j.setZero(n_);
    for (Piece& p : pieces_) p.steps.assign(static_cast<std::size_t>(kPoints * n_), ModeStep{});
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
    at(tau, qo_, qdo_);
    out = x0_;
    out.segment(1, n_) = qo_;
    out.segment(n_ + 2, n_) = qdo_;
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

  // ---- the record walk (docs/theory.md, "Walking the record"): one exact update per record
  // interval, in the modes; the energies exactly from the interval's ends; and bounds over it on
  // the excursion of the guards from their chord between its ends

  // bounds on |f - (its chord)| over a part of the last piece, in evaluate()'s units
  struct Excursion {
    double fi = 0.0, fj = 0.0;  // floor reaction over M g
    double u1 = 0.0, u2 = 0.0;  // uplift functions over M g h
    double moment = 0.0;        // moment about the c.g. projection over M g h
  };

  // the longest piece, in radians of the fastest mode: the doublings of mode_step stay few (7),
  // so a piece's update keeps the accuracy of the stepped propagation's
  static constexpr double kWalkPhase = 64.0;
  // the points across a piece kept for the extremes' search: tau = h k / kPoints, 0 < k < kPoints
  static constexpr int kPoints = 8;

  /// The longest piece of the walk [s] (the guards are bounded between its ends, not sampled).
  double walk_cap() const { return kWalkPhase / rate_; }

  /// Starts the walk at the state x.
  void walk_start(const State& x) {
    q_ = x.segment(1, n_);
    qd_ = x.segment(n_ + 2, n_);
    eta_.noalias() = to_modal_ * q_;
    wv_.noalias() = to_modal_ * qd_;
    wd_ = omega_.cwiseProduct(eta_ - eta_static_);
    ww_ = x(2 * n_ + 2);
    wl_ = x(2 * n_ + 3);
  }

  /// One exact piece of length h under the base acceleration a0 + slope tau: the modal state at
  /// its end, the input work and damping loss across it, and the bounds over it.
  /// `keep`: keep the piece length's steps for later pieces (false: a length met once).
  void walk_piece(double h, BaseAcceleration a0, BaseAcceleration slope, bool keep = true) {
    sd0_ = wd_;
    sv0_ = wv_;
    a0_ = a0;
    slope_ = slope;
    h_ = h;
    g0_ = gxm_ * a0.x + gym_ * (a0.y / dyn_.g());
    g1_ = gxm_ * slope.x + gym_ * (slope.y / dyn_.g());
    const Piece& pc = piece(h, keep);
    piece_ = &pc;
    // a piece differing from the kept length by rounding: s(h + d) = s(h) + d s'(h)
    const double d = h - pc.h;
    double work = 0.0, loss = 0.0;
    for (int i = 0; i < n_; ++i) {
      const double g = g0_(i), g1 = g1_(i), x0 = sd0_(i), v0 = sv0_(i);
      const double w = omega_(i), c = damp_(i);
      double sd = 0.0, sv = 0.0;
      from_start(pc.steps[static_cast<std::size_t>(i)], i, sd, sv);
      nudge(i, pc.h, d, sd, sv);
      wd_(i) = sd;
      wv_(i) = sv;
      // the energies exactly from the ends (docs/theory.md): s_v = (s_d/w)' and the mode's
      // equation give int s_d, then int g s_v by parts, and the mode's energy balance
      // d|s|^2/2 = g s_v - c s_v^2 the damping's share
      const double wi = inv_omega_(i);
      const double int_sd = (g * h + 0.5 * g1 * h * h - c * (sd - x0) * wi - (sv - v0)) * wi;
      const double input = ((g + g1 * h) * sd - g * x0 - g1 * int_sd) * wi;
      work += input;
      if (c > 0.0) loss += input - 0.5 * ((sd * sd + sv * sv) - (x0 * x0 + v0 * v0));
      // the piece's bounds: |e^{B tau}| <= 1 (B + B^T = diag(0, -2c) <= 0), so |s| stays below
      // |s(0)| + h max|g|; each derivative of s' = B s + (0, g0 + g1 tau) multiplies by at most
      // |B| <= w + c and adds the forcing's term (docs/theory.md)
      const double gmax = std::max(std::abs(g), std::abs(g + g1 * h));
      // |s| by sqrt, not hypot: modal states are far from hypot's overflow range, and hypot's
      // care costs 50 instructions a call, three a mode and piece
      const double s0 = std::sqrt(x0 * x0 + v0 * v0) + h * gmax, b = w + c;
      const double s1 = b * s0 + gmax, s2 = b * s1 + std::abs(g1), s3 = b * s2;
      bound_[0](i) = s0 * wi + std::abs(eta_static_(i));  // |eta|
      bound_[1](i) = s0;                                  // |eta'|  <= |s|
      bound_[2](i) = s1;                                  // |eta''| <= |s'|
      bound_[3](i) = s2;
      bound_[4](i) = s3;
      // the free part: s minus the particular solution s_p = P0 + P1 tau of the linear forcing,
      // P1 = (g1/w, 0), P0 = (g0/w - c g1/w^3, g1/w^2); its norm never grows, and eta'' is its
      // alone: |eta - eta_p| <= hom/w, |eta''| <= |(w, c)| hom
      p0d_(i) = (g - c * g1 * wi * wi) * wi;
      p0v_(i) = g1 * wi * wi;
      hd_(i) = x0 - p0d_(i);
      hv_(i) = v0 - p0v_(i);
      hom_(i) = std::sqrt(hd_(i) * hd_(i) + hv_(i) * hv_(i));
      acc_hom_(i) = std::sqrt(w * w + c * c) * hom_(i);
    }
    ww_ += mh2_ * work;
    wl_ += mh2_ * loss;
  }

  /// The walk's state into x: q, q_dot, input work and damping loss (the rest is left as is).
  void walk_state(State& x) const {
    eta_ = wd_.cwiseProduct(inv_omega_) + eta_static_;
    x.segment(1, n_).noalias() = from_modal_ * eta_;
    x.segment(n_ + 2, n_).noalias() = from_modal_ * wv_;
    x(2 * n_ + 2) = ww_;
    x(2 * n_ + 3) = wl_;
  }

  /// q and q_dot at tau within the last piece into x, exactly (the energies are left as is).
  void walk_dense(double tau, State& x) const {
    // at a kept point of the piece length, from its steps; elsewhere computed
    const double k = tau * kPoints / h_, kr = std::round(k);
    if (piece_ != nullptr && std::abs(k - kr) <= 1e-9 && kr >= 1.0 && kr < kPoints) {
      const double tk = kr * piece_->h / kPoints;
      eval(&piece_->steps[static_cast<std::size_t>(kr) * static_cast<std::size_t>(n_)], tk,
           tau - tk, qo_, qdo_);
    } else {
      modal_at(tau);
      qo_.noalias() = Dyn::mv(from_modal_, eta_);
      qdo_.noalias() = Dyn::mv(from_modal_, etad_);
    }
    x.segment(1, n_) = qo_;
    x.segment(n_ + 2, n_) = qdo_;
  }

  /// The deformation as the run reports it, u = T q (the body's coordinates, where the state's
  /// are its modal ones): walk_q and walk_q_excursion are of u.
  void output_basis(const Mat& t) {
    if (available()) user_from_modal_ = t * from_modal_;
  }
  /// u_j and its first two time derivatives at tau within the last piece, exactly: what the
  /// search for u_j's extreme needs of walk_dense, without the other components. The modes'
  /// equation s' = B s + (0, g0 + g1 tau) gives eta' = s_v and eta'' = -w s_d - c s_v + g0 + g1
  /// tau.
  std::array<double, 3> walk_q_jet(double tau, int j) const {
    std::array<double, 3> u{0.0, 0.0, 0.0};
    const int kept = kept_index(tau);
    for (int i = 0; i < n_; ++i) {
      double sd = 0.0, sv = 0.0;
      mode_at(i, tau, kept, sd, sv);
      const double r = user_from_modal_(j, i);
      u[0] += r * (sd * inv_omega_(i) + eta_static_(i));
      u[1] += r * sv;
      u[2] += r * (-omega_(i) * sd - damp_(i) * sv + g0_(i) + g1_(i) * tau);
    }
    return u;
  }

  /// q (the state's coordinates) and its first four time derivatives at tau within the last
  /// piece, exactly, into d[0..4]: eta' = s_v, eta'' = -w s_d - c s_v + g0 + g1 tau, and
  /// differentiating the modes' equation, eta''' = -w^2 eta' - c eta'' + g1 and
  /// eta'''' = -w^2 eta'' - c eta'''. The base acceleration there is walk_base(tau).
  void walk_q_derivatives(double tau, std::array<Vec, 5>& d) const {
    const int kept = kept_index(tau);
    for (int i = 0; i < n_; ++i) {
      double sd = 0.0, sv = 0.0;
      mode_at(i, tau, kept, sd, sv);
      const double w = omega_(i), c = damp_(i), w2 = w * w;
      const double e2 = -w * sd - c * sv + g0_(i) + g1_(i) * tau, e3 = -w2 * sv - c * e2 + g1_(i);
      jet_[0](i) = sd * inv_omega_(i) + eta_static_(i);
      jet_[1](i) = sv;
      jet_[2](i) = e2;
      jet_[3](i) = e3;
      jet_[4](i) = -w2 * e2 - c * e3;
    }
    for (std::size_t k = 0; k < 5; ++k) d[k].noalias() = Dyn::mv(from_modal_, jet_[k]);
  }
  /// The base acceleration at tau within the last piece [m/s^2], and its rate [m/s^3].
  BaseAcceleration walk_base(double tau) const {
    return {a0_.x + slope_.x * tau, a0_.y + slope_.y * tau};
  }
  BaseAcceleration walk_slope() const { return slope_; }

  /// Bounds on the excursion from their chord, over any part of length w of the last piece, of the
  /// floor reaction, the uplift functions and the moment about the c.g. projection. They are
  /// quadratic in (q, q'', a) with a linear in time:
  ///   F_I = a_x + psi_x.q''/(g/h),  F_J = a_y + psi_y.q''/(g/h),
  ///   R(al) = (b(al) + Gamma^T q).q''/(g/h) + (-al + psi_x.q) a_y - (1 + psi_y.q) a_x
  /// (a_x = X''/g, a_y = 1 + Y''/g, b(al) = beta - al psi_y - psi_x). Each term is bounded by
  /// the less of two bounds: |f''| w^2/8 (through the bounds on eta^(k); fits the slow modes) and
  /// twice the largest value of its free part (fits the fast ones, whose curvature is large but
  /// whose amplitude is not); the chord of a term linear in time is the term itself.
  /// `ax`, `ay`: max |a_x|, |a_y| over the piece; `dax`, `day`: |a_x'|, |a_y'| [1/s].
  Excursion walk_excursion(double w, double ax, double ay, double dax, double day) const {
    const double w8 = 0.125 * w * w, w4 = 0.25 * w * w;
    double fi = 0.0, fj = 0.0, rest = 0.0;
    for (int i = 0; i < n_; ++i) {
      const double d2 = std::min(w8 * bound_[4](i), 2.0 * acc_hom_(i));  // eta_i''
      dev2_(i) = d2;
      const double px = std::abs(pxm_(i)), py = std::abs(pym_(i));
      fi += px * d2;
      fj += py * d2;
      // psi_x.q a_y and psi_y.q a_x, mode by mode: the particular part times a_y is quadratic
      // (eta_p' = P1_d / w = g1/w^2 = P0_v)
      const double free = 2.0 * hom_(i) * inv_omega_(i), lin = std::abs(p0v_(i)) * w4;
      rest +=
          px * std::min(w8 * (bound_[2](i) * ay + 2.0 * bound_[1](i) * day), free * ay + lin * day);
      rest +=
          py * std::min(w8 * (bound_[2](i) * ax + 2.0 * bound_[1](i) * dax), free * ax + lin * dax);
    }
    const double gh = dyn_.g_over_h();
    // eta.G eta'' (G = phi^T Gamma phi), eta'' being the free part's alone
    const double n0 = bound_[0].norm(), n1 = bound_[1].norm(), n2 = bound_[2].norm(),
                 n3 = bound_[3].norm(), n4 = bound_[4].norm();
    const double quad = gamma_norm_ * std::min(w8 * (n0 * n4 + 2.0 * n1 * n3 + n2 * n2),
                                               2.0 * n0 * acc_hom_.norm());
    auto moment = [&](double al) {
      bm_ = betam_ - al * pym_ - pxm_;
      return (bm_.cwiseAbs().dot(dev2_) + quad) / gh + rest;
    };
    Excursion e;
    e.fi = fi / gh;
    e.fj = fj / gh;
    e.u1 = moment(-dyn_.alpha1());
    e.u2 = moment(dyn_.alpha2());
    e.moment = moment(0.0);
    return e;
  }

  /// Bounds on the values themselves over the whole last piece, from the modes' bounds alone (no
  /// value at its ends): |F_I| <= fi, fj_lo <= F_J <= fj_hi, |R(0)| <= moment, in evaluate()'s
  /// units. A piece within them, with every guard and extreme clear, needs no evaluation at all
  /// (docs/theory.md, "Walking the record"). `ax`: max |a_x|; `ay_lo`, `ay_hi`: a_y's range.
  struct Reach {
    double fi = 0.0, fj_lo = 0.0, fj_hi = 0.0, moment = 0.0;
  };
  Reach walk_reach(double ax, double ay_lo, double ay_hi) const {
    double px2 = 0.0, py2 = 0.0, b2 = 0.0, px0 = 0.0, py0 = 0.0;
    for (int i = 0; i < n_; ++i) {
      const double e0 = bound_[0](i), e2 = bound_[2](i);  // |eta_i|, |eta_i''|
      px2 += std::abs(pxm_(i)) * e2;
      py2 += std::abs(pym_(i)) * e2;
      b2 += std::abs(betam_(i) - pxm_(i)) * e2;  // b(0) = beta - psi_x
      px0 += std::abs(pxm_(i)) * e0;
      py0 += std::abs(pym_(i)) * e0;
    }
    const double gh = dyn_.g_over_h();
    Reach r;
    r.fi = ax + px2 / gh;
    r.fj_lo = ay_lo - py2 / gh;
    r.fj_hi = ay_hi + py2 / gh;
    // R(0) = (b(0) + Gamma^T q).q''/(g/h) + psi_x.q a_y - (1 + psi_y.q) a_x, term by term
    const double quad = gamma_norm_ * bound_[0].norm() * bound_[2].norm();
    r.moment =
        (b2 + quad) / gh + px0 * std::max(std::abs(ay_lo), std::abs(ay_hi)) + (1.0 + py0) * ax;
    return r;
  }
  /// A bound on |u_j| over the whole last piece.
  double walk_q_reach(int j) const {
    double e = 0.0;
    for (int i = 0; i < n_; ++i) e += std::abs(user_from_modal_(j, i)) * bound_[0](i);
    return e;
  }

  /// A bound on the excursion of u_j from its chord over any part of length w of the last piece.
  double walk_q_excursion(int j, double w) const {
    const double w8 = 0.125 * w * w;
    double e = 0.0;
    for (int i = 0; i < n_; ++i)
      e += std::abs(user_from_modal_(j, i)) *
           std::min(w8 * bound_[2](i), 2.0 * hom_(i) * inv_omega_(i));
    return e;
  }

 private:
  // the modal state (eta_, etad_) at tau within the last piece, as the particular solution plus
  // the free part, s = P0 + P1 tau + e^{B tau} (s(0) - P0), by the closed form of e^{B tau}
  void modal_at(double tau) const {
    for (int i = 0; i < n_; ++i) {
      double sd = 0.0, sv = 0.0;
      mode_at(i, tau, -1, sd, sv);
      eta_(i) = sd * inv_omega_(i) + eta_static_(i);
      etad_(i) = sv;
    }
  }
  // mode i's s = (s_d, s_v) at tau within the last piece
  // `kept`: where tau lies (kept_index); at the piece's start, end or kept points s comes from
  // what the piece already holds, s(tk + d) = s(tk) + d s'(tk) for the rounding d of tau
  void mode_at(int i, double tau, int kept, double& sd, double& sv) const {
    if (kept < 0) {
      const Eigen::Matrix2d e = mode_exponential(omega_(i), damp_(i), tau);
      sd = e(0, 0) * hd_(i) + e(0, 1) * hv_(i) + p0d_(i) + g1_(i) * inv_omega_(i) * tau;
      sv = e(1, 0) * hd_(i) + e(1, 1) * hv_(i) + p0v_(i);
      return;
    }
    double tk = 0.0;
    if (kept == 0) {
      sd = sd0_(i);
      sv = sv0_(i);
    } else if (kept == kPoints) {
      tk = h_;
      sd = wd_(i);
      sv = wv_(i);
    } else {
      tk = kept * piece_->h / kPoints;
      from_start(piece_->steps[static_cast<std::size_t>(kept) * static_cast<std::size_t>(n_) +
                               static_cast<std::size_t>(i)],
                 i, sd, sv);
    }
    nudge(i, tk, tau - tk, sd, sv);
  }
  // mode i's s at the end of its step m from the start of the current step or piece (sd0_, sv0_)
  // under the forcing g0 + g1 tau
  void from_start(const ModeStep& m, int i, double& sd, double& sv) const {
    const double g = g0_(i), g1 = g1_(i), x0 = sd0_(i), v0 = sv0_(i);
    sd = m.e(0, 0) * x0 + m.e(0, 1) * v0 + m.p1(0) * g + m.p2(0) * g1;
    sv = m.e(1, 0) * x0 + m.e(1, 1) * v0 + m.p1(1) * g + m.p2(1) * g1;
  }
  // mode i's s at tk + d from s at tk: s + d s'(tk), s' = B s + (0, g0 + g1 tk), for a time off
  // a kept one by rounding (the error O((|lambda| d)^2) is ~1e-20)
  void nudge(int i, double tk, double d, double& sd, double& sv) const {
    if (d == 0.0) return;
    const double w = omega_(i), dsd = w * sv, dsv = -w * sd - damp_(i) * sv + g0_(i) + g1_(i) * tk;
    sd += d * dsd;
    sv += d * dsv;
  }
  // where tau lies in the last piece, for mode_at: its start (0), a kept point (1 to kPoints - 1),
  // its end (kPoints), within rounding; elsewhere -1
  int kept_index(double tau) const {
    if (piece_ == nullptr || !(h_ > 0.0)) return -1;
    const double k = tau * kPoints / h_, kr = std::round(k);
    if (!(std::abs(k - kr) <= 1e-9) || kr < 0.0 || kr > kPoints) return -1;
    return static_cast<int>(kr);
  }

  // a piece length's steps of the modes: at its end, then at its kept points h k / kPoints
  struct Piece {
    double h = -1.0;
    std::vector<ModeStep> steps;
  };
  static constexpr int kPieces = 8;  // piece lengths kept (a uniform record needs one or two)
  const Piece& piece(double h, bool keep) {
    for (int k = 0; k < pieces_used_; ++k) {
      const Piece& p = pieces_[static_cast<std::size_t>(k)];
      if (std::abs(h - p.h) <= 1e-9 * h) return p;
    }
    // a new length: kept while there is room, else computed for this piece alone
    Piece& p = keep && pieces_used_ < kPieces ? pieces_[static_cast<std::size_t>(pieces_used_++)]
                                              : pieces_[static_cast<std::size_t>(kPieces)];
    p.h = h;
    for (int k = 0; k < kPoints; ++k) {
      const double tau = k == 0 ? h : h * k / kPoints;
      for (int i = 0; i < n_; ++i)
        mode_step(omega_(i), damp_(i), tau, p.steps[static_cast<std::size_t>(k * n_ + i)]);
    }
    return p;
  }

  // the base acceleration on [t, t + h] as a0 + slope tau, from two interior points: exact for
  // the linear pieces of a record, and blind to the jump where a record starts late or ends
  void forcing(double t, double h) {
    GroundMotion::Cursor& c = cursor_;
    const BaseAcceleration l = motion_.at(t + h / 3.0, c), r = motion_.at(t + 2.0 * h / 3.0, c);
    slope_ = {3.0 * (r.x - l.x) / h, 3.0 * (r.y - l.y) / h};
    a0_ = {l.x - slope_.x * h / 3.0, l.y - slope_.y * h / 3.0};
  }

  // the usual step length (a record interval, or a part of it): the modes' steps at its
  // event-sample fractions and quadrature nodes, kept. Steps of a uniform record differ from it
  // by rounding (a few ulp of t); s(tau + d) = s(tau) + d s'(tau) + O((|lambda| d)^2) corrects
  // that to ~1e-20.
  bool usual(double h) const { return std::abs(h - cache_h_) <= 1e-9 * h; }
  void fill_cache(double h) {
    cache_h_ = h;
    for (int k = 0; k <= samples_ + kNodes; ++k) {
      const double tau = k <= samples_ ? h * k / samples_ : h * kGaussX[k - samples_ - 1];
      for (int i = 0; i < n_; ++i) mode_step(omega_(i), damp_(i), tau, cell(k, i));
    }
  }
  ModeStep& cell(int k, int i) {
    return cache_[static_cast<std::size_t>(k) * static_cast<std::size_t>(n_) +
                  static_cast<std::size_t>(i)];
  }
  const ModeStep* row(int k) const {
    return &cache_[static_cast<std::size_t>(k) * static_cast<std::size_t>(n_)];
  }

  // the input and damping powers [W] at tau in the current step (base acceleration a), from the
  // modes' steps `ms` at tau_k = tau - d, without going back to q
  void node_powers(const ModeStep* ms, double tau_k, double d, BaseAcceleration a, double& p,
                   double& dl) const {
    double px = 0.0, py = 0.0, dd = 0.0;
    for (int i = 0; i < n_; ++i) {
      const ModeStep& m = ms[i];
      const double g = g0_(i), g1 = g1_(i);
      double sv = m.e(1, 0) * sd0_(i) + m.e(1, 1) * sv0_(i) + m.p1(1) * g + m.p2(1) * g1;
      if (d != 0.0) {
        const double sd = m.e(0, 0) * sd0_(i) + m.e(0, 1) * sv0_(i) + m.p1(0) * g + m.p2(0) * g1;
        sv += d * (-omega_(i) * sd - damp_(i) * sv + g + g1 * tau_k);
      }
      px += pxm_(i) * sv;
      py += pym_(i) * sv;
      dd += damp_(i) * sv * sv;
    }
    p = -mh_ * (a.x * px + a.y * py);
    dl = mh2_ * dd;
  }

  // q, q_dot at tau in the current step, from the modes' steps `ms` at tau_k = tau - d
  void eval(const ModeStep* ms, double tau_k, double d, Vec& q, Vec& qd) const {
    for (int i = 0; i < n_; ++i) {
      double sd = 0.0, sv = 0.0;
      from_start(ms[i], i, sd, sv);
      nudge(i, tau_k, d, sd, sv);
      eta_(i) = sd * inv_omega_(i) + eta_static_(i);
      etad_(i) = sv;
    }
    q.noalias() = Dyn::mv(from_modal_, eta_);
    qd.noalias() = Dyn::mv(from_modal_, etad_);
  }

  // q, q_dot at tau in the current step: from the cache at the usual fractions, else computed
  void at(double tau, Vec& q, Vec& qd) const {
    if (cached_) {
      const double k = tau * samples_ / h_;
      const double kr = std::round(k);
      if (std::abs(k - kr) <= 1e-9 && kr >= 0 && kr <= samples_) {
        const double tk = kr * cache_h_ / samples_;
        eval(row(static_cast<int>(kr)), tk, tau - tk, q, qd);
        return;
      }
    }
    for (int i = 0; i < n_; ++i)
      mode_step(omega_(i), damp_(i), tau, scratch_[static_cast<std::size_t>(i)]);
    eval(scratch_.data(), tau, 0.0, q, qd);
  }

  // input power and damping power at (q, q_dot) and base acceleration a [W]
  void powers(const Vec& q, const Vec& qd, BaseAcceleration a, double& p, double& d) const {
    p = dyn_.input_power(0.0, 0.0, q, 0.0, qd, a);
    d = dyn_.damping_power(qd);
  }

  void propagate(double t, const State& x, double h, State& out) {
    forcing(t, h);
    // the modal forcing g0 + g1 tau net of gravity's static part, and the state in the modes
    g0_ = gxm_ * a0_.x + gym_ * (a0_.y / dyn_.g());
    g1_ = gxm_ * slope_.x + gym_ * (slope_.y / dyn_.g());
    q_ = x.segment(1, n_);
    qd_ = x.segment(n_ + 2, n_);
    eta_.noalias() = Dyn::mv(to_modal_, q_);
    sv0_.noalias() = Dyn::mv(to_modal_, qd_);
    sd0_ = omega_.cwiseProduct(eta_ - eta_static_);
    h_ = h;
    // the usual step fills the cache; a short one after an event computes its own
    if (!usual(h) && h >= 0.5 * std::min(max_step_, h_cap_)) fill_cache(h);
    cached_ = usual(h);
    const int iw = 2 * n_ + 2, id = 2 * n_ + 3;
    powers(q_, qd_, a0_, p0_, d0_);
    at(h, q_, qd_);
    out = x;
    out.segment(1, n_) = q_;
    out.segment(n_ + 2, n_) = qd_;
    powers(q_, qd_, {a0_.x + slope_.x * h, a0_.y + slope_.y * h}, p1_, d1_);
    // the energies by 8-point Gauss-Legendre on the exact integrands
    double work = 0.0, loss = 0.0;
    for (int j = 0; j < kNodes; ++j) {
      const double tau = h * kGaussX[j];
      const BaseAcceleration a{a0_.x + slope_.x * tau, a0_.y + slope_.y * tau};
      double p = 0.0, d = 0.0;
      if (cached_) {
        const double tk = cache_h_ * kGaussX[j];
        node_powers(row(samples_ + 1 + j), tk, tau - tk, a, p, d);
      } else {
        for (int i = 0; i < n_; ++i)
          mode_step(omega_(i), damp_(i), tau, scratch_[static_cast<std::size_t>(i)]);
        node_powers(scratch_.data(), tau, 0.0, a, p, d);
      }
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
  Mat from_modal_, to_modal_;                  // phi and phi^T mu
  Mat user_from_modal_;                        // T phi (output_basis)
  Vec omega_, damp_, gxm_, gym_, eta_static_;  // per mode: w, c, forcing per X'' and per g
  Vec inv_omega_, pxm_, pym_;                  // 1/w, Phi^T psi_x, Phi^T psi_y
  double mh_ = 0.0, mh2_ = 0.0;                // M h [kg m], M h^2 [kg m^2]
  Vec g0_, g1_, sd0_, sv0_;                    // this step: modal forcing and initial s
  mutable Vec eta_, etad_, qo_, qdo_;
  Vec q_, qd_;
  std::vector<ModeStep> cache_;            // the usual step's modes: sample fractions, then nodes
  mutable std::vector<ModeStep> scratch_;  // one step of each mode at an unusual tau
  double cache_h_ = -1.0;
  bool cached_ = false;  // this step has the usual length
  GroundMotion::Cursor cursor_;
  BaseAcceleration a0_, slope_;
  double h_ = 0.0;
  double p0_ = 0.0, p1_ = 0.0, d0_ = 0.0, d1_ = 0.0;  // input and damping power at the ends [W]
  double t0_ = 0.0, t1_ = 0.0;
  State x0_, x1_, xn_;
  // the walk
  Vec wd_, wv_;                     // the modal state s = (w (eta - eta_static), eta')
  double ww_ = 0.0, wl_ = 0.0;      // input work and damping loss [J]
  std::array<Vec, 5> bound_;        // per mode: bounds over the piece on |eta^(k)|, k = 0..4
  Vec hom_;                         // per mode: |s - s_p|, the free part's norm at the start
  Vec acc_hom_;                     // per mode: the bound |(w, c)| hom on |eta''|
  Vec p0d_, p0v_, hd_, hv_;         // per mode: P0, and s(0) - P0 (the free part at the start)
  mutable Vec dev2_;                // scratch: per mode, the excursion bound of eta''
  mutable std::array<Vec, 5> jet_;  // scratch: eta and its first four derivatives
  const Piece* piece_ = nullptr;    // the last piece's kept steps
  double rate_ = 0.0;               // [1/s] the largest |eigenvalue|
  Vec betam_;                       // phi^T beta
  mutable Vec bm_;                  // scratch: phi^T b(alpha)
  double gamma_norm_ = 0.0;         // Frobenius norm of phi^T Gamma phi (>= its 2-norm)
  std::array<Piece, kPieces + 1> pieces_;  // kept piece lengths, then one computed afresh
  int pieces_used_ = 0;
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
  struct Excursion {
    double fi = 0.0, fj = 0.0, u1 = 0.0, u2 = 0.0, moment = 0.0;
  };
  static constexpr int kPoints = 8;
  double walk_cap() const { return 0.0; }
  void walk_start(const State&) {}
  void walk_piece(double, BaseAcceleration, BaseAcceleration, bool = true) {}
  void walk_state(State&) const {}
  void walk_dense(double, State&) const {}
  std::array<double, 3> walk_q_jet(double, int) const { return {}; }
  template <class Vec>
  void walk_q_derivatives(double, std::array<Vec, 5>&) const {}
  BaseAcceleration walk_base(double) const { return {}; }
  BaseAcceleration walk_slope() const { return {}; }
  template <class Mat>
  void output_basis(const Mat&) {}
  Excursion walk_excursion(double, double, double, double, double) const { return {}; }
  double walk_q_excursion(int, double) const { return 0.0; }
  struct Reach {
    double fi = 0.0, fj_lo = 0.0, fj_hi = 0.0, moment = 0.0;
  };
  Reach walk_reach(double, double, double) const { return {}; }
  double walk_q_reach(int) const { return 0.0; }
  double t0() const { return 0.0; }
  double t1() const { return 0.0; }
  const State& x0() const { return x_; }
  const State& x1() const { return x_; }

 private:
  State x_;
};

}  // namespace flexrock::detail
