// SPDX-License-Identifier: BSD-3-Clause
// Similarity of rigid rocking (Dimitrakopoulos & DeJong 2012): theta'' = p^2 F(theta, a/g) with
// a(t) = a_p f(omega_p t), so in tau = p t the equation depends on alpha, omega_p/p and
// a_p/(g tan alpha) only. Blocks of different size under the same dimensionless pulse must give
// the same theta/alpha against p t: exactly in the equations, and in the engine up to its
// integration error, which shrinks as the tolerance is tightened.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

constexpr double g = kStandardGravity;

struct Response {
  std::vector<double> theta_over_alpha;  // at tau = 0, 0.05, 0.10, ...
  std::vector<double> impact_tau;        // p t of the impacts
  Status status;
};

Response respond(double alpha, double R, double Omega, double A, double rtol) {
  const Body body(
      BodyParameters::rectangular_block(700.0, R * std::sin(alpha), R * std::cos(alpha)));
  const double p = body.rocking_frequency();
  SimulationOptions o;
  o.rtol = rtol;
  o.atol = 1e-2 * rtol;
  o.max_step = 0.05 / p;
  o.t_end = 40.0 / p;
  o.output_dt = 0.05 / p;
  const auto r =
      simulate(body, cycloidal_pulse_a(A * g * std::tan(alpha), Omega * p, o.t_end), {}, o);
  Response out;
  out.status = r.status;
  for (double th : r.history.theta) out.theta_over_alpha.push_back(th / alpha);
  for (const auto& e : r.events)
    if (e.kind == EventKind::kImpact) out.impact_tau.push_back(p * e.time);
  return out;
}

double max_difference(const Response& a, const Response& b) {
  EXPECT_EQ(a.theta_over_alpha.size(), b.theta_over_alpha.size());
  double d = 0;
  for (std::size_t i = 0; i < std::min(a.theta_over_alpha.size(), b.theta_over_alpha.size()); ++i)
    d = std::max(d, std::abs(a.theta_over_alpha[i] - b.theta_over_alpha[i]));
  return d;
}

TEST(Similarity, BlocksOfDifferentSizeShareTheDimensionlessResponse) {
  // rocking with many impacts, no overturning: the most sensitive case for drift
  const double alpha = 0.15, Omega = 4.0, A = 1.5;
  const Response ref = respond(alpha, 1.0, Omega, A, 1e-12);
  ASSERT_EQ(ref.status, Status::kCompleted);
  ASSERT_GT(ref.impact_tau.size(), 10u);
  for (double R : {0.3, 3.7, 20.0}) {
    const Response r = respond(alpha, R, Omega, A, 1e-12);
    EXPECT_EQ(r.status, ref.status);
    ASSERT_EQ(r.impact_tau.size(), ref.impact_tau.size()) << "R = " << R;
    for (std::size_t k = 0; k < ref.impact_tau.size(); ++k)
      EXPECT_NEAR(r.impact_tau[k], ref.impact_tau[k], 1e-7) << "impact " << k << ", R = " << R;
    // integration error at rtol 1e-12 over ~30 impacts: well below 1e-7 of alpha
    EXPECT_LT(max_difference(r, ref), 1e-7) << "R = " << R;
  }
}

TEST(Similarity, RemainingDifferenceIsIntegrationErrorThatShrinksWithTolerance) {
  const double alpha = 0.15, Omega = 4.0, A = 1.5;
  const double loose =
      max_difference(respond(alpha, 0.4, Omega, A, 1e-7), respond(alpha, 6.0, Omega, A, 1e-7));
  const double tight =
      max_difference(respond(alpha, 0.4, Omega, A, 1e-11), respond(alpha, 6.0, Omega, A, 1e-11));
  EXPECT_LT(tight, 1e-7);
  // four decades tighter: at least two decades closer
  EXPECT_LT(tight, 1e-2 * loose + 1e-12);
}

TEST(Similarity, OverturningDependsOnTheDimensionlessGroupsOnly) {
  // one block overturns and one does not; every size follows its dimensionless twin
  const double alpha = 0.15, Omega = 2.0;
  for (double A : {1.1, 3.0}) {
    const Status ref = respond(alpha, 1.0, Omega, A, 1e-10).status;
    EXPECT_EQ(ref, A < 2 ? Status::kCompleted : Status::kOverturned);
    for (double R : {0.2, 5.0, 50.0}) EXPECT_EQ(respond(alpha, R, Omega, A, 1e-10).status, ref);
  }
}

}  // namespace
}  // namespace flexrock
