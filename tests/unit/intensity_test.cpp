// SPDX-License-Identifier: BSD-3-Clause
// Record intensity measures against closed forms: the oscillator's exact response to a step and
// to a ramp of ground acceleration (the recurrence is exact for piecewise-linear records, so it
// must match to rounding), the rigid-oscillator limit Sa -> PGA, and PGV of records whose
// velocity is known by hand, including a peak between two samples.
#include "flexrock/excitation/intensity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
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

// u'' + 2 z w u' + w^2 u = -A sin(W t) from rest: steady state C sin + D cos plus the free
// vibration that starts it from rest
struct Harmonic {
  double A, W, w, z, C, D, E, F, wd;
  Harmonic(double A_, double W_, double w_, double z_) : A(A_), W(W_), w(w_), z(z_) {
    const double k = w * w - W * W, c = 2.0 * z * w * W, det = k * k + c * c;
    C = -A * k / det;
    D = A * c / det;
    wd = w * std::sqrt(1.0 - z * z);
    E = -D;
    F = (z * w * E - C * W) / wd;
  }
  double u(double t) const {
    return C * std::sin(W * t) + D * std::cos(W * t) +
           std::exp(-z * w * t) * (E * std::cos(wd * t) + F * std::sin(wd * t));
  }
  double v(double t) const {
    const double e = std::exp(-z * w * t);
    return C * W * std::cos(W * t) - D * W * std::sin(W * t) -
           z * w * e * (E * std::cos(wd * t) + F * std::sin(wd * t)) +
           e * wd * (-E * std::sin(wd * t) + F * std::cos(wd * t));
  }
};

// omega^2 max |u| over the samples of the record and of one period of free vibration after it
// (the definition of spectral_acceleration), from closed forms u(t) during and the free
// vibration from (u, v) at the end
template <class U>
double closed_form_sa(const std::vector<double>& t, double w, double z, U u, double u_end,
                      double v_end) {
  double peak = 0.0;
  for (double ti : t) peak = std::max(peak, std::abs(u(ti)));
  const double h = t[t.size() - 1] - t[t.size() - 2], T = 2.0 * std::numbers::pi / w;
  const double wd = w * std::sqrt(1.0 - z * z);
  int k = 1;
  for (double s = 0.0; s < T; s += h, ++k) {
    const double x = k * h;
    const double f = std::exp(-z * w * x) *
                     (u_end * std::cos(wd * x) + (v_end + z * w * u_end) / wd * std::sin(wd * x));
    peak = std::max(peak, std::abs(f));
  }
  return w * w * peak;
}

TEST(SpectralAcceleration, HarmonicInputMatchesTheClosedForm) {
  // a = A sin(W t) sampled at 0.5 ms and taken piecewise linear: the sampled sine differs from
  // the sine by at most A (W dt)^2 / 8 (its mean over a chord by (W dt)^2 / 12 relative), so Sa
  // agrees to that relative error
  const double A = 2.0, dt = 5e-4;
  for (const double period : {0.1, 0.5, 2.0}) {
    const double w = 2.0 * std::numbers::pi / period;
    for (const double z : {0.0, 0.05, 0.2}) {
      // off resonance, and at resonance where the amplitude grows towards A / (2 z)
      for (const double W : {2.0 * std::numbers::pi * 1.7, w}) {
        if (z == 0.0 && W == w) continue;  // undamped resonance: the closed form above divides by 0
        std::vector<double> t, a;
        for (int i = 0; i <= 8000; ++i) {
          t.push_back(dt * i);
          a.push_back(A * std::sin(W * t.back()));
        }
        const Harmonic hm(A, W, w, z);
        const double exact = closed_form_sa(
            t, w, z, [&](double x) { return hm.u(x); }, hm.u(t.back()), hm.v(t.back()));
        const double sa = spectral_acceleration(t, a, period, z);
        const double tol = W * dt * W * dt / 8.0;
        EXPECT_NEAR(sa, exact, tol * exact) << "T " << period << " zeta " << z << " W " << W;
      }
    }
  }
}

