// SPDX-License-Identifier: BSD-3-Clause
// The impact of a rigid block on a support that moves with it (docs/theory.md §24): a pure map.
#pragma once

namespace flexrock {

/// A rigid block (mass M, c.g. height h, zeta^2 = I_cg/(M h^2)) rocking about the corner of
/// alpha_pre lands at theta = 0 on the corner of alpha_post, which sticks to the support (mass
/// m_s). The impulse acts at the landing corner, between block and support; the spring and dashpot
/// to the ground give none. So the block's moment of momentum about the landing corner and the
/// linear momentum of block and support are conserved. With chi = M/(M + m_s):
///   theta_dot+ / theta_dot- = (1 + zeta^2 + alpha_pre alpha_post - chi)
///                             / (1 + zeta^2 + alpha_post^2 - chi),
///   u_dot+ = u_dot- + chi h (theta_dot+ - theta_dot-)   (the linear momentum, for any theta_dot+).
/// m_s -> infinity (chi -> 0) gives Housner's ratio on a rigid floor; m_s -> 0 (chi = 1) a block on
/// a support that takes no horizontal impulse. u_dot is relative to the ground (whose velocity is
/// continuous and drops out).
struct SupportImpact {
  double ratio = 0.0;  // theta_dot+ / theta_dot- of the conservative map
  double chi = 0.0;    // M / (M + m_s)
};

inline SupportImpact support_impact(double mass, double support_mass, double zeta2,
                                    double alpha_pre, double alpha_post) {
  SupportImpact s;
  s.chi = mass / (mass + support_mass);
  s.ratio = (1.0 + zeta2 + alpha_pre * alpha_post - s.chi) /
            (1.0 + zeta2 + alpha_post * alpha_post - s.chi);
  return s;
}

/// u_dot+ from the linear momentum of block and support, for any theta_dot+ (the law's, a
/// restitution ratio's, or 0 when both edges stay down).
inline double support_velocity_after(const SupportImpact& s, double height, double theta_dot_minus,
                                     double theta_dot_plus, double u_dot_minus) {
  return u_dot_minus + s.chi * height * (theta_dot_plus - theta_dot_minus);
}

/// The kinetic energy of block and support relative to the ground at theta = 0, rocking about the
/// corner of alpha (the c.g. moves at (u_dot - h theta_dot, -h alpha theta_dot)).
inline double support_kinetic_at_rest_angle(double mass, double support_mass, double height,
                                            double zeta2, double alpha, double theta_dot,
                                            double u_dot) {
  const double vx = u_dot - height * theta_dot, vy = -height * alpha * theta_dot;
  return 0.5 * support_mass * u_dot * u_dot + 0.5 * mass * (vx * vx + vy * vy) +
         0.5 * mass * zeta2 * height * height * theta_dot * theta_dot;
}

}  // namespace flexrock
