// SPDX-License-Identifier: BSD-3-Clause
// Event location on a step: the guard functions sampled across it, brackets of their first
// crossing, and the crossing time refined by TOMS 748 on the stepper's dense output. Ordinary
// code, the same for every body size: the stepper is reached through GuardProbe. Internal header.
#pragma once

#include <array>

#include "automaton.hpp"

namespace flexrock::detail {

inline constexpr int kMaxSamples = 32;

/// The guard functions of the current mode at one time, in the mode's slot order, with the floor
/// reaction that the extremes need.
struct GuardSample {
  double t = 0.0;                      // [s]
  std::array<double, kMaxGuards> v{};  // guard values, slot order
  double fi = 0.0, fj = 0.0;           // floor reaction over M g, inertial I and J
  double moment = 0.0;                 // overturning moment about the c.g. projection, over M g h
};

/// The guard values at any time within the last step (from its dense output).
class GuardProbe {
 public:
  virtual double guard_value(int slot, double t) = 0;

 protected:
  ~GuardProbe() = default;
};

/// Time of the first crossing of `slot` from positive to non-positive among smp[0..count]
/// (+infinity if none). A guard that starts at exactly zero (`zero_start`: it is known to turn
/// positive, e.g. the impact function right after an uplift) is treated as positive at the start;
/// if no positive point is found by halving toward the start, it fires at the start when
/// `fires_if_unresolved`, else never in this step. Between three positive samples whose parabola
/// dips below a quarter of the smaller end value, the vertex is probed too.
double first_crossing(int slot, const GuardSample* smp, int count, bool zero_start,
                      bool fires_if_unresolved, GuardProbe& probe);

/// The crossing in [tl, tr] (gl > 0 >= gr) to 2e-15 relative in time: the side where g <= 0.
double locate_crossing(int slot, double tl, double tr, double gl, double gr, GuardProbe& probe);

}  // namespace flexrock::detail