TEST(SpectralAcceleration, PiecewiseLinearPulseMatchesSuperposedRampsToRounding) {
  // a triangle 0 -> 3 m/s^2 at 0.2 s -> 0 at 0.4 s, then zero to 2 s: the sum of the ramps
  // 15 (t)+, -30 (t - 0.2)+, 15 (t - 0.4)+, each answered by the closed form from rest
  std::vector<double> t, a;
  for (int i = 0; i <= 200; ++i) {
    t.push_back(0.01 * i);
    a.push_back(i <= 20 ? 0.15 * i : i <= 40 ? 0.15 * (40 - i) : 0.0);
  }
  for (const double period : {0.15, 0.7, 3.0}) {
    const double w = 2.0 * std::numbers::pi / period;
    for (const double z : {0.0, 0.05}) {
      auto u = [&](double x) {
        double sum = 0.0;
        for (auto [t0, c] : {std::pair{0.0, 15.0}, std::pair{0.2, -30.0}, std::pair{0.4, 15.0}}) {
          if (x > t0) sum += closed_form(0.0, c, w, z, x - t0);
        }
        return sum;
      };
      // the recurrence at every sample, to rounding
      const std::vector<double> num = sdof_displacement(t, a, w, z);
      double worst = 0.0, scale = 0.0;
      for (std::size_t i = 0; i < t.size(); ++i) {
        scale = std::max(scale, std::abs(u(t[i])));
        worst = std::max(worst, std::abs(num[i] - u(t[i])));
      }
      EXPECT_LT(worst, 1e-12 * scale) << "T " << period << " zeta " << z;
      // after the pulse the input is zero: the closed form continues past the record's end, so
      // Sa is omega^2 max |u| over the samples and one period after, all from the closed form
      double peak = 0.0;
      for (std::size_t i = 0; i < t.size(); ++i) peak = std::max(peak, std::abs(u(t[i])));
      for (double s = 0.01, e = 0.0; e < period; s += 0.01, e += 0.01) {
        peak = std::max(peak, std::abs(u(t.back() + s)));
      }
      EXPECT_NEAR(spectral_acceleration(t, a, period, z), w * w * peak, 1e-11 * w * w * peak)
          << "T " << period << " zeta " << z;
    }
  }
}

TEST(PeakGroundDisplacement, ClosedForms) {
  // one step, a = 1 -> -2 over 3 s: v = s - s^2/2 is 0 at s = 2, inside the step; there
  // d = s^2/2 - s^3/6 = 2/3, and d(3) = 0
  EXPECT_NEAR(peak_ground_displacement({0, 3}, {1, -2}), 2.0 / 3.0, 1e-15);
  // constant a = c over T: d = c T^2 / 2
  EXPECT_NEAR(peak_ground_displacement({0, 0.5, 4}, {-3, -3, -3}), 1.5 * 16.0, 1e-12);
  // a = A sin(W t) over n periods: d = A/W (t - sin(W t)/W), largest at the end, A t_end / W;
  // the sampled sine is within A (W dt)^2/8 of it, and so is d relative to its size
  const double A = 1.3, W = 2.0 * std::numbers::pi * 1.5, dt = 1e-3;
  std::vector<double> t, a;
  for (int i = 0; i <= 4000; ++i) {
    t.push_back(dt * i);
    a.push_back(A * std::sin(W * t.back()));
  }
  const double exact = A / W * (t.back() - std::sin(W * t.back()) / W);
  EXPECT_NEAR(peak_ground_displacement(t, a), exact, 1e-5 * exact);
}

