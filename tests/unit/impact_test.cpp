// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/contact/impact.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/bodies.hpp"

namespace flexrock {
namespace {

using DynX = Dynamics<Eigen::Dynamic, Eigen::Dynamic>;

TEST(ImpactMap, RigidRatioMatchesClosedForm) {
  // (1 + zeta^2 - alpha1 alpha2)/(1 + zeta^2 + alpha_new^2), asymmetric body, both landings
  const Body body(BodyParameters::rigid(500, 1.3, 0.3, 0.5, 0.41));
  const DynX dyn(body);
  const double a1 = 0.3 / 1.3, a2 = 0.5 / 1.3, z2 = 0.41;
  const VectorX none(0);
  const auto on1 = resolve_impact(dyn, 1, none, 0.7, none);
  EXPECT_NEAR(on1.theta_dot / 0.7, (1 + z2 - a1 * a2) / (1 + z2 + a1 * a1), 1e-14);
  const auto on2 = resolve_impact(dyn, 2, none, -0.7, none);
  EXPECT_NEAR(on2.theta_dot / -0.7, (1 + z2 - a1 * a2) / (1 + z2 + a2 * a2), 1e-14);
}

TEST(ImpactMap, UniformBlockGivesHousnersRestitution) {
  for (double b : {0.05, 0.2, 0.5}) {
    const Body body(BodyParameters::rectangular_block(100, b, 1.0));
    const DynX dyn(body);
    const VectorX none(0);
    const auto out = resolve_impact(dyn, 1, none, 1.0, none);
    const double s = std::sin(std::atan(b));
    EXPECT_NEAR(out.theta_dot, 1 - 1.5 * s * s, 1e-14) << "b/h = " << b;
  }
}

TEST(ImpactMap, SquatRigidBlockStopsOnBothEdges) {
  // b/h > sqrt(2): the single-edge map would reverse theta_dot
  const Body body(BodyParameters::rectangular_block(100, 1.6, 1.0));
  const DynX dyn(body);
  const VectorX none(0);
  double raw;
  VectorX raw_q;
  single_edge_impact(dyn, 1, none, 1.0, none, raw, raw_q);
  EXPECT_LT(raw, 0.0);
  const auto out = resolve_impact(dyn, 1, none, 1.0, none);
  EXPECT_TRUE(out.both_edges);
  EXPECT_EQ(out.theta_dot, 0.0);
  // all the relative kinetic energy is lost
  EXPECT_NEAR(out.energy_loss, dyn.kinetic_energy(dyn.alpha(2), none, 1.0, none), 1e-12);
}

// velocity of each point mass relative to the base at theta = 0, rocking on `edge`
std::vector<Eigen::Vector2d> point_velocities(const test::LumpedBody& lb, int edge,
                                              const VectorX& q, double thd, const VectorX& qd) {
  std::vector<Eigen::Vector2d> v;
  const double px = edge == 1 ? lb.x1 : lb.x2;
  for (const auto& p : lb.pts) {
    double x = p.x, y = p.y, vx = 0, vy = 0;
    for (int i = 0; i < q.size(); ++i) {
      x += p.phix[i] * q(i);
      y += p.phiy[i] * q(i);
      vx += p.phix[i] * qd(i);
      vy += p.phiy[i] * qd(i);
    }
    v.emplace_back(vx - thd * y, vy + thd * (x - px));
  }
  return v;
}

class FlexibleImpact : public ::testing::TestWithParam<int> {};

TEST_P(FlexibleImpact, ConservesModalAndAngularMomentumMassByMass) {
  const int n = GetParam();
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto lb = test::random_lumped(n, seed);
    const Body body(lb.params());
    const DynX dyn(body);
    const VectorX q = 0.02 * VectorX::Random(n);
    const VectorX qd = 0.5 * VectorX::Random(n);
    for (int landing : {1, 2}) {
      const double thd = landing == 1 ? 0.8 : -0.8;
      double thp;
      VectorX qdp;
      single_edge_impact(dyn, landing, q, thd, qd, thp, qdp);
      const auto before = point_velocities(lb, landing == 1 ? 2 : 1, q, thd, qd);
      const auto after = point_velocities(lb, landing, q, thp, qdp);
      const double lx = landing == 1 ? lb.x1 : lb.x2;
      double h_before = 0, h_after = 0, carnot = 0;
      VectorX p_before = VectorX::Zero(n), p_after = VectorX::Zero(n);
      for (std::size_t k = 0; k < lb.pts.size(); ++k) {
        const auto& p = lb.pts[k];
        double x = p.x, y = p.y;
        for (int i = 0; i < n; ++i) {
          x += p.phix[i] * q(i);
          y += p.phiy[i] * q(i);
        }
        // moment of momentum about the landing point
        h_before += p.m * ((x - lx) * before[k](1) - y * before[k](0));
        h_after += p.m * ((x - lx) * after[k](1) - y * after[k](0));
        for (int i = 0; i < n; ++i) {
          p_before(i) += p.m * (p.phix[i] * before[k](0) + p.phiy[i] * before[k](1));
          p_after(i) += p.m * (p.phix[i] * after[k](0) + p.phiy[i] * after[k](1));
        }
        carnot += 0.5 * p.m * (after[k] - before[k]).squaredNorm();
      }
      const double scale = std::abs(h_before) + 1.0;
      EXPECT_NEAR(h_after, h_before, 1e-12 * scale) << "n=" << n << " seed=" << seed;
      EXPECT_LT((p_after - p_before).norm(), 1e-12 * (p_before.norm() + 1.0));
      // Carnot: a plastic impact loses the kinetic energy of the velocity jump
      const auto out = resolve_impact(dyn, landing, q, thd, qd);
      if (!out.both_edges) {
        EXPECT_NEAR(out.energy_loss, carnot, 1e-10 * (carnot + 1.0));
      }
      EXPECT_GE(out.energy_loss, 0.0);
    }
  }
}

TEST_P(FlexibleImpact, RestitutionFactorKeepsModalMomenta) {
  const int n = GetParam();
  const auto lb = test::random_lumped(n, 3);
  const Body body(lb.params());
  const DynX dyn(body);
  const VectorX q = 0.01 * VectorX::Ones(n), qd = 0.3 * VectorX::Ones(n);
  const auto plain = resolve_impact(dyn, 1, q, 0.6, qd, 1.0);
  const auto scaled = resolve_impact(dyn, 1, q, 0.6, qd, 1.2);
  ASSERT_FALSE(plain.both_edges);
  EXPECT_NEAR(scaled.theta_dot, 1.2 * plain.theta_dot, 1e-14);
  // p = mu q_dot + b theta_dot (post pivot) is the same whatever the factor
  const VectorX p1 = dyn.mu() * plain.q_dot + dyn.coupling(dyn.alpha(1), q) * plain.theta_dot;
  const VectorX p2 = dyn.mu() * scaled.q_dot + dyn.coupling(dyn.alpha(1), q) * scaled.theta_dot;
  EXPECT_LT((p1 - p2).norm(), 1e-13);
}

INSTANTIATE_TEST_SUITE_P(Modes, FlexibleImpact, ::testing::Values(1, 2, 3, 5));

}  // namespace
}  // namespace flexrock
