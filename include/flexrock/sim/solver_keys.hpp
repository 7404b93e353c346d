// SPDX-License-Identifier: BSD-3-Clause
// The [solver] keys, one row each: name, unit, default, meaning, the option it sets, the values it
// accepts and the floor or law it applies to. The case and study readers (io), Python's
// SimulationOptions, the engine's check of its options (simulate) and the generated reference of
// docs/case-file.md (`flexrock keys --markdown`) all read this table. Pure data and the rules
// that are stated nowhere else.
#pragma once

#include <cmath>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "flexrock/contact/compliant.hpp"
#include "flexrock/contact/impact.hpp"
#include "flexrock/sim/option_bounds.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {

// ---------------------------------------------------------------------------------------------
// the rules that concern more than one key, each stated once

/// A static Coulomb coefficient mu_s: > 0, or +inf (the floor holds whatever the demand). NaN,
/// zero and negative values are refused.
inline bool friction_coefficient_ok(double mu_s) { return mu_s > 0.0; }

/// A kinetic coefficient mu_k beside the static mu_s: > 0, and at most mu_s unless +inf (then
/// equal to mu_s).
inline bool kinetic_friction_coefficient_ok(double mu_k, double mu_s) {
  return mu_k > 0.0 && (std::isinf(mu_k) || mu_k <= mu_s);
}

/// The smallest relative tolerance double precision can deliver.
inline constexpr double kMinRelativeTolerance = 1e-14;

// ---------------------------------------------------------------------------------------------
// the table

/// What values a key accepts.
enum class SolverRule {
  kNonnegative,  // a finite number >= 0
  kPositive,     // a finite number > 0
  kBounded,      // a finite number in `bound`'s closed range (option_bounds.hpp)
  kFraction,     // a finite number in [0, 1]
  kCoefficient,  // a friction coefficient: friction_coefficient_ok (+inf admitted)
  kCount,        // an integer >= 1 (in `bound`'s range if it has one)
  kChoice,       // a name of the option's enum (solver_choices)
};

/// Which floor or law a key applies to; elsewhere the readers refuse the key and the engine a
/// value other than the default.
enum class SolverScope {
  kAlways,
  kImpulsive,       // contact_model = "impulsive": the impact law's keys
  kRestitutionLaw,  // impact_law = "restitution" (and so the impulsive floor)
  kCompliant,       // contact_model = "compliant": the springs' keys
  kCaseFile,        // case files only (a study sets the end of each run itself)
};

/// The option a key sets; monostate: a shorthand that sets others (restitution_ratio).
using SolverField =
    std::variant<std::monostate, double SimulationOptions::*, int SimulationOptions::*,
                 long SimulationOptions::*, OverturnCriterion SimulationOptions::*,
                 ImpactLaw SimulationOptions::*, ContactModel SimulationOptions::*,
                 ContactForceLaw SimulationOptions::*>;

struct SolverKey {
  const char* name;          // in [solver], and the attribute of Python's SimulationOptions
  const char* unit;          // of the value ("" for names)
  const char* default_text;  // as the reference shows it
  const char* doc;           // the reference's meaning (Markdown; also Python's docstring)
  SolverField field;         // the option it sets
  SolverRule rule;           // the values it accepts
  const char* what;          // the rule in words, for messages (nullptr: from `bound` or names)
  const OptionBound* bound = nullptr;        // kBounded: the range
  SolverScope scope = SolverScope::kAlways;  // where it applies
};

