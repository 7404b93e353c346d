// SPDX-License-Identifier: BSD-3-Clause
// Stiff rocking: a slender slab carrying a stiff damped oscillator rocks with a coupled motion far
// faster than any pinned-base mode, which holds an explicit step by stability alone. The rocking
// integrator switches to the Rosenbrock method by itself; its answers must be those of an
// independent explicit run at a tighter tolerance, and must not depend on where the switch is
// made (a numerical device changes the cost, never the answer).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "flexrock/integrate/dopri5.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"
#include "flexrock/sim/step_cost.hpp"

namespace flexrock {
namespace {

// 1 t on a 1 t slab 4 m tall and 4 cm wide (b/h = 0.01), the oscillator at 120 Hz with 5 % damping:
// it rocks with a coupled motion near 15.7 kHz (docs/theory.md, "Stiff rocking")
Body stiff_slab() { return Body(oscillator_on_slab(1000.0, 120.0, 1000.0, 4.0, 0.04, 0.05)); }

// one cycle of a 1 Hz sine of amplitude a_p [m/s^2], sampled every 0.01 s as a record is, then
// rest: a_p = 0.12 uplifts the slab (g alpha = 0.098) and it rocks with impacts
GroundMotion sine_record(double a_p, double duration) {
  std::vector<double> a;
  constexpr double kDt = 0.01;
  for (int i = 0; i * kDt <= duration + 1e-12; ++i) {
    const double t = i * kDt;
    a.push_back(t < 1.0 ? a_p * std::sin(2.0 * 3.141592653589793 * t) : 0.0);
  }
  return GroundMotion::uniform(kDt, a);
}

SimulationOptions options(ContactIntegrator how, double rtol = 1e-9) {
  SimulationOptions o;
  o.rtol = rtol;
  o.atol = 1e-3 * rtol;
  o.methods.rocking_integrator = how;
  o.max_steps = 100'000'000;
  return o;
}

std::vector<double> event_times(const SimulationResult& r, EventKind kind) {
  std::vector<double> t;
  for (const Event& e : r.events)
    if (e.kind == kind) t.push_back(e.time);
  return t;
}

double max_theta(const SimulationResult& r) {
  return std::max(r.extremes.max_theta_edge1, r.extremes.max_theta_edge2);
}

// Both runs keep a local error of rtol = 1e-9 and 1e-10 per step; the rocking between impacts
// is stable (no exponential growth over its half-second), so the global error stays within a
// few hundred times rtol: 1e-7 relative on angles and event times, 1e-7 of the energy scale.
void expect_same_motion(const SimulationResult& r, const SimulationResult& ref, const char* what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(r.status, ref.status) << r.message << " / " << ref.message;
  EXPECT_EQ(r.final_phase, ref.final_phase);
  EXPECT_EQ(r.extremes.impacts, ref.extremes.impacts);
  EXPECT_EQ(r.extremes.overturn_edge, ref.extremes.overturn_edge);
  EXPECT_NEAR(max_theta(r), max_theta(ref), 1e-7 * max_theta(ref));
  // the uplift's extreme is observed at the steps' samples and at the peaks; an overturning run
  // ends rising, between samples, so there it depends on the steps (max_theta is the exact one)
  if (ref.status != Status::kOverturned) {
    EXPECT_NEAR(r.extremes.max_uplift, ref.extremes.max_uplift, 1e-7 * ref.extremes.max_uplift);
  }
  for (EventKind kind : {EventKind::kUplift, EventKind::kRockingEnded, EventKind::kImpact,
                         EventKind::kPeak, EventKind::kOverturn}) {
    const std::vector<double> a = event_times(r, kind), b = event_times(ref, kind);
    ASSERT_EQ(a.size(), b.size()) << "event kind " << static_cast<int>(kind);
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-7 * std::max(b[i], 1.0));
  }
  const double scale = ref.energy.scale;
  EXPECT_NEAR(r.energy.input_work, ref.energy.input_work, 1e-7 * scale);
  EXPECT_NEAR(r.energy.kinetic_change, ref.energy.kinetic_change, 1e-7 * scale);
  EXPECT_NEAR(r.energy.potential_change, ref.energy.potential_change, 1e-7 * scale);
  EXPECT_NEAR(r.energy.damping_loss, ref.energy.damping_loss, 1e-7 * scale);
  EXPECT_NEAR(r.energy.impact_loss, ref.energy.impact_loss, 1e-7 * scale);
  EXPECT_FALSE(r.energy_unbalanced);
}

// DOPRI5's stability polynomial leaves the unit disc at |h mu| = 3.3 on the negative real axis
// and just under 1 on the imaginary one (Hairer & Wanner II, IV.2, Fig. 2.1)
TEST(StiffRocking, Dopri5StableStepOnTheAxes) {
  EXPECT_NEAR(dopri5_stable_step({-1.0, 0.0}), 3.3066, 1e-3);
  EXPECT_NEAR(dopri5_stable_step({-0.0, 1000.0}), 0.997e-3, 1e-6);
  // 5 % damping: already twice the undamped bound
  const double z = 0.05;
  EXPECT_GT(dopri5_stable_step({-z, std::sqrt(1.0 - z * z)}), 2.0);
  EXPECT_TRUE(std::isinf(dopri5_stable_step({1.0, 0.0})));
  EXPECT_TRUE(std::isinf(dopri5_stable_step({0.0, 0.0})));
}

// the bound the switch uses is the stiffest coupled motion's: far below the pinned-base mode's
TEST(StiffRocking, StableStepIsTheCoupledMotions) {
  const Body body = stiff_slab();
  const StepCost c = estimate_step_cost(body);
  for (int e : {1, 2}) {
    const double h = rocking_stable_step(body, e);
    // between the undamped bound and the real-axis one
    EXPECT_GE(h * c.rocking_omega, 0.99) << "edge " << e;
    EXPECT_LE(h * c.rocking_omega, 3.31) << "edge " << e;
    EXPECT_LT(h, 0.01 / c.full_contact_omega) << "edge " << e;
  }
}

// the switch is made without being asked for, and it pays: a few thousand steps where the
// explicit method takes over a hundred times more
TEST(StiffRocking, SlabUnderStiffOscillatorMatchesAnIndependentExplicitRun) {
  const Body body = stiff_slab();
  const GroundMotion motion = sine_record(0.12, 1.5);
  const SimulationResult auto_run =
      simulate(body, motion, InitialState{}, options(ContactIntegrator::kAuto));
  const SimulationResult explicit_run =
      simulate(body, motion, InitialState{}, options(ContactIntegrator::kExplicit, 1e-10));
  ASSERT_EQ(auto_run.status, Status::kCompleted) << auto_run.message;
  ASSERT_EQ(auto_run.extremes.impacts, 2);
  EXPECT_LT(auto_run.steps, 2000);
  EXPECT_GT(explicit_run.steps, 100 * auto_run.steps);
  expect_same_motion(auto_run, explicit_run, "auto against explicit at rtol 1e-10");
  // forced to the Rosenbrock method throughout the rocking: the same again
  const SimulationResult implicit_run =
      simulate(body, motion, InitialState{}, options(ContactIntegrator::kImplicit));
  expect_same_motion(implicit_run, explicit_run, "implicit against explicit at rtol 1e-10");
}

// the switch's threshold ten times stricter (switching at a tenth of the explicit step) and ten
// times looser (never: the explicit method all the way) gives the same motion
TEST(StiffRocking, SwitchThresholdDoesNotChangeTheAnswer) {
  const Body body = stiff_slab();
  const GroundMotion motion = sine_record(0.12, 1.5);
  SimulationOptions o = options(ContactIntegrator::kAuto);
  const SimulationResult base = simulate(body, motion, InitialState{}, o);
  for (double scale : {10.0, 0.1}) {
    o.methods.stiff_switch_scale = scale;
    const SimulationResult r = simulate(body, motion, InitialState{}, o);
    expect_same_motion(r, base, scale > 1.0 ? "stricter" : "looser");
  }
}

// a stronger pulse overturns the slab (at its static overturning angle): the outcome, side and
// time agree with the explicit run
TEST(StiffRocking, OverturnAgreesWithTheExplicitRun) {
  const Body body = stiff_slab();
  const GroundMotion motion = sine_record(0.5, 1.5);
  SimulationOptions o = options(ContactIntegrator::kAuto);
  o.overturn = OverturnCriterion::kStaticInstability;
  const SimulationResult auto_run = simulate(body, motion, InitialState{}, o);
  o.methods.rocking_integrator = ContactIntegrator::kExplicit;
  o.rtol = 1e-10;
  o.atol = 1e-13;
  const SimulationResult explicit_run = simulate(body, motion, InitialState{}, o);
  ASSERT_EQ(auto_run.status, Status::kOverturned) << auto_run.message;
  EXPECT_LT(auto_run.steps, explicit_run.steps / 100);
  expect_same_motion(auto_run, explicit_run, "overturning");
  EXPECT_NEAR(auto_run.t_end, explicit_run.t_end, 1e-7);
}

// a body with no stiff rocking motion keeps DOPRI5: the same steps, to the step, as when forced
TEST(StiffRocking, OrdinaryBodyKeepsTheExplicitMethod) {
  const Body body(oscillator_on_slab(1000.0, 2.0, 500.0, 2.0, 0.8, 0.05));
  const GroundMotion motion = sine_record(4.0, 3.0);
  const SimulationResult a =
      simulate(body, motion, InitialState{}, options(ContactIntegrator::kAuto));
  const SimulationResult b =
      simulate(body, motion, InitialState{}, options(ContactIntegrator::kExplicit));
  ASSERT_GT(a.extremes.impacts, 0);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.rhs_evaluations, b.rhs_evaluations);
  EXPECT_EQ(max_theta(a), max_theta(b));
}

