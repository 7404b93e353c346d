// SPDX-License-Identifier: BSD-3-Clause
// The explicit-step cost known before a run: the rigid block's closed form, the engine's own step
// count on a stiff slender body, and the warning `check`, `params` and `run` print.
#include "flexrock/sim/step_cost.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/integrate/dop853.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

// theta'' = -(g/h) (alpha cos theta - sin theta) / (1 + zeta^2 + alpha^2) rocking on a rigid
// body: linearized at theta = 0 its eigenvalues are +-p sqrt(cos(atan alpha)), p^2 = M g R / I_O
TEST(StepCost, RigidBlockRocksAtTheClosedFormRate) {
  for (const auto& [b, h] : {std::pair{0.4, 1.8}, std::pair{1.0, 1.0}, std::pair{0.02, 2.0}}) {
    const Body body(rigid_block(b, h, 500.0));
    const StepCost c = estimate_step_cost(body);
    const double alpha = b / h;
    const double p = body.rocking_frequency();
    EXPECT_NEAR(c.rocking_omega / (p * std::sqrt(std::cos(std::atan(alpha)))), 1.0, 1e-7);
    EXPECT_DOUBLE_EQ(c.rocking_time_scale, 1.0 / p);
    // a slow rocker: the step is max_step (0.01 s)
    EXPECT_DOUBLE_EQ(c.rocking_steps_per_second, 100.0);
    EXPECT_EQ(c.full_contact_omega, 0.0);
    EXPECT_EQ(step_cost_warning(c, 1e4, 50'000'000), "");
  }
}

// DOP853's error norm on y' = z y to leading order, from its table: the 5th- and 3rd-order
// estimates are h sum_i E_i k_i = z sum_i E_i Y_i(z) y with the stage values Y_i(z) = 1 + z sum_j
// a_ij Y_j(z), polynomials in z formed here; their leading terms a z^6 and b z^4 give Hairer's
// norm e5^2 / sqrt(e5^2 + 0.01 e3^2) ~ (10 a^2 / b) z^8, the constant step_cost.hpp uses
TEST(StepCost, Dop853ErrorConstantFromItsTable) {
  constexpr int kTerms = 13;
  std::array<std::array<double, kTerms>, 12> y{};  // y[i][k]: z^k in Y_i
  for (std::size_t i = 0; i < 12; ++i) {
    y[i][0] = 1.0;
    for (std::size_t j = 0; j < i; ++j)
      for (std::size_t k = 0; k + 1 < kTerms; ++k) y[i][k + 1] += dop853::kA[i][j] * y[j][k];
  }
  auto coefficient = [&](const std::array<double, 12>& e, std::size_t power) {
    double s = 0.0;  // z^power in z sum_i e_i Y_i(z)
    for (std::size_t i = 0; i < 12; ++i) s += e[i] * y[i][power - 1];
    return s;
  };
  // the estimates vanish to their orders
  for (std::size_t k = 1; k <= 5; ++k) EXPECT_NEAR(coefficient(dop853::kE5, k), 0.0, 1e-13) << k;
  for (std::size_t k = 1; k <= 3; ++k) EXPECT_NEAR(coefficient(dop853::kE3, k), 0.0, 1e-13) << k;
  const double a = coefficient(dop853::kE5, 6), b = coefficient(dop853::kE3, 4);
  EXPECT_NEAR(a, -1.350e-5, 1e-8);
  EXPECT_NEAR(b, 4.202e-3, 1e-6);
  EXPECT_NEAR(10.0 * a * a / b, kDop853ErrorConstant, 1e-3 * kDop853ErrorConstant);
  EXPECT_NEAR(dop853_stable_step({0.0, 1.0}), kDop853ImaginaryStability, 0.01);
}

