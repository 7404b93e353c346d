// SPDX-License-Identifier: BSD-3-Clause
// The compliant contact's step cost known before a run: the linearization's eigenvalues against
// the closed form of a rigid block bouncing on its corner springs, the estimate against the
// engine's own step counts on slender stiff slabs, and the warning `check` and `run` print.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"
#include "flexrock/sim/step_cost.hpp"
#include "sim/compliant.hpp"

namespace flexrock {
namespace {

// a symmetric rigid block at rest on both corners bounces vertically apart from its rocking and
// sway: M y'' = -2 k y - 2 c y', c = 2 zeta sqrt(k M / 2), so lambda = omega_v (-zeta +- i
// sqrt(1 - zeta^2)) with omega_v = sqrt(2 k / M)
TEST(CompliantStepCost, RigidBlockBouncesAtTheSpringsClosedForm) {
  const Body body(rigid_block(0.4, 1.8, 500.0));
  for (double zeta : {0.0, 0.1, 0.5}) {
    SimulationOptions o;
    o.contact_model = ContactModel::kCompliant;
    const double omega_v = 500.0 * body.rocking_frequency();
    o.contact_stiffness = 0.5 * 500.0 * omega_v * omega_v;
    o.contact_damping_ratio = zeta;
    const std::complex<double> bounce{-zeta * omega_v, omega_v * std::sqrt(1.0 - zeta * zeta)};
    double nearest = 1e300;
    for (const std::complex<double>& mu : detail::compliant_rest_eigenvalues(body, o, 0))
      nearest = std::min(nearest, std::abs(mu - bounce));
    EXPECT_LT(nearest, 1e-6 * omega_v) << "zeta " << zeta;
  }
}

struct Slab {
  double frequency_hz, base_width;  // [Hz], [m] (height 2 m: b/h = base_width / 4)
};

// the slabs of the step-cost report: b/h 0.01 and 0.04, 57 and 860 Hz, the contact at omega_v =
// 1000 p, critically damped; a 0.3 g one-sine pulse of 1 s
struct SlabRun {
  Body body;
  GroundMotion pulse;
  SimulationOptions options;
};

SlabRun slab_run(const Slab& s) {
  const Body body(oscillator_on_slab(1000.0, s.frequency_hz, 500.0, 2.0, s.base_width, 0.02));
  const double g = body.g(), m = body.params().mass;
  GroundMotion pulse = GroundMotion::analytic(
      [g](double t) {
        return BaseAcceleration{t < 1.0 ? 0.3 * g * std::sin(2.0 * std::numbers::pi * t) : 0.0,
                                0.0};
      },
      2.0, {1.0});
  SimulationOptions o;
  o.contact_model = ContactModel::kCompliant;
  const double omega_v = 1000.0 * body.rocking_frequency();
  o.contact_stiffness = 0.5 * m * omega_v * omega_v;
  o.contact_damping_ratio = 1.0;
  return {body, std::move(pulse), o};
}

constexpr Slab kSlabs[] = {{57.0, 0.04}, {57.0, 0.16}, {860.0, 0.04}, {860.0, 0.16}};

// At rest on both corners (the pulse lifts these slabs at 0.03-0.04 s) nothing drives the fast
// motions, and Dopri5's steps are those its stability allows on the fastest eigenvalue: the
// estimate's floor, predicted from the linearization alone, must be the engine's rate. The 10%
// band is the start's and the rejected steps' share of 0.02 s (a few hundred steps of 500 to
// 78,000), not a fit: the estimates are 1.6-8.7 x apart from slab to slab
TEST(CompliantStepCost, AtRestTheEngineStepsAtTheStabilityBound) {
  for (const Slab& s : kSlabs) {
    SlabRun r = slab_run(s);
    const StepCost c = estimate_step_cost(r.body, r.options);
    r.options.t_end = 0.02;
    const SimulationResult res = simulate(r.body, r.pulse, {}, r.options);
    ASSERT_EQ(res.status, Status::kCompleted);
    ASSERT_TRUE(res.events.empty()) << "lifted before 0.02 s";
    const double measured = static_cast<double>(res.steps) / res.t_end;
    EXPECT_NEAR(measured / c.contact_stable_steps_per_second, 1.0, 0.1)
        << s.frequency_hz << " Hz, b = " << s.base_width << ": measured " << measured
        << " /s, estimate " << c.contact_stable_steps_per_second << " /s";
    EXPECT_GE(c.contact_steps_per_second, c.contact_stable_steps_per_second);
  }
}

// Rocking, the estimate is a floor: DOPRI5 cannot step past its stability bound, and accuracy at
// atol on the fast motions the rocking drives holds it shorter still (docs/theory.md, "Compliant
// contact: step cost"); 0.3 s takes these slabs from rest into rocking. The 5% allows the rest
// phase's start (above); the engine's rate above the floor is reported, not bounded here
TEST(CompliantStepCost, RockingTakesAtLeastTheEstimate) {
  for (const Slab& s : kSlabs) {
    SlabRun r = slab_run(s);
    const StepCost c = estimate_step_cost(r.body, r.options);
    r.options.t_end = 0.3;
    const SimulationResult res = simulate(r.body, r.pulse, {}, r.options);
    ASSERT_EQ(res.status, Status::kCompleted);
    ASSERT_FALSE(res.events.empty()) << "did not lift";
    const double measured = static_cast<double>(res.steps) / res.t_end;
    EXPECT_GE(measured, 0.95 * c.contact_steps_per_second)
        << s.frequency_hz << " Hz, b = " << s.base_width;
  }
}

// the warning names the estimate, the duration, max_steps and what to do; a run that heeds it
// (max_steps raised) is not warned; an impulsive run keeps the rocking estimate
TEST(CompliantStepCost, WarnsBeforeARunThatWouldPassMaxSteps) {
  const SlabRun r = slab_run({860.0, 0.04});
  const StepCost c = estimate_step_cost(r.body, r.options);
  const std::string w = step_cost_warning(c, 2.0, 3'000'000);
  for (const char* part : {"stiff compliant contact", "steps per simulated second", "the 2 s",
                           "above max_steps = 3000000", "raise [solver] max_steps",
                           "soften contact_stiffness", "\"Compliant contact: step cost\""})
    EXPECT_NE(w.find(part), std::string::npos) << part << " not in: " << w;
  // 3.9e6 steps per second is also slow
  EXPECT_NE(step_cost_warning(c, 2.0, 1'000'000'000).find("a long run is slow"), std::string::npos);
  const SlabRun q = slab_run({57.0, 0.16});
  const StepCost cq = estimate_step_cost(q.body, q.options);
  EXPECT_NE(step_cost_warning(cq, 2.0, 40'000), "");
  EXPECT_EQ(step_cost_warning(cq, 2.0, 1'000'000), "");
  SimulationOptions impulsive;
  const StepCost ci = estimate_step_cost(r.body, impulsive);
  EXPECT_EQ(ci.contact_steps_per_second, 0.0);
  EXPECT_EQ(ci.rocking_steps_per_second, c.rocking_steps_per_second);
  // the Rosenbrock method alone is not DOPRI5: no estimate
  SimulationOptions implicit = r.options;
  implicit.methods.contact_integrator = ContactIntegrator::kImplicit;
  EXPECT_EQ(estimate_step_cost(r.body, implicit).contact_steps_per_second, 0.0);
}

}  // namespace
}  // namespace flexrock
