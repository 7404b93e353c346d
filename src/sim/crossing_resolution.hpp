// SPDX-License-Identifier: BSD-3-Clause
// The time resolution of a located guard crossing. Internal header.
#pragma once

#include <algorithm>
#include <cmath>

namespace flexrock::detail {

/// The width [s] of the bracket to which locate_crossing closes a crossing near time t: two
/// crossings whose brackets overlap at this resolution cannot be ordered, and the compliant
/// contact takes them as one instant.
inline double crossing_resolution(double t) { return 2e-15 * std::max(1.0, std::abs(t)); }

}  // namespace flexrock::detail
