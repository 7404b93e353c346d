// SPDX-License-Identifier: BSD-3-Clause
// Record intensity measures against closed forms: the oscillator's exact response to a step and
// to a ramp of ground acceleration (the recurrence is exact for piecewise-linear records, so it
// must match to rounding), the rigid-oscillator limit Sa -> PGA, and PGV of records whose
// velocity is known by hand, including a peak between two samples.
#include "flexrock/excitation/intensity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "flexrock/core/error.hpp"

namespace flexrock {
namespace {

// u'' + 2 z w u' + w^2 u = -a(t) from rest, for a = a0 + c t: particular solution
// u_p = -(a0 + c t)/w^2 + 2 z c / w^3, free vibration matching u(0) = u'(0) = 0
double closed_form(double a0, double c, double w, double z, double t) {
  const double wd = w * std::sqrt(1.0 - z * z);
  const double up0 = -a0 / (w * w) + 2.0 * z * c / (w * w * w), vp = -c / (w * w);
  const double A = -up0, B = (-vp + z * w * A) / wd;
  return -(a0 + c * t) / (w * w) + 2.0 * z * c / (w * w * w) +
         std::exp(-z * w * t) * (A * std::cos(wd * t) + B * std::sin(wd * t));
}

TEST(SdofResponse, StepAndRampMatchTheClosedFormToRounding) {
  const double w = 2.0 * std::numbers::pi / 0.7;
  for (double z : {0.0, 0.05, 0.3}) {
    for (auto [a0, c] : {std::pair{2.0, 0.0}, std::pair{0.0, 1.5}, std::pair{-1.0, 0.8}}) {
      // uneven steps: each one forms its own recurrence
      std::vector<double> t{0.0}, a{a0};
      for (int i = 1; i <= 400; ++i) {
        t.push_back(t.back() + (i % 3 == 0 ? 0.013 : 0.007));
        a.push_back(a0 + c * t.back());
      }
      const std::vector<double> u = sdof_displacement(t, a, w, z);
      double scale = 0.0, worst = 0.0;
      for (std::size_t i = 0; i < t.size(); ++i) {
        const double exact = closed_form(a0, c, w, z, t[i]);
        scale = std::max(scale, std::abs(exact));
        worst = std::max(worst, std::abs(u[i] - exact));
      }
      EXPECT_LT(worst, 1e-12 * scale) << "zeta " << z << " a0 " << a0 << " c " << c;
    }
  }
}

TEST(SpectralAcceleration, StepGivesTwiceTheStaticResponseUndamped) {
  // u = -(a0/w^2)(1 - cos w t): peak 2 a0/w^2, Sa = 2 a0, reached at t = T/2
  std::vector<double> t, a;
  for (int i = 0; i <= 1000; ++i) {
    t.push_back(0.001 * i);
    a.push_back(3.0);
  }
  EXPECT_NEAR(spectral_acceleration(t, a, 0.5, 0.0), 6.0, 1e-9);
  // 5 % damping: the first peak at t = pi/wd, 1 + exp(-z pi / sqrt(1 - z^2))
  const double z = 0.05, wd = 2.0 * std::numbers::pi / 0.5 * std::sqrt(1 - z * z);
  const double peak = 3.0 * (1.0 + std::exp(-z * std::numbers::pi / std::sqrt(1 - z * z)));
  // sampled at 1 ms around a peak at t = pi/wd: the sampled maximum is within (w dt)^2/2 of it
  const double sa = spectral_acceleration(t, a, 0.5, z);
  EXPECT_LE(sa, peak * (1 + 1e-12));
  EXPECT_GT(sa, peak * (1 - 2e-4));
  (void)wd;
}

TEST(SpectralAcceleration, RigidOscillatorFollowsTheGround) {
  // a stiff oscillator (T = 0.005 s, 10 samples a period) carries the ground's PGA
  std::vector<double> t, a;
  for (int i = 0; i <= 4000; ++i) {
    t.push_back(5e-4 * i);
    a.push_back(std::sin(2.0 * std::numbers::pi * 1.3 * t.back()) * std::exp(-t.back()));
  }
  const double pga = peak_ground_acceleration(a);
  EXPECT_NEAR(spectral_acceleration(t, a, 0.005), pga, 2e-3 * pga);
}

TEST(SpectralAcceleration, PeakAfterTheShakingIsCounted) {
  // a half-second pulse, then rest: a 4 s oscillator peaks after the record ends
  std::vector<double> t, a;
  for (int i = 0; i <= 50; ++i) {
    t.push_back(0.01 * i);
    a.push_back(i < 50 ? 1.0 : 0.0);
  }
  const double w = 2.0 * std::numbers::pi / 4.0;
  const std::vector<double> u = sdof_displacement(t, a, w, 0.0);
  double during = 0.0;
  for (double x : u) during = std::max(during, std::abs(w * w * x));
  EXPECT_GT(spectral_acceleration(t, a, 4.0, 0.0), 1.5 * during);
}

TEST(PeakGroundVelocity, TrianglesAndAPeakBetweenSamples) {
  // a = 0, 1, 0, -1, 0 at 1 s: v = 0, 0.5, 1, 0.5, 0
  EXPECT_DOUBLE_EQ(peak_ground_velocity({0, 1, 2, 3, 4}, {0, 1, 0, -1, 0}), 1.0);
  // a = 1 -> -1 over 1 s: v(s) = s - s^2, peak 0.25 at s = 0.5, back to 0 at the sample
  EXPECT_DOUBLE_EQ(peak_ground_velocity({0, 1}, {1, -1}), 0.25);
  EXPECT_DOUBLE_EQ(peak_ground_acceleration({0.5, -2.0, 1.0}), 2.0);
}

TEST(SpectralAcceleration, RejectsBadArguments) {
  EXPECT_THROW(spectral_acceleration({0, 1}, {0, 1}, 0.0), InputError);
  EXPECT_THROW(spectral_acceleration({0}, {0}, 1.0), InputError);
  EXPECT_THROW(spectral_acceleration({0, 1}, {0, 1}, 1.0, 1.0), InputError);
  EXPECT_THROW(sdof_displacement({0, 1, 1}, {0, 1, 2}, 1.0, 0.0), InputError);
}

}  // namespace
}  // namespace flexrock
