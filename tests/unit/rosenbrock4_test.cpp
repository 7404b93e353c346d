// SPDX-License-Identifier: BSD-3-Clause
// The Rosenbrock method (include/flexrock/integrate/rosenbrock4.hpp): fourth order on a problem
// that depends on time (Odeint's d4 = +0.0362 makes it first order: this test fails with it), its
// dense output and re-step, and steps that a stiff problem does not hold to its fast rate.
#include "flexrock/integrate/rosenbrock4.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "flexrock/integrate/dopri5.hpp"

namespace flexrock {
namespace {

using V = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 4, 1>;

// y' = -lambda (y - cos t): y = (lambda^2 cos t + lambda sin t) / (lambda^2 + 1) + C e^(-lambda t)
double exact(double lambda, double y0, double t) {
  const double l2 = lambda * lambda;
  const double c = y0 - l2 / (l2 + 1.0);
  return (l2 * std::cos(t) + lambda * std::sin(t)) / (l2 + 1.0) + c * std::exp(-lambda * t);
}

auto forced(double lambda) {
  return [lambda](double t, const V& x, V& dx) {
    dx.resize(1);
    dx(0) = -lambda * (x(0) - std::cos(t));
  };
}

TEST(Rosenbrock4, FourthOrderOnATimeDependentProblem) {
  // one step from t = 0.5 of length h, h/2, h/4: the local error falls as h^5
  const auto sys = forced(1.0);
  std::vector<double> err;
  for (const double h : {0.08, 0.04, 0.02}) {
    Rosenbrock4<V> st;
    StepControl c;
    V x(1);
    x << exact(1.0, 1.0, 0.5);
    st.start(sys, c, 0.5, x, h);
    st.restep_to(sys, 0.5 + h);  // a step without error control
    err.push_back(std::abs(st.x1()(0) - exact(1.0, 1.0, 0.5 + h)));
  }
  for (std::size_t i = 0; i + 1 < err.size(); ++i) {
    const double order = std::log2(err[i] / err[i + 1]) - 1.0;  // global order = local - 1
    EXPECT_GT(order, 3.7) << "step " << i;
  }
}

TEST(Rosenbrock4, StiffProblemStepsFollowTheSolutionNotTheFastRate) {
  // lambda = 1e4 over [0, 10] at rtol 1e-6: the solution is cos-like after 1e-3 s; DOPRI5 is
  // held to h < 3.3/lambda (about 30000 steps), the Rosenbrock method is not
  const double lambda = 1e4;
  const auto sys = forced(lambda);
  StepControl c;
  c.rtol = 1e-6;
  c.atol = 1e-9;
  c.max_step = 0.05;  // the dense output is third order: checked on steps of this size
  V x(1);
  x << 1.0;
  Rosenbrock4<V> ros;
  ros.start(sys, c, 0.0, x);
  int steps = 0;
  while (ros.t1() < 10.0) {
    ASSERT_EQ(ros.step(sys, 10.0), Rosenbrock4<V>::Status::kAccepted);
    ++steps;
    // the dense output at mid-step against the exact solution
    V mid;
    const double tm = 0.5 * (ros.t0() + ros.t1());
    ros.dense(tm, mid);
    EXPECT_NEAR(mid(0), exact(lambda, 1.0, tm), 1e-5);
  }
  EXPECT_NEAR(ros.x1()(0), exact(lambda, 1.0, 10.0), 1e-6);
  Dopri5<V> dop;
  dop.start(sys, c, 0.0, x);
  int explicit_steps = 0;
  while (dop.t1() < 10.0) {
    ASSERT_EQ(dop.step(sys, 10.0), Dopri5<V>::Status::kAccepted);
    ++explicit_steps;
  }
  EXPECT_LT(steps * 50, explicit_steps) << steps << " vs " << explicit_steps;
}

}  // namespace
}  // namespace flexrock
