// SPDX-License-Identifier: BSD-3-Clause
// The equations of motion of the paper's body, as derived in docs/theory.md, on fixed-size types.
//
// Physical time t; theta [rad], q [-], theta_dot [rad/s], q_dot [1/s]. Rocking on edge 1 means
// theta >= 0 about the left tipping point (alpha = -alpha1); on edge 2, theta <= 0 about the
// right one (alpha = alpha2). Everything here is pure: no state, no allocation for fixed N.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/model/body.hpp"

namespace flexrock {

/// Which edges touch the floor.
enum class Phase : int {
  kFullContact = 0,   // theta = 0, both edges down
  kRockingEdge1 = 1,  // theta > 0, pivot on the left tipping point
  kRockingEdge2 = 2,  // theta < 0, pivot on the right tipping point
};

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
                body.damping_matrix().cwiseAbs().maxCoeff() > 0) {}

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
    return 1.0 + zeta2_ + a * a + 2.0 * (delta_ - a * psi_x_ + psi_y_).dot(q) + q.dot(mu_ * q);
  }
  /// Coupling of theta_dot and q_dot in the kinetic energy: b_j = beta_j + gamma_ij q_i -
  /// alpha psi_yj - psi_xj.
  Vec coupling(double a, const Vec& q) const {
    return beta_ + gamma_.transpose() * q - a * psi_y_ - psi_x_;
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
    const double a = alpha(edge);
    const double ax = base.x / g_, ay = 1.0 + base.y / g_;
    // effective gravity over g in body axes: G = f(Xdd/g, 1 + Ydd/g, theta)
    const double gx = ax * c + ay * s, gy = ay * c - ax * s;
    const double wx = -a + psi_x_.dot(q), wy = 1.0 + psi_y_.dot(q);
    const Vec cv = delta_ - a * psi_x_ + psi_y_ + mu_ * q;  // half the gradient of m in q
    const Vec b = coupling(a, q);
    const double m = 1.0 + zeta2_ + a * a + (cv + delta_ - a * psi_x_ + psi_y_).dot(q);
    const double f_theta = -2.0 * cv.dot(q_dot) * theta_dot - gh_ * (wx * gy - wy * gx);
    Vec f_q = theta_dot * (theta_dot * cv - 2.0 * (gamma_.transpose() * q_dot)) - stiffness_ * q -
              gh_ * (psi_x_ * gx + psi_y_ * gy);
    if (damped_) f_q.noalias() -= damping_ * q_dot;
    // block elimination with the constant mu^-1: (m - b^T mu^-1 b) thdd = f_theta - b^T mu^-1 f_q
    const Vec z = mu_inv_ * b;
    const Vec y = mu_inv_ * f_q;
    theta_ddot = (f_theta - b.dot(y)) / (m - b.dot(z));
    q_ddot = y - z * theta_ddot;
  }

  /// Deformation accelerations in full contact (theta = 0): mu q'' = -K q - C q' - (g/h) psi.G.
  void full_contact_acceleration(const Vec& q, const Vec& q_dot, BaseAcceleration base,
                                 Vec& q_ddot) const {
    const double ax = base.x / g_, ay = 1.0 + base.y / g_;
    Vec f = -(stiffness_ * q) - gh_ * (psi_x_ * ax + psi_y_ * ay);
    if (damped_) f.noalias() -= damping_ * q_dot;
    q_ddot = mu_inv_ * f;
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

  /// Location of the resultant in full contact over h, from the c.g. projection (paper eq. 4).
  double resultant_location(const Vec& q, const Vec& q_ddot, BaseAcceleration base) const {
    const double fj = 1.0 + base.y / g_ + psi_y_.dot(q_ddot) / gh_;
    return contact_moment(0.0, q, q_ddot, base) / fj;
  }

  /// Kinetic energy relative to the base [J]: T = 1/2 M h^2 nu^T A nu.
  double kinetic_energy(double a, const Vec& q, double theta_dot, const Vec& q_dot) const {
    return 0.5 * mass_ * h_ * h_ *
           (inertia(a, q) * theta_dot * theta_dot + 2.0 * theta_dot * coupling(a, q).dot(q_dot) +
            q_dot.dot(mu_ * q_dot));
  }
  /// Gravity and strain energy [J]: V = M g h (J.w + 1/2 q^T kappa q).
  double potential_energy(double a, double theta, const Vec& q) const {
    const double wx = -a + psi_x_.dot(q), wy = 1.0 + psi_y_.dot(q);
    return mass_ * g_ * h_ *
           (std::sin(theta) * wx + std::cos(theta) * wy + 0.5 * q.dot(kappa_ * q));
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
    return damped_ ? mass_ * h_ * h_ * q_dot.dot(damping_ * q_dot) : 0.0;
  }

  /// Linear velocity of the c.g. relative to the base [m/s], body axes at theta = 0 (= inertial).
  Eigen::Vector2d cg_velocity(double a, const Vec& q, double theta_dot, const Vec& q_dot) const {
    const double wx = -a + psi_x_.dot(q), wy = 1.0 + psi_y_.dot(q);
    return {h_ * (psi_x_.dot(q_dot) - theta_dot * wy), h_ * (psi_y_.dot(q_dot) + theta_dot * wx)};
  }

  const Vec& psi_x() const { return psi_x_; }  // participation, body i component
  const Vec& psi_y() const { return psi_y_; }  // participation, body j component

 private:
  int n_;
  double mass_, h_, g_, gh_, zeta2_, alpha1_, alpha2_;
  Mat mu_, mu_inv_, kappa_, stiffness_, damping_, gamma_;
  Vec psi_x_, psi_y_, delta_, beta_;
  bool damped_;
};

}  // namespace flexrock
