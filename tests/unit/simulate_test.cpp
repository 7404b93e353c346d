// SPDX-License-Identifier: BSD-3-Clause
// What a run says when the model's assumptions break or a limit is reached.
#include "flexrock/sim/simulate.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <random>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "support/bodies.hpp"

namespace flexrock {
namespace {

using ::testing::HasSubstr;
constexpr double g = kStandardGravity;

GroundMotion one_sine(double ap, double wp, double duration) {
  return GroundMotion::analytic(
      [=](double t) {
        return BaseAcceleration{t < 2 * M_PI / wp ? ap * std::sin(wp * t) : 0.0, 0.0};
      },
      duration, {2 * M_PI / wp});
}

bool has_event(const SimulationResult& r, EventKind k) {
  for (const auto& e : r.events)
    if (e.kind == k) return true;
  return false;
}

TEST(Simulate, FrictionLimitStartsASlide) {
  const Body body(BodyParameters::rectangular_block(100, 0.3, 1.0));
  SimulationOptions opt;
  opt.friction_coefficient = 0.2;  // below the 0.3 the block needs before it can uplift
  const auto r = simulate(body, one_sine(0.4 * g, 8.0, 3.0), {}, opt);
  EXPECT_TRUE(r.friction_exceeded);
  EXPECT_TRUE(has_event(r, EventKind::kSlipStart));
  EXPECT_TRUE(has_event(r, EventKind::kStick));
  // while the base sticks the demand never exceeds the coefficient
  EXPECT_LE(r.extremes.max_friction_demand, 0.2 * (1 + 1e-12));
  EXPECT_GT(r.extremes.sliding_time, 0.0);
  // in full contact the demand is |Xdd|/(g + Ydd): the slide starts where Xdd = 0.2 g
  for (const auto& e : r.events) {
    if (e.kind == EventKind::kSlipStart) {
      EXPECT_NEAR(e.time, std::asin(0.2 / 0.4) / 8.0, 1e-9);
      break;
    }
  }
}

TEST(Simulate, RestitutionFactorThatAddsEnergyIsFlagged) {
  const Body body(BodyParameters::rectangular_block(100, 0.1, 1.0));  // Housner r = 0.985
  InitialState init;
  init.theta = 0.05;
  SimulationOptions opt;
  opt.t_end = 2.0;
  opt.restitution_factor = 1.1;
  const auto r = simulate(body, GroundMotion::none(opt.t_end), init, opt);
  EXPECT_TRUE(r.impact_gained_energy);
  EXPECT_TRUE(has_event(r, EventKind::kImpactGainedEnergy));
  // the balance still closes: the "loss" is negative and booked as such
  EXPECT_LT(r.energy.impact_loss, 0.0);
  EXPECT_LT(std::abs(r.energy.residual), 1e-8 * r.energy.scale);
}

TEST(Simulate, EnergyBalanceThatDoesNotCloseIsFlagged) {
  // a two-mode body rocking under 4 s of 0.6 g noise: at the default tolerances the residual is
  // ~1e-8 of the scale; at rtol = atol = 1e-3 the integration error breaks the balance by ~3e-3
  // of the scale, far above the documented bound 1e-5 scale + 1e-10 M g h
  BodyParameters p = test::random_lumped_body(2, 7u, 1e4);
  p.damping.kind = DampingKind::kModal;
  p.damping.modal_ratios = VectorX::Constant(2, 0.05);
  const Body body(p);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> ax;
  for (int k = 0; k < 400; ++k) ax.push_back(0.6 * g * u(rng));
  const GroundMotion m = GroundMotion::uniform(0.01, ax, {});
  const double mgh = p.mass * p.gravity * p.height;
  SimulationOptions opt;
  const SimulationResult ok = simulate(body, m, {}, opt);
  ASSERT_GT(ok.extremes.first_uplift_time, 0.0);
  EXPECT_FALSE(ok.energy_unbalanced);
  EXPECT_FALSE(has_event(ok, EventKind::kEnergyUnbalanced));
  EXPECT_LT(std::abs(ok.energy.residual), 1e-5 * ok.energy.scale);
  opt.rtol = opt.atol = 1e-3;
  // DOPRI5 rocking: the default DOP853 keeps this balance to 1e-5 of the scale even at 1e-3
  opt.methods.high_order_rocking = false;
  const SimulationResult bad = simulate(body, m, {}, opt);
  EXPECT_EQ(bad.status, Status::kCompleted);
  EXPECT_GT(std::abs(bad.energy.residual), 1e-4 * bad.energy.scale + 1e-10 * mgh);
  EXPECT_TRUE(bad.energy_unbalanced);
  ASSERT_FALSE(bad.events.empty());
  // the event is the last, at the end, and carries the residual
  const Event& last = bad.events.back();
  EXPECT_EQ(last.kind, EventKind::kEnergyUnbalanced);
  EXPECT_EQ(last.time, bad.t_end);
  EXPECT_EQ(last.energy_loss, bad.energy.residual);
  EXPECT_STREQ(to_string(EventKind::kEnergyUnbalanced), "energy_unbalanced");
}

TEST(Simulate, EnergyResidualBoundIsTheDocumentedOne) {
  // 1e-5 of the scale plus 1e-10 M g h (docs/reliability.md), M g h from the inputs
  const Body body(BodyParameters::rectangular_block(250.0, 0.4, 1.0));  // h = 1 m
  EXPECT_DOUBLE_EQ(energy_residual_bound(body, 0.0), 1e-10 * 250.0 * g * 1.0);
  EXPECT_DOUBLE_EQ(energy_residual_bound(body, 3.0), 3e-5 + 1e-10 * 250.0 * g * 1.0);
}

TEST(Simulate, StepLimitStopsWithAReason) {
  const Body body(BodyParameters::rectangular_block(100, 0.2, 1.0));
  SimulationOptions opt;
  opt.max_steps = 10;
  const auto r = simulate(body, one_sine(0.3 * g, 6.0, 5.0), {}, opt);
  EXPECT_EQ(r.status, Status::kStopped);
  EXPECT_THAT(r.message, HasSubstr("step limit"));
  EXPECT_EQ(r.events.back().kind, EventKind::kStopped);
}

TEST(Simulate, RejectsBadOptionsWithMessages) {
  const Body body(BodyParameters::rectangular_block(100, 0.2, 1.0));
  const auto motion = GroundMotion::none(1.0);
  auto expect_throw = [&](SimulationOptions o, const char* fragment) {
    try {
      simulate(body, motion, {}, o);
      ADD_FAILURE() << "accepted bad options";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr(fragment));
    }
  };
  SimulationOptions o;
  o.rtol = -1;
  expect_throw(o, "rtol must be a number > 0");
  o = {};
  o.max_step = 0;
  expect_throw(o, "max_step");
  o = {};
  o.friction_coefficient = 0;
  expect_throw(o, "friction_coefficient must be a number > 0");
  o = {};
  o.event_samples = 0;
  expect_throw(o, "event_samples");
  // refused numbers are written as given, not rounded to six decimals ("0.000000")
  o = {};
  o.rtol = 1e-15;
  expect_throw(o, "rtol = 1e-15 is below");
  o = {};
  o.output_dt = -2.5e-7;
  expect_throw(o, "got -2.5e-07");
  InitialState init;
  init.theta = 1.6;  // beyond pi/2, the default overturning angle
  try {
    simulate(body, motion, init, {});
    ADD_FAILURE() << "accepted a tilt past overturning";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("already past the overturning angle"));
  }
}

