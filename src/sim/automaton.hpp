// SPDX-License-Identifier: BSD-3-Clause
// The hybrid automaton of contact as data (inline: the loop consults it after every step): which
// contact modes exist, which guard functions each mode watches and which reset each guard triggers.
// docs/theory.md, "Contact modes and transitions", is this table in words. Internal header.
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
  kFrictionLimit,  // (mu_s F_J - |F_I|) / M g while sticking; 1 when no coefficient is given
  kImpact,         // s theta, s = +1 on edge 1, -1 on edge 2
  kOverturn,       // theta_c - s theta (rocking); min(theta_c1 - theta, theta_c2 + theta) (flight)
  kPeak,           // s theta_dot: a rocking amplitude
  kLandingEdge1,   // y_1 / h: height of tipping point 1 over h (flight)
  kLandingEdge2,   // y_2 / h
  kSlipStop,       // s d_dot: the slip velocity in the mode's direction s (sliding, theory §18)
};

/// What happens when a guard fires.
enum class Reset : int {
  kRecord,    // nothing changes; an event is recorded (friction exceeded, peak)
  kUplift,    // full contact -> rocking on the guard's edge, no impulse
  kLiftOff,   // full contact or rocking -> flight, no impulse
  kImpact,    // the impact law at theta = 0 -> rocking on the other edge, or full contact
  kOverturn,  // the run ends overturned
  kLanding,   // the landing map -> rocking on the guard's edge, or full contact when flat
  kSlip,      // sticking -> sliding the way the floor cannot hold, no impulse
  kStick,     // sliding -> sticking when friction holds, else sliding the other way
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
  int pivot;  // 0: full contact (both edges down), 1 or 2: rocking on that edge, -1: flight
  int slip;   // 0: the base sticks (or flies), +1 / -1: it slides along +I / -I
  int count;  // guards watched in this mode
  std::array<Guard, kMaxGuards> guards;  // in slot order
};

inline constexpr std::array<GuardSpec, 10> kGuards = {{
    {Guard::kUpliftEdge1, "uplift_edge1", Reset::kUplift, 1, false},
    {Guard::kUpliftEdge2, "uplift_edge2", Reset::kUplift, 2, false},
    {Guard::kLiftOff, "lift_off", Reset::kLiftOff, 0, false},
    {Guard::kFrictionLimit, "friction_limit", Reset::kSlip, 0, false},
    {Guard::kImpact, "impact", Reset::kImpact, 0, true},
    {Guard::kOverturn, "overturn", Reset::kOverturn, 0, false},
    {Guard::kPeak, "peak", Reset::kRecord, 0, false},
    {Guard::kLandingEdge1, "landing_edge1", Reset::kLanding, 1, true},
    {Guard::kLandingEdge2, "landing_edge2", Reset::kLanding, 2, true},
    // a slide that starts and cannot be resolved as growing ends at once (friction holds)
    {Guard::kSlipStop, "slip_stop", Reset::kStick, 0, true},
}};

inline constexpr std::array<ModeSpec, 10> kModes = {{
    {ContactMode::kFullContact,
     "full_contact",
     0,
     0,
     4,
     {Guard::kUpliftEdge1, Guard::kUpliftEdge2, Guard::kLiftOff, Guard::kFrictionLimit,
      Guard::kPeak}},
    {ContactMode::kRockingEdge1,
     "rocking_edge1",
     1,
     0,
     5,
     {Guard::kImpact, Guard::kOverturn, Guard::kLiftOff, Guard::kFrictionLimit, Guard::kPeak}},
    {ContactMode::kRockingEdge2,
     "rocking_edge2",
     2,
     0,
     5,
     {Guard::kImpact, Guard::kOverturn, Guard::kLiftOff, Guard::kFrictionLimit, Guard::kPeak}},
    {ContactMode::kFlight,
     "flight",
     -1,
     0,
     3,
     {Guard::kLandingEdge1, Guard::kLandingEdge2, Guard::kOverturn, Guard::kPeak, Guard::kPeak}},
    {ContactMode::kSlidingPlus,
     "sliding_plus",
     0,
     1,
     4,
     {Guard::kUpliftEdge1, Guard::kUpliftEdge2, Guard::kLiftOff, Guard::kSlipStop, Guard::kPeak}},
    {ContactMode::kSlidingMinus,
     "sliding_minus",
     0,
     -1,
     4,
     {Guard::kUpliftEdge1, Guard::kUpliftEdge2, Guard::kLiftOff, Guard::kSlipStop, Guard::kPeak}},
    {ContactMode::kRockingEdge1SlidingPlus,
     "rocking_edge1_sliding_plus",
     1,
     1,
     5,
     {Guard::kImpact, Guard::kOverturn, Guard::kLiftOff, Guard::kSlipStop, Guard::kPeak}},
    {ContactMode::kRockingEdge1SlidingMinus,
     "rocking_edge1_sliding_minus",
     1,
     -1,
     5,
     {Guard::kImpact, Guard::kOverturn, Guard::kLiftOff, Guard::kSlipStop, Guard::kPeak}},
    {ContactMode::kRockingEdge2SlidingPlus,
     "rocking_edge2_sliding_plus",
     2,
     1,
     5,
     {Guard::kImpact, Guard::kOverturn, Guard::kLiftOff, Guard::kSlipStop, Guard::kPeak}},
    {ContactMode::kRockingEdge2SlidingMinus,
     "rocking_edge2_sliding_minus",
     2,
     -1,
     5,
     {Guard::kImpact, Guard::kOverturn, Guard::kLiftOff, Guard::kSlipStop, Guard::kPeak}},
}};

// the tables are indexed by their enums
inline constexpr bool tables_in_order() {
  for (std::size_t i = 0; i < kGuards.size(); ++i)
    if (static_cast<std::size_t>(kGuards[i].guard) != i) return false;
  for (std::size_t i = 0; i < kModes.size(); ++i)
    if (static_cast<std::size_t>(kModes[i].mode) != i) return false;
  return true;
}
static_assert(tables_in_order());

/// The guard table, indexed by Guard.
constexpr const GuardSpec& guard_spec(Guard g) { return kGuards[static_cast<std::size_t>(g)]; }
/// The mode table, indexed by ContactMode.
constexpr const ModeSpec& mode_spec(ContactMode m) { return kModes[static_cast<std::size_t>(m)]; }
/// The mode with this pivot (0: full contact, 1, 2: rocking on that edge) and slip sign (0, +1,
/// -1).
constexpr ContactMode contact_mode(int pivot, int slip) {
  for (const ModeSpec& m : kModes)
    if (m.pivot == pivot && m.slip == slip) return m.mode;
  return ContactMode::kFlight;
}
// every contact mode's sliding and sticking variants exist
static_assert(contact_mode(0, 1) == ContactMode::kSlidingPlus &&
              contact_mode(2, -1) == ContactMode::kRockingEdge2SlidingMinus &&
              contact_mode(1, 0) == ContactMode::kRockingEdge1);
/// Slot of `g` in mode `m`'s list, or -1.
constexpr int guard_slot(ContactMode m, Guard g) {
  const ModeSpec& s = mode_spec(m);
  for (int j = 0; j < s.count; ++j)
    if (s.guards[static_cast<std::size_t>(j)] == g) return j;
  return -1;
}

}  // namespace flexrock::detail
