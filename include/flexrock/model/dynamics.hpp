// SPDX-License-Identifier: BSD-3-Clause
// The equations of motion of the paper's body, as derived in docs/theory.md, on fixed-size types.
//
// Physical time t; theta [rad], q [-], theta_dot [rad/s], q_dot [1/s]. Rocking on edge 1 means
// theta >= 0 about the left tipping point (alpha = -alpha1); on edge 2, theta <= 0 about the
// right one (alpha = alpha2). Everything here is pure: no state, no allocation for fixed N.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/model/body.hpp"

namespace flexrock {

/// Position of an edge relative to the c.g., over h: alpha = -alpha1 (edge 1) or alpha2 (edge 2).
inline double edge_sign(int edge) { return edge == 1 ? 1.0 : -1.0; }

template <int N, int MaxN = N>
class Dynamics {
 public:
  using Vec = Eigen::Matrix<double, N, 1, Eigen::ColMajor, MaxN, 1>;
  using Mat = Eigen::Matrix<double, N, N, Eigen::ColMajor, MaxN, MaxN>;

  explicit Dynamics(const Body& body)
      : n_(body.modes()),
        mass_(body.params().mass),
        h_(body.params().height),
        g_(body.g()),
        gh_(body.g_over_h()),
        zeta2_(body.params().zeta2),
        alpha1_(body.alpha1()),
        alpha2_(body.alpha2()),
        mu_(body.params().mu),
        mu_inv_(body.mu_inverse()),
        kappa_(body.params().kappa),
        stiffness_(body.stiffness()),
        damping_(body.damping_matrix()),
        gamma_(body.params().gamma),
        psi_x_(body.params().psi_x),
        psi_y_(body.params().psi_y),
        delta_(body.params().delta),
        beta_(body.params().beta),
        damped_(body.damping_matrix().size() > 0 &&
                body.damping_matrix().cwiseAbs().maxCoeff() > 0) {
    // about the deformed c.g. (flight, docs/theory.md "Flight"): mu_cg = mu - psi_x psi_x^T -
    // psi_y psi_y^T is constant, Gamma = gamma + psi_y psi_x^T - psi_x psi_y^T antisymmetric
    mu_cg_ = mu_ - psi_x_ * psi_x_.transpose() - psi_y_ * psi_y_.transpose();
    mu_cg_inv_ = body.flight_mu_inverse();
    gamma_cg_ = gamma_ + psi_y_ * psi_x_.transpose() - psi_x_ * psi_y_.transpose();
    // the potential energy about the static sag (see potential_energy): r, rho = kappa r +
    // psi_y and c = psi_y.r + 1/2 r.kappa.r = 1/2 psi_y.r + 1/2 r.rho, in long double
    sag_ = body.static_deformation();
    if (n_ > 0) {
      using Long = Eigen::Matrix<long double, Eigen::Dynamic, 1>;
      const Long r = body.static_deformation().cast<long double>();
      const Long rho =
          body.params().kappa.cast<long double>() * r + body.params().psi_y.cast<long double>();
      sag_residual_ = rho.cast<double>();
      sag_energy_ =
          static_cast<double>(0.5L * (body.params().psi_y.cast<long double>().dot(r) + r.dot(rho)));
    } else {
      sag_residual_ = sag_;
    }
    // in the pinned-base modal coordinates (Body::in_modal_coordinates) mu = I and K, C are
    // diagonal: the equations then need no product with mu, mu^-1, K or C, and with gamma = 0
    // (modes along the centre line) none at all, so their cost is linear in n
    auto diagonal = [](const Mat& a) {
      for (Eigen::Index j = 0; j < a.cols(); ++j)
        for (Eigen::Index i = 0; i < a.rows(); ++i)
          if (i != j && a(i, j) != 0.0) return false;
      return true;
    };
    modal_ = n_ > 0 && diagonal(mu_) && (mu_.diagonal().array() == 1.0).all() &&
             diagonal(stiffness_) && diagonal(damping_);
    uncoupled_ = n_ == 0 || (gamma_.array() == 0.0).all();
    stiffness_diag_ = stiffness_.diagonal();
    damping_diag_ = damping_.diagonal();
    // the parts of d, b and m that depend on the pivot alone (rocking_rates_sc)
    for (int e = 0; e < 2; ++e) {
      const double a = alpha(e + 1);
      pivot_d_[e] = delta_ - a * psi_x_ + psi_y_;
      pivot_b_[e] = beta_ - a * psi_y_ - psi_x_;
      pivot_m_[e] = 1.0 + zeta2_ + a * a;
    }
  }

  /// A matrix-vector product: unrolled in place for fixed sizes above 4, where Eigen would call
  /// its general kernel at a cost above the product's own (up to 4 it unrolls by itself); the
  /// kernel for dynamic sizes.
  template <class A, class V>
  static auto mv(const A& a, const V& v) {
    if constexpr (N != Eigen::Dynamic && N > 4) {
      return a.lazyProduct(v);
    } else {
      return a * v;
    }
  }

