// SPDX-License-Identifier: BSD-3-Clause
// Impact laws at theta = 0 (paper eqs. 6-10, derived in docs/theory.md): pure functions.
#pragma once

#include <Eigen/Core>

#include "flexrock/model/dynamics.hpp"

namespace flexrock {

/// State just after an impact and what the impact did.
template <class Vec>
struct ImpactOutcome {
  double theta_dot = 0.0;    // post-impact angular velocity [rad/s]
  Vec q_dot;                 // post-impact modal velocities [1/s]
  Eigen::Vector2d impulse;   // impulse of the floor on the body, (I, J) components [N s]
  double energy_loss = 0.0;  // T_rel- - T_rel+ [J] (= work of the impulse on the base - dT)
  bool both_edges = false;   // true when rocking ended with both edges on the floor
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

/// The impact with the both-edges rule and an optional restitution factor on theta_dot+.
/// If the single-edge map gives a theta_dot+ that would not turn the body about the landing edge,
/// both edges stay on the floor: theta_dot+ = 0 and the modal momenta are conserved,
/// mu q_dot+ = mu q_dot- + b_pre theta_dot- (docs/theory.md, "Impacts that end rocking").
/// With a restitution factor e != 1, theta_dot+ is scaled by e and q_dot+ follows from the same
/// conservation: mu q_dot+ = mu q_dot- + b_pre theta_dot- - b_post theta_dot+.
template <class Dyn, class Vec>
ImpactOutcome<Vec> resolve_impact(const Dyn& dyn, int landing_edge, const Vec& q,
                                  double theta_dot_minus, const Vec& q_dot_minus,
                                  double restitution_factor = 1.0, bool force_both_edges = false) {
  ImpactOutcome<Vec> out;
  const int pre_edge = landing_edge == 1 ? 2 : 1;
  const double a_pre = dyn.alpha(pre_edge), a_post = dyn.alpha(landing_edge);
  single_edge_impact(dyn, landing_edge, q, theta_dot_minus, q_dot_minus, out.theta_dot, out.q_dot);
  // modal momenta, conserved in every case: p = mu q_dot- + b_pre theta_dot-
  const Vec p = dyn.mu() * q_dot_minus + dyn.coupling(a_pre, q) * theta_dot_minus;
  if (force_both_edges || edge_sign(landing_edge) * out.theta_dot <= 0.0) {
    out.both_edges = true;
    out.theta_dot = 0.0;
    out.q_dot = dyn.mu_inverse() * p;
  } else if (restitution_factor != 1.0) {
    out.theta_dot *= restitution_factor;
    out.q_dot = dyn.mu_inverse() * (p - dyn.coupling(a_post, q) * out.theta_dot);
  }
  const Eigen::Vector2d v_minus = dyn.cg_velocity(a_pre, q, theta_dot_minus, q_dot_minus);
  const Eigen::Vector2d v_plus = dyn.cg_velocity(a_post, q, out.theta_dot, out.q_dot);
  out.impulse = dyn.mass() * (v_plus - v_minus);
  if (out.both_edges || restitution_factor == 1.0) {
    // a plastic impact loses the kinetic energy of the velocity jump (Carnot): >= 0 by
    // construction, where the difference of the energies can round below zero
    out.energy_loss = dyn.flight_kinetic_energy(q, out.theta_dot - theta_dot_minus,
                                                out.q_dot - q_dot_minus, v_plus - v_minus);
  } else {
    out.energy_loss = dyn.kinetic_energy(a_pre, q, theta_dot_minus, q_dot_minus) -
                      dyn.kinetic_energy(a_post, q, out.theta_dot, out.q_dot);
  }
  return out;
}

}  // namespace flexrock
