// SPDX-License-Identifier: BSD-3-Clause
// Impact laws at theta = 0 (paper eqs. 6-10, derived in docs/theory.md): pure functions.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <numbers>

#include "flexrock/model/dynamics.hpp"

namespace flexrock {

/// A kinetic-energy difference across an impact below -this * T- is a gain, not rounding.
inline constexpr double kImpactEnergyRounding = 1e-12;

/// The impact laws a run can choose (docs/theory.md, "Impact laws"): one table drives the case
/// file, the studies, the Python module and the docs.
enum class ImpactLaw {
  kPaper,        // the paper's: modal momenta and the moment of momentum about the landing point
                 // conserved (exact for a contact much shorter than the highest modal period)
  kRigidBody,    // the body is rigid during the impact: modal velocities continuous, the moment
                 // of momentum about the landing point conserved (Housner's law in the rigid limit)
  kRestitution,  // theta_dot+ = r_e theta_dot- with a measured ratio r_e per landing edge, the
                 // modal momenta conserved
};

/// What the modes do during an impact under a law (docs/theory.md §21).
enum class ModesInImpact {
  kMomentaConserved,  // the impulse acts where the modes vanish: the modal momenta are conserved
  kVelocitiesKept,    // the body is rigid during the impact: the modal velocities are continuous,
                      // and only the moment of momentum about the landing point is conserved
};

/// Where theta_dot+ of the rocking impact at theta = 0 comes from.
enum class Rebound {
  kMap,            // the law's own map: the moment of momentum about the landing edge (times
                   // restitution_factor)
  kMeasuredRatio,  // a measured ratio theta_dot+/theta_dot- per landing edge (restitution_ratio)
};

/// What an impact does where its law would add energy (said as impact_law_fallback).
enum class OnEnergyGain {
  kNothing,       // the impact stands (a gain is said as impact_gained_energy)
  kPaperLaw,      // the paper's law takes the impact
  kElasticRatio,  // the measured ratio is capped at the elastic sqrt(S_pre/S_post)
};

/// One row of the impact laws: its name and what it does. The maps below and the maps with
/// friction and from flight (friction_impact.hpp, flight_maps.hpp) read the row, never the law's
/// name: a new law that combines these behaviours is one row here.
struct ImpactLawInfo {
  ImpactLaw law;
  const char* name;         // as written in case files, studies and Python
  const char* description;  // what it does (Markdown): the impact_law key's reference
                            // (solver_key_doc) and Python's docstrings list the rows
  ModesInImpact modes;      // the modes during every impact of the law (rocking, landing, flat)
  Rebound rebound;          // theta_dot+ of the rocking impact
  OnEnergyGain on_gain;     // where the law would add energy
};

inline constexpr ImpactLawInfo kImpactLaws[] = {
    {ImpactLaw::kPaper, "paper",
     "an instantaneous impulse at the landing edge, the modal momenta conserved: exact when the "
     "contact is much shorter than the highest modal period",
     ModesInImpact::kMomentaConserved, Rebound::kMap, OnEnergyGain::kNothing},
    {ImpactLaw::kRigidBody, "rigid_body",
     "the body is rigid during the impact: the modal velocities are continuous; Housner's law for "
     "a stiff body; an impact where it would add energy takes `paper` and is said as "
     "`impact_law_fallback`",
     ModesInImpact::kVelocitiesKept, Rebound::kMap, OnEnergyGain::kPaperLaw},
    {ImpactLaw::kRestitution, "restitution",
     "a measured ratio theta_dot+/theta_dot-, the modal momenta conserved; an impact where the "
     "ratio would add energy, as on an asymmetric body, takes the elastic ratio and is said as "
     "`impact_law_fallback`",
     ModesInImpact::kMomentaConserved, Rebound::kMeasuredRatio, OnEnergyGain::kElasticRatio},
};

/// The row of `law`.
constexpr const ImpactLawInfo& impact_law_info(ImpactLaw law) {
  for (const auto& i : kImpactLaws)
    if (i.law == law) return i;
  return kImpactLaws[0];
}

/// Whether `law` takes a measured rebound ratio (restitution_ratio) rather than its own map: the
/// readers, checks and outputs ask this, not the law's name.
constexpr bool takes_measured_ratio(ImpactLaw law) {
  return impact_law_info(law).rebound == Rebound::kMeasuredRatio;
}

inline const char* to_string(ImpactLaw law) {
  for (const auto& i : kImpactLaws)
    if (i.law == law) return i.name;
  return "?";
}

/// How a run resolves impacts: the law and its parameters.
struct ImpactRule {
  ImpactLaw law = ImpactLaw::kPaper;
  double restitution_factor = 1.0;  // paper and rigid_body: factor on theta_dot+
  // restitution: theta_dot+/theta_dot- when landing on edge 1 and on edge 2
  double ratio_edge1 = 1.0, ratio_edge2 = 1.0;
};

/// Which corner impact: the landing tipping point, and how the outcome may be chosen (the maps with
/// friction, friction_impact.hpp).
struct CornerImpactCase {
  int edge = 1;              // the tipping point that lands
  bool from_flight = false;  // a landing after a flight (at theta = 0 the other tipping point may
                             // take the floor); false: a rocking impact at theta = 0
  bool flat = false;         // both edges land whatever the single-point map gives (chatter)
  bool grazing = false;      // below the chatter interval: a sliding impulse that would pull is
                             // replaced by the sticking one (§16: Carnot's loss)
};

/// State just after an impact and what the impact did.
template <class Vec>
struct ImpactOutcome {
  double theta_dot = 0.0;    // post-impact angular velocity [rad/s]
  Vec q_dot;                 // post-impact modal velocities [1/s]
  Eigen::Vector2d impulse;   // impulse of the floor on the body, (I, J) components [N s]
  double energy_loss = 0.0;  // T_rel- - T_rel+ [J] (= work of the impulse on the base - dT)
  bool both_edges = false;   // true when rocking ended with both edges on the floor
  // the law would have added energy: rigid_body took the paper's law, restitution the elastic
  // ratio sqrt(S_pre/S_post)
  bool law_fallback = false;
};

/// The single-edge impact map. The body rocks on the other edge before; `landing_edge` hits the
/// floor and becomes the pivot. Conservation of the modal momenta p_i = int phi_i.Rdot dm (the
/// impulse acts where phi_i = 0, paper eq. 7) and of the moment of momentum about the landing
/// point (eq. 8) give, with Dalpha = alpha_pre - alpha_post:
///   A_post [theta_dot+; q_dot+] = A_post [theta_dot-; q_dot-] - Dalpha theta_dot- [w_x,post;
///   psi_y]
/// Rigid limit: theta_dot+/theta_dot- = (1 + zeta^2 - alpha1 alpha2)/(1 + zeta^2 + alpha_new^2).
template <class Dyn, class Vec>
void single_edge_impact(const Dyn& dyn, int landing_edge, const Vec& q, double theta_dot_minus,
                        const Vec& q_dot_minus, double& theta_dot_plus, Vec& q_dot_plus) {
  const double a_post = dyn.alpha(landing_edge);
  const double a_pre = dyn.alpha(landing_edge == 1 ? 2 : 1);
  const double d_alpha = a_pre - a_post;
  const double m = dyn.inertia(a_post, q);
  const Vec b = dyn.coupling(a_post, q);
  const double wx = -a_post + dyn.psi_x().dot(q);
  // solve A_post x = [w_x; psi_y] by block elimination with the constant mu^-1
  const Vec z = dyn.mu_inverse() * b;
  const Vec y = dyn.mu_inverse() * dyn.psi_y();
  const double x_theta = (wx - b.dot(y)) / (m - b.dot(z));
  theta_dot_plus = theta_dot_minus - d_alpha * theta_dot_minus * x_theta;
  q_dot_plus = q_dot_minus - d_alpha * theta_dot_minus * (y - z * x_theta);
}

/// The single-edge impact of a body that is rigid during the impact: q_dot+ = q_dot-, and the
/// first row of the map above alone, m_post theta_dot+ = (m_post - Dalpha w_x,post) theta_dot-
/// (the q_dot terms cancel). Rigid limit: Housner's ratio, as the paper's law.
template <class Dyn, class Vec>
void rigid_body_impact(const Dyn& dyn, int landing_edge, const Vec& q, double theta_dot_minus,
                       const Vec& q_dot_minus, double& theta_dot_plus, Vec& q_dot_plus) {
  const double a_post = dyn.alpha(landing_edge);
  const double d_alpha = dyn.alpha(landing_edge == 1 ? 2 : 1) - a_post;
  const double wx = -a_post + dyn.psi_x().dot(q);
  theta_dot_plus = theta_dot_minus * (1.0 - d_alpha * wx / dyn.inertia(a_post, q));
  q_dot_plus = q_dot_minus;
}

/// The plastic impact of tipping point `edge` (it sticks) under a law whose modes do `modes`:
/// with the modal momenta conserved, Dynamics::corner_impact (the paper's map, docs/theory.md
/// "Landing"); with the body rigid during the impact the modal velocities are continuous,
/// q_dot+ = q_dot-, and only the moment of momentum about the tipping point is conserved,
/// m theta_dot+ = r_theta - b.q_dot- (the first row of the landing system).
template <class Dyn, class Vec>
void law_corner_impact(const Dyn& dyn, ModesInImpact modes, int edge, const Vec& q,
                       double theta_dot_minus, const Vec& q_dot_minus,
                       const Eigen::Vector2d& v_corner_body, double& theta_dot_plus,
                       Vec& q_dot_plus) {
  if (modes == ModesInImpact::kMomentaConserved) {
    dyn.corner_impact(edge, q, theta_dot_minus, q_dot_minus, v_corner_body, theta_dot_plus,
                      q_dot_plus);
    return;
  }
  const double a = dyn.alpha(edge);
  const double wx = -a + dyn.psi_x().dot(q), wy = 1.0 + dyn.psi_y().dot(q);
  const double m = dyn.inertia(a, q);
  const Vec b = dyn.coupling(a, q);
  const double r_theta = m * theta_dot_minus + b.dot(q_dot_minus) +
                         (wx * v_corner_body(1) - wy * v_corner_body(0)) / dyn.height();
  q_dot_plus = q_dot_minus;
  theta_dot_plus = (r_theta - b.dot(q_dot_minus)) / m;
}

/// The impact under `rule`, with the both-edges rule. If the law's theta_dot+ would not turn the
/// body about the landing edge (or `force_both_edges`, the chatter cut-off), both edges stay on
/// the floor: theta_dot+ = 0, and the modal momenta are conserved (paper, restitution),
/// mu q_dot+ = mu q_dot- + b_pre theta_dot-, or the modal velocities (rigid_body). A restitution
/// factor scales theta_dot+; q_dot+ follows from the law's conservation. rigid_body can add
/// energy when the modes move fast against theta_dot (its rigidifying impulses work on them;
/// docs/theory.md, "Impact laws"): such an impact takes the paper's law and says so. A restitution
/// ratio that would add energy takes the elastic ratio sqrt(S_pre/S_post), and says so too.
template <class Dyn, class Vec>
ImpactOutcome<Vec> resolve_impact(const Dyn& dyn, int landing_edge, const Vec& q,
                                  double theta_dot_minus, const Vec& q_dot_minus,
                                  const ImpactRule& rule = {}, bool force_both_edges = false) {
  ImpactOutcome<Vec> out;
  const int pre_edge = landing_edge == 1 ? 2 : 1;
  const double a_pre = dyn.alpha(pre_edge), a_post = dyn.alpha(landing_edge);
  const ImpactLawInfo& law = impact_law_info(rule.law);
  const bool rigid = law.modes == ModesInImpact::kVelocitiesKept;
  const bool ratio = law.rebound == Rebound::kMeasuredRatio;
  double factor = rule.restitution_factor;
  if (ratio) {
    // the measured ratio replaces the law's theta_dot+; 0 ends rocking. Its loss is
    // 1/2 M h^2 (S_pre - r^2 S_post) theta_dot-^2 with the modal momenta conserved: above the
    // elastic ratio sqrt(S_pre/S_post) (an asymmetric or flexible body) it would add energy
    out.theta_dot = theta_dot_minus;
    if (rigid) out.q_dot = q_dot_minus;
    factor = landing_edge == 1 ? rule.ratio_edge1 : rule.ratio_edge2;
    if (law.on_gain == OnEnergyGain::kElasticRatio) {
      auto schur = [&](double a) {
        const Vec b = dyn.coupling(a, q);
        return dyn.inertia(a, q) - b.dot(dyn.mu_inverse() * b);  // S = m - b^T mu^-1 b
      };
      const double elastic = std::sqrt(schur(a_pre) / schur(a_post));
      if (factor > elastic) {
        factor = elastic;
        out.law_fallback = true;
      }
    }
  } else if (rigid) {
    rigid_body_impact(dyn, landing_edge, q, theta_dot_minus, q_dot_minus, out.theta_dot, out.q_dot);
  } else {
    single_edge_impact(dyn, landing_edge, q, theta_dot_minus, q_dot_minus, out.theta_dot,
                       out.q_dot);
  }
  // modal momenta, conserved by paper and restitution: p = mu q_dot- + b_pre theta_dot-
  const Vec p = dyn.mu() * q_dot_minus + dyn.coupling(a_pre, q) * theta_dot_minus;
  const bool ends = force_both_edges || edge_sign(landing_edge) * out.theta_dot * factor <= 0.0;
  if (ends) {
    out.both_edges = true;
    out.law_fallback = false;  // no ratio was applied
    out.theta_dot = 0.0;
    out.q_dot = rigid ? q_dot_minus : Vec(dyn.mu_inverse() * p);
  } else if (factor != 1.0 || ratio) {
    out.theta_dot *= factor;
    if (!rigid) out.q_dot = dyn.mu_inverse() * (p - dyn.coupling(a_post, q) * out.theta_dot);
  }
  const Eigen::Vector2d v_minus = dyn.cg_velocity(a_pre, q, theta_dot_minus, q_dot_minus);
  const Eigen::Vector2d v_plus = dyn.cg_velocity(a_post, q, out.theta_dot, out.q_dot);
  out.impulse = dyn.mass() * (v_plus - v_minus);
  if ((!rigid && out.both_edges) || (!rigid && !ratio && factor == 1.0)) {
    // a plastic impact loses the kinetic energy of the velocity jump (Carnot): >= 0 by
    // construction, where the difference of the energies can round below zero
    out.energy_loss = dyn.flight_kinetic_energy(q, out.theta_dot - theta_dot_minus,
                                                out.q_dot - q_dot_minus, v_plus - v_minus);
  } else {
    const double before = dyn.kinetic_energy(a_pre, q, theta_dot_minus, q_dot_minus);
    out.energy_loss = out.law_fallback  // the elastic ratio: no loss, by construction
                          ? 0.0
                          : before - dyn.kinetic_energy(a_post, q, out.theta_dot, out.q_dot);
    if (law.on_gain == OnEnergyGain::kPaperLaw &&
        out.energy_loss < -kImpactEnergyRounding * before) {
      ImpactRule paper = rule;
      paper.law = ImpactLaw::kPaper;
      out = resolve_impact(dyn, landing_edge, q, theta_dot_minus, q_dot_minus, paper,
                           force_both_edges);
      out.law_fallback = true;
    }
  }
  return out;
}

/// Which impulsive law a body's impacts are closest to, from the contact duration against its
/// pinned-base modal periods (docs/theory.md, "Impact laws"): modes much slower than the contact
/// cannot respond during it (the paper's law treats every mode so), modes much faster follow it
/// quasi-statically (the rigid_body law treats every mode so).
struct ImpactRegime {
  double duration_over_fastest = 0.0;  // tau / the shortest modal period (0: no modes)
  double duration_over_slowest = 0.0;  // tau / the longest modal period
  ImpactLaw closest = ImpactLaw::kPaper;
  bool between = false;  // some modes neither much slower nor much faster than the contact
};

/// `omega`: the pinned-base modal frequencies [rad/s], ascending; `duration` tau [s]. "Much" is
/// a factor of 10 on the period.
template <class Vec>
ImpactRegime impact_regime(const Vec& omega, double duration) {
  ImpactRegime r;
  if (omega.size() == 0) return r;  // a rigid body: every law is Housner's (or the ratio given)
  const double two_pi = 2.0 * std::numbers::pi;
  r.duration_over_fastest = duration * omega(omega.size() - 1) / two_pi;
  r.duration_over_slowest = duration * omega(0) / two_pi;
  if (r.duration_over_fastest < 0.1) {
    r.closest = ImpactLaw::kPaper;
  } else if (r.duration_over_slowest > 10.0) {
    r.closest = ImpactLaw::kRigidBody;
  } else {
    r.between = true;
    // the law of the slowest mode, which carries most of the body's momentum
    r.closest = r.duration_over_slowest > 1.0 ? ImpactLaw::kRigidBody : ImpactLaw::kPaper;
  }
  return r;
}

}  // namespace flexrock
