// SPDX-License-Identifier: BSD-3-Clause
// Sa at any period: the free vibration after the record in closed form (the extrema of u, one
// every half damped period) against the sampled free vibration stepped sample by sample, the
// recurrence against the stepped one of before at ordinary periods, the long-period limit (the
// mass stays still, then drifts back: Sa -> omega |v_end| e^(-zeta acos(zeta)/sqrt(1-zeta^2)))
// and the refusal of periods too short to mean anything but the PGA.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/excitation/intensity.hpp"

namespace flexrock {
namespace {

constexpr double kPi = std::numbers::pi;

// the free vibration from (u0, v0), written as an amplitude and a phase (not as the library's
// cos/sin pair): u = R e^(-z w s) cos(wd s - phi)
double free_u(double u0, double v0, double w, double z, double s) {
  const double wd = w * std::sqrt(1.0 - z * z);
  const double B = (v0 + z * w * u0) / wd;
  return std::hypot(u0, B) * std::exp(-z * w * s) * std::cos(wd * s - std::atan2(B, u0));
}

// the definition, sample by sample: the largest |u(k h)| for k = 1 .. ceil(T / h)
double sampled_peak(double u0, double v0, double w, double z, double h, double T) {
  const auto n = static_cast<long>(std::ceil(T / h));
  double peak = 0.0;
  for (long k = 1; k <= n; ++k) {
    peak = std::max(peak, std::abs(free_u(u0, v0, w, z, static_cast<double>(k) * h)));
  }
  return peak;
}

// Sa as computed before the closed form: the particular solution of each linear segment plus
// the free vibration, then one period of free vibration stepped at the record's last step
double stepped_sa(const std::vector<double>& t, const std::vector<double>& a, double period,
                  double z) {
  const double w = 2.0 * kPi / period, wd = w * std::sqrt(1.0 - z * z), w2 = w * w;
  double u = 0.0, v = 0.0, peak = 0.0;
  auto step = [&](double h, double a0, double a1) {
    const double e = std::exp(-z * w * h), c = std::cos(wd * h), s = std::sin(wd * h);
    const double r = z / std::sqrt(1.0 - z * z);
    const double f0 = -a0, f1 = -(a1 - a0) / h;
    const double p1 = f1 / w2, p0 = f0 / w2 - 2.0 * z * f1 / (w2 * w);
    const double du = u - p0, dv = v - p1;
    u = p0 + p1 * h + e * (c + r * s) * du + e * s / wd * dv;
    v = p1 - e * w2 * s / wd * du + e * (c - r * s) * dv;
    peak = std::max(peak, std::abs(u));
  };
  for (std::size_t i = 0; i + 1 < t.size(); ++i) step(t[i + 1] - t[i], a[i], a[i + 1]);
  const double h = t[t.size() - 1] - t[t.size() - 2];
  for (double s = 0.0; s < period; s += h) step(h, 0.0, 0.0);
  return w2 * peak;
}

// a 15 s record of random sines under an envelope, ending with the ground still moving
void test_record(std::vector<double>& t, std::vector<double>& a) {
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  double f[6], ph[6], amp[6];
  for (int k = 0; k < 6; ++k) {
    f[k] = 0.3 + 6.0 * U(rng);
    ph[k] = 2.0 * kPi * U(rng);
    amp[k] = 0.5 + 2.0 * U(rng);
  }
  for (int i = 0; i <= 1500; ++i) {
    const double x = 0.01 * i;
    double s = 0.0;
    for (int k = 0; k < 6; ++k) s += amp[k] * std::sin(2.0 * kPi * f[k] * x + ph[k]);
    t.push_back(x);
    a.push_back(s * x * std::exp(-0.3 * x));
  }
}

TEST(FreeVibrationPeak, EqualsTheLargestSampleOfOnePeriod) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (const double z : {0.0, 0.05, 0.5, 0.95}) {
    for (int trial = 0; trial < 200; ++trial) {
      // states of either sign, one of them zero now and then; 3 to 30000 samples a period
      double u0 = U(rng), v0 = U(rng) * 10.0;
      if (trial % 10 == 1) u0 = 0.0;
      if (trial % 10 == 2) v0 = 0.0;
      const double T = std::pow(10.0, 1.5 * (U(rng) + 1.0)) * 0.03, w = 2.0 * kPi / T;
      const double h = T / (3.0 + 30000.0 * std::abs(U(rng)) * std::abs(U(rng)));
      const double want = sampled_peak(u0, v0, w, z, h, T);
      EXPECT_NEAR(free_vibration_peak(u0, v0, w, z, h, T), want, 1e-13 * want)
          << "zeta " << z << " u0 " << u0 << " v0 " << v0 << " T " << T << " h " << h;
    }
  }
  // sampled finely, the sampled peak is the continuous one, which lies in the first half damped
  // period (the extremum there, or u0): a million samples of a period
  for (const double z : {0.0, 0.1, 0.7}) {
    const double w = 2.0, T = kPi;
    for (auto [u0, v0] :
         {std::pair{1.0, 0.0}, std::pair{0.0, 1.0}, std::pair{1.0, -3.0}, std::pair{-0.2, 5.0}}) {
      const double h = T * 1e-6;
      const double fine = sampled_peak(u0, v0, w, z, h, T);
      EXPECT_NEAR(free_vibration_peak(u0, v0, w, z, h, T), fine, 1e-12 * fine);
      // the continuous peak over the half damped period from the first sample, on a grid of
      // its own: within (w h)^2 / 8 of the samples' (4e-12 here)
      double half = 0.0;
      const double wd = w * std::sqrt(1.0 - z * z);
      for (int k = 0; k <= 1000000; ++k) {
        half = std::max(half, std::abs(free_u(u0, v0, w, z, h + kPi / wd * k * 1e-6)));
      }
      EXPECT_NEAR(fine, half, 1e-11 * half) << "zeta " << z << " u0 " << u0 << " v0 " << v0;
    }
  }
}

TEST(SpectralAcceleration, OrdinaryPeriodsAgreeWithTheSteppedFreeVibrationToRounding) {
  std::vector<double> t, a;
  test_record(t, a);
  // and a record whose oscillators peak after it: a half-second pulse, then rest
  std::vector<double> tp, ap;
  for (int i = 0; i <= 50; ++i) {
    tp.push_back(0.01 * i);
    ap.push_back(i < 50 ? 1.0 : 0.0);
  }
  double worst = 0.0;
  for (const auto* rec : {&t, &tp}) {
    const auto& rt = rec == &t ? t : tp;
    const auto& ra = rec == &t ? a : ap;
    // up to 3 s: beyond, the stepped closed form loses (w h)^-2 of its digits (the test below)
    for (const double T : {0.001, 0.02, 0.0628, 0.0629, 0.1, 0.3, 1.0, 3.0}) {
      for (const double z : {0.0, 0.02, 0.05, 0.2}) {
        const double before = stepped_sa(rt, ra, T, z), now = spectral_acceleration(rt, ra, T, z);
        worst = std::max(worst, std::abs(now - before) / before);
        // the stepped closed form loses (w h)^-2 of the digits of each step's forced part
        const double wh = std::min(1.0, 2.0 * kPi / T * 0.01);
        EXPECT_NEAR(now, before, (1e-14 + 1e-14 / (wh * wh)) * before)
            << "T " << T << " zeta " << z;
      }
    }
  }
  RecordProperty("worst_relative_change", std::to_string(worst));
}

// the response from rest to a = c (t - t0)+ in long double, the closed form of a ramp: its
// cancellation goes as (w (t - t0))^-2, not as (w h)^-2
long double ramp(long double c, long double w, long double z, long double x) {
  if (x <= 0) return 0;
  const long double wd = w * std::sqrt(1.0L - z * z);
  const long double up0 = 2.0L * z * c / (w * w * w), vp = -c / (w * w);
  const long double A = -up0, B = (-vp + z * w * A) / wd;
  return -c * x / (w * w) + up0 +
         std::exp(-z * w * x) * (A * std::cos(wd * x) + B * std::sin(wd * x));
}

TEST(SdofResponse, LongPeriodsMatchSuperposedRampsInLongDouble) {
  // the triangle 0 -> 3 m/s^2 at 0.2 s -> 0 at 0.4 s, then zero to 2 s: three ramps. At T = 100
  // s the stepped closed form of before kept 8 digits of Sa; the series keeps them all
  std::vector<double> t, a;
  for (int i = 0; i <= 200; ++i) {
    t.push_back(0.01 * i);
    a.push_back(i <= 20 ? 0.15 * i : i <= 40 ? 0.15 * (40 - i) : 0.0);
  }
  // (longer periods need more than long double here: the test after next takes them)
  for (const double T : {3.0, 10.0, 30.0, 100.0}) {
    const double w = 2.0 * kPi / T;
    for (const double z : {0.0, 0.05, 0.5}) {
      const std::vector<double> u = sdof_displacement(t, a, w, z);
      double worst = 0.0, scale = 0.0;
      for (std::size_t i = 0; i < t.size(); ++i) {
        long double exact = 0;
        for (auto [t0, c] :
             {std::pair{0.0L, 15.0L}, std::pair{0.2L, -30.0L}, std::pair{0.4L, 15.0L}}) {
          exact += ramp(c, w, z, static_cast<long double>(t[i]) - t0);
        }
        scale = std::max(scale, std::abs(static_cast<double>(exact)));
        worst = std::max(worst, std::abs(u[i] - static_cast<double>(exact)));
      }
      EXPECT_LT(worst, 1e-13 * scale) << "T " << T << " zeta " << z;
    }
  }
}

TEST(SpectralAcceleration, TheRecurrenceIsContinuousWhereItsSeriesTakesOver) {
  // the coefficients come from their power series where w h <= 1 and from the closed form
  // above: on either side of w h = 1 the response agrees to rounding
  std::vector<double> t, a;
  test_record(t, a);
  for (const double z : {0.0, 0.05, 0.5}) {
    const double w = 1.0 / 0.01;
    const std::vector<double> below = sdof_displacement(t, a, w * (1.0 - 1e-13), z);
    const std::vector<double> above = sdof_displacement(t, a, w * (1.0 + 1e-13), z);
    double scale = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) {
      scale = std::max(scale, std::abs(below[i]));
      worst = std::max(worst, std::abs(below[i] - above[i]));
    }
    EXPECT_LT(worst, 1e-12 * scale) << "zeta " << z;
  }
}