// clang-format off
inline constexpr SolverKey kSolverKeys[] = {
    {"t_end", "s", "end of the motion",
     "end time (may run past the motion: free vibration)",
     &SimulationOptions::t_end, SolverRule::kNonnegative, "a number >= 0 [s]", nullptr,
     SolverScope::kCaseFile},
    {"rtol", "-", "1e-9", "relative tolerance of the integrator (>= 1e-14)",
     &SimulationOptions::rtol, SolverRule::kPositive, "a number > 0 [-]"},
    {"atol", "-", "1e-11", "absolute tolerance (rad, -, rad/s, 1/s)",
     &SimulationOptions::atol, SolverRule::kPositive, "a number > 0 [-]"},
    {"max_step", "s", "0.01",
     "largest step of the steppers that sample their events within each step; a rigid body "
     "rocking on its Taylor series bounds its events over the whole step (docs/theory.md, "
     "\"Guards of the series step by bounds\") and is not capped by it, unless a friction limit "
     "is set",
     &SimulationOptions::max_step, SolverRule::kPositive, "a number > 0 [s]"},
    {"event_samples", "-", "4",
     "points a step where event functions are checked (an integer in [1, 32])",
     &SimulationOptions::event_samples, SolverRule::kCount, nullptr, &kEventSamplesBound},
    {"overturn", "", "`half_pi`",
     "overturning criterion, the same for `run`, studies and Python, rocking or in flight: "
     "`half_pi` (|theta| reaches pi/2; a body past its static overturning angle can still be "
     "brought back by a base motion that reverses) or `static_instability` (the tilt at which the "
     "deformed c.g. stands over the pivot, paper eq. 5)",
     &SimulationOptions::overturn, SolverRule::kChoice, nullptr},
    {"chatter_ratio", "-", "1e-4",
     "impacts closer in time than this times the shortest period end rocking (chatter criterion; "
     "the default changes no outcome when made 10 or 100 times finer: docs/validation.md)",
     &SimulationOptions::chatter_ratio, SolverRule::kNonnegative, "a number >= 0 [-]"},
    {"restitution_factor", "-", "1",
     "factor on theta_dot after an impact under the `paper` or `rigid_body` law (1: the law's "
     "own; with `rigid_body`, a factor on Housner's ratio for a stiff body, e.g. 0.95 on "
     "concrete); in [0, 2]: above 1 an impact adds energy (reported), 2 quadruples it at every "
     "impact",
     &SimulationOptions::restitution_factor, SolverRule::kBounded, nullptr,
     &kRestitutionFactorBound, SolverScope::kImpulsive},
    {"impact_law", "", "`paper`",
     "how impacts and landings are resolved (docs/theory.md §21)",  // + the laws' rows
     &SimulationOptions::impact_law, SolverRule::kChoice, nullptr, nullptr,
     SolverScope::kImpulsive},
    {"restitution_ratio", "-", "(required with `restitution`)",
     "`impact_law = \"restitution\"`: theta_dot+/theta_dot- at every impact, in [0, 1] (0 ends "
     "rocking); e.g. 0.95 x Housner's ratio on concrete, 0.67 x on rubber",
     std::monostate{}, SolverRule::kFraction,
     "a number in [0, 1] (theta_dot+/theta_dot- at an impact)", nullptr,
     SolverScope::kRestitutionLaw},
    {"restitution_ratio_edge1", "-", "`restitution_ratio`",
     "the same ratio for impacts landing on edge 1",
     &SimulationOptions::restitution_ratio_edge1, SolverRule::kFraction,
     "a number in [0, 1] (theta_dot+/theta_dot- at an impact)", nullptr,
     SolverScope::kRestitutionLaw},
    {"restitution_ratio_edge2", "-", "`restitution_ratio`",
     "the same ratio for impacts landing on edge 2",
     &SimulationOptions::restitution_ratio_edge2, SolverRule::kFraction,
     "a number in [0, 1] (theta_dot+/theta_dot- at an impact)", nullptr,
     SolverScope::kRestitutionLaw},
    {"impact_duration", "s", "0.002",
     "the contact duration assumed to turn an impact's impulse into a force estimate "
     "(`force_estimate_N` in the events, `max_impact_force_estimate_N` in the summary): the peak "
     "of a half-sine pulse, pi |I| / (2 impact_duration); in [1e-06, 1] s: contacts last from "
     "tens of microseconds (steel on steel) to tenths of a second (rubber)",
     &SimulationOptions::impact_duration, SolverRule::kBounded, nullptr, &kImpactDurationBound,
     SolverScope::kImpulsive},
    {"friction_coefficient", "-", "`inf` (no limit)",
     "static Coulomb coefficient mu_s of the base on the floor: where the demand reaches it the "
     "base slides (docs/theory.md §18-§20); `inf`: the floor holds whatever the demand (the "
     "paper's assumption), and the run is what it was before friction existed; it then reports, "
     "with their magnitudes, where a sticking contact cannot hold (the floor pulling on a held "
     "pivot, `pivot_tension`; a landing needing a pulling impulse, `tensile_landing`: summary "
     "`warnings`, console, events, sweep columns), which a finite coefficient removes",
     &SimulationOptions::friction_coefficient, SolverRule::kCoefficient,
     "a number > 0 [-] (or inf: no friction limit)"},
    {"kinetic_friction_coefficient", "-", "`inf` (= static)",
     "kinetic coefficient mu_k while sliding, at most `friction_coefficient`",
     &SimulationOptions::kinetic_friction_coefficient, SolverRule::kCoefficient,
     "a number > 0 [-], at most friction_coefficient (or inf: equal to it)"},
    {"max_steps", "-", "50000000", "steps before the run stops (status `stopped`, exit 1)",
     &SimulationOptions::max_steps, SolverRule::kCount, "an integer >= 1"},
    {"max_impacts", "-", "10000000",
     "impacts before the run stops (touches of the floor with the compliant contact)",
     &SimulationOptions::max_impacts, SolverRule::kCount, "an integer >= 1"},
    {"contact_model", "", "`impulsive`",
     "how the floor acts (docs/theory.md §22): `impulsive` (a rigid floor; impacts are impulses "
     "under `impact_law`) or `compliant` (a no-tension spring-dashpot at each tipping point: "
     "impact durations, the peak force of each touch and the force history are resolved; flight "
     "and sliding as usual)",
     &SimulationOptions::contact_model, SolverRule::kChoice, nullptr},
    {"contact_stiffness", "N/m (N/m^p)", "(required with `compliant`)",
     "the spring of each tipping point; the body bounces on both at omega_v = sqrt(2 k / M), and "
     "`flexrock params` says how long its half bounce lasts against the modal periods; k (1 mm)^p, "
     "the force of a tipping point pressed 1 mm into the floor, in [1, 1e12] N (a soft foam to far "
     "stiffer than steel on steel): k in [1000, 1e+15] N/m for the linear law, [31622.8, "
     "3.16228e+16] N/m^1.5 for Hertz",
     &SimulationOptions::contact_stiffness, SolverRule::kPositive, "a number > 0 [N/m^p]",
     nullptr, SolverScope::kCompliant},
    {"contact_force_law", "", "`linear`",
     "`compliant`: `linear` (k delta + c delta_dot, no pull) or `hunt_crossley` (k delta^p (1 + 3 "
     "(1 - e^2) delta_dot / (4 v_in)), no pull)",
     &SimulationOptions::contact_force_law, SolverRule::kChoice, nullptr, nullptr,
     SolverScope::kCompliant},
    {"contact_damping_ratio", "-", "1",
     "`linear`: the dashpot as the damping ratio of the body bouncing on both springs; about 4 "
     "makes a landing corner plastic (the limit of Housner's and the paper's laws); in [0, 100]; "
     "not with `contact_restitution`",
     &SimulationOptions::contact_damping_ratio, SolverRule::kBounded, nullptr,
     &kContactDampingRatioBound, SolverScope::kCompliant},
    {"contact_restitution", "-", "(from the damping ratio)",
     "`linear`: the restitution of a free bounce, which sets the damping ratio; `hunt_crossley` "
     "(required): e in (0, 1] of its damping",
     &SimulationOptions::contact_restitution, SolverRule::kFraction,
     "a number in [0, 1] (the restitution of a free bounce)", nullptr, SolverScope::kCompliant},
    {"contact_exponent", "-", "1.5", "`hunt_crossley`: p in k delta^p (1.5: Hertz)",
     &SimulationOptions::contact_exponent, SolverRule::kPositive, "a number > 0 [-]", nullptr,
     SolverScope::kCompliant},
    {"contact_tangential_stiffness", "N/m",
     "the normal spring's secant stiffness under half the weight",
     "the horizontal spring of a sticking tipping point at rest under half the weight, > 0; it "
     "scales with the normal spring's force, so that it lets go continuously as the corner leaves "
     "the floor (docs/theory.md §22); with a friction coefficient the corner slips at mu_s F_n. 0 "
     "is refused (omit the key for the default)",
     &SimulationOptions::contact_tangential_stiffness, SolverRule::kPositive,
     "a number > 0 [N/m] (omit it for the default, the normal spring's secant stiffness under "
     "half the weight)",
     nullptr, SolverScope::kCompliant},
};
// clang-format on

