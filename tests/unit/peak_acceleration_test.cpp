// SPDX-License-Identifier: BSD-3-Clause
// peak_acceleration(GroundMotion), the one statement of a motion's peak |acceleration| (summary
// JSON, Python's repr, the studies' overflow checks): the samples' extremes, a pulse's amplitude
// in closed form, and a peak that only a breakpoint reaches.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/excitation/intensity.hpp"
#include "flexrock/excitation/pulses.hpp"

namespace flexrock {
namespace {

TEST(PeakAcceleration, OfASampledMotionIsTheLargestSamplePerComponent) {
  const GroundMotion m =
      GroundMotion::sampled({0.0, 1.0, 2.0, 3.0}, {0.5, -2.0, 1.0, 0.0}, {0.1, 0.2, -0.7, 0.0});
  const BaseAcceleration p = peak_acceleration(m);
  EXPECT_EQ(p.x, 2.0);
  EXPECT_EQ(p.y, 0.7);
  // scaled in place: the peak scales with the factor
  EXPECT_EQ(peak_acceleration(m.scaled(-3.0)).x, 6.0);
}

TEST(PeakAcceleration, OfAHalfSinePulseIsItsAmplitude) {
  // a_p sin(omega_p t) on [0, pi/omega_p]: the peak a_p at t = 0.5 s
  const GroundMotion m = half_sine_pulse(3.0, std::numbers::pi, 5.0);
  const BaseAcceleration p = peak_acceleration(m);
  EXPECT_NEAR(p.x, 3.0, 1e-12);
  EXPECT_EQ(p.y, 0.0);
}

TEST(PeakAcceleration, ReachesAPeakThatOnlyABreakpointHolds) {
  // a ramp to 4 m/s^2 that drops to zero at b: no even time of the grid is b, the breakpoint is
  const double b = 0.123456789;
  const GroundMotion m = GroundMotion::analytic(
      [b](double t) {
        return BaseAcceleration{t <= b ? 4.0 * t / b : 0.0, 0.0};
      },
      1.0, {b});
  EXPECT_EQ(peak_acceleration(m).x, 4.0);
}

}  // namespace
}  // namespace flexrock
