// SPDX-License-Identifier: BSD-3-Clause
// The solver keys that only one floor uses, stated once: the options check (simulate) refuses a
// value the chosen floor would ignore, and the case and study readers refuse the key itself,
// naming the file and line. Pure data.
#pragma once

#include "flexrock/sim/simulate.hpp"

namespace flexrock {

/// A key of the impulsive floor's impact law that the compliant contact has no use for, and
/// whether options leave it at its default.
struct ImpulsiveOnlyKey {
  const char* key;                                 // as in case files, studies and Python
  bool (*is_default)(const SimulationOptions& o);  // unset (then nothing is ignored)
};

inline constexpr ImpulsiveOnlyKey kImpulsiveOnlyKeys[] = {
    {"impact_law", [](const SimulationOptions& o) { return o.impact_law == ImpactLaw::kPaper; }},
    {"restitution_factor", [](const SimulationOptions& o) { return o.restitution_factor == 1.0; }},
    {"restitution_ratio_edge1",
     [](const SimulationOptions& o) { return o.restitution_ratio_edge1 == 1.0; }},
    {"restitution_ratio_edge2",
     [](const SimulationOptions& o) { return o.restitution_ratio_edge2 == 1.0; }},
    {"impact_duration", [](const SimulationOptions& o) { return o.impact_duration == 0.002; }},
};

/// Why they are refused with contact_model = "compliant".
inline constexpr const char* kImpulsiveOnlyWhy =
    "it applies to contact_model = \"impulsive\": the compliant contact resolves each impact by "
    "its springs and dashpots (its losses from contact_damping_ratio or contact_restitution, its "
    "duration and peak force from contact_stiffness), so no impact law, restitution or assumed "
    "impact duration enters";

/// contact_tangential_stiffness when not given: the normal spring's secant stiffness under half
/// the weight. Any other value must be > 0 (0 would be no tangential spring at all: a floor that
/// holds nothing sideways, which friction_coefficient already expresses).
inline constexpr double kTangentialStiffnessUnset = -1.0;

}  // namespace flexrock
