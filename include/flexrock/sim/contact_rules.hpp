// SPDX-License-Identifier: BSD-3-Clause
// The compliant contact's rules beside the table of solver keys (solver_keys.hpp). Pure data.
#pragma once

#include "flexrock/sim/simulate.hpp"

namespace flexrock {

/// contact_tangential_stiffness when not given: the normal spring's secant stiffness under half
/// the weight. Any other value must be > 0 (0 would be no tangential spring at all: a floor that
/// holds nothing sideways, which friction_coefficient already expresses).
inline constexpr double kTangentialStiffnessUnset = -1.0;

}  // namespace flexrock