  int modes() const { return n_; }
  double mass() const { return mass_; }
  double height() const { return h_; }
  double g() const { return g_; }
  double g_over_h() const { return gh_; }
  double alpha1() const { return alpha1_; }
  double alpha2() const { return alpha2_; }
  const Mat& mu() const { return mu_; }
  const Mat& mu_inverse() const { return mu_inv_; }
  const Mat& damping() const { return damping_; }
  const Mat& stiffness() const { return stiffness_; }  // K = (g/h) kappa [1/s^2]
  /// alpha of the pivot when rocking on `edge` (paper: -alpha1 for theta > 0, alpha2 for theta < 0)
  double alpha(int edge) const { return edge == 1 ? -alpha1_ : alpha2_; }

  /// Rotational inertia about the pivot, over M h^2: m = 1 + zeta^2 + alpha^2 +
  /// 2 (delta - alpha psi_x + psi_y).q + q^T mu q.
  double inertia(double a, const Vec& q) const {
    return 1.0 + zeta2_ + a * a + 2.0 * (delta_ - a * psi_x_ + psi_y_).dot(q) + mu_form(q, q);
  }
  /// Coupling of theta_dot and q_dot in the kinetic energy: b_j = beta_j + gamma_ij q_i -
  /// alpha psi_yj - psi_xj.
  Vec coupling(double a, const Vec& q) const {
    if (uncoupled_) return beta_ - a * psi_y_ - psi_x_;
    return beta_ + mv(gamma_.transpose(), q) - a * psi_y_ - psi_x_;
  }

  /// Accelerations while rocking on `edge` (the paper's eqs. 1 and 2, derived in theory.md).
  void rocking_acceleration(int edge, double theta, const Vec& q, double theta_dot,
                            const Vec& q_dot, BaseAcceleration base, double& theta_ddot,
                            Vec& q_ddot) const {
    rocking_acceleration_sc(edge, std::sin(theta), std::cos(theta), q, theta_dot, q_dot, base,
                            theta_ddot, q_ddot);
  }
  /// The same with s = sin(theta), c = cos(theta) given (the event loop computes them once).
  void rocking_acceleration_sc(int edge, double s, double c, const Vec& q, double theta_dot,
                               const Vec& q_dot, BaseAcceleration base, double& theta_ddot,
                               Vec& q_ddot) const {
    if constexpr (N != 0) {  // a rigid body (N = 0) has no modal coordinates
      if (modal_) {
        // in modal coordinates (mu = mu^-1 = I, K and C diagonal): the right-hand side's single
        // pass over the modes (its powers go unused)
        q_ddot.resize(n_);
        RockingRates r;
        modal_rates(edge, s, c, q.data(), theta_dot, q_dot.data(), base, q_ddot.data(), r);
        theta_ddot = r.theta_ddot;
        return;
      }
    }
    const double a = alpha(edge);
    const double ax = base.x / g_, ay = 1.0 + base.y / g_;
    // effective gravity over g in body axes: G = f(Xdd/g, 1 + Ydd/g, theta)
    const double gx = ax * c + ay * s, gy = ay * c - ax * s;
    const double wx = -a + psi_x_.dot(q), wy = 1.0 + psi_y_.dot(q);
    const Vec cv = delta_ - a * psi_x_ + psi_y_ + mv(mu_, q);  // half the gradient of m in q
    const Vec b = coupling(a, q);
    const double m = 1.0 + zeta2_ + a * a + (cv + delta_ - a * psi_x_ + psi_y_).dot(q);
    const double f_theta = -2.0 * cv.dot(q_dot) * theta_dot - gh_ * (wx * gy - wy * gx);
    Vec f_q = theta_dot * (theta_dot * cv - 2.0 * mv(gamma_.transpose(), q_dot)) -
              mv(stiffness_, q) - gh_ * (psi_x_ * gx + psi_y_ * gy);
    if (damped_) f_q.noalias() -= mv(damping_, q_dot);
    // block elimination with the constant mu^-1: (m - b^T mu^-1 b) thdd = f_theta - b^T mu^-1 f_q
    const Vec z = mv(mu_inv_, b);
    const Vec y = mv(mu_inv_, f_q);
    theta_ddot = (f_theta - b.dot(y)) / (m - b.dot(z));
    q_ddot = y - z * theta_ddot;
  }

