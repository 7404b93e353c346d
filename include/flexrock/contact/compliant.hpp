// SPDX-License-Identifier: BSD-3-Clause
// The compliant contact (docs/theory.md, "Compliant contact"): no-tension spring-dashpots at the
// two tipping points instead of impulses. Tables of the models and force laws, and the laws
// themselves as pure functions.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

namespace flexrock {

/// How the floor acts on the body: by impulses at instants (the impact laws) or by forces that
/// last (springs and dashpots at the tipping points).
enum class ContactModel {
  kImpulsive,  // rigid floor: contact modes, impacts and landings as impulses (the impact law)
  kCompliant,  // a spring-dashpot at each tipping point, no tension; the body moves freely in the
               // plane otherwise (flight's equations plus the corner forces)
};

struct ContactModelInfo {
  ContactModel model;
  const char* name;         // as written in case files, studies and Python
  const char* description;  // one line, for `--help` and the docs
};

inline constexpr ContactModelInfo kContactModels[] = {
    {ContactModel::kImpulsive, "impulsive",
     "a rigid floor: impacts are instantaneous impulses under the chosen impact_law"},
    {ContactModel::kCompliant, "compliant",
     "a no-tension spring-dashpot at each tipping point (contact_stiffness): impact durations "
     "and forces are resolved"},
};

inline const char* to_string(ContactModel m) {
  for (const auto& i : kContactModels)
    if (i.model == m) return i.name;
  return "?";
}

/// How the compliant contact is integrated (the event loop's choice; tests force one).
enum class ContactIntegrator {
  kAuto = 0,      // DOPRI5 while accuracy sets the step, Rosenbrock while stability would
  kExplicit = 1,  // DOPRI5 only
  kImplicit = 2,  // the Rosenbrock method only
};

/// The normal force of a compliant corner as a function of its penetration delta >= 0 and rate.
enum class ContactForceLaw {
  kLinear,        // Kelvin-Voigt: F = k delta + c delta_dot (>= 0)
  kHuntCrossley,  // F = k delta^p (1 + 3 (1 - e^2) delta_dot / (4 v_in)) (>= 0), Lankarani and
                  // Nikravesh's damping from the restitution e and the approach speed v_in
};

struct ContactForceLawInfo {
  ContactForceLaw law;
  const char* name;
  const char* description;
};

inline constexpr ContactForceLawInfo kContactForceLaws[] = {
    {ContactForceLaw::kLinear, "linear",
     "Kelvin-Voigt: k delta + c delta_dot, c from contact_damping_ratio or contact_restitution"},
    {ContactForceLaw::kHuntCrossley, "hunt_crossley",
     "k delta^p (1 + 3 (1 - e^2) delta_dot / (4 v_in)), e = contact_restitution, p = "
     "contact_exponent"},
};

inline const char* to_string(ContactForceLaw l) {
  for (const auto& i : kContactForceLaws)
    if (i.law == l) return i.name;
  return "?";
}

/// The constants of one corner's spring-dashpot, derived once per run from the options and the
/// body's mass (docs/theory.md, "Compliant contact").
struct CornerContact {
  ContactForceLaw law = ContactForceLaw::kLinear;
  double k = 0.0;         // [N/m^p] normal stiffness
  double p = 1.0;         // exponent of the penetration
  double c = 0.0;         // [N s/m] linear: normal dashpot
  double hc = 0.0;        // [-] Hunt-Crossley: 3 (1 - e^2) / 4 (times delta_dot / v_in)
  double v_floor = 0.0;   // [m/s] Hunt-Crossley: the approach speed below which a contact is
                          // quasi-static: sqrt(g delta_static)
  double k_secant = 0.0;  // [N/m] the normal spring's secant stiffness under half the weight
  double k_t = 0.0;       // [N/m] tangential spring of a sticking corner
  double c_t = 0.0;       // [N s/m] tangential dashpot
};

/// The penetration [m] at which a spring k delta^p [N/m^p] carries `load` [N].
inline double static_penetration(double k, double p, double load) {
  return std::pow(load / k, 1.0 / p);
}

/// The damping ratio of a linear spring-dashpot whose free rebound has restitution e:
/// e = exp(-zeta pi / sqrt(1 - zeta^2)); e = 0 gives critical damping.
inline double damping_ratio_for_restitution(double e) {
  if (e <= 0.0) return 1.0;
  const double l = std::log(e);
  return -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
}

/// Normal force [N] of a corner in contact at penetration delta [m], rate delta_dot [m/s]
/// (positive into the floor), approach speed v_in [m/s] (Hunt-Crossley); never a pull. A corner
/// is in contact from its touch to its release (both events), so the force is continuous in the
/// state while it lasts: a penetration that rounding leaves a hair below zero counts as zero
/// (the dashpot of the linear law acts from the touch on).
inline double normal_force(const CornerContact& cc, double delta, double delta_dot, double v_in) {
  const double d = std::max(delta, 0.0);
  double f = 0.0;
  if (cc.law == ContactForceLaw::kLinear) {
    f = cc.k * d + cc.c * delta_dot;
  } else {
    const double dp = cc.p == 1.0 ? d : std::pow(d, cc.p);
    f = cc.k * dp * (1.0 + cc.hc * delta_dot / std::max(v_in, cc.v_floor));
  }
  return std::max(f, 0.0);
}

/// Elastic energy [J] stored in a corner's normal spring at penetration delta: k delta^(p+1) /
/// (p + 1).
inline double normal_spring_energy(const CornerContact& cc, double delta) {
  if (!(delta > 0.0)) return 0.0;
  return cc.k * std::pow(delta, cc.p + 1.0) / (cc.p + 1.0);
}

}  // namespace flexrock
