// SPDX-License-Identifier: BSD-3-Clause
// Where the sticking contact breaks without a friction limit the result says so with the
// magnitudes (docs/theory.md §15, §16): the floor's pull on a held pivot, against the time
// history's vertical reaction written at a fine output step; the landings that need a pulling
// impulse, against the event log; and a finite friction coefficient removes both.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

constexpr double kPi = std::numbers::pi;

// a 3 Hz oscillator on a slab under a 0.6 g, 2 Hz one-sine pulse: its pivot force vanishes while
// rocking where only sliding could free it, and the floor pulls for about 11 ms
Body oscillator() { return Body(oscillator_on_slab(500.0, 3.0, 500.0, 2.0, 1.0, 0.02)); }
GroundMotion sine_2hz() { return one_sine_pulse(0.6 * kStandardGravity, 2.0 * kPi * 2.0, 3.0); }

SimulationResult run(const Body& b, const GroundMotion& m, int samples, double dt,
                     double mu = std::numeric_limits<double>::infinity()) {
  SimulationOptions o;
  o.event_samples = samples;
  o.output_dt = dt;
  o.friction_coefficient = mu;
  return simulate(b, m, {}, o);
}

TEST(AssumptionBreaks, PivotPullMatchesTheTimeHistoryAndTheSamplesDoNotMatter) {
  const Body body = oscillator();
  const double dt = 1e-5;
  const SimulationResult r = run(body, sine_2hz(), 4, dt);
  const Extremes& x = r.extremes;
  ASSERT_TRUE(r.pivot_tension);
  // every pivot_tension event counts, and carries its episode's most negative F_J
  long episodes = 0;
  double worst_event = 0.0;
  for (const Event& e : r.events) {
    if (e.kind != EventKind::kPivotTension) continue;
    ++episodes;
    worst_event = std::min(worst_event, e.force_estimate);
  }
  EXPECT_EQ(x.tension_episodes, episodes);
  EXPECT_EQ(worst_event, -x.max_pivot_pull);
  // the time history's vertical reaction at 10 us: its least value is the pull sampled, at most
  // the located one and within its curvature over half a row (F_J'' ~ M g w^2 here: 1e-4 of it)
  double least = 0.0;
  long rows_pulling = 0;
  for (std::size_t i = 0; i < r.history.size(); ++i) {
    least = std::min(least, r.history.reaction_y[i]);
    if (r.history.reaction_y[i] < 0.0) ++rows_pulling;
  }
  const double weight = body.params().mass * body.g();
  EXPECT_GT(x.max_pivot_pull, 0.01 * weight);
  EXPECT_GE(x.max_pivot_pull, -least);
  EXPECT_NEAR(x.max_pivot_pull, -least, 1e-4 * x.max_pivot_pull);
  // the time under tension: the rows with F_J < 0, to a row at each end of each episode
  EXPECT_GT(x.tension_time, 0.005);
  EXPECT_NEAR(x.tension_time, static_cast<double>(rows_pulling) * dt,
              2.0 * dt * static_cast<double>(episodes));
  // located, not sampled: 2 and 32 guard samples a step give the same figures
  for (int samples : {2, 32}) {
    const SimulationResult s = run(body, sine_2hz(), samples, 0.01);
    EXPECT_NEAR(s.extremes.max_pivot_pull, x.max_pivot_pull, 1e-9 * x.max_pivot_pull) << samples;
    EXPECT_NEAR(s.extremes.tension_time, x.tension_time, 1e-9) << samples;
    EXPECT_EQ(s.extremes.tension_episodes, x.tension_episodes) << samples;
  }
  // a finite coefficient: the pivot slides before its force vanishes, and nothing pulls
  const SimulationResult f = run(body, sine_2hz(), 4, 0.01, 0.5);
  EXPECT_GT(f.extremes.slips, 0);
  EXPECT_FALSE(f.pivot_tension);
  EXPECT_EQ(f.extremes.tension_episodes, 0);
  EXPECT_EQ(f.extremes.max_pivot_pull, 0.0);
  EXPECT_EQ(f.extremes.tension_time, 0.0);
}

// a rigid block of slenderness 0.25 rad (b/h = tan 0.25 to 6 digits, 2 m tall, 1 t) under a
// one-sine pulse of 20 g tan(alpha) at omega_p = 2 p (T_p = 1.176638 s, p = 2.66952 rad/s): after a
// flight one landing needs the floor to pull about 3.9 kN s, spins the block up and decides its
// overturning. (At omega_p = 2 p to the last bit the lift-off at 0.202 s is a grazing one that
// lands at once, a chatter cut-off, and no flight follows: the period is given as a case file
// would, the same case as tests/cli/assumption_breaks.sh.)
TEST(AssumptionBreaks, TensileLandingIsCountedWithItsImpulse) {
  const Body body(rigid_block(0.510684, 2.0, 1000.0));
  const GroundMotion m = one_sine_pulse(5.10684 * kStandardGravity, 2.0 * kPi / 1.176638, 8.0);
  const SimulationResult r = run(body, m, 4, 0.01);
  long tensile = 0;
  double least = 0.0;
  for (const Event& e : r.events) {
    if (e.kind != EventKind::kTensileLanding) continue;
    ++tensile;
    least = std::min(least, e.impulse_y);
  }
  ASSERT_GE(tensile, 1);
  EXPECT_EQ(r.extremes.tensile_landings, tensile);
  EXPECT_EQ(r.extremes.max_tensile_impulse, -least);
  EXPECT_GT(r.extremes.max_tensile_impulse, 3000.0);
  EXPECT_EQ(r.extremes.max_impulse, 0.0);  // the largest pressing one: none pressed
  EXPECT_EQ(r.status, Status::kOverturned);
  // with friction the landing slides (theory §19: never tensile)
  const SimulationResult f = run(body, m, 4, 0.01, 0.5);
  EXPECT_EQ(f.extremes.tensile_landings, 0);
  EXPECT_EQ(f.extremes.max_tensile_impulse, 0.0);
  EXPECT_EQ(f.extremes.max_pivot_pull, 0.0);
}

}  // namespace
}  // namespace flexrock