  /// What the rocking state's derivative needs, at once: theta_ddot and q_ddot (as
  /// rocking_acceleration_sc), the base's input power (input_power_sc) and the damping power
  /// (damping_power). The rocking right-hand side is most of a flexible body's run; in modal
  /// coordinates one pass over the modes forms every sum the three share (psi.q, psi.q', c.q',
  /// b.f_q, b.b, q'.C q'), where apart they take about a dozen dot products and copies. q, q_dot
  /// and q_ddot point at n entries each (the stepper's state and its derivative, in place).
  struct RockingRates {
    double theta_ddot, input_power, damping_power;
  };
  [[gnu::always_inline]] void rocking_rates_sc(int edge, double s, double c, const double* q,
                                               double theta_dot, const double* q_dot,
                                               BaseAcceleration base, double* q_ddot,
                                               RockingRates& r) const {
    if (!modal_) {
      const Vec qv = Eigen::Map<const Vec>(q, n_), qdv = Eigen::Map<const Vec>(q_dot, n_);
      Vec qdd(n_);
      rocking_acceleration_sc(edge, s, c, qv, theta_dot, qdv, base, r.theta_ddot, qdd);
      Eigen::Map<Vec>(q_ddot, n_) = qdd;
      r.input_power = input_power_sc(alpha(edge), s, c, qv, theta_dot, qdv, base);
      r.damping_power = damping_power(qdv);
      return;
    }
    modal_rates(edge, s, c, q, theta_dot, q_dot, base, q_ddot, r);
  }

  /// Deformation accelerations in full contact (theta = 0): mu q'' = -K q - C q' - (g/h) psi.G.
  void full_contact_acceleration(const Vec& q, const Vec& q_dot, BaseAcceleration base,
                                 Vec& q_ddot) const {
    const double ax = base.x / g_, ay = 1.0 + base.y / g_;
    // K q and the static load cancel at rest before mu^-1 applies: a product mu^-1 K formed once
    // would round at cond(K) ulp of the sag, where a soft mode beside a stiff one then swings
    if (modal_) {
      q_ddot = -stiffness_diag_.cwiseProduct(q) - gh_ * (psi_x_ * ax + psi_y_ * ay);
      if (damped_) q_ddot -= damping_diag_.cwiseProduct(q_dot);
      return;
    }
    Vec f = -mv(stiffness_, q) - gh_ * (psi_x_ * ax + psi_y_ * ay);
    if (damped_) f.noalias() -= mv(damping_, q_dot);
    q_ddot = mv(mu_inv_, f);
  }

  /// Reaction of the floor on the body over M g, inertial components (I, J), while rocking on
  /// `edge` (paper eq. 3, rotated to I, J as in its section on sliding).
  Eigen::Vector2d rocking_reaction(int edge, double theta, const Vec& q, double theta_dot,
                                   const Vec& q_dot, double theta_ddot, const Vec& q_ddot,
                                   BaseAcceleration base) const {
    return rocking_reaction_sc(edge, std::sin(theta), std::cos(theta), q, theta_dot, q_dot,
                               theta_ddot, q_ddot, base);
  }
  /// The same with s = sin(theta), c = cos(theta) given.
  Eigen::Vector2d rocking_reaction_sc(int edge, double s, double c, const Vec& q, double theta_dot,
                                      const Vec& q_dot, double theta_ddot, const Vec& q_ddot,
                                      BaseAcceleration base) const {
    const double a = alpha(edge);
    const double ax = base.x / g_, ay = 1.0 + base.y / g_;
    const double gx = ax * c + ay * s, gy = ay * c - ax * s;
    const double wx = -a + psi_x_.dot(q), wy = 1.0 + psi_y_.dot(q);
    const double px = psi_x_.dot(q_dot), py = psi_y_.dot(q_dot);
    const double t2 = theta_dot * theta_dot;
    const double fx =
        gx + (psi_x_.dot(q_ddot) - theta_ddot * wy - 2.0 * theta_dot * py - t2 * wx) / gh_;
    const double fy =
        gy + (psi_y_.dot(q_ddot) + theta_ddot * wx + 2.0 * theta_dot * px - t2 * wy) / gh_;
    return {fx * c - fy * s, fx * s + fy * c};
  }

  /// Reaction over M g in full contact.
  Eigen::Vector2d full_contact_reaction(const Vec& q_ddot, BaseAcceleration base) const {
    return {base.x / g_ + psi_x_.dot(q_ddot) / gh_, 1.0 + base.y / g_ + psi_y_.dot(q_ddot) / gh_};
  }

  /// Moment about the pivot at `a` that the floor must supply in full contact, over M g h:
  /// R(a) = (h/g) b(a).q'' + w_x(a) G_y - w_y G_x. Linear in a with slope -F_J/(M g).
  double contact_moment(double a, const Vec& q, const Vec& q_ddot, BaseAcceleration base) const {
    const double ax = base.x / g_, ay = 1.0 + base.y / g_;
    return coupling(a, q).dot(q_ddot) / gh_ + (-a + psi_x_.dot(q)) * ay -
           (1.0 + psi_y_.dot(q)) * ax;
  }