TEST(Simulate, ProgressEndsAtTheTimeReached) {
  const Body body(BodyParameters::rectangular_block(100, 0.2, 1.0));
  for (double ap : {0.1 * g, 0.3 * g}) {  // stays down; overturns at about 1.1 s
    std::atomic<double> reached{-1.0};
    SimulationOptions opt;
    opt.progress = &reached;
    const auto r = simulate(body, one_sine(ap, 6.0, 3.0), {}, opt);
    EXPECT_EQ(reached.load(), r.t_end);
    EXPECT_EQ(r.t_end == 3.0, r.status == Status::kCompleted);
  }
}

TEST(Simulate, RigidFullContactHistoryIsExact) {
  // a rigid body in full contact feels the record directly: reaction = M (g + Ydd), M Xdd
  const Body body(BodyParameters::rectangular_block(250, 0.3, 1.0));
  const auto motion =
      GroundMotion::uniform(0.01, {0.0, 0.5, -1.0, 0.8, 0.0}, {0.0, 1.0, 0.5, -2.0, 0.0});
  SimulationOptions opt;
  opt.output_dt = 0.005;
  const auto r = simulate(body, motion, {}, opt);
  ASSERT_EQ(r.history.size(), 9u);
  for (std::size_t i = 0; i < r.history.size(); ++i) {
    const BaseAcceleration a = motion.at(r.history.time[i]);
    EXPECT_NEAR(r.history.reaction_x[i], 250 * a.x, 1e-9);
    EXPECT_NEAR(r.history.reaction_y[i], 250 * (g + a.y), 1e-9);
    EXPECT_EQ(r.history.phase[i], 0);
  }
}

