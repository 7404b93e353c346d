// SPDX-License-Identifier: BSD-3-Clause
// The landing of a body of revolution rolling on its rim as its tilt passes through upright
// (docs/theory.md §27): a pure map of the rates, checked against tools/derive/axisymmetric3d.py.
#pragma once

#include "flexrock/model/axisymmetric_body.hpp"

namespace flexrock {

struct RimLanding {
  Vector3 omega_after;       // [rad/s] world components
  Vector3 impulse;           // [N s] floor on body at the landing rim point
  double energy_loss = 0.0;  // [J] kinetic energy lost (>= 0)
  bool lifts = false;        // the body tilts up about the landing point afterwards
};

/// The body stands upright (axis `axis`, |k_h| ~ 0) rolling on the rim point toward `contact_old`
/// (horizontal unit vector) with angular velocity `omega_before`; the opposite rim point P' lands.
/// Assumed, as Housner's planar law: one impulse, at P', none at the leaving point, and P' sticks
/// afterwards (rolls without slip). Then the moment of momentum about P' is conserved in all three
/// components: I_P' omega+ = I omega- + M r' x v_G-, r' = r_P'G. Nothing is assumed of the spin
/// about the axis: it follows from the same balance (it couples to the tilting rates through the
/// off-axis products of I_P'). In one plane omega+ = omega- (A + M(h^2 - R^2)) / (A + M(h^2 +
/// R^2)).
inline RimLanding rim_landing(const AxisymmetricBody& b, const Vector3& axis,
                              const Vector3& contact_old, const Vector3& omega_before) {
  const double m = b.mass, a = b.inertia_diameter, cc = b.inertia_axis;
  const Matrix3 iw = a * Matrix3::Identity() + (cc - a) * axis * axis.transpose();
  // upright: the rim points toward +-c lie at R c from the base centre
  const Vector3 r_old = b.height * axis - b.radius * axis.z() * contact_old;
  const Vector3 r_new = b.height * axis + b.radius * axis.z() * contact_old;
  const Vector3 v_before = omega_before.cross(r_old);
  const Vector3 h_new = iw * omega_before + m * r_new.cross(v_before);
  const Matrix3 ip =
      iw + m * (r_new.squaredNorm() * Matrix3::Identity() - r_new * r_new.transpose());
  RimLanding out;
  out.omega_after = ip.ldlt().solve(h_new);
  const Vector3 v_after = out.omega_after.cross(r_new);
  out.impulse = m * (v_after - v_before);
  const double t_before = 0.5 * (m * v_before.squaredNorm() + omega_before.dot(iw * omega_before));
  const double t_after =
      0.5 * (m * v_after.squaredNorm() + out.omega_after.dot(iw * out.omega_after));
  out.energy_loss = t_before - t_after;
  // the axis moves toward the new contact (-c): k_dot . (-c) > 0
  out.lifts = -out.omega_after.cross(axis).dot(contact_old) > 0.0;
  return out;
}

}  // namespace flexrock