  /// Uplift functions over M g h: the moment the contact must supply about edge 1 (U1) and about
  /// edge 2 (U2); both positive while the resultant lies inside the base (docs/theory.md).
  Eigen::Vector2d uplift_functions(const Vec& q, const Vec& q_ddot, BaseAcceleration base) const {
    return {contact_moment(-alpha1_, q, q_ddot, base), -contact_moment(alpha2_, q, q_ddot, base)};
  }
  /// The contact moments of a guard sample at once: R(0) (returned) and the uplift functions
  /// (U1, U2) = (R(-alpha1), -R(alpha2)). R is linear in a, R(a) = R(0) - a (psi_y.q''/(g/h) +
  /// 1 + Ydd/g), so one product gamma^T q serves all three.
  double contact_moments(const Vec& q, const Vec& q_ddot, BaseAcceleration base,
                         Eigen::Vector2d& uplift) const {
    const double ax = base.x / g_, ay = 1.0 + base.y / g_;
    const double r0 =
        coupling(0.0, q).dot(q_ddot) / gh_ + psi_x_.dot(q) * ay - (1.0 + psi_y_.dot(q)) * ax;
    const double slope = psi_y_.dot(q_ddot) / gh_ + ay;  // -dR/da
    uplift = {r0 + alpha1_ * slope, alpha2_ * slope - r0};
    return r0;
  }

  /// The full-contact reaction F_I, F_J (over M g) and the moment R(0) about the c.g. projection
  /// (over M g h), each with its first two time derivatives, along a motion whose q and first four
  /// derivatives are d[0..4] and whose base acceleration is base + rate t: full_contact_reaction
  /// and contact_moments differentiated, c(q) = coupling(0, q) being affine in q (c' = Gamma^T q'):
  ///   F_I' = a_x' + psi_x.q'''/(g/h),  F_I'' = psi_x.q''''/(g/h)  (F_J alike, with psi_y, a_y),
  ///   R' = (c'.q'' + c.q''')/(g/h) + psi_x.q' a_y + psi_x.q a_y' - psi_y.q' a_x - (1 + psi_y.q)
  ///   a_x', R'' = (c''.q'' + 2 c'.q''' + c.q'''')/(g/h) + psi_x.q'' a_y + 2 psi_x.q' a_y'
  ///         - psi_y.q'' a_x - 2 psi_y.q' a_x'.
  struct ReactionRates {
    std::array<double, 3> fi, fj, moment;
  };
  ReactionRates full_contact_reaction_rates(const std::array<Vec, 5>& d, BaseAcceleration base,
                                            BaseAcceleration rate) const {
    const double ax = base.x / g_, ay = 1.0 + base.y / g_, dax = rate.x / g_, day = rate.y / g_;
    const double x0 = psi_x_.dot(d[0]), x1 = psi_x_.dot(d[1]), x2 = psi_x_.dot(d[2]);
    const double y0 = psi_y_.dot(d[0]), y1 = psi_y_.dot(d[1]), y2 = psi_y_.dot(d[2]);
    ReactionRates r;
    r.fi = {ax + x2 / gh_, dax + psi_x_.dot(d[3]) / gh_, psi_x_.dot(d[4]) / gh_};
    r.fj = {ay + y2 / gh_, day + psi_y_.dot(d[3]) / gh_, psi_y_.dot(d[4]) / gh_};
    const Vec c = coupling(0.0, d[0]);
    double c1q2 = 0.0, c1q3 = 0.0, c2q2 = 0.0;  // c'.q'', c'.q''', c''.q''
    if (!uncoupled_) {
      const Vec g2 = mv(gamma_, d[2]);  // Gamma q'': c'.q'' = q'.Gamma q'', c''.q'' = q''.Gamma q''
      c1q2 = d[1].dot(g2);
      c2q2 = d[2].dot(g2);
      c1q3 = d[1].dot(mv(gamma_, d[3]));
    }
    r.moment = {c.dot(d[2]) / gh_ + x0 * ay - (1.0 + y0) * ax,
                (c1q2 + c.dot(d[3])) / gh_ + x1 * ay + x0 * day - y1 * ax - (1.0 + y0) * dax,
                (c2q2 + 2.0 * c1q3 + c.dot(d[4])) / gh_ + x2 * ay + 2.0 * x1 * day - y2 * ax -
                    2.0 * y1 * dax};
    return r;
  }

  /// Location of the resultant in full contact over h, from the c.g. projection (paper eq. 4).
  double resultant_location(const Vec& q, const Vec& q_ddot, BaseAcceleration base) const {
    const double fj = 1.0 + base.y / g_ + psi_y_.dot(q_ddot) / gh_;
    return contact_moment(0.0, q, q_ddot, base) / fj;
  }