/// The row of `name`; nullptr if none.
inline const SolverKey* find_solver_key(std::string_view name) {
  for (const SolverKey& k : kSolverKeys)
    if (name == k.name) return &k;
  return nullptr;
}

/// The reference's meaning of `k` (the generated key reference, Python's docstrings): its doc, and
/// for impact_law the laws, each with its row's description (kImpactLaws), so that a new law is
/// written in its row only.
inline std::string solver_key_doc(const SolverKey& k) {
  std::string s = k.doc;
  if (std::holds_alternative<ImpactLaw SimulationOptions::*>(k.field)) {
    const char* sep = ": ";
    for (const ImpactLawInfo& l : kImpactLaws) {
      s.append(sep).append("`").append(l.name).append("` (").append(l.description).append(")");
      sep = ", ";
    }
  }
  return s;
}

/// The names an enum-valued option accepts, in the order messages list them.
template <class E>
std::vector<std::pair<const char*, E>> solver_choices() {
  std::vector<std::pair<const char*, E>> v;
  if constexpr (std::is_same_v<E, OverturnCriterion>) {
    v = {{"static_instability", OverturnCriterion::kStaticInstability},
         {"half_pi", OverturnCriterion::kHalfPi}};
  } else if constexpr (std::is_same_v<E, ImpactLaw>) {
    for (const ImpactLawInfo& l : kImpactLaws) v.emplace_back(l.name, l.law);
  } else if constexpr (std::is_same_v<E, ContactModel>) {
    for (const ContactModelInfo& m : kContactModels) v.emplace_back(m.name, m.model);
  } else {
    static_assert(std::is_same_v<E, ContactForceLaw>, "an enum without names");
    for (const ContactForceLawInfo& l : kContactForceLaws) v.emplace_back(l.name, l.law);
  }
  return v;
}

