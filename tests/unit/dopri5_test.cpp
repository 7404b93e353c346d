// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/integrate/dopri5.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>

namespace flexrock {
namespace {

using V2 = Eigen::Vector2d;

// x'' = -x: x = cos t
struct Harmonic {
  void operator()(double, const V2& x, V2& dx) const { dx << x(1), -x(0); }
};

TEST(Dopri5, HarmonicOscillatorToTolerance) {
  Dopri5<V2> rk;
  StepControl c;
  c.rtol = 1e-10;
  c.atol = 1e-12;
  rk.start(Harmonic{}, c, 0.0, V2(1.0, 0.0));
  while (rk.t1() < 10.0) ASSERT_EQ(rk.step(Harmonic{}, 10.0), Dopri5<V2>::Status::kAccepted);
  EXPECT_EQ(rk.t1(), 10.0);  // lands exactly on the stop time
  EXPECT_NEAR(rk.x1()(0), std::cos(10.0), 1e-8);
  EXPECT_NEAR(rk.x1()(1), -std::sin(10.0), 1e-8);
}

// x'' = -1 from x = 1e-15, far below atol: Hairer's starting step (0.01 |x| / |x'|) would be
// ~1e-18, below the collapse limit, and the run stopped before its first try
struct Falling {
  void operator()(double, const V2& x, V2& dx) const { dx << x(1), -1.0; }
};

TEST(Dopri5, ATinyStateNextToItsDerivativeDoesNotCollapse) {
  Dopri5<V2> rk;
  StepControl c;
  c.rtol = 1e-9;
  c.atol = 1e-11;
  c.max_step = 0.01;
  rk.start(Falling{}, c, 0.0, V2(1e-15, 0.0));
  EXPECT_GE(rk.suggested_step(), c.min_step);
  while (rk.t1() < 1.0) ASSERT_EQ(rk.step(Falling{}, 1.0), Dopri5<V2>::Status::kAccepted);
  EXPECT_NEAR(rk.x1()(0), 1e-15 - 0.5, 1e-12);  // x = x0 - t^2/2, exact for the 5th order
  EXPECT_NEAR(rk.x1()(1), -1.0, 1e-12);
}

TEST(Dopri5, DenseOutputIsFourthOrder) {
  // the interpolant's error at mid-step falls ~32x when the step halves
  double err[2];
  for (int r = 0; r < 2; ++r) {
    Dopri5<V2> rk;
    StepControl c;
    c.rtol = 1.0;  // accept every step: the step is set by max_step
    c.atol = 1.0;
    c.max_step = 0.2 / (1 << r);
    rk.start(Harmonic{}, c, 0.0, V2(1.0, 0.0), c.max_step);
    rk.step(Harmonic{}, 10.0);
    // local error of the interpolant, measured against the exact flow from the step's start
    const double t0 = rk.t0(), t1 = rk.t1(), tm = 0.5 * (t0 + t1);
    V2 xm;
    rk.dense(tm, xm);
    const double exact = std::cos(tm);
    err[r] = std::abs(xm(0) - exact);
  }
  EXPECT_GT(err[0] / err[1], 20.0);
}

TEST(Dopri5, RestepLandsOnTheTargetTime) {
  Dopri5<V2> rk;
  StepControl c;
  c.rtol = 1e-11;
  c.atol = 1e-13;
  rk.start(Harmonic{}, c, 0.0, V2(1.0, 0.0));
  rk.step(Harmonic{}, 10.0);
  const double tt = rk.t0() + 0.37 * (rk.t1() - rk.t0());
  rk.restep_to(Harmonic{}, tt);
  EXPECT_EQ(rk.t1(), tt);
  EXPECT_NEAR(rk.x1()(0), std::cos(tt), 1e-11);
  EXPECT_NEAR(rk.dxdt1()(1), -std::cos(tt), 1e-11);
}

TEST(Dopri5, ErrorFallsWithTolerance) {
  auto run = [](double tol) {
    Dopri5<V2> rk;
    StepControl c;
    c.rtol = tol;
    c.atol = tol;
    rk.start(Harmonic{}, c, 0.0, V2(1.0, 0.0));
    while (rk.t1() < 20.0) rk.step(Harmonic{}, 20.0);
    return std::abs(rk.x1()(0) - std::cos(20.0));
  };
  EXPECT_LT(run(1e-10), run(1e-6) * 1e-2);
}

}  // namespace
}  // namespace flexrock