TEST(SpectralAcceleration, LongPeriodsKeepTheMassStillAndTendToTheDriftLimit) {
  std::vector<double> t, a;
  test_record(t, a);
  // the ground's velocity and displacement, exact for the piecewise-linear record
  std::vector<double> vg{0.0}, dg{0.0};
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double h = t[i + 1] - t[i];
    dg.push_back(dg.back() + vg.back() * h + h * h * (a[i] / 3.0 + a[i + 1] / 6.0));
    vg.push_back(vg.back() + 0.5 * h * (a[i] + a[i + 1]));
  }
  double pgd = 0.0;
  for (double d : dg) pgd = std::max(pgd, std::abs(d));
  ASSERT_GT(std::abs(vg.back()), 1e-3);
  for (const double T : {1e6, 1e9, 1e15, 1e100, 1e300, 1e308}) {
    const double w = 2.0 * kPi / T;
    // over the record the relative displacement is minus the ground's: the mass x = u + d_g
    // obeys x'' = 2 z w (v_g - x') + w^2 (d_g - x), so the dashpot drags it by about 2 z w t
    // and the spring by (w t)^2 / 2 of the ground's displacement
    const double wt = w * t.back(), zr = 0.05;
    const std::vector<double> u = sdof_displacement(t, a, w, zr);
    double worst = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) worst = std::max(worst, std::abs(u[i] + dg[i]));
    EXPECT_LT(worst, (1e-12 + 2.0 * zr * wt + wt * wt) * pgd) << "T " << T;
    for (const double z : {0.0, 0.05, 0.5}) {
      const double q = std::sqrt(1.0 - z * z);
      // the free vibration from (-d_end, -v_end): its first extremum v_end/w e^(-z acos z / q)
      // (at wd s = acos z); d_end moves it by about w d_end / v_end of itself, and the peak
      // over the record, w^2 PGD, is smaller by as much
      const double limit = std::abs(vg.back()) * std::exp(-z * std::acos(z) / q);
      const double tol = 1e-12 + 10.0 * w * (pgd / std::abs(vg.back()) + t.back());
      const double sa = spectral_acceleration(t, a, T, z);
      EXPECT_NEAR(sa / w, limit, tol * limit) << "T " << T << " zeta " << z;
    }
  }
}

TEST(SpectralAcceleration, PeriodsTooShortAreRefusedNamingThePeriod) {
  std::vector<double> t, a;
  test_record(t, a);
  for (const double T : {1e-300, 1e-7, 0.0, -1.0, std::nan("")}) {
    try {
      spectral_acceleration(t, a, T, 0.05);
      ADD_FAILURE() << "T " << T << " was taken";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("period"), std::string::npos) << m;
      EXPECT_NE(m.find(">= 1e-06 s"), std::string::npos) << m;
    }
  }
  // the shortest one taken is the PGA (the oscillator follows the ground) to 1e-4
  const double pga = peak_ground_acceleration(a);
  EXPECT_NEAR(spectral_acceleration(t, a, kMinSpectralPeriod, 0.05), pga, 1e-4 * pga);
}

}  // namespace
}  // namespace flexrock
