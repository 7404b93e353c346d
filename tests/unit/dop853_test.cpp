// SPDX-License-Identifier: BSD-3-Clause
// DOP853: its table against the conditions it must meet, its step and dense output against the
// Kepler problem's closed form (their orders, 8 and 7), and its stability bound against the
// growth of an actual step.
#include "flexrock/integrate/dop853.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <complex>

namespace flexrock {
namespace {

using V2 = Eigen::Vector2d;
using V4 = Eigen::Vector4d;

TEST(Dop853, TableMeetsTheRowSumAndQuadratureConditions) {
  // c_i = sum_j a_ij for all 16 stages; the 8th-order weights integrate c^(k-1) exactly for
  // k <= 8 and not for k = 9 (the order is 8, not more)
  for (int i = 0; i < 16; ++i) {
    double s = 0.0;
    for (int j = 0; j < 16; ++j) s += dop853::kA[i][j];
    // the a_ij reach 44 in size and are given to 17 digits: their sums round to ~1e-14
    EXPECT_NEAR(s, dop853::kC[static_cast<std::size_t>(i)], 1e-14) << "row " << i;
  }
  for (int k = 1; k <= 9; ++k) {
    double s = 0.0;
    for (int j = 0; j < 12; ++j)
      s += dop853::kA[12][j] * std::pow(dop853::kC[static_cast<std::size_t>(j)], k - 1);
    if (k <= 8) {
      EXPECT_NEAR(s, 1.0 / k, 1e-15) << "k = " << k;
    } else {
      EXPECT_GT(std::abs(s - 1.0 / k), 1e-6);
    }
  }
  // the error estimators vanish on constants (they are differences of two weightings)
  double e5 = 0.0, e3 = 0.0;
  for (std::size_t j = 0; j < 12; ++j) {
    e5 += dop853::kE5[j];
    e3 += dop853::kE3[j];
  }
  EXPECT_NEAR(e5, 0.0, 1e-14);
  EXPECT_NEAR(e3, 0.0, 1e-14);
}

// Kepler's problem, eccentricity 0.5, period 2 pi: r'' = -r / |r|^3, solved by Kepler's equation
constexpr double kEcc = 0.5;
struct Kepler {
  void operator()(double, const V4& x, V4& dx) const {
    const double r2 = x(0) * x(0) + x(1) * x(1);
    const double r3 = r2 * std::sqrt(r2);
    dx << x(2), x(3), -x(0) / r3, -x(1) / r3;
  }
};
V4 kepler_exact(double t) {
  double e_anom = t;  // E - e sin E = t by Newton
  for (int i = 0; i < 50; ++i)
    e_anom -= (e_anom - kEcc * std::sin(e_anom) - t) / (1.0 - kEcc * std::cos(e_anom));
  const double b = std::sqrt(1.0 - kEcc * kEcc), den = 1.0 - kEcc * std::cos(e_anom);
  return {std::cos(e_anom) - kEcc, b * std::sin(e_anom), -std::sin(e_anom) / den,
          b * std::cos(e_anom) / den};
}

// fixed steps: tolerances so loose that every step is accepted, the step set by max_step
StepControl fixed_steps(double h) {
  StepControl c;
  c.rtol = 1e3;
  c.atol = 1e3;
  c.max_step = h;
  return c;
}

TEST(Dop853, StepIsEighthOrderOnKepler) {
  // the global error at t = 2 falls by 2^8 = 256 when the step halves
  double err[2];
  for (int r = 0; r < 2; ++r) {
    const double h = 0.1 / (1 << r);
    Dop853<V4> rk;
    rk.start(Kepler{}, fixed_steps(h), 0.0, kepler_exact(0.0), h);
    while (rk.t1() < 2.0) ASSERT_EQ(rk.step(Kepler{}, 2.0), Dop853<V4>::Status::kAccepted);
    err[r] = (rk.x1() - kepler_exact(2.0)).norm();
  }
  EXPECT_GT(err[0], 1e-13);  // above rounding: the ratio measures the method
  EXPECT_GT(err[0] / err[1], 180.0);
  EXPECT_LT(err[0] / err[1], 360.0);
}

TEST(Dop853, DenseOutputIsSeventhOrderOnKepler) {
  // one step from the exact state: the interpolant's error at 0.3 of the step (local, O(h^8))
  // falls toward 2^8 = 256 when the step halves (117, 166, 204 from h = 0.4 down); a 6th-order
  // interpolant's would fall by 2^7 = 128
  double err[2];
  for (int r = 0; r < 2; ++r) {
    const double h = 0.1 / (1 << r);
    Dop853<V4> rk;
    rk.start(Kepler{}, fixed_steps(h), 0.5, kepler_exact(0.5), h);
    rk.step(Kepler{}, 10.0);
    const double tm = rk.t0() + 0.3 * (rk.t1() - rk.t0());
    V4 xm;
    rk.dense(tm, xm);
    err[r] = (xm - kepler_exact(tm)).norm();
  }
  EXPECT_GT(err[0], 1e-13);
  EXPECT_GT(err[0] / err[1], 180.0);
}

struct Harmonic {
  void operator()(double, const V2& x, V2& dx) const { dx << x(1), -x(0); }
};

TEST(Dop853, AdaptiveStepsMeetTheToleranceAndLandOnTheStop) {
  auto run = [](double tol, double& t_end) {
    Dop853<V2> rk;
    StepControl c;
    c.rtol = tol;
    c.atol = tol;
    rk.start(Harmonic{}, c, 0.0, V2(1.0, 0.0));
    while (rk.t1() < 20.0) EXPECT_EQ(rk.step(Harmonic{}, 20.0), Dop853<V2>::Status::kAccepted);
    t_end = rk.t1();
    return std::abs(rk.x1()(0) - std::cos(20.0));
  };
  double t_end = 0.0;
  const double e6 = run(1e-6, t_end);
  EXPECT_EQ(t_end, 20.0);
  const double e10 = run(1e-10, t_end);
  EXPECT_LT(e10, 1e-8);
  EXPECT_LT(e10, e6 * 1e-2);
}

TEST(Dop853, RestepLandsOnTheTargetTime) {
  Dop853<V4> rk;
  StepControl c;
  c.rtol = 1e-11;
  c.atol = 1e-13;
  rk.start(Kepler{}, c, 0.0, kepler_exact(0.0));
  rk.step(Kepler{}, 10.0);
  const double tt = rk.t0() + 0.37 * (rk.t1() - rk.t0());
  rk.restep_to(Kepler{}, tt);
  EXPECT_EQ(rk.t1(), tt);
  EXPECT_LT((rk.x1() - kepler_exact(tt)).norm(), 1e-10);
}

// y' = mu y, one step of length h: |y1 / y0| is |R(h mu)|
struct Linear {
  std::complex<double> mu;
  void operator()(double, const V2& x, V2& dx) const {
    dx << mu.real() * x(0) - mu.imag() * x(1), mu.imag() * x(0) + mu.real() * x(1);
  }
};
double growth(std::complex<double> mu, double h) {
  Dop853<V2> rk;
  rk.start(Linear{mu}, fixed_steps(h), 0.0, V2(1.0, 0.0), h);
  rk.step(Linear{mu}, h);
  return rk.x1().norm();
}

TEST(Dop853, StableStepIsWhereAnActualStepStopsGrowing) {
  // the bound from the stability polynomial against the actual stages: a step just inside it does
  // not grow, one just past it does
  for (const std::complex<double> mu :
       {std::complex<double>(-1.0, 0.0), std::complex<double>(-0.05, 1.0),
        std::complex<double>(-0.5, 0.8)}) {
    const double h = dop853_stable_step(mu);
    ASSERT_TRUE(std::isfinite(h));
    EXPECT_LE(growth(mu, 0.999 * h), 1.0 + 1e-9) << mu;
    EXPECT_GT(growth(mu, 1.01 * h), 1.0) << mu;
  }
  // on the negative real axis (6.39) well past DOPRI5's 3.31
  EXPECT_GT(dop853_stable_step({-1.0, 0.0}), 1.5 * dopri5_stable_step({-1.0, 0.0}));
  EXPECT_FALSE(std::isfinite(dop853_stable_step({0.3, 1.0})));  // a growing mode bounds nothing
}

}  // namespace
}  // namespace flexrock