  /// Kinetic energy relative to the base [J]: T = 1/2 M h^2 nu^T A nu.
  double kinetic_energy(double a, const Vec& q, double theta_dot, const Vec& q_dot) const {
    return 0.5 * mass_ * h_ * h_ *
           (inertia(a, q) * theta_dot * theta_dot + 2.0 * theta_dot * coupling(a, q).dot(q_dot) +
            mu_form(q_dot, q_dot));
  }
  /// Gravity and strain energy [J]: V = M g h (J.w + 1/2 q^T kappa q), evaluated as
  /// M g h (sin(theta) w_x + cos(theta) + (cos(theta) - 1) psi_y.q + sag_terms(q)).
  double potential_energy(double a, double theta, const Vec& q) const {
    const double wx = -a + psi_x_.dot(q), half = std::sin(0.5 * theta);
    return mass_ * g_ * h_ *
           (std::sin(theta) * wx + std::cos(theta) - 2.0 * half * half * psi_y_.dot(q) +
            sag_terms(q));
  }
  /// Power of the base's d'Alembert force on the body [W]: -M a_base . v_cm (relative velocity).
  double input_power(double a, double theta, const Vec& q, double theta_dot, const Vec& q_dot,
                     BaseAcceleration base) const {
    return input_power_sc(a, std::sin(theta), std::cos(theta), q, theta_dot, q_dot, base);
  }
  /// The same with s = sin(theta), c = cos(theta) given.
  double input_power_sc(double a, double s, double c, const Vec& q, double theta_dot,
                        const Vec& q_dot, BaseAcceleration base) const {
    const double wx = -a + psi_x_.dot(q), wy = 1.0 + psi_y_.dot(q);
    const double vx = h_ * (psi_x_.dot(q_dot) - theta_dot * wy);
    const double vy = h_ * (psi_y_.dot(q_dot) + theta_dot * wx);
    const double abx = base.x * c + base.y * s, aby = base.y * c - base.x * s;
    return -mass_ * (abx * vx + aby * vy);
  }
  /// Power dissipated by material damping [W]: M h^2 q_dot^T C q_dot.
  double damping_power(const Vec& q_dot) const {
    if (!damped_) return 0.0;
    if (modal_) return mass_ * h_ * h_ * q_dot.dot(damping_diag_.cwiseProduct(q_dot));
    return mass_ * h_ * h_ * q_dot.dot(mv(damping_, q_dot));
  }

  /// Linear velocity of the c.g. relative to the base [m/s], body axes at theta = 0 (= inertial).
  Eigen::Vector2d cg_velocity(double a, const Vec& q, double theta_dot, const Vec& q_dot) const {
    const double wx = -a + psi_x_.dot(q), wy = 1.0 + psi_y_.dot(q);
    return {h_ * (psi_x_.dot(q_dot) - theta_dot * wy), h_ * (psi_y_.dot(q_dot) + theta_dot * wx)};
  }

  // ---- flight (docs/theory.md, "Flight"): state (x_c, y_c) of the deformed c.g. relative to the
  // base, theta, q; the c.g. is ballistic and the internal motion feels no gravity

  /// Rotational inertia about the deformed c.g. over M h^2: m_cg = zeta^2 + 2 delta.q + q^T mu q -
  /// (psi_x.q)^2 - (psi_y.q)^2.
  double flight_inertia(const Vec& q) const {
    const double px = psi_x_.dot(q), py = psi_y_.dot(q);
    return zeta2_ + 2.0 * delta_.dot(q) + q.dot(mu_ * q) - px * px - py * py;
  }
  /// Coupling about the c.g.: b_cg = beta + Gamma^T q.
  Vec flight_coupling(const Vec& q) const { return beta_ + gamma_cg_.transpose() * q; }

  /// Accelerations of theta and q in flight: A_cg [thdd; qdd] = [-2 (c_cg.qd) thd;
  /// thd (thd c_cg - 2 Gamma^T qd) - K q - C qd].
  void flight_acceleration(const Vec& q, double theta_dot, const Vec& q_dot, double& theta_ddot,
                           Vec& q_ddot) const {
    const double px = psi_x_.dot(q), py = psi_y_.dot(q);
    const Vec cv = delta_ + mu_ * q - px * psi_x_ - py * psi_y_;  // half the gradient of m_cg
    const Vec b = flight_coupling(q);
    const double m = zeta2_ + (cv + delta_).dot(q);  // m_cg: (c_cg + delta).q holds the psi terms
    const double f_theta = -2.0 * cv.dot(q_dot) * theta_dot;
    Vec f_q = theta_dot * (theta_dot * cv - 2.0 * (gamma_cg_.transpose() * q_dot)) - stiffness_ * q;
    if (damped_) f_q.noalias() -= damping_ * q_dot;
    if (n_ == 0) {
      theta_ddot = 0.0;  // a rigid body turns at constant speed about its c.g.
      return;
    }
    const Vec z = mu_cg_inv_ * b;
    const Vec y = mu_cg_inv_ * f_q;
    theta_ddot = (f_theta - b.dot(y)) / (m - b.dot(z));
    q_ddot = y - z * theta_ddot;
  }

