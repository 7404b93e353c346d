// SPDX-License-Identifier: BSD-3-Clause
// Every transition of the contact automaton fires: for each mode of kModes, each guard it watches
// and each body kind (rigid, N = 0, whose full contact and rocking have steppers of their own, and
// flexible, N = 1), a run built through simulate() whose result shows that guard ending that mode
// (the event its reset records, after a history row in that mode), and every transition seen leads
// to a mode the table's "next mode" allows. The pairs that cannot fire are a named list with the
// reason, and the table check requires the cases and that list to cover kModes x guards x body
// kinds exactly, so a new mode or guard without a case fails here.
#include "unit/automaton_transitions.hpp"

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace flexrock::test {
namespace {

using detail::Guard;
using G = detail::Guard;
using M = ContactMode;

enum BodyClass : int { kRigid = 0, kFlexible = 1 };
const char* name_of(BodyClass k) { return k == kRigid ? "rigid" : "flexible"; }

struct NamedScenario {
  const char* name;
  Scenario scenario;
};

/// A transition and the scenario whose run shows it.
struct Firing {
  ContactMode mode;
  Guard guard;
  BodyClass body;
  const char* scenario;
};

/// A transition that no run of that body kind can show by a guard crossing, and why.
struct CannotFire {
  ContactMode mode;
  Guard guard;
  BodyClass body;
  const char* reason;
};

// the scenarios: all but the first found by a random search over the parameters (bodies, records,
// vertical drops, friction, initial states), each kept for transitions that also fire with rtol
// and atol ten times finer
const std::vector<NamedScenario>& scenarios() {
  static const std::vector<NamedScenario> s = {
      // released at a tilt on a floor at rest: the closed-form arcs of a rigid block
      {"rigid_released", {.modes = 0, .alpha = 0.25, .theta0 = 0.1}},
      {"flexible_friction_1",
       {.modes = 1,
        .alpha = 0.47,
        .freq_hz = 4.6,
        .ax_g = 1.25,
        .fx_hz = 2.2,
        .cycles = 2,
        .mu_s = 0.76,
        .mu_k = 0.6,
        .static_overturn = true}},
      {"rigid_friction_drop_1",
       {.modes = 0,
        .alpha = 0.34,
        .ax_g = -1.17,
        .fx_hz = 3.3,
        .cycles = 1.5,
        .ay_g = -2.1,
        .ty0 = 1.25,
        .ty1 = 1.34,
        .mu_s = 0.46,
        .mu_k = 0.31,
        .static_overturn = true}},
      {"rigid_friction_drop_2",
       {.modes = 0,
        .alpha = 0.15,
        .ax_g = 0.65,
        .fx_hz = 1.7,
        .cycles = 1.5,
        .ay_g = -1.6,
        .ty0 = 0.85,
        .ty1 = 1.02,
        .mu_s = 0.15,
        .mu_k = 0.11,
        .theta0 = -0.004,
        .theta_dot0 = -0.24}},
      {"flexible_friction_drop_1",
       {.modes = 1,
        .alpha = 0.31,
        .freq_hz = 4,
        .ax_g = 1.49,
        .fx_hz = 3,
        .cycles = 1,
        .ay_g = -1.5,
        .ty0 = 0.91,
        .ty1 = 0.94,
        .mu_s = 0.3,
        .mu_k = 0.2,
        .theta0 = 0.062,
        .theta_dot0 = -0.58}},
      {"rigid_friction_drop_3",
       {.modes = 0,
        .alpha = 0.55,
        .ax_g = 1.44,
        .fx_hz = 1.7,
        .cycles = 2,
        .ay_g = -1.2,
        .ty0 = 0.15,
        .ty1 = 0.45,
        .mu_s = 0.68,
        .mu_k = 0.61,
        .static_overturn = true}},
      {"rigid_friction_drop_4",
       {.modes = 0,
        .alpha = 0.33,
        .ax_g = -0.6,
        .fx_hz = 2.1,
        .cycles = 2,
        .ay_g = -1.4,
        .ty0 = 0.66,
        .ty1 = 0.89,
        .mu_s = 0.19,
        .mu_k = 0.13}},
      {"rigid_friction_drop_9",
       {.modes = 0,
        .alpha = 0.24,
        .ax_g = -1.46,
        .fx_hz = 0.9,
        .cycles = 1,
        .ay_g = -1.3,
        .ty0 = 0.28,
        .ty1 = 0.48,
        .mu_s = 0.36,
        .mu_k = 0.28}},
      {"flexible_drop_1",
       {.modes = 1,
        .alpha = 0.3,
        .freq_hz = 7,
        .ax_g = -1.35,
        .fx_hz = 1.1,
        .cycles = 1,
        .ay_g = -1.6,
        .ty0 = 0.16,
        .ty1 = 0.32,
        .theta0 = -0.087,
        .theta_dot0 = 0.75}},
      {"rigid_friction_drop_5",
       {.modes = 0,
        .alpha = 0.17,
        .ax_g = -1.46,
        .fx_hz = 2.2,
        .cycles = 1,
        .ay_g = -1.4,
        .ty0 = 1.59,
        .ty1 = 1.75,
        .mu_s = 0.15,
        .mu_k = 0.14,
        .theta0 = -0.006,
        .theta_dot0 = 0.68}},
      {"rigid_drop_1",
       {.modes = 0,
        .alpha = 0.16,
        .ax_g = 0.74,
        .fx_hz = 1.7,
        .cycles = 1.5,
        .ay_g = -1.4,
        .ty0 = 0.06,
        .ty1 = 0.18}},
      {"flexible_drop_2",
       {.modes = 1,
        .alpha = 0.3,
        .freq_hz = 2,
        .ax_g = 0,
        .fx_hz = 1,
        .cycles = 1,
        .ay_g = -1.5,
        .ty0 = 0.5,
        .ty1 = 0.7}},
      {"flexible_drop_3",
       {.modes = 1,
        .alpha = 0.25,
        .freq_hz = 5.6,
        .ax_g = -0.91,
        .fx_hz = 0.5,
        .cycles = 1.5,
        .ay_g = -2,
        .ty0 = 0.93,
        .ty1 = 1.03,
        .static_overturn = true}},
      {"rigid_friction_drop_6",
       {.modes = 0,
        .alpha = 0.15,
        .ax_g = 0.91,
        .fx_hz = 3.9,
        .cycles = 1.5,
        .ay_g = -2,
        .ty0 = 1.05,
        .ty1 = 1.29,
        .mu_s = 0.6,
        .mu_k = 0.46}},
      {"rigid_friction_drop_7",
       {.modes = 0,
        .alpha = 0.58,
        .ax_g = 0.41,
        .fx_hz = 1.5,
        .cycles = 2,
        .ay_g = -2.1,
        .ty0 = 1.09,
        .ty1 = 1.17,
        .mu_s = 0.09,
        .mu_k = 0.05,
        .theta0 = -0.02,
        .theta_dot0 = 0.15}},
      {"flexible_drop_4",
       {.modes = 1,
        .alpha = 0.11,
        .freq_hz = 2.8,
        .ax_g = 1.3,
        .fx_hz = 1.2,
        .cycles = 0.5,
        .ay_g = -1.4,
        .ty0 = 0.04,
        .ty1 = 0.08}},
      {"flexible_friction_drop_2",
       {.modes = 1,
        .alpha = 0.19,
        .freq_hz = 5.3,
        .ax_g = 0.71,
        .fx_hz = 1.1,
        .cycles = 1,
        .ay_g = -2.4,
        .ty0 = 1.9,
        .ty1 = 1.93,
        .mu_s = 0.51,
        .mu_k = 0.38}},
      {"rigid_friction_1",
       {.modes = 0,
        .alpha = 0.22,
        .ax_g = 1.27,
        .fx_hz = 1.6,
        .cycles = 1,
        .mu_s = 0.65,
        .mu_k = 0.4,
        .theta0 = 0.061,
        .theta_dot0 = 0.58}},
      {"flexible_friction_drop_3",
       {.modes = 1,
        .alpha = 0.14,
        .freq_hz = 5.6,
        .ax_g = -1.23,
        .fx_hz = 2.2,
        .cycles = 2,
        .ay_g = -0.7,
        .ty0 = 0.44,
        .ty1 = 0.55,
        .mu_s = 0.73,
        .mu_k = 0.52,
        .theta0 = 0.013,
        .theta_dot0 = 0.19}},
      {"rigid_drop_2",
       {.modes = 0,
        .alpha = 0.34,
        .ax_g = -0.76,
        .fx_hz = 0.8,
        .cycles = 0.5,
        .ay_g = -2.4,
        .ty0 = 0.25,
        .ty1 = 0.43}},
      {"flexible_friction_2",
       {.modes = 1,
        .alpha = 0.18,
        .freq_hz = 5,
        .ax_g = 1.01,
        .fx_hz = 2.3,
        .cycles = 2,
        .mu_s = 0.21,
        .mu_k = 0.14,
        .theta0 = 0.003,
        .theta_dot0 = 0.77,
        .static_overturn = true}},
      {"flexible_friction_3",
       {.modes = 1,
        .alpha = 0.14,
        .freq_hz = 5.2,
        .ax_g = -1.5,
        .fx_hz = 1.2,
        .cycles = 1,
        .mu_s = 0.49,
        .mu_k = 0.48}},
      {"rigid_friction_drop_8",
       {.modes = 0,
        .alpha = 0.24,
        .ax_g = -1.28,
        .fx_hz = 1.1,
        .cycles = 2,
        .ay_g = -0.9,
        .ty0 = 1.67,
        .ty1 = 1.69,
        .mu_s = 0.36,
        .mu_k = 0.34,
        .theta0 = 0.025,
        .theta_dot0 = 0.74}},
  };
  return s;
}

const std::vector<Firing>& firings() {
  static const std::vector<Firing> f = {
      {M::kFullContact, G::kUpliftEdge1, kRigid, "rigid_friction_drop_3"},
      {M::kFullContact, G::kUpliftEdge1, kFlexible, "flexible_friction_1"},
      {M::kFullContact, G::kUpliftEdge2, kRigid, "rigid_friction_drop_1"},
      {M::kFullContact, G::kUpliftEdge2, kFlexible, "flexible_friction_1"},
      {M::kFullContact, G::kLiftOff, kRigid, "rigid_friction_drop_1"},
      {M::kFullContact, G::kLiftOff, kFlexible, "flexible_drop_2"},
      {M::kFullContact, G::kFrictionLimit, kRigid, "rigid_friction_drop_4"},
      {M::kFullContact, G::kFrictionLimit, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge1, G::kLiftOff, kRigid, "rigid_drop_1"},
      {M::kRockingEdge1, G::kLiftOff, kFlexible, "flexible_drop_1"},
      {M::kRockingEdge1, G::kFrictionLimit, kRigid, "rigid_friction_drop_2"},
      {M::kRockingEdge1, G::kFrictionLimit, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge1, G::kImpact, kRigid, "rigid_released"},
      {M::kRockingEdge1, G::kImpact, kRigid, "rigid_friction_drop_1"},
      {M::kRockingEdge1, G::kImpact, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge1, G::kOverturn, kRigid, "rigid_drop_1"},
      {M::kRockingEdge1, G::kOverturn, kFlexible, "flexible_drop_1"},
      {M::kRockingEdge1, G::kPeak, kRigid, "rigid_released"},
      {M::kRockingEdge1, G::kPeak, kRigid, "rigid_friction_drop_2"},
      {M::kRockingEdge1, G::kPeak, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge2, G::kLiftOff, kRigid, "rigid_drop_2"},
      {M::kRockingEdge2, G::kLiftOff, kFlexible, "flexible_drop_1"},
      {M::kRockingEdge2, G::kFrictionLimit, kRigid, "rigid_friction_drop_1"},
      {M::kRockingEdge2, G::kFrictionLimit, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge2, G::kImpact, kRigid, "rigid_released"},
      {M::kRockingEdge2, G::kImpact, kRigid, "rigid_friction_drop_1"},
      {M::kRockingEdge2, G::kImpact, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge2, G::kOverturn, kRigid, "rigid_friction_drop_3"},
      {M::kRockingEdge2, G::kOverturn, kFlexible, "flexible_drop_3"},
      {M::kRockingEdge2, G::kPeak, kRigid, "rigid_released"},
      {M::kRockingEdge2, G::kPeak, kRigid, "rigid_friction_drop_2"},
      {M::kRockingEdge2, G::kPeak, kFlexible, "flexible_friction_1"},
      {M::kFlight, G::kOverturn, kRigid, "rigid_friction_drop_5"},
      {M::kFlight, G::kOverturn, kFlexible, "flexible_drop_4"},
      {M::kFlight, G::kLandingEdge1, kRigid, "rigid_friction_drop_3"},
      {M::kFlight, G::kLandingEdge1, kFlexible, "flexible_friction_1"},
      {M::kFlight, G::kLandingEdge2, kRigid, "rigid_friction_drop_2"},
      {M::kFlight, G::kLandingEdge2, kFlexible, "flexible_friction_1"},
      {M::kSlidingPlus, G::kUpliftEdge1, kFlexible, "flexible_friction_drop_1"},
      {M::kSlidingPlus, G::kUpliftEdge2, kFlexible, "flexible_friction_1"},
      {M::kSlidingPlus, G::kLiftOff, kRigid, "rigid_friction_drop_4"},
      {M::kSlidingPlus, G::kSlipStop, kRigid, "rigid_friction_drop_1"},
      {M::kSlidingPlus, G::kSlipStop, kFlexible, "flexible_friction_drop_1"},
      {M::kSlidingMinus, G::kUpliftEdge1, kFlexible, "flexible_friction_1"},
      {M::kSlidingMinus, G::kUpliftEdge2, kFlexible, "flexible_friction_drop_1"},
      {M::kSlidingMinus, G::kLiftOff, kRigid, "rigid_friction_drop_7"},
      {M::kSlidingMinus, G::kSlipStop, kRigid, "rigid_friction_drop_4"},
      {M::kSlidingMinus, G::kSlipStop, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge1SlidingPlus, G::kLiftOff, kRigid, "rigid_friction_drop_5"},
      {M::kRockingEdge1SlidingPlus, G::kLiftOff, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge1SlidingPlus, G::kImpact, kRigid, "rigid_friction_drop_1"},
      {M::kRockingEdge1SlidingPlus, G::kImpact, kFlexible, "flexible_friction_drop_1"},
      {M::kRockingEdge1SlidingPlus, G::kOverturn, kRigid, "rigid_friction_1"},
      {M::kRockingEdge1SlidingPlus, G::kOverturn, kFlexible, "flexible_friction_2"},
      {M::kRockingEdge1SlidingPlus, G::kPeak, kRigid, "rigid_friction_drop_1"},
      {M::kRockingEdge1SlidingPlus, G::kPeak, kFlexible, "flexible_friction_drop_1"},
      {M::kRockingEdge1SlidingPlus, G::kSlipStop, kRigid, "rigid_friction_drop_2"},
      {M::kRockingEdge1SlidingPlus, G::kSlipStop, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge1SlidingMinus, G::kLiftOff, kRigid, "rigid_friction_drop_3"},
      {M::kRockingEdge1SlidingMinus, G::kLiftOff, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge1SlidingMinus, G::kImpact, kRigid, "rigid_friction_drop_1"},
      {M::kRockingEdge1SlidingMinus, G::kImpact, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge1SlidingMinus, G::kOverturn, kRigid, "rigid_friction_drop_2"},
      {M::kRockingEdge1SlidingMinus, G::kOverturn, kFlexible, "flexible_friction_drop_3"},
      {M::kRockingEdge1SlidingMinus, G::kPeak, kRigid, "rigid_friction_drop_1"},
      {M::kRockingEdge1SlidingMinus, G::kPeak, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge1SlidingMinus, G::kSlipStop, kRigid, "rigid_friction_drop_1"},
      {M::kRockingEdge1SlidingMinus, G::kSlipStop, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge2SlidingPlus, G::kLiftOff, kRigid, "rigid_friction_drop_9"},
      {M::kRockingEdge2SlidingPlus, G::kLiftOff, kFlexible, "flexible_friction_drop_1"},
      {M::kRockingEdge2SlidingPlus, G::kImpact, kRigid, "rigid_friction_drop_1"},
      {M::kRockingEdge2SlidingPlus, G::kImpact, kFlexible, "flexible_friction_drop_1"},
      {M::kRockingEdge2SlidingPlus, G::kOverturn, kRigid, "rigid_friction_drop_6"},
      {M::kRockingEdge2SlidingPlus, G::kOverturn, kFlexible, "flexible_friction_drop_2"},
      {M::kRockingEdge2SlidingPlus, G::kPeak, kRigid, "rigid_friction_drop_1"},
      {M::kRockingEdge2SlidingPlus, G::kPeak, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge2SlidingPlus, G::kSlipStop, kRigid, "rigid_friction_drop_1"},
      {M::kRockingEdge2SlidingPlus, G::kSlipStop, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge2SlidingMinus, G::kLiftOff, kRigid, "rigid_friction_drop_2"},
      {M::kRockingEdge2SlidingMinus, G::kLiftOff, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge2SlidingMinus, G::kImpact, kRigid, "rigid_friction_drop_1"},
      {M::kRockingEdge2SlidingMinus, G::kImpact, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge2SlidingMinus, G::kOverturn, kRigid, "rigid_friction_drop_8"},
      {M::kRockingEdge2SlidingMinus, G::kOverturn, kFlexible, "flexible_friction_3"},
      {M::kRockingEdge2SlidingMinus, G::kPeak, kRigid, "rigid_friction_drop_1"},
      {M::kRockingEdge2SlidingMinus, G::kPeak, kFlexible, "flexible_friction_1"},
      {M::kRockingEdge2SlidingMinus, G::kSlipStop, kRigid, "rigid_friction_drop_5"},
      {M::kRockingEdge2SlidingMinus, G::kSlipStop, kFlexible, "flexible_friction_1"},
  };
  return f;
}

// U_e is the moment the contact must supply about edge e over M g h (§6), with the sliding frame's
// acceleration a_x + d_dot_dot / g (§17). A rigid base sliding flat has one horizontal force on it,
// the kinetic friction, so X_dot_dot + d_dot_dot = -s mu_k (g + Y_dot_dot) (§18) and
// U_1 = (alpha_1 + s mu_k) F_J / M g, U_2 = (alpha_2 - s mu_k) F_J / M g: U_e reaches zero only
// together with F_J, a tie that the uplift reset hands to lift_off (F_J <= 0 there), or starts at
// or below zero, an uplift at the slide's entry that no crossing makes. (At the tie, rounding can
// leave F_J an ulp above zero where U_e's root is located and the run records an uplift at
// F_J ~ 0: 6 of 10,000 random rigid runs with friction and a floor falling at g or faster.)
constexpr const char* kRigidSlideUplift =
    "a rigid base sliding flat has U_1 = (alpha_1 + s mu_k) F_J / M g, U_2 = (alpha_2 - s mu_k) "
    "F_J / M g: U_e reaches zero only with F_J (a lift-off) or at the slide's entry, never by a "
    "crossing of its own";

// U_1 + U_2 = (alpha_1 + alpha_2) F_J / M g (§6, §15): F_J cannot reach zero before one uplift
// function does, and they reach it together only where the modes exert no moment about the c.g.;
// the friction force of a slide drives this body's mode (psi_x != 0), so the uplift comes first.
constexpr const char* kFlexibleSlideLiftOff =
    "U_1 + U_2 = (alpha_1 + alpha_2) F_J / M g: the floor stops pressing no earlier than an uplift "
    "function reaches zero, and with the mode driven by the slide's friction the uplift comes "
    "first";

const std::vector<CannotFire>& cannot_fire() {
  static const std::vector<CannotFire> c = {
      {M::kSlidingPlus, G::kUpliftEdge1, kRigid, kRigidSlideUplift},
      {M::kSlidingPlus, G::kUpliftEdge2, kRigid, kRigidSlideUplift},
      {M::kSlidingMinus, G::kUpliftEdge1, kRigid, kRigidSlideUplift},
      {M::kSlidingMinus, G::kUpliftEdge2, kRigid, kRigidSlideUplift},
      {M::kSlidingPlus, G::kLiftOff, kFlexible, kFlexibleSlideLiftOff},
      {M::kSlidingMinus, G::kLiftOff, kFlexible, kFlexibleSlideLiftOff},
  };
  return c;
}

const Scenario& scenario_named(const std::string& name) {
  for (const NamedScenario& s : scenarios())
    if (name == s.name) return s.scenario;
  ADD_FAILURE() << "no scenario " << name;
  return scenarios().front().scenario;
}

// each scenario's transitions at the default tolerances and at ten times finer ones (run once)
struct Runs {
  std::vector<Seen> normal, finer;
};
const Runs& runs_of(const std::string& name) {
  static std::map<std::string, Runs> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  const Scenario& s = scenario_named(name);
  Runs r{transitions(run_scenario(s)), transitions(run_scenario(s, 10.0))};
  return cache.emplace(name, std::move(r)).first->second;
}

bool shows(const std::vector<Seen>& seen, ContactMode m, Guard g) {
  for (const Seen& s : seen)
    if (s.from == m && s.guard == g) return true;
  return false;
}

std::string pair_name(ContactMode m, Guard g, BodyClass b) {
  return std::string(to_string(m)) + " x " + detail::guard_spec(g).name + " (" + name_of(b) + ")";
}

std::string listing(const std::vector<Seen>& seen) {
  std::ostringstream os;
  for (const Seen& s : seen)
    os << "  t = " << s.event.time << ": " << to_string(s.from) << " --"
       << detail::guard_spec(s.guard).name << "--> " << to_string(s.event.kind) << "\n";
  return os.str();
}

// the reader of a run against two runs whose transitions are known independently: a rigid block
// released at a tilt rocks freely, each impact onto the other edge followed by a peak on it; a
// squat block (b / h = 2, it cannot uplift) starts to slide where the record's linear pieces reach
// mu g, backwards (the floor pulls ahead), and then sticks
TEST(AutomatonTransitions, TheReaderNamesTheModeLeftAndTheGuard) {
  const std::vector<Seen> rocking = transitions(run_scenario(scenario_named("rigid_released")));
  const std::vector<std::pair<ContactMode, Guard>> expected = {
      {M::kRockingEdge1, G::kImpact}, {M::kRockingEdge2, G::kPeak},
      {M::kRockingEdge2, G::kImpact}, {M::kRockingEdge1, G::kPeak},
      {M::kRockingEdge1, G::kImpact}, {M::kRockingEdge2, G::kPeak}};
  ASSERT_GE(rocking.size(), expected.size()) << listing(rocking);
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(rocking[k].from, expected[k].first) << k << "\n" << listing(rocking);
    EXPECT_EQ(rocking[k].guard, expected[k].second) << k << "\n" << listing(rocking);
  }
  const double mu = 0.3;
  const Scenario squat{.modes = 0, .alpha = 2.0, .ax_g = 0.5, .fx_hz = 1.0, .mu_s = mu};
  const std::vector<Seen> slide = transitions(run_scenario(squat));
  ASSERT_GE(slide.size(), 2u) << listing(slide);
  EXPECT_EQ(slide[0].from, M::kFullContact);
  EXPECT_EQ(slide[0].guard, G::kFrictionLimit);
  EXPECT_EQ(slide[1].from, M::kSlidingMinus);
  EXPECT_EQ(slide[1].guard, G::kSlipStop);
  EXPECT_EQ(slide[1].event.kind, EventKind::kStick);
  // the slip starts where the record, linear between its samples, reaches mu g
  const GroundMotion record = scenario_motion(squat);
  const std::vector<double>& t = record.times();
  const std::vector<double>& ax = record.horizontal();
  std::size_t k = 0;
  while (ax[k + 1] < mu * kStandardGravity) ++k;
  const double t_slip =
      t[k] + (mu * kStandardGravity - ax[k]) / (ax[k + 1] - ax[k]) * (t[k + 1] - t[k]);
  EXPECT_NEAR(slide[0].event.time, t_slip, 1e-12);
}

// every (mode, watched guard, body kind) of the automaton's table has a case or a reason, never
// both, and every row of either list is a pair of the table
TEST(AutomatonTransitions, EveryPairOfTheTableHasACaseOrAReasonItCannotFire) {
  int pairs = 0;
  for (const detail::ModeSpec& m : detail::kModes) {
    for (int j = 0; j < m.count; ++j) {
      const Guard g = m.guards[static_cast<std::size_t>(j)];
      ++pairs;
      for (BodyClass b : {kRigid, kFlexible}) {
        int cases = 0, reasons = 0;
        for (const Firing& f : firings())
          if (f.mode == m.mode && f.guard == g && f.body == b) ++cases;
        for (const CannotFire& c : cannot_fire())
          if (c.mode == m.mode && c.guard == g && c.body == b) ++reasons;
        EXPECT_TRUE(cases > 0 || reasons > 0)
            << pair_name(m.mode, g, b) << ": no case fires it and no reason says it cannot";
        EXPECT_FALSE(cases > 0 && reasons > 0)
            << pair_name(m.mode, g, b) << ": listed as unable to fire, yet a case fires it";
      }
    }
  }
  EXPECT_EQ(pairs, 45);  // ten modes, their watched guards (automaton.hpp)
  for (const Firing& f : firings()) {
    EXPECT_GE(detail::guard_slot(f.mode, f.guard), 0)
        << pair_name(f.mode, f.guard, f.body) << ": not a pair of the table";
    EXPECT_EQ(scenario_named(f.scenario).modes, f.body == kRigid ? 0 : 1) << f.scenario;
  }
  for (const CannotFire& c : cannot_fire())
    EXPECT_GE(detail::guard_slot(c.mode, c.guard), 0)
        << pair_name(c.mode, c.guard, c.body) << ": not a pair of the table";
}

// each case's run shows its transition, also with rtol and atol ten times finer: no case rests on
// a tolerance
TEST(AutomatonTransitions, EachCaseFiresItsTransition) {
  for (const Firing& f : firings()) {
    const Runs& r = runs_of(f.scenario);
    EXPECT_TRUE(shows(r.normal, f.mode, f.guard))
        << pair_name(f.mode, f.guard, f.body) << " does not fire in " << f.scenario
        << "; its run shows\n"
        << listing(r.normal);
    EXPECT_TRUE(shows(r.finer, f.mode, f.guard))
        << pair_name(f.mode, f.guard, f.body) << " does not fire in " << f.scenario
        << " at ten times finer tolerances; its run shows\n"
        << listing(r.finer);
  }
}

// every transition of every case leads where §17's table says, where the history shows the mode
// that follows; an overturn ends the run, overturned
TEST(AutomatonTransitions, EachTransitionLeadsWhereTheTableSays) {
  int checked = 0;
  for (const NamedScenario& s : scenarios()) {
    const Runs& r = runs_of(s.name);
    for (const Seen& x : r.normal) {
      if (x.guard == G::kOverturn) {
        EXPECT_FALSE(x.to.has_value()) << s.name << ": a mode follows an overturn";
        continue;
      }
      if (!x.to) continue;
      ++checked;
      EXPECT_TRUE(leads_where_the_table_says(x.from, x.guard, *x.to))
          << s.name << " at t = " << x.event.time << ": " << to_string(x.from) << " --"
          << detail::guard_spec(x.guard).name << "--> " << to_string(*x.to);
    }
  }
  EXPECT_GT(checked, 200);
  // and each pair of the table is seen leading somewhere at least once (some resets are followed
  // at once by another, which hides the mode between them)
  for (const detail::ModeSpec& m : detail::kModes) {
    for (int j = 0; j < m.count; ++j) {
      const Guard g = m.guards[static_cast<std::size_t>(j)];
      if (g == G::kOverturn) continue;
      bool seen = false;
      for (const Firing& f : firings())
        if (f.mode == m.mode && f.guard == g)
          for (const Seen& x : runs_of(f.scenario).normal)
            if (x.from == m.mode && x.guard == g && x.to) seen = true;
      EXPECT_TRUE(seen) << to_string(m.mode) << " x " << detail::guard_spec(g).name
                        << ": the mode it leads to is seen in none of its cases";
    }
  }
}

// the pairs listed as unable to fire fire in no run of that body kind here
TEST(AutomatonTransitions, NoCaseFiresAPairListedAsUnableTo) {
  for (const NamedScenario& s : scenarios()) {
    const BodyClass b = s.scenario.modes == 0 ? kRigid : kFlexible;
    const Runs& r = runs_of(s.name);
    for (const CannotFire& c : cannot_fire()) {
      if (c.body != b) continue;
      EXPECT_FALSE(shows(r.normal, c.mode, c.guard) || shows(r.finer, c.mode, c.guard))
          << pair_name(c.mode, c.guard, b) << " fired in " << s.name << " (listed: " << c.reason
          << ")";
    }
  }
}

}  // namespace
}  // namespace flexrock::test