// an analytic motion that jumps (a rectangular pulse ending while the slab rocks): the Rosenbrock
// steps restart from the jump's right-hand limit as DOPRI5's do, and the runs agree
TEST(StiffRocking, JumpOfAnAnalyticMotionWhileRocking) {
  const Body body = stiff_slab();
  const GroundMotion motion = rectangular_pulse(0.15, 0.3, 1.0);
  const SimulationResult auto_run =
      simulate(body, motion, InitialState{}, options(ContactIntegrator::kAuto));
  const SimulationResult explicit_run =
      simulate(body, motion, InitialState{}, options(ContactIntegrator::kExplicit, 1e-10));
  ASSERT_GE(auto_run.extremes.first_uplift_time, 0.0);
  ASSERT_LT(auto_run.extremes.first_uplift_time, 0.3);  // rocking when the pulse ends
  EXPECT_LT(auto_run.steps, explicit_run.steps / 100);
  expect_same_motion(auto_run, explicit_run, "rectangular pulse");
}

TEST(StiffRocking, SwitchScaleMustBePositive) {
  SimulationOptions o;
  for (double bad : {0.0, -1.0, std::nan("")}) {
    o.methods.stiff_switch_scale = bad;
    try {
      simulate(stiff_slab(), sine_record(0.12, 0.1), InitialState{}, o);
      ADD_FAILURE() << "stiff_switch_scale = " << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("stiff_switch_scale must be positive"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace flexrock
