// SPDX-License-Identifier: BSD-3-Clause
// The maps into and out of flight (docs/theory.md, "Lift-off" and "Landing"): the lift-off map (no
// impulse) and the plastic landing of a tipping point without friction. Pure functions of the
// body's dynamics at the state of the transition; the event loop keeps the bookkeeping.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "flexrock/contact/impact.hpp"
#include "flexrock/model/dynamics.hpp"

namespace flexrock {

/// A body at a corner impact: its tilt, modal coordinates, rates and c.g. velocity just before.
template <class Vec>
struct ImpactState {
  double theta;                // [rad]
  const Vec& q;                // [-] modal coordinates
  double theta_dot;            // [rad/s] before
  const Vec& q_dot;            // [1/s] before
  const Eigen::Vector2d& v_c;  // [m/s] c.g. velocity relative to the base, inertial, before
};

/// A body in contact as it leaves the floor.
template <class Vec>
struct LiftOffState {
  int pivot;                   // 1 or 2: the tipping point it rocks on; 0: full contact
  double theta;                // [rad]
  const Vec& q;                // [-]
  double theta_dot;            // [rad/s]
  const Vec& q_dot;            // [1/s]
  double offset;               // [m] the base centre's horizontal offset d
  bool sliding;                // the pivot slides along the floor at slip_velocity
  double slip_velocity = 0.0;  // [m/s] d_dot
};

/// Where flight starts: the c.g. relative to the base origin, and its velocity.
struct FlightStart {
  Eigen::Vector2d r_c;  // [m] (x_c, y_c)
  Eigen::Vector2d v_c;  // [m/s]
};

/// Whether a body whose floor stops pressing would move a touching tipping point down if it flew:
/// then it cannot leave a sticking pivot (it could only slide off it, which is not modelled), and
/// the floor is let pull (theory "Lift-off"). A sliding pivot never does: its friction vanishes
/// with F_J, and the corner's free acceleration is zero to rounding there.
template <class Dyn, class Vec>
bool lift_off_pulls(const Dyn& dyn, const LiftOffState<Vec>& s, BaseAcceleration a) {
  const double sn = std::sin(s.theta), cs = std::cos(s.theta);
  return !s.sliding && ((s.pivot != 2 && dyn.free_corner_acceleration(1, sn, cs, s.q, s.theta_dot,
                                                                      s.q_dot, a) < 0.0) ||
                        (s.pivot != 1 && dyn.free_corner_acceleration(2, sn, cs, s.q, s.theta_dot,
                                                                      s.q_dot, a) < 0.0));
}

/// The lift-off map: no impulse, the rates carry over and the c.g. takes its place and velocity
/// about the pivot (in full contact theta = 0 and either edge gives the same); a sliding pivot's
/// slip carries the c.g. along I.
template <class Dyn, class Vec>
FlightStart lift_off_map(const Dyn& dyn, const LiftOffState<Vec>& s) {
  const int e = s.pivot == 2 ? 2 : 1;
  const double sn = std::sin(s.theta), cs = std::cos(s.theta);
  Eigen::Vector2d r, v;
  dyn.cg_from_pivot(e, sn, cs, s.q, s.theta_dot, s.q_dot, r, v);
  if (s.sliding) v(0) += s.slip_velocity;
  return {Eigen::Vector2d(s.offset + dyn.height() * dyn.alpha(e) + r(0), r(1)), v};
}

/// What a landing without friction did.
template <class Vec>
struct LandingOutcome {
  int edge = 0;            // the tipping point on the floor after (the landing one, or at theta = 0
                           // the other where the map turns the body up about it)
  bool flat = false;       // both edges on the floor: theta_dot+ = 0
  double theta_dot = 0.0;  // [rad/s] after
  Vec q_dot;               // [1/s] after
  Eigen::Vector2d v_c;     // [m/s] the c.g. velocity after
  Eigen::Vector2d impulse;    // [N s] M (v_c+ - v_c-), inertial components
  double energy_loss = 0.0;   // [J] T- - T+
  bool law_fallback = false;  // rigid_body would have added energy: the paper's law took it
};

/// The plastic landing of tipping point `edge` after a flight, the corner sticking (theory
/// "Landing"): the modal momenta and the moment of momentum about the corner are conserved
/// (Dynamics::corner_impact). At theta = 0 with the map turning the body into the floor about
/// `edge`, the other tipping point takes the floor if its map turns the body up about it, else
/// both land: theta_dot+ = 0 with the modal momenta conserved (rigid_body: the modal velocities).
/// The loss is Carnot's, the kinetic energy of the velocity jump (>= 0 by construction); the
/// rigid_body law's is the difference of the energies, and where that is a gain the paper's law
/// takes the landing (law_fallback).
template <class Dyn, class Vec>
LandingOutcome<Vec> landing_map(const Dyn& dyn, int edge, const ImpactState<Vec>& s,
                                const ImpactRule& rule) {
  const ImpactLawInfo& law = impact_law_info(rule.law);
  const bool rigid = law.modes == ModesInImpact::kVelocitiesKept;
  const int n = dyn.modes();
  const Vec& q = s.q;
  const Vec& qd = s.q_dot;
  const Eigen::Vector2d& v_c = s.v_c;
  const double th = s.theta, thd_minus = s.theta_dot;
  const double sn = std::sin(th), cs = std::cos(th);
  int e = edge;
  const Eigen::Vector2d v_corner = dyn.corner_velocity_body(e, sn, cs, q, thd_minus, qd, v_c);
  double thd_plus = 0.0;
  Vec qd_plus(n);
  law_corner_impact(dyn, law.modes, e, q, thd_minus, qd, v_corner, thd_plus, qd_plus);
  bool flat = false;
  if (th == 0.0 && edge_sign(e) * thd_plus <= 0.0) {
    // level: the body rocks on the other tipping point if its map turns it up about that one,
    // else both land (both vertical impulses are then compressive; theory "Landing")
    const int o = e == 1 ? 2 : 1;
    const Eigen::Vector2d v_other = dyn.corner_velocity_body(o, sn, cs, q, thd_minus, qd, v_c);
    double thd_o = 0.0;
    Vec qd_o(n);
    law_corner_impact(dyn, law.modes, o, q, thd_minus, qd, v_other, thd_o, qd_o);
    if (edge_sign(o) * thd_o > 0.0) {
      e = o;
      thd_plus = thd_o;
      qd_plus = qd_o;
    } else {
      flat = true;
    }
  }
  if (flat) {
    // both edges on the floor: theta_dot = 0, the modal momenta are conserved (rigid_body: the
    // modal velocities)
    thd_plus = 0.0;
    if (rigid) {
      qd_plus = qd;
    } else {
      const Vec p = dyn.flight_modal_momenta(e, q, thd_minus, qd, v_corner);
      qd_plus = dyn.mu_inverse() * p;
    }
  }
  // the c.g. velocity after, for the impulse
  Eigen::Vector2d r, v_after;
  dyn.cg_from_pivot(e, sn, cs, q, thd_plus, qd_plus, r, v_after);
  if (flat)
    v_after = dyn.height() * Eigen::Vector2d(dyn.psi_x().dot(qd_plus), dyn.psi_y().dot(qd_plus));
  const Eigen::Vector2d impulse = dyn.mass() * (v_after - v_c);
  // a plastic impact loses the kinetic energy of the velocity jump (Carnot), which is >= 0 by
  // construction: the jump's c.g. velocity and its motion about the c.g. (theory §16). The
  // rigid_body law is no projection: its loss is the difference of the energies, and where that
  // is a gain the paper's law takes the landing
  const Vec dqd = qd_plus - qd;
  double loss = dyn.flight_kinetic_energy(q, thd_plus - thd_minus, dqd, v_after - v_c);
  if (rigid) {
    const double before = dyn.flight_kinetic_energy(q, thd_minus, qd, v_c);
    loss = before - dyn.flight_kinetic_energy(q, thd_plus, qd_plus, v_after);
    if (law.on_gain == OnEnergyGain::kPaperLaw && loss < -kImpactEnergyRounding * before) {
      ImpactRule paper = rule;
      paper.law = ImpactLaw::kPaper;
      LandingOutcome<Vec> out = landing_map(dyn, edge, s, paper);
      out.law_fallback = true;
      return out;
    }
  }
  LandingOutcome<Vec> out;
  out.edge = e;
  out.flat = flat;
  out.theta_dot = thd_plus;
  out.q_dot = qd_plus;
  out.v_c = v_after;
  out.impulse = impulse;
  out.energy_loss = loss;
  return out;
}

}  // namespace flexrock
