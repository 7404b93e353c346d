// SPDX-License-Identifier: BSD-3-Clause
// The compliant contact's constants and entry points, and its loop for bodies of up to 16 modes
// (compliant_dynamic.cpp: more).
#include "compliant.hpp"

#include <Eigen/Core>
#include <cmath>

#include "compliant_loop.hpp"
#include "flexrock/contact/corner_potential.hpp"

namespace flexrock::detail {

CornerContact corner_contact(const Body& body, const SimulationOptions& opt) {
  CornerContact cc;
  const double m = body.params().mass, g = body.g();
  cc.law = opt.contact_force_law;
  cc.k = opt.contact_stiffness;
  cc.p = cc.law == ContactForceLaw::kLinear ? 1.0 : opt.contact_exponent;
  // the static penetration with the weight shared by both tipping points, and the secant
  // stiffness there: the tangential spring's default, and the Hunt-Crossley law's slowest
  // meaningful approach speed (a contact that begins slower than sqrt(g delta_static) is
  // quasi-static: its damping is that of one beginning at that speed)
  const double delta_static = static_penetration(cc.k, cc.p, 0.5 * m * g);
  cc.k_secant = 0.5 * m * g / delta_static;
  const double zeta = opt.contact_restitution >= 0.0
                          ? damping_ratio_for_restitution(opt.contact_restitution)
                          : opt.contact_damping_ratio;
  if (cc.law == ContactForceLaw::kLinear) {
    // the body bouncing on both springs: omega_v = sqrt(2 k / M), each dashpot 2 zeta sqrt(k M/2)
    cc.c = 2.0 * zeta * std::sqrt(0.5 * cc.k * m);
  } else {
    const double e = opt.contact_restitution;
    cc.hc = 0.75 * (1.0 - e * e);
    cc.v_floor = std::sqrt(g * delta_static);
  }
  cc.k_t = opt.contact_tangential_stiffness == kTangentialStiffnessUnset
               ? cc.k_secant
               : opt.contact_tangential_stiffness;
  cc.c_t = 2.0 * (cc.law == ContactForceLaw::kLinear ? zeta : 1.0) * std::sqrt(0.5 * cc.k_t * m);
  return cc;
}

// the loop for bodies of up to 16 modes (compliant_loop.hpp)
template SimulationResult run_compliant<16>(const Body&, const GroundMotion&, const InitialState&,
                                            const SimulationOptions&, CompliantAudit*);
template Eigen::VectorXcd run_compliant_rest_eigenvalues<16>(const Body&, const GroundMotion&,
                                                             const SimulationOptions&, int,
                                                             const InitialState&);

SimulationResult simulate_compliant(const Body& body, const GroundMotion& motion,
                                    const InitialState& init, const SimulationOptions& opt,
                                    CompliantAudit* audit) {
  // a stack-bounded state up to 16 modes, heap beyond
  if (body.modes() <= 16) return run_compliant<16>(body, motion, init, opt, audit);
  return run_compliant<Eigen::Dynamic>(body, motion, init, opt, audit);
}

Eigen::VectorXcd compliant_rest_eigenvalues(const Body& body, const SimulationOptions& opt,
                                            int pivot, const InitialState& at) {
  const GroundMotion still = GroundMotion::none(1.0);
  if (body.modes() <= 16) return run_compliant_rest_eigenvalues<16>(body, still, opt, pivot, at);
  return run_compliant_rest_eigenvalues<Eigen::Dynamic>(body, still, opt, pivot, at);
}

}  // namespace flexrock::detail