// a slender slab (b/h = 0.01) carrying a stiff oscillator: the rocking pivot couples the mode
// with the tilt, and the coupled motion is far stiffer than the pinned-base mode. The engine's
// own step count must lie above the stability bound and near the accuracy estimate, at two
// tolerances, for each explicit method (DOP853, the default: h omega ~ (rtol / 4.34e-7)^(1/8),
// 1e-9 -> 0.47, 1e-6 -> 1.1; DOPRI5: h omega ~ rtol^(1/5) ..., 1e-9 -> 0.066, 1e-6 -> 0.26)
TEST(StepCost, StiffSlenderBodyPredictsTheEnginesSteps) {
  for (const bool eighth : {true, false}) {
    for (double f : {120.0, 980.0}) {
      for (double rtol : {1e-9, 1e-6}) {
        // c.g. at h = 2 m, tipping points 0.02 m from it
        const Body body(oscillator_on_slab(1000.0, f, 1000.0, 4.0, 0.04));
        ASSERT_NEAR(body.alpha1(), 0.01, 1e-12);
        SimulationOptions o;
        o.rtol = rtol;
        o.atol = rtol * 1e-2;
        o.t_end = 0.02;
        // the explicit integrator's cost (the rocking integrator would switch to the Rosenbrock
        // method: tests/unit/stiff_rocking_test.cpp)
        o.methods.rocking_integrator = ContactIntegrator::kExplicit;
        o.methods.high_order_rocking = eighth;
        const StepCost c = estimate_step_cost(body, o);
        EXPECT_NEAR(c.full_contact_omega, 2.0 * 3.141592653589793 * f, 1e-6 * f);
        EXPECT_GT(c.rocking_omega, 10.0 * c.full_contact_omega) << "f = " << f;
        EXPECT_NEAR(c.h_omega,
                    eighth ? std::pow(rtol / kDop853ErrorConstant, 0.125)
                           : std::pow(rtol * 120000.0 / 97.0, 0.2),
                    1e-12);
        // rocking from half the overturning angle, no base motion: it rocks the whole time
        InitialState init;
        init.theta = 0.005;
        const SimulationResult r = simulate(body, GroundMotion::none(o.t_end), init, o);
        ASSERT_EQ(r.status, Status::kCompleted) << r.message;
        ASSERT_EQ(r.extremes.impacts, 0);
        const double rate = static_cast<double>(r.steps) / o.t_end;
        const std::string where = std::string(eighth ? "DOP853" : "DOPRI5") +
                                  ", f = " + std::to_string(f) + ", rtol = " + std::to_string(rtol);
        EXPECT_GE(rate, c.rocking_min_steps_per_second) << where;
        EXPECT_GE(rate, 0.25 * c.rocking_steps_per_second) << where;
        EXPECT_LE(rate, 4.0 * c.rocking_steps_per_second) << where;
      }
    }
  }
}

TEST(StepCost, WarningGivesTheFiguresAndTheStepLimit) {
  const Body body(oscillator_on_slab(1000.0, 980.0, 1000.0, 4.0, 0.04));
  const StepCost c = estimate_step_cost(body);
  ASSERT_GT(c.rocking_steps_per_second, kSlowStepsPerSecond);
  EXPECT_EQ(step_cost_warning(c, 0.0, 1).empty(), false);
  // slow, but within max_steps
  const std::string slow = step_cost_warning(c, 1.0, 50'000'000);
  EXPECT_NE(slow.find("stiff rocking"), std::string::npos) << slow;
  EXPECT_NE(slow.find("steps per simulated second"), std::string::npos) << slow;
  EXPECT_NE(slow.find("Hz"), std::string::npos) << slow;
  EXPECT_EQ(slow.find("max_steps"), std::string::npos) << slow;
  // a long record: above max_steps, named with the time it would stop after
  const double t_over = 2.0 * 50'000'000 / c.rocking_steps_per_second;
  const std::string over = step_cost_warning(c, t_over, 50'000'000);
  EXPECT_NE(over.find("above max_steps = 50000000"), std::string::npos) << over;
  EXPECT_NE(over.find("raise [solver] max_steps"), std::string::npos) << over;
  // a modest body: nothing to say
  const Body tank(oscillator_on_slab(1000.0, 5.0, 1000.0, 4.0, 1.0));
  EXPECT_EQ(step_cost_warning(estimate_step_cost(tank), 60.0, 50'000'000), "");
}

}  // namespace
}  // namespace flexrock