  /// Height of tipping point `edge` above the floor [m] in flight, with s = sin(theta),
  /// c = cos(theta): y_e = y_c + h [s (alpha_e - psi_x.q) - c (1 + psi_y.q)].
  double corner_height(int edge, double s, double c, const Vec& q, double y_c) const {
    return y_c + h_ * (s * (alpha(edge) - psi_x_.dot(q)) - c * (1.0 + psi_y_.dot(q)));
  }
  /// Horizontal position of tipping point `edge` relative to the base origin [m] in flight.
  double corner_x(int edge, double s, double c, const Vec& q, double x_c) const {
    return x_c + h_ * (c * (alpha(edge) - psi_x_.dot(q)) + s * (1.0 + psi_y_.dot(q)));
  }

  /// Velocity of tipping point `edge` relative to the base [m/s], body components, in flight
  /// (the c.g. velocity v_c given in inertial components).
  Eigen::Vector2d corner_velocity_body(int edge, double s, double c, const Vec& q, double theta_dot,
                                       const Vec& q_dot, const Eigen::Vector2d& v_c) const {
    const double vbx = c * v_c(0) + s * v_c(1), vby = -s * v_c(0) + c * v_c(1);
    return {vbx + h_ * (theta_dot * (1.0 + psi_y_.dot(q)) - psi_x_.dot(q_dot)),
            vby + h_ * (theta_dot * (alpha(edge) - psi_x_.dot(q)) - psi_y_.dot(q_dot))};
  }

  /// Vertical acceleration [m/s^2] relative to the base of tipping point `edge` if the body were
  /// free (flight) in this state: y_e'' = y_c'' + h [thdd (c a + s b) + thd^2 (c b - s a) +
  /// 2 thd (c a' + s b') + s a'' - c b''], a = alpha_e - psi_x.q, b = 1 + psi_y.q. Negative means a
  /// body whose pivot force vanishes cannot fly off a sticking pivot: it must slide.
  double free_corner_acceleration(int edge, double s, double c, const Vec& q, double theta_dot,
                                  const Vec& q_dot, BaseAcceleration base) const {
    double thdd = 0.0;
    Vec qdd = Vec::Zero(n_);
    flight_acceleration(q, theta_dot, q_dot, thdd, qdd);
    const double a = alpha(edge) - psi_x_.dot(q), b = 1.0 + psi_y_.dot(q);
    const double ad = -psi_x_.dot(q_dot), bd = psi_y_.dot(q_dot);
    const double add = -psi_x_.dot(qdd), bdd = psi_y_.dot(qdd);
    return -g_ - base.y +
           h_ * (thdd * (c * a + s * b) + theta_dot * theta_dot * (c * b - s * a) +
                 2.0 * theta_dot * (c * ad + s * bd) + s * add - c * bdd);
  }

  /// Kinetic energy in flight relative to the base [J]: 1/2 M |v_c|^2 + 1/2 M h^2 nu^T A_cg nu.
  double flight_kinetic_energy(const Vec& q, double theta_dot, const Vec& q_dot,
                               const Eigen::Vector2d& v_c) const {
    return 0.5 * mass_ * v_c.squaredNorm() +
           0.5 * mass_ * h_ * h_ *
               (flight_inertia(q) * theta_dot * theta_dot +
                2.0 * theta_dot * flight_coupling(q).dot(q_dot) + q_dot.dot(mu_cg_ * q_dot));
  }
  /// Gravity and strain energy in flight [J]: M g y_c + 1/2 M g h q^T kappa q, evaluated as
  /// M g (y_c - h psi_y.q) + M g h sag_terms(q).
  double flight_potential_energy(double y_c, const Vec& q) const {
    return mass_ * g_ * (y_c - h_ * psi_y_.dot(q) + h_ * sag_terms(q));
  }
  /// Power of the base's d'Alembert force in flight [W]: -M a_base . v_c.
  double flight_input_power(const Eigen::Vector2d& v_c, BaseAcceleration base) const {
    return -mass_ * (base.x * v_c(0) + base.y * v_c(1));
  }

  /// Position and velocity of the deformed c.g. relative to the pivot of `edge` [m, m/s],
  /// inertial components, while rocking at theta (the lift-off map: no impulse).
  void cg_from_pivot(int edge, double s, double c, const Vec& q, double theta_dot, const Vec& q_dot,
                     Eigen::Vector2d& r, Eigen::Vector2d& v) const {
    const double a = alpha(edge);
    const double wx = -a + psi_x_.dot(q), wy = 1.0 + psi_y_.dot(q);
    r = {h_ * (c * wx - s * wy), h_ * (s * wx + c * wy)};
    const double vbx = h_ * (psi_x_.dot(q_dot) - theta_dot * wy);
    const double vby = h_ * (psi_y_.dot(q_dot) + theta_dot * wx);
    v = {c * vbx - s * vby, s * vbx + c * vby};
  }

