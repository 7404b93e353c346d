// SPDX-License-Identifier: BSD-3-Clause
// A rigid body of revolution in three dimensions (docs/theory.md §27): its parameters, the
// rolling-on-the-rim equations as a pure function of the state, and its planar equivalent.
// No files, no loop: the engine is src/sim/axisymmetric.cpp.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "flexrock/core/types.hpp"
#include "flexrock/model/body.hpp"

namespace flexrock {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

/// A rigid body of revolution standing on the circular rim of its flat base. The c.g. is on the
/// axis; the inertia tensor about the c.g. is diag(A, A, C) in any frame with the axis third.
struct AxisymmetricBody {
  double mass = 0.0;                  // M [kg]
  double height = 0.0;                // h [m] c.g. above the base centre
  double radius = 0.0;                // R [m] base (rim) radius
  double inertia_diameter = 0.0;      // A [kg m^2] about a diameter through the c.g.
  double inertia_axis = 0.0;          // C [kg m^2] about the axis
  double gravity = kStandardGravity;  // g [m/s^2]
};

/// A uniform solid (inner_radius 0) or hollow circular cylinder of full `height`, outer `radius`
/// [m] and `mass` [kg]: h = height/2, A = M (3 (R^2 + Ri^2) + H^2) / 12, C = M (R^2 + Ri^2) / 2.
AxisymmetricBody uniform_cylinder(double radius, double height, double mass,
                                  double inner_radius = 0.0);

/// Throws InputError naming the value when the body is not physical (M, h, R, A, C > 0, finite;
/// the triangle inequality of a rigid body's principal inertias, C <= 2 A).
void validate(const AxisymmetricBody& body);

/// Rocking about a rim point: p = sqrt(M g sqrt(R^2 + h^2) / (A + M (R^2 + h^2))) [rad/s].
double rocking_frequency(const AxisymmetricBody& body);

/// The landing map's ratio theta_dot+/theta_dot- for a motion in one plane:
/// (A + M (h^2 - R^2)) / (A + M (h^2 + R^2)) (Housner's with the body's own inertia).
double planar_landing_ratio(const AxisymmetricBody& body);

/// The planar rigid body with the same section through the axis: M, I_cg = A, h, b1 = b2 = R.
BodyParameters planar_equivalent(const AxisymmetricBody& body);

/// The orientation and rates of a body rolling on its rim (world frame, z up).
struct RimState {
  Eigen::Quaterniond orientation;  // body to world; the body's axis is its third axis
  Vector3 omega;                   // [rad/s] angular velocity, world components
};

/// Everything the rolling equations give at one state.
struct RimRates {
  Vector3 axis;         // k: the body's axis, world
  Vector3 contact_dir;  // c: horizontal unit vector from the base centre toward the rim contact
  Vector3 r;            // [m] r_PG, from the contact point to the c.g.
  Vector3 v_cg;         // [m/s] c.g. velocity relative to the floor, omega x r_PG
  Vector3 omega_dot;    // [rad/s^2]
  Vector3 force;        // [N] floor on body at the contact point
  double sin_tilt = 0;  // sin(theta) = |k_h|
  double tilt = 0;      // theta [rad]
};

/// Rolling on the rim without slip (docs/theory.md §27): the Newton-Euler balance about the
/// contact point P, I_P omega_dot = -omega x I omega - M r x (omega x r_dot) - M r x (g e_z + a_f),
/// with I_P = I + M (|r|^2 1 - r r^T), r = r_PG, and the floor force F = M (a_G + g e_z + a_f).
/// `floor_acc` is the floor's acceleration a_f (x, y horizontal, z up) [m/s^2]; `contact_ref`
/// the contact direction to use when the body stands upright (|k_h| = 0), where it is undefined.
RimRates rim_rates(const AxisymmetricBody& body, const RimState& s, const Vector3& floor_acc,
                   const Vector3& contact_ref);

/// The same balance pivoting on one material rim point, `pivot_body` (unit vector from the base
/// centre to it, body frame), instead of rolling: r_dot = omega x r. Near upright, where the
/// lowest rim point races round the rim, the engine pivots (docs/theory.md §27).
RimRates pivot_rates(const AxisymmetricBody& body, const RimState& s, const Vector3& floor_acc,
                     const Vector3& pivot_body);

}  // namespace flexrock
