// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/model/axisymmetric_body.hpp"

#include <cmath>
#include <string>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"
#include "flexrock/model/builders.hpp"

namespace flexrock {

AxisymmetricBody uniform_cylinder(double radius, double height, double mass, double inner_radius) {
  FLEXROCK_THROW_UNLESS(std::isfinite(inner_radius) && inner_radius >= 0.0 && inner_radius < radius,
                        "cylinder: expected 0 <= inner_radius < radius, got inner_radius = " +
                            format_number(inner_radius) + " m, radius = " + format_number(radius) +
                            " m");
  AxisymmetricBody b;
  b.mass = mass;
  b.height = 0.5 * height;
  b.radius = radius;
  const double rr = radius * radius + inner_radius * inner_radius;
  b.inertia_diameter = mass * (3.0 * rr + height * height) / 12.0;
  b.inertia_axis = 0.5 * mass * rr;
  validate(b);
  return b;
}

void validate(const AxisymmetricBody& b) {
  auto positive = [](double v, const char* name, const char* unit) {
    FLEXROCK_THROW_UNLESS(std::isfinite(v) && v > 0.0, std::string("body of revolution: ") + name +
                                                           " must be a finite number > 0 " + unit +
                                                           ", got " + format_number(v));
  };
  positive(b.mass, "mass", "[kg]");
  positive(b.height, "c.g. height", "[m]");
  positive(b.radius, "base radius", "[m]");
  positive(b.inertia_diameter, "inertia about a diameter", "[kg m^2]");
  positive(b.inertia_axis, "inertia about the axis", "[kg m^2]");
  positive(b.gravity, "gravity", "[m/s^2]");
  // principal inertias of a rigid body: C <= A + A
  FLEXROCK_THROW_UNLESS(
      b.inertia_axis <= 2.0 * b.inertia_diameter * (1.0 + 1e-12),
      "body of revolution: the inertia about the axis (" + format_number(b.inertia_axis) +
          " kg m^2) exceeds twice the inertia about a diameter (" +
          format_number(b.inertia_diameter) + " kg m^2): no rigid body has these (C <= 2 A)");
}

double rocking_frequency(const AxisymmetricBody& b) {
  const double l2 = b.radius * b.radius + b.height * b.height;
  return std::sqrt(b.mass * b.gravity * std::sqrt(l2) / (b.inertia_diameter + b.mass * l2));
}

double planar_landing_ratio(const AxisymmetricBody& b) {
  const double h2 = b.height * b.height, r2 = b.radius * b.radius;
  return (b.inertia_diameter + b.mass * (h2 - r2)) / (b.inertia_diameter + b.mass * (h2 + r2));
}

BodyParameters planar_equivalent(const AxisymmetricBody& b) {
  BodyParameters p = rigid_body(b.mass, b.inertia_diameter, b.height, b.radius, b.radius);
  p.gravity = b.gravity;
  return p;
}

namespace {

// the Newton-Euler balance about the contact, given r = r_PG and its rate
RimRates balance(const AxisymmetricBody& b, const Vector3& k, const Vector3& w, const Vector3& r,
                 const Vector3& rd, const Vector3& floor_acc) {
  RimRates out;
  // inertia about the c.g. in world components: A 1 + (C - A) k k^T (axisymmetric)
  const double a = b.inertia_diameter, cc = b.inertia_axis, m = b.mass;
  const Matrix3 iw = a * Matrix3::Identity() + (cc - a) * k * k.transpose();
  const Matrix3 ip = iw + m * (r.squaredNorm() * Matrix3::Identity() - r * r.transpose());
  const Vector3 ge = Vector3(0.0, 0.0, b.gravity) + floor_acc;
  const Vector3 rhs = -w.cross(iw * w) - m * r.cross(w.cross(rd)) - m * r.cross(ge);
  out.omega_dot = ip.ldlt().solve(rhs);
  out.axis = k;
  out.r = r;
  out.v_cg = w.cross(r);
  const Vector3 acc = out.omega_dot.cross(r) + w.cross(rd);
  out.force = m * (acc + ge);
  out.sin_tilt = std::hypot(k.x(), k.y());
  out.tilt = std::atan2(out.sin_tilt, k.z());
  return out;
}

}  // namespace

RimRates rim_rates(const AxisymmetricBody& b, const RimState& s, const Vector3& floor_acc,
                   const Vector3& contact_ref) {
  const Eigen::Quaterniond qn = s.orientation.normalized();
  const Vector3 k = qn * Vector3::UnitZ();
  const Vector3& w = s.omega;
  const double sn = std::hypot(k.x(), k.y());
  // the contact direction: toward the side the axis leans (undefined upright: the reference)
  const Vector3 c = sn > 0.0 ? Vector3(k.x() / sn, k.y() / sn, 0.0) : contact_ref;
  // u: unit vector in the base plane from the base centre to the lowest rim point
  const Vector3 u(k.z() * c.x(), k.z() * c.y(), -sn);
  const Vector3 r = b.height * k - b.radius * u;
  // rates of the geometric vectors (the contact point moves along the rim)
  const Vector3 kd = w.cross(k);
  const double sd = c.x() * kd.x() + c.y() * kd.y();
  Vector3 cd = Vector3::Zero();
  if (sn > 0.0) cd = (Vector3(kd.x(), kd.y(), 0.0) - sd * c) / sn;
  const Vector3 ud(kd.z() * c.x() + k.z() * cd.x(), kd.z() * c.y() + k.z() * cd.y(), -sd);
  const Vector3 rd = b.height * kd - b.radius * ud;
  RimRates out = balance(b, k, w, r, rd, floor_acc);
  out.contact_dir = c;
  return out;
}

RimRates pivot_rates(const AxisymmetricBody& b, const RimState& s, const Vector3& floor_acc,
                     const Vector3& pivot_body) {
  const Eigen::Quaterniond qn = s.orientation.normalized();
  const Vector3 k = qn * Vector3::UnitZ();
  const Vector3 u = qn * pivot_body;
  const Vector3 r = b.height * k - b.radius * u;
  // a material point: r_dot = v_G - v_P = omega x r
  RimRates out = balance(b, k, s.omega, r, s.omega.cross(r), floor_acc);
  const double uh = std::hypot(u.x(), u.y());
  out.contact_dir = Vector3(u.x() / uh, u.y() / uh, 0.0);
  return out;
}

}  // namespace flexrock