  /// The plastic impact of tipping point `edge` (it sticks): the body then rocks on it. The
  /// impulse acts where the modes vanish, so the modal momenta and the moment of momentum about
  /// the tipping point are conserved (docs/theory.md, "Landing"):
  ///   A_e nu+ = A_e nu- + (1/h) [w_e x V_b ; psi.V_b],
  /// nu- = (theta_dot, q_dot) before, V_b the tipping point's velocity before (body components).
  /// At theta = 0 with V_b that of a point turning about the other edge this is the paper's map.
  /// (The impact laws' other maps are in contact/impact.hpp, law_corner_impact.)
  void corner_impact(int edge, const Vec& q, double theta_dot_minus, const Vec& q_dot_minus,
                     const Eigen::Vector2d& v_corner_body, double& theta_dot_plus,
                     Vec& q_dot_plus) const {
    const double a = alpha(edge);
    const double wx = -a + psi_x_.dot(q), wy = 1.0 + psi_y_.dot(q);
    const double m = inertia(a, q);
    const Vec b = coupling(a, q);
    // the right-hand side: A_e nu- plus the momenta of the tipping point's motion
    const double r_theta = m * theta_dot_minus + b.dot(q_dot_minus) +
                           (wx * v_corner_body(1) - wy * v_corner_body(0)) / h_;
    const Vec r_q = b * theta_dot_minus + mu_ * q_dot_minus +
                    (psi_x_ * v_corner_body(0) + psi_y_ * v_corner_body(1)) / h_;
    solve_rocking_inertia(m, b, r_theta, r_q, theta_dot_plus, q_dot_plus);
  }

  /// Modal momenta over M h^2 of a flight state: p = b_e theta_dot + mu q_dot + psi.V_b/h for any
  /// edge e (the same for both: the modes vanish at both tipping points).
  Vec flight_modal_momenta(int edge, const Vec& q, double theta_dot, const Vec& q_dot,
                           const Eigen::Vector2d& v_corner_body) const {
    return coupling(alpha(edge), q) * theta_dot + mu_ * q_dot +
           (psi_x_ * v_corner_body(0) + psi_y_ * v_corner_body(1)) / h_;
  }

  /// Solves [m b^T; b mu] [x; y] = [r_theta; r_q] by block elimination with the constant mu^-1.
  void solve_rocking_inertia(double m, const Vec& b, double r_theta, const Vec& r_q, double& x,
                             Vec& y) const {
    if (n_ == 0) {
      x = r_theta / m;
      return;
    }
    if (modal_) {
      x = (r_theta - b.dot(r_q)) / (m - b.squaredNorm());
      y = r_q - b * x;
      return;
    }
    const Vec z = mu_inv_ * b;
    const Vec u = mu_inv_ * r_q;
    x = (r_theta - b.dot(u)) / (m - b.dot(z));
    y = u - z * x;
  }

  const Vec& psi_x() const { return psi_x_; }  // participation, body i component
  const Vec& psi_y() const { return psi_y_; }  // participation, body j component
  const Vec& beta() const { return beta_; }    // coupling of theta_dot and q_dot at q = 0
  const Mat& gamma() const { return gamma_; }  // its change with q: b = beta + Gamma^T q - ...

