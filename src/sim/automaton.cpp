// SPDX-License-Identifier: BSD-3-Clause
#include "automaton.hpp"

namespace flexrock::detail {

namespace {

constexpr std::array<GuardSpec, 9> kGuards = {{
    {Guard::kUpliftEdge1, "uplift_edge1", Reset::kUplift, 1, false},
    {Guard::kUpliftEdge2, "uplift_edge2", Reset::kUplift, 2, false},
    {Guard::kLiftOff, "lift_off", Reset::kLiftOff, 0, false},
    {Guard::kFrictionLimit, "friction_limit", Reset::kRecord, 0, false},
    {Guard::kImpact, "impact", Reset::kImpact, 0, true},
    {Guard::kOverturn, "overturn", Reset::kOverturn, 0, false},
    {Guard::kPeak, "peak", Reset::kRecord, 0, false},
    {Guard::kLandingEdge1, "landing_edge1", Reset::kLanding, 1, true},
    {Guard::kLandingEdge2, "landing_edge2", Reset::kLanding, 2, true},
}};

constexpr std::array<ModeSpec, 4> kModes = {{
    {ContactMode::kFullContact,
     "full_contact",
     4,
     {Guard::kUpliftEdge1, Guard::kUpliftEdge2, Guard::kLiftOff, Guard::kFrictionLimit,
      Guard::kPeak}},
    {ContactMode::kRockingEdge1,
     "rocking_edge1",
     5,
     {Guard::kImpact, Guard::kOverturn, Guard::kLiftOff, Guard::kFrictionLimit, Guard::kPeak}},
    {ContactMode::kRockingEdge2,
     "rocking_edge2",
     5,
     {Guard::kImpact, Guard::kOverturn, Guard::kLiftOff, Guard::kFrictionLimit, Guard::kPeak}},
    {ContactMode::kFlight,
     "flight",
     3,
     {Guard::kLandingEdge1, Guard::kLandingEdge2, Guard::kOverturn, Guard::kPeak, Guard::kPeak}},
}};

// the tables are indexed by their enums
constexpr bool tables_in_order() {
  for (std::size_t i = 0; i < kGuards.size(); ++i)
    if (static_cast<std::size_t>(kGuards[i].guard) != i) return false;
  for (std::size_t i = 0; i < kModes.size(); ++i)
    if (static_cast<std::size_t>(kModes[i].mode) != i) return false;
  return true;
}
static_assert(tables_in_order());

}  // namespace

const GuardSpec& guard_spec(Guard g) { return kGuards[static_cast<std::size_t>(g)]; }

const ModeSpec& mode_spec(ContactMode m) { return kModes[static_cast<std::size_t>(m)]; }

int guard_slot(ContactMode m, Guard g) {
  const ModeSpec& s = mode_spec(m);
  for (int j = 0; j < s.count; ++j)
    if (s.guards[static_cast<std::size_t>(j)] == g) return j;
  return -1;
}

}  // namespace flexrock::detail