TEST(Simulate, RigidBodyAtRestAfterAPulseSkipsToTheEnd) {
  // once a pulse has ended a rigid body at rest stays at rest: the run jumps to its end, and its
  // rows, extremes and events are those of the same motion stepped to the end (known only by its
  // function, so the engine cannot tell it has ended)
  const Body body(BodyParameters::rectangular_block(250, 0.3, 1.0));
  const double duration = 30.0, wp = 6.0;
  const GroundMotion pulse = one_sine_pulse(0.5 * 0.3 * g, wp, duration);
  ASSERT_NEAR(pulse.quiet_from(), 2 * M_PI / wp, 1e-15);
  const GroundMotion plain =
      GroundMotion::analytic([pulse](double t) { return pulse.at(t); }, duration, {2 * M_PI / wp});
  SimulationOptions opt;
  opt.output_dt = 0.05;
  const auto quick = simulate(body, pulse, {}, opt);
  const auto stepped = simulate(body, plain, {}, opt);
  ASSERT_EQ(quick.status, Status::kCompleted);
  EXPECT_EQ(quick.t_end, duration);
  EXPECT_EQ(quick.extremes.first_uplift_time, -1.0);
  // the pulse's steps and one to the end, where the stepped run takes max_step to the end
  EXPECT_LT(quick.steps, stepped.steps / 10);
  ASSERT_EQ(quick.history.size(), stepped.history.size());
  EXPECT_EQ(quick.history.time, stepped.history.time);
  EXPECT_EQ(quick.history.reaction_x, stepped.history.reaction_x);
  EXPECT_EQ(quick.history.reaction_y, stepped.history.reaction_y);
  EXPECT_EQ(quick.history.phase, stepped.history.phase);
  EXPECT_EQ(quick.extremes.max_base_shear, stepped.extremes.max_base_shear);
  EXPECT_EQ(quick.extremes.max_overturning_moment, stepped.extremes.max_overturning_moment);
  EXPECT_EQ(quick.extremes.max_friction_demand, stepped.extremes.max_friction_demand);
  EXPECT_EQ(quick.events.size(), stepped.events.size());
  EXPECT_EQ(quick.final_phase, ContactMode::kFullContact);
}

TEST(Simulate, RigidUpliftUnderARecordIsAtTheExactCrossing) {
  // a rigid body in full contact uplifts about edge 1 when Xdd = alpha1 (g + Ydd); both are linear
  // between samples, so the crossing time has a closed form in the sample interval
  const double m = 250.0, a1 = 0.3;
  const Body body(BodyParameters::rectangular_block(m, a1, 1.0));
  const std::vector<double> ax{0.0, 1.0, -2.0, 0.5, 2.0, 4.0, 1.0};
  const std::vector<double> ay{0.0, 0.5, -0.5, 1.0, 0.2, -1.0, 0.0};
  const double dt = 0.02;
  const auto motion = GroundMotion::uniform(dt, ax, ay);
  // U1 = a1 (g + ay) - ax at samples 4 and 5, linear between them
  const double u4 = a1 * (g + ay[4]) - ax[4], u5 = a1 * (g + ay[5]) - ax[5];
  ASSERT_GT(u4, 0.0);
  ASSERT_LT(u5, 0.0);
  const double t_exact = dt * (4.0 + u4 / (u4 - u5));
  const auto r = simulate(body, motion);
  EXPECT_NEAR(r.extremes.first_uplift_time, t_exact, 1e-14);
  EXPECT_EQ(r.extremes.first_uplift_edge, 1);
}

TEST(Simulate, RigidFullContactExtremesAreThoseOfTheSamples) {
  // no uplift (alpha1 = 0.3): the base shear M |Xdd| and the friction demand |Xdd| / (g + Ydd)
  // are largest at a sample (linear, or a ratio of linear functions, between samples)
  const double m = 250.0;
  const Body body(BodyParameters::rectangular_block(m, 0.3, 1.0));
  const auto motion =
      GroundMotion::uniform(0.02, {0.0, 1.0, -2.0, 0.5, 0.0}, {0.0, 0.5, -0.5, 1.0, 0.0});
  const auto r = simulate(body, motion);
  EXPECT_EQ(r.extremes.first_uplift_time, -1.0);
  EXPECT_NEAR(r.extremes.max_base_shear, m * 2.0, 1e-9);
  EXPECT_NEAR(r.extremes.max_overturning_moment, m * 2.0 * 1.0, 1e-9);
  EXPECT_NEAR(r.extremes.max_friction_demand, 2.0 / (g - 0.5), 1e-12);
}

TEST(Simulate, RigidFullContactSlipStartsAtTheLinearCrossing) {
  // |Xdd| / g rises above mu = 0.2 at 0.25 g: the slide starts at the linear crossing between the
  // samples, with no uplift (alpha1 = 0.3), and ends with the record
  const Body body(BodyParameters::rectangular_block(250, 0.3, 1.0));
  const auto motion = GroundMotion::uniform(0.01, {0.0, 0.25 * g, 0.1 * g, 0.25 * g, 0.0});
  SimulationOptions opt;
  opt.friction_coefficient = 0.2;
  opt.t_end = 0.2;
  const auto r = simulate(body, motion, {}, opt);
  std::vector<double> times;
  for (const auto& e : r.events)
    if (e.kind == EventKind::kSlipStart) times.push_back(e.time);
  ASSERT_GE(times.size(), 1u);
  EXPECT_NEAR(times[0], 0.01 * 0.2 / 0.25, 1e-14);
  EXPECT_TRUE(has_event(r, EventKind::kStick));
  EXPECT_EQ(r.extremes.first_uplift_time, -1.0);
  EXPECT_LE(r.extremes.max_friction_demand, 0.2 * (1 + 1e-12));
  EXPECT_EQ(r.status, Status::kCompleted);
}

}  // namespace
}  // namespace flexrock