TEST(AriasAndCav, HandSumsOnSmallRecords) {
  // a = 0, 2, -2, 0 at 1 s steps: integral of a^2 per step h (a0^2 + a0 a1 + a1^2)/3 = 4/3, 4/3,
  // 4/3; |a|: the triangles 1, then 2 -> -2 crosses zero at mid-step: two triangles of 1/2,
  // then 1
  const std::vector<double> t{0, 1, 2, 3}, a{0, 2, -2, 0};
  EXPECT_NEAR(arias_intensity(t, a), std::numbers::pi / (2.0 * 9.80665) * 4.0, 1e-15);
  EXPECT_NEAR(cumulative_absolute_velocity(t, a), 3.0, 1e-15);
  // uneven steps: a = 1, 3, -1 at t = 0, 0.5, 2: a^2: 0.5 (1 + 3 + 9)/3 + 1.5 (9 - 3 + 1)/3 =
  // 13/6 + 7/2; |a|: 0.5 * 2 + the crossing at 3/4 of the second step: 1.5 * (3/4 * 3 + 1/4)/2
  const std::vector<double> t2{0, 0.5, 2}, a2{1, 3, -1};
  EXPECT_NEAR(arias_intensity(t2, a2), std::numbers::pi / (2.0 * 9.80665) * (13.0 / 6 + 3.5),
              1e-14);
  EXPECT_NEAR(cumulative_absolute_velocity(t2, a2), 1.0 + 1.5 * (2.25 + 0.25) / 2.0, 1e-15);
}

TEST(SignificantDuration, ConstantAndRampRecords) {
  // constant a: the integral of a^2 grows linearly, 5 % to 95 % of 10 s is 9 s
  EXPECT_NEAR(significant_duration({0, 2.5, 10}, {4, 4, 4}), 9.0, 1e-12);
  // a = t on [0, 1]: the integral t^3/3, instants p^(1/3)
  EXPECT_NEAR(significant_duration({0, 1}, {0, 1}), std::cbrt(0.95) - std::cbrt(0.05), 1e-12);
  EXPECT_EQ(significant_duration({0, 1}, {0, 0}), 0.0);
}

TEST(IntensityMeasures, EachScalesWithItsDeclaredPowerAndHasAUniqueColumn) {
  std::vector<double> t, a, a3;
  for (int i = 0; i <= 3000; ++i) {
    t.push_back(0.002 * i);
    a.push_back(std::sin(7.0 * t.back()) * std::exp(-0.5 * t.back()) +
                0.2 * std::cos(19.0 * t.back()));
    a3.push_back(3.0 * a.back());
  }
  std::vector<std::string> columns;
  for (const IntensityMeasure& m : intensity_measures()) {
    const double x = m.compute(t, a, 0.4, 0.05), x3 = m.compute(t, a3, 0.4, 0.05);
    EXPECT_GT(x, 0.0) << m.name;
    EXPECT_NEAR(x3, std::pow(3.0, m.scale_power) * x, 1e-12 * x3) << m.name;
    EXPECT_EQ(find_intensity_measure(m.name), &m);
    const std::string c = m.needs_period ? spectral_column(0.4, 0.05) : m.column;
    EXPECT_EQ(std::count(columns.begin(), columns.end(), c), 0) << c;
    columns.push_back(c);
  }
  EXPECT_EQ(spectral_column(0.5, 0.05), "sa_T0.5_z0.05_m_per_s2");
  EXPECT_EQ(find_intensity_measure("pgx"), nullptr);
}

TEST(SpectralAcceleration, RejectsBadArguments) {
  EXPECT_THROW(spectral_acceleration({0, 1}, {0, 1}, 0.0), InputError);
  EXPECT_THROW(spectral_acceleration({0}, {0}, 1.0), InputError);
  EXPECT_THROW(spectral_acceleration({0, 1}, {0, 1}, 1.0, 1.0), InputError);
  EXPECT_THROW(sdof_displacement({0, 1, 1}, {0, 1, 2}, 1.0, 0.0), InputError);
}

}  // namespace
}  // namespace flexrock
