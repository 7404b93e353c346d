// SPDX-License-Identifier: BSD-3-Clause
// Coulomb friction at the contact (docs/theory.md §18-§19): Moreau's impact law with friction on
// the impulse, and the stick/slip decisions of a sliding or sticking contact. Pure functions of
// the body's dynamics at the pre-impact state; the event loop keeps the bookkeeping.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "flexrock/contact/flight_maps.hpp"
#include "flexrock/contact/impact.hpp"
#include "flexrock/model/dynamics.hpp"

namespace flexrock {

/// The floor's Coulomb friction.
struct CoulombFriction {
  double mu_s = std::numeric_limits<double>::infinity();  // static coefficient (inf: no limit)
  double mu_k = std::numeric_limits<double>::infinity();  // kinetic coefficient, <= mu_s
};

/// |F_I| / F_J of a force or an impulse (I, J): the friction it needs; infinite where it does not
/// press.
inline double friction_ratio(double f_i, double f_j) {
  return f_j > 0.0 ? std::abs(f_i) / f_j : std::numeric_limits<double>::infinity();
}

/// A force or impulse (I, J) lies in the friction cone of mu: it presses, and |I| <= mu J.
inline bool inside_friction_cone(double f_i, double f_j, double mu) {
  return f_j > 0.0 && std::abs(f_i) <= mu * f_j;
}

/// The slip a sticking contact starts when static friction cannot hold the tangential force F_I
/// (theory §18): the base slides against it, from rest. +1: along I.
inline int slip_direction(double f_i) { return f_i > 0.0 ? -1 : 1; }

/// A sliding contact whose slip velocity reached zero (theory §18): it sticks where static
/// friction holds with a strictly positive margin mu_s F_J - |F_I|; where the margin is <= 0 it
/// slides the way the floor cannot hold it. The tie: a slide that started here from rest and did
/// not grow (`never_grew`: its slip velocity had no value of its sign to resolution) is the floor
/// holding at m_s = 0 (Coulomb's law holds up to and including |F_I| = mu_s F_J; a margin that is
/// not positive there is zero to rounding, since a negative one makes the slide grow): it sticks.
struct StickOrSlip {
  bool sticks = true;
  int slip = 0;      // the slide after: 0 none, +1 along I, -1 against
  bool tie = false;  // it sticks at a margin <= 0 (zero to rounding): the limit starts at zero
};
inline StickOrSlip stick_or_slip(double f_i, double margin, bool never_grew = false) {
  if (margin > 0.0) return {true, 0, false};
  if (never_grew) return {true, 0, true};
  return {false, slip_direction(f_i), false};
}

/// What an impact with friction did.
template <class Vec>
struct FrictionImpactOutcome {
  bool consistent = true;      // false: no outcome of the law fits (k_s <= 0, or none at theta = 0)
  bool law_fallback = false;   // rigid_body would have added energy: the paper's law took it
  int edge = 0;                // the tipping point on the floor after (the pivot unless flat)
  bool flat = false;           // both edges on the floor after (theta_dot+ = 0)
  bool slid = false;           // the sticking impulse lay outside the friction cone
  int slip = 0;                // the contact's slide after: 0 sticks, +1 along I, -1 against
  double slip_velocity = 0.0;  // [m/s] d_dot+ (0 unless it slides)
  double theta_dot = 0.0;      // [rad/s] after (0 when flat)
  Vec q_dot;                   // [1/s] after
  Eigen::Vector2d v_c;         // [m/s] the c.g. velocity after, relative to the base
  Eigen::Vector2d impulse;     // [N s] M (v_c+ - v_c-), inertial components
  double energy_loss = 0.0;    // [J] T- - T+ (relative to the base)
  double sticking_demand = 0.0;  // |I|/J of the sticking impulse: the friction sticking needs
};

/// One outcome of the impact, affine in the slip velocity after: the post-impact rates and c.g.
/// velocity at d_dot+ = 0 (index 0) and per unit d_dot+ (index 1).
template <class Vec>
struct ImpactCandidate {
  double thd0 = 0.0, thd1 = 0.0;  // [rad/s], [rad/m]
  Vec qd0, qd1;                   // [1/s], [1/m]
  Eigen::Vector2d vc0, vc1;       // [m/s], [-]
};

/// Coulomb's law on one candidate's impulse M (v_c+ - v_c-) = L0 + d_dot+ L1: d_dot+ = 0 inside
/// the cone, else on its edge (the slip the cone cannot hold).
struct CoulombResolution {
  double v = 0.0;       // [m/s] d_dot+
  double demand = 0.0;  // |L0_I| / L0_J: the friction the sticking impulse needs
  bool slid = false;
  bool ok = true;  // false: the slide has no consistent solution (k_s <= 0)
};

/// The tipping point `c` sticks (d_dot+ = 0) or slides at unit d_dot+: each the plastic corner
/// impact of Dynamics::corner_impact, the second with the corner's velocity after set to I.
template <class Dyn, class Vec>
void corner_candidate(const Dyn& dyn, int c, const ImpactState<Vec>& s, ModesInImpact modes,
                      ImpactCandidate<Vec>& k) {
  const int n = dyn.modes();
  const double sn = std::sin(s.theta), cs = std::cos(s.theta);
  const Eigen::Vector2d unit_body(cs, -sn);  // I in body components
  const Eigen::Vector2d v_corner =
      dyn.corner_velocity_body(c, sn, cs, s.q, s.theta_dot, s.q_dot, s.v_c);
  k.qd0.resize(n);
  k.qd1.resize(n);
  law_corner_impact(dyn, modes, c, s.q, s.theta_dot, s.q_dot, v_corner, k.thd0, k.qd0);
  law_corner_impact(dyn, modes, c, s.q, 0.0, Vec(Vec::Zero(n)), -unit_body, k.thd1, k.qd1);
  Eigen::Vector2d r;
  dyn.cg_from_pivot(c, sn, cs, s.q, k.thd0, k.qd0, r, k.vc0);
  dyn.cg_from_pivot(c, sn, cs, s.q, k.thd1, k.qd1, r, k.vc1);
  k.vc1(0) += 1.0;
}

/// Both edges land at theta = 0 (theta_dot+ = 0): the modal momenta p = mu q_dot + psi_x d_dot / h
/// (over M h^2) are conserved; rigid_body: the slip carries the body as a whole, the modes keep
/// their rates. `edge`: the tipping point whose velocity gives p (the same for both).
template <class Dyn, class Vec>
void flat_candidate(const Dyn& dyn, int edge, const ImpactState<Vec>& s, ModesInImpact modes,
                    ImpactCandidate<Vec>& k) {
  const bool rigid = modes == ModesInImpact::kVelocitiesKept;
  const int n = dyn.modes();
  const double h = dyn.height();
  const double sn = std::sin(s.theta), cs = std::cos(s.theta);
  const Eigen::Vector2d v_corner =
      dyn.corner_velocity_body(edge, sn, cs, s.q, s.theta_dot, s.q_dot, s.v_c);
  const Vec p = dyn.flight_modal_momenta(edge, s.q, s.theta_dot, s.q_dot, v_corner);
  k.thd0 = k.thd1 = 0.0;
  k.qd0 = rigid ? s.q_dot : Vec(dyn.mu_inverse() * p);
  k.qd1 = rigid ? Vec(Vec::Zero(n)) : Vec(-(dyn.mu_inverse() * dyn.psi_x()) / h);
  k.vc0 = h * Eigen::Vector2d(dyn.psi_x().dot(k.qd0), dyn.psi_y().dot(k.qd0));
  k.vc1 = Eigen::Vector2d(1.0 + h * dyn.psi_x().dot(k.qd1), h * dyn.psi_y().dot(k.qd1));
}

/// Coulomb's law on a candidate (theory §19): the sticking impulse L0 if it lies in the cone of
/// mu_s, else d_dot+ such that L0 + d_dot+ L1 lies on the edge of the cone of mu_k, sliding the
/// way the cone cannot hold (k_s = L1_I + sg mu_k L1_J > 0 for a consistent slide).
template <class Vec>
CoulombResolution coulomb_resolution(const ImpactCandidate<Vec>& c, const Eigen::Vector2d& v_c,
                                     double mass, const CoulombFriction& f) {
  CoulombResolution z;
  const Eigen::Vector2d l0 = mass * (c.vc0 - v_c), l1 = mass * c.vc1;
  z.demand = friction_ratio(l0(0), l0(1));
  if (inside_friction_cone(l0(0), l0(1), f.mu_s)) return z;
  const double sg = l0(0) > 0.0 ? -1.0 : 1.0;
  const double k_s = l1(0) + sg * f.mu_k * l1(1);
  z.v = -(l0(0) + sg * f.mu_k * l0(1)) / k_s;
  z.slid = true;
  z.ok = k_s > 0.0;
  return z;
}

namespace detail {

template <class Dyn, class Vec>
FrictionImpactOutcome<Vec> friction_impact(const Dyn& dyn, const ImpactState<Vec>& s,
                                           const CornerImpactCase& ic, bool flat,
                                           const ImpactLawInfo& law, const CoulombFriction& f) {
  using Candidate = ImpactCandidate<Vec>;
  const int e = ic.edge;
  const double th = s.theta, thd_minus = s.theta_dot, m = dyn.mass();
  const Eigen::Vector2d& v_c = s.v_c;
  const double kinetic_before = dyn.flight_kinetic_energy(s.q, thd_minus, s.q_dot, v_c);
  auto turn = [](const Candidate& c, double v) { return c.thd0 + v * c.thd1; };
  Candidate k;
  CoulombResolution z;
  int lands = e;
  if (flat) {
    flat_candidate(dyn, e, s, law.modes, k);
    z = coulomb_resolution(k, v_c, m, f);
  } else if (th != 0.0) {
    corner_candidate(dyn, e, s, law.modes, k);
    z = coulomb_resolution(k, v_c, m, f);
  } else {
    // theta = 0 (theory §19): corner 1, corner 2 and flat, each resolved with friction; the one
    // that is consistent (the body turns away from the other corner; flat: both corners press),
    // and where two are, the one the sticking rule of §16 names
    std::array<Candidate, 3> c;  // corner 1, corner 2, flat
    corner_candidate(dyn, 1, s, law.modes, c[0]);
    corner_candidate(dyn, 2, s, law.modes, c[1]);
    flat_candidate(dyn, e, s, law.modes, c[2]);
    std::array<CoulombResolution, 3> r = {coulomb_resolution(c[0], v_c, m, f),
                                          coulomb_resolution(c[1], v_c, m, f),
                                          coulomb_resolution(c[2], v_c, m, f)};
    std::array<bool, 3> fits = {r[0].ok && turn(c[0], r[0].v) > 0.0,
                                r[1].ok && -turn(c[1], r[1].v) > 0.0,
                                r[2].ok && turn(c[0], r[2].v) <= 0.0 && -turn(c[1], r[2].v) <= 0.0};
    // the sticking rule: the landing corner if it turns the body up about itself, else (landing
    // from flight) the other one, else flat
    const int o = e == 1 ? 2 : 1;
    int pick = 2;
    if (edge_sign(e) * c[static_cast<std::size_t>(e - 1)].thd0 > 0.0) {
      pick = e - 1;
    } else if (ic.from_flight && edge_sign(o) * c[static_cast<std::size_t>(o - 1)].thd0 > 0.0) {
      pick = o - 1;
    }
    if (!fits[static_cast<std::size_t>(pick)]) {
      for (int j = 0; j < 3; ++j)
        if (fits[static_cast<std::size_t>(j)]) pick = j;
    }
    const auto pk = static_cast<std::size_t>(pick);
    k = c[pk];
    z = r[pk];
    z.ok = z.ok && fits[pk];
    flat = pick == 2;
    lands = flat ? e : pick + 1;
  }
  if (ic.grazing && z.slid && !((k.vc0 + z.v * k.vc1 - v_c)(1) > 0.0)) {
    // a grazing landing (below the chatter interval) whose sliding impulse would pull: the
    // sticking one, as without friction (§16: Carnot's loss, a tensile_landing said)
    z = CoulombResolution{};
  }
  FrictionImpactOutcome<Vec> out;
  out.consistent = z.ok;
  out.edge = lands;
  out.flat = flat;
  out.slid = z.slid;
  out.sticking_demand = z.demand;
  if (!z.ok) return out;
  const double v_plus = z.v;
  const double thd_plus = k.thd0 + v_plus * k.thd1;
  out.q_dot = k.qd0 + v_plus * k.qd1;
  out.v_c = k.vc0 + v_plus * k.vc1;
  out.impulse = m * (out.v_c - v_c);
  out.energy_loss = kinetic_before - dyn.flight_kinetic_energy(s.q, thd_plus, out.q_dot, out.v_c);
  if (law.on_gain == OnEnergyGain::kPaperLaw &&
      out.energy_loss < -kImpactEnergyRounding * kinetic_before) {
    // the paper's law takes the impact, with the outcome chosen so far (flat stays flat)
    out = friction_impact(dyn, s, ic, flat, impact_law_info(ImpactLaw::kPaper), f);
    out.law_fallback = true;
    return out;
  }
  out.theta_dot = flat ? 0.0 : thd_plus;
  out.slip = !z.slid || v_plus == 0.0 ? 0 : (v_plus > 0.0 ? 1 : -1);
  out.slip_velocity = out.slip != 0 ? v_plus : 0.0;
  return out;
}

}  // namespace detail

/// Moreau's impact law for one contact, plastic normally, with Coulomb friction on the impulse
/// (theory §19): the moment of momentum about the landing tipping point and the modal momenta are
/// conserved; after the impact the tipping point rests on the floor (stick) or slides along it at
/// d_dot+ (slip), and every post-impact quantity is affine in d_dot+. The sticking impulse is
/// taken if it lies in the friction cone; else the slip direction is the one the cone cannot
/// hold, and d_dot+ puts the impulse on the cone's edge. At theta = 0 the three outcomes (corner
/// 1, corner 2, both edges flat with theta_dot+ = 0 and the modal momenta conserved) are each
/// resolved with friction, and the consistent one taken; where two are, the sticking rule of §16
/// names it. The rigid_body law keeps the modal velocities; where it would add energy the paper's
/// law takes the impact (law_fallback). `s.theta` is 0 for a rocking impact.
template <class Dyn, class Vec>
FrictionImpactOutcome<Vec> friction_impact(const Dyn& dyn, const ImpactState<Vec>& s,
                                           const CornerImpactCase& ic, const ImpactRule& rule,
                                           const CoulombFriction& f) {
  return detail::friction_impact(dyn, s, ic, ic.flat, impact_law_info(rule.law), f);
}

}  // namespace flexrock