/// The name of an enum-valued option's value ("?" if none).
template <class E>
const char* solver_choice_name(E value) {
  for (const auto& [name, v] : solver_choices<E>())
    if (v == value) return name;
  return "?";
}

/// The rule of a key with a numeric value in words: "a number > 0 [s]", "a number in [0, 2] (...)".
inline std::string solver_rule_text(const SolverKey& k) {
  if (k.rule == SolverRule::kBounded)
    return "a number in " + range_text(*k.bound) + " (" + k.bound->why + ")";
  if (k.rule == SolverRule::kCount && k.bound)
    return "an integer in " + range_text(*k.bound) + " (" + k.bound->why + ")";
  return k.what ? k.what : "";
}

/// Whether `v` satisfies a numeric key's own rule (not the rules among keys).
inline bool solver_value_ok(const SolverKey& k, double v) {
  switch (k.rule) {
    case SolverRule::kNonnegative:
      return std::isfinite(v) && v >= 0.0;
    case SolverRule::kPositive:
      return std::isfinite(v) && v > 0.0;
    case SolverRule::kBounded:
      return in_range(*k.bound, v);
    case SolverRule::kFraction:
      return v >= 0.0 && v <= 1.0;
    case SolverRule::kCoefficient:
      return friction_coefficient_ok(v);
    case SolverRule::kCount:
      return v >= 1.0 && (!k.bound || in_range(*k.bound, v));
    case SolverRule::kChoice:
      return true;
  }
  return false;
}

/// Whether a key applies to options `o` (its floor and law); kCaseFile keys always apply.
inline bool solver_key_applies(const SolverKey& k, const SimulationOptions& o) {
  switch (k.scope) {
    case SolverScope::kAlways:
    case SolverScope::kCaseFile:
      return true;
    case SolverScope::kImpulsive:
      return o.contact_model == ContactModel::kImpulsive;
    case SolverScope::kRestitutionLaw:
      return o.contact_model == ContactModel::kImpulsive && takes_measured_ratio(o.impact_law);
    case SolverScope::kCompliant:
      return o.contact_model == ContactModel::kCompliant;
  }
  return true;
}

/// Why the impact law's keys are refused with contact_model = "compliant".
inline constexpr const char* kImpulsiveOnlyWhy =
    "it applies to contact_model = \"impulsive\": the compliant contact resolves each impact by "
    "its springs and dashpots (its losses from contact_damping_ratio or contact_restitution, its "
    "duration and peak force from contact_stiffness), so no impact law, restitution or assumed "
    "impact duration enters";

}  // namespace flexrock
