// SPDX-License-Identifier: BSD-3-Clause
// The hybrid automaton of contact as data: which contact modes exist, which guard functions each
// mode watches and which reset each guard triggers. docs/theory.md, "Contact modes and
// transitions", is this table in words. Internal header.
#pragma once

#include <array>

#include "flexrock/sim/simulate.hpp"

namespace flexrock::detail {

/// Guard functions: each is positive while nothing happens and fires when it reaches zero from
/// above (the only crossing direction any guard has).
enum class Guard : int {
  kUpliftEdge1,    // U1 = moment the contact must supply about edge 1, over M g h (theory §6)
  kUpliftEdge2,    // U2, the same about edge 2
  kLiftOff,        // F_J / M g: the vertical floor reaction (theory §5, §6)
  kFrictionLimit,  // (mu F_J - |F_I|) / M g; 1 when no friction coefficient is given
  kImpact,         // s theta, s = +1 on edge 1, -1 on edge 2
  kOverturn,       // theta_c - s theta (rocking); min(theta_c1 - theta, theta_c2 + theta) (flight)
  kPeak,           // s theta_dot: a rocking amplitude
  kLandingEdge1,   // y_1 / h: height of tipping point 1 over h (flight)
  kLandingEdge2,   // y_2 / h
};

/// What happens when a guard fires.
enum class Reset : int {
  kRecord,    // nothing changes; an event is recorded (friction exceeded, peak)
  kUplift,    // full contact -> rocking on the guard's edge, no impulse
  kLiftOff,   // full contact or rocking -> flight, no impulse
  kImpact,    // the impact law at theta = 0 -> rocking on the other edge, or full contact
  kOverturn,  // the run ends overturned
  kLanding,   // the landing map -> rocking on the guard's edge, or full contact when flat
};

struct GuardSpec {
  Guard guard;
  const char* name;  // as in docs/theory.md
  Reset reset;
  int edge;                  // the edge the reset acts on (uplift, landing); 0 otherwise
  bool fires_if_unresolved;  // when it starts at zero and its positive excursion is below
                             // resolution, it fires at once (an impact or landing at the start)
};

inline constexpr int kMaxGuards = 5;

struct ModeSpec {
  ContactMode mode;
  const char* name;
  int count;                             // guards watched in this mode
  std::array<Guard, kMaxGuards> guards;  // in slot order
};

/// The guard table, indexed by Guard.
const GuardSpec& guard_spec(Guard g);
/// The mode table, indexed by ContactMode.
const ModeSpec& mode_spec(ContactMode m);
/// Slot of `g` in mode `m`'s list, or -1.
int guard_slot(ContactMode m, Guard g);

}  // namespace flexrock::detail
