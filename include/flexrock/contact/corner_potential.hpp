// SPDX-License-Identifier: BSD-3-Clause
// The compliant corner's contact potential (docs/theory.md, "Compliant contact"): the normal
// spring, and a tangential spring whose stiffness scales with the normal spring's force, so that
// the contact's stored energy is continuous and vanishes as the penetration does. Pure functions,
// checked against tools/derive/derive.py ("compliant_potential").
#pragma once

#include <cmath>

#include "flexrock/contact/compliant.hpp"

namespace flexrock {

/// phi(delta) = k delta^p / f_ref [-]: the tangential stiffness's scale, the normal spring's force
/// over f_ref (the force under half the weight, so phi = 1 at rest on both corners, where k_t is
/// the tangential stiffness); 0 at and above the floor.
inline double tangential_scale(const CornerContact& cc, double f_ref, double delta) {
  if (!(delta > 0.0)) return 0.0;
  return cc.k * (cc.p == 1.0 ? delta : std::pow(delta, cc.p)) / f_ref;
}

/// d phi / d delta [1/m].
inline double tangential_scale_slope(const CornerContact& cc, double f_ref, double delta) {
  if (!(delta > 0.0)) return 0.0;
  return cc.p * cc.k * (cc.p == 1.0 ? 1.0 : std::pow(delta, cc.p - 1.0)) / f_ref;
}

/// The sticking corner's stored energy [J] at penetration delta [m] and tangential stretch
/// u = x_e - xi_e [m]: V = k delta^(p+1) / (p+1) + k_t phi(delta) u^2 / 2, zero at delta = 0
/// whatever u.
inline double corner_potential(const CornerContact& cc, double f_ref, double delta, double u) {
  return normal_spring_energy(cc, delta) +
         0.5 * cc.k_t * tangential_scale(cc, f_ref, delta) * u * u;
}

/// The floor's force on a sticking corner [N]: tangential (along +I) and normal (up).
struct CornerForce {
  double t = 0.0;
  double n = 0.0;
};

/// The sticking corner's force at penetration delta, its rate delta_dot (into the floor), the
/// stretch u and the corner's horizontal speed u_dot: the potential's gradient plus the dashpots,
/// F_t = -phi (k_t u + c_t u_dot), F_n = normal_force + k_t phi'(delta) u^2 / 2 (never a pull:
/// the second term pushes).
inline CornerForce sticking_corner_force(const CornerContact& cc, double f_ref, double delta,
                                         double delta_dot, double u, double u_dot, double v_in) {
  const double phi = tangential_scale(cc, f_ref, delta);
  return {-phi * (cc.k_t * u + cc.c_t * u_dot),
          normal_force(cc, delta, delta_dot, v_in) +
              0.5 * cc.k_t * tangential_scale_slope(cc, f_ref, delta) * u * u};
}

}  // namespace flexrock