 private:
  // modal_rocking_rates with the body's two flags: fixed at compile time, they keep the pass over
  // the modes free of branches. Inlined where it is called (as modal_rocking_rates): out of line,
  // the pass costs the right-hand side 3 % more instructions at n = 1 (callgrind)
  [[gnu::always_inline]] void modal_rates(int edge, double s, double c, const double* q,
                                          double theta_dot, const double* q_dot,
                                          BaseAcceleration base, double* q_ddot,
                                          RockingRates& r) const {
    if (damped_) {
      if (uncoupled_)
        return modal_rocking_rates<true, false>(edge, s, c, q, theta_dot, q_dot, base, q_ddot, r);
      return modal_rocking_rates<true, true>(edge, s, c, q, theta_dot, q_dot, base, q_ddot, r);
    }
    if (uncoupled_)
      return modal_rocking_rates<false, false>(edge, s, c, q, theta_dot, q_dot, base, q_ddot, r);
    modal_rocking_rates<false, true>(edge, s, c, q, theta_dot, q_dot, base, q_ddot, r);
  }
  // rocking_rates_sc in modal coordinates (mu = I, K and C diagonal): the terms of
  // rocking_acceleration_sc's modal path, input_power_sc and damping_power, summed in one pass
  template <bool kDamped, bool kCoupled>
  [[gnu::always_inline]] void modal_rocking_rates(int edge, double s, double c, const double* q,
                                                  double theta_dot, const double* q_dot,
                                                  BaseAcceleration base, double* q_ddot,
                                                  RockingRates& r) const {
    constexpr int kFixed = N;
    const int n = kFixed == Eigen::Dynamic ? n_ : kFixed;
    const int e = edge == 1 ? 0 : 1;
    const double a = alpha(edge);
    const double ax = base.x / g_, ay = 1.0 + base.y / g_;
    const double gx = ax * c + ay * s, gy = ay * c - ax * s;  // effective gravity, body axes
    const double ghx = gh_ * gx, ghy = gh_ * gy, thd2 = theta_dot * theta_dot;
    const Vec& d = pivot_d_[e];   // delta - alpha psi_x + psi_y
    const Vec& b0 = pivot_b_[e];  // beta - alpha psi_y - psi_x
    Vec gq, gqd;                  // Gamma^T q, Gamma^T q' (coupled bodies)
    if constexpr (kCoupled) {
      gq.noalias() = mv(gamma_.transpose(), Eigen::Map<const Vec>(q, n_));
      gqd.noalias() = mv(gamma_.transpose(), Eigen::Map<const Vec>(q_dot, n_));
    }
    Vec f(n_), b(n_);                                 // f_q and b(q)
    double px = 0.0, py = 0.0, pxd = 0.0, pyd = 0.0;  // psi_x.q, psi_y.q, psi_x.q', psi_y.q'
    double cqd = 0.0, mq = 0.0, bf = 0.0, bb = 0.0,
           cdq = 0.0;  // c.q', (c + d).q, b.f, b.b, q'.C q'
    for (int j = 0; j < n; ++j) {
      const double qj = q[j], vj = q_dot[j], cj = d[j] + qj;  // c = d + q: half of m's gradient
      px += psi_x_[j] * qj;
      py += psi_y_[j] * qj;
      pxd += psi_x_[j] * vj;
      pyd += psi_y_[j] * vj;
      cqd += cj * vj;
      mq += (cj + d[j]) * qj;
      double fj = thd2 * cj - stiffness_diag_[j] * qj - (psi_x_[j] * ghx + psi_y_[j] * ghy);
      double bj = b0[j];
      if constexpr (kDamped) {
        const double cvj = damping_diag_[j] * vj;
        fj -= cvj;
        cdq += cvj * vj;
      }
      if constexpr (kCoupled) {
        fj -= 2.0 * theta_dot * gqd[j];
        bj += gq[j];
      }
      f[j] = fj;
      b[j] = bj;
      bf += bj * fj;
      bb += bj * bj;
    }
    const double wx = -a + px, wy = 1.0 + py;
    const double f_theta = -2.0 * cqd * theta_dot - gh_ * (wx * gy - wy * gx);
    const double thdd = (f_theta - bf) / (pivot_m_[e] + mq - bb);
    for (int j = 0; j < n; ++j) q_ddot[j] = f[j] - b[j] * thdd;
    r.theta_ddot = thdd;
    // the c.g.'s velocity relative to the base and the base's acceleration, body axes
    const double vx = h_ * (pxd - theta_dot * wy), vy = h_ * (pyd + theta_dot * wx);
    const double abx = base.x * c + base.y * s, aby = base.y * c - base.x * s;
    r.input_power = -mass_ * (abx * vx + aby * vy);
    r.damping_power = kDamped ? mass_ * h_ * h_ * cdq : 0.0;
  }

  /// u^T mu v, without the product where mu = I
  double mu_form(const Vec& u, const Vec& v) const { return modal_ ? u.dot(v) : u.dot(mv(mu_, v)); }

  /// psi_y.q + 1/2 q^T kappa q, written about the static sag r (kappa r = -psi_y to rounding):
  /// 1/2 d^T kappa d + rho.d + c with d = q - r. Summed directly, the two terms cancel: a
  /// 0.1 Hz mode beside a 1 kHz one sags tens of times h, |q| |kappa| |q| reaches 1e7 and the
  /// rounding 1e-9 M g h, ten times the energy balance's floor on a body barely moved.
  double sag_terms(const Vec& q) const {
    if (n_ == 0) return 0.0;
    const Vec d = q - sag_;
    return 0.5 * d.dot(kappa_ * d) + sag_residual_.dot(d) + sag_energy_;
  }

  int n_;
  double mass_, h_, g_, gh_, zeta2_, alpha1_, alpha2_;
  Mat mu_, mu_inv_, kappa_, stiffness_, damping_, gamma_;
  Mat mu_cg_, mu_cg_inv_, gamma_cg_;  // about the deformed c.g. (flight)
  Vec psi_x_, psi_y_, delta_, beta_;
  bool damped_;
  Vec sag_, sag_residual_;   // the static sag r and kappa r + psi_y (sag_terms)
  double sag_energy_ = 0.0;  // psi_y.r + 1/2 r^T kappa r [-]
  bool modal_ = false;       // mu = I, K and C diagonal (modal coordinates)
  bool uncoupled_ = true;    // gamma = 0
  Vec stiffness_diag_, damping_diag_;
  std::array<Vec, 2> pivot_d_, pivot_b_;  // per edge: delta - alpha psi_x + psi_y, beta - ...
  std::array<double, 2> pivot_m_{};       // per edge: 1 + zeta^2 + alpha^2
};

}  // namespace flexrock
