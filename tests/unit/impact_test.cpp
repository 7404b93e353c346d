// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/contact/impact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

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

// position of a point mass in the deformed body at theta = 0 (the modal displacement added)
Eigen::Vector2d deformed_position(const test::PointMass& p, const VectorX& q) {
  Eigen::Vector2d r(p.x, p.y);
  for (int i = 0; i < q.size(); ++i) r += Eigen::Vector2d(p.phix[i], p.phiy[i]) * q(i);
  return r;
}

// velocity of each point mass relative to the base at theta = 0, rocking on `edge`
std::vector<Eigen::Vector2d> point_velocities(const test::LumpedBody& lb, int edge,
                                              const VectorX& q, double thd, const VectorX& qd) {
  std::vector<Eigen::Vector2d> v;
  const double px = edge == 1 ? lb.x1 : lb.x2;
  for (const auto& p : lb.pts) {
    const Eigen::Vector2d r = deformed_position(p, q);
    double vx = 0, vy = 0;
    for (int i = 0; i < q.size(); ++i) {
      vx += p.phix[i] * qd(i);
      vy += p.phiy[i] * qd(i);
    }
    v.emplace_back(vx - thd * r(1), vy + thd * (r(0) - px));
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
        const Eigen::Vector2d r = deformed_position(p, q);
        const double x = r(0), y = r(1);
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
  const auto plain = resolve_impact(dyn, 1, q, 0.6, qd, {.restitution_factor = 1.0});
  const auto scaled = resolve_impact(dyn, 1, q, 0.6, qd, {.restitution_factor = 1.2});
  ASSERT_FALSE(plain.both_edges);
  EXPECT_NEAR(scaled.theta_dot, 1.2 * plain.theta_dot, 1e-14);
  // p = mu q_dot + b theta_dot (post pivot) is the same whatever the factor
  const VectorX p1 = dyn.mu() * plain.q_dot + dyn.coupling(dyn.alpha(1), q) * plain.theta_dot;
  const VectorX p2 = dyn.mu() * scaled.q_dot + dyn.coupling(dyn.alpha(1), q) * scaled.theta_dot;
  EXPECT_LT((p1 - p2).norm(), 1e-13);
}

// the impact laws (docs/theory.md, "Impact laws"), checked mass by mass on random lumped bodies
TEST_P(FlexibleImpact, RigidBodyLawMassByMass) {
  const int n = GetParam();
  int rigid = 0, fallbacks = 0;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const auto lb = test::random_lumped(n, seed);
    const Body body(lb.params());
    const DynX dyn(body);
    for (const double rate : {0.05, 0.5, 5.0, 50.0}) {
      const VectorX q = 0.02 * VectorX::Random(n);
      const VectorX qd = rate * VectorX::Random(n);
      for (int landing : {1, 2}) {
        const double thd = landing == 1 ? 0.8 : -0.8;
        const auto out = resolve_impact(dyn, landing, q, thd, qd, {.law = ImpactLaw::kRigidBody});
        const auto paper = resolve_impact(dyn, landing, q, thd, qd);
        const auto before = point_velocities(lb, landing == 1 ? 2 : 1, q, thd, qd);
        const auto after = point_velocities(lb, landing, q, out.theta_dot, out.q_dot);
        const double lx = landing == 1 ? lb.x1 : lb.x2;
        double h_before = 0, h_after = 0, t_before = 0, t_after = 0;
        Eigen::Vector2d momentum = Eigen::Vector2d::Zero();
        for (std::size_t k = 0; k < lb.pts.size(); ++k) {
          const auto& p = lb.pts[k];
          const Eigen::Vector2d r = deformed_position(p, q);
          const double x = r(0), y = r(1);
          h_before += p.m * ((x - lx) * before[k](1) - y * before[k](0));
          h_after += p.m * ((x - lx) * after[k](1) - y * after[k](0));
          t_before += 0.5 * p.m * before[k].squaredNorm();
          t_after += 0.5 * p.m * after[k].squaredNorm();
          momentum += p.m * (after[k] - before[k]);
        }
        // the impulse is the change of the momenta summed mass by mass; the loss is that of the
        // kinetic energies summed mass by mass, and never a gain
        EXPECT_LT((out.impulse - momentum).norm(), 1e-10 * (momentum.norm() + 1.0));
        EXPECT_NEAR(out.energy_loss, t_before - t_after, 1e-9 * (t_before + 1.0));
        EXPECT_GE(out.energy_loss, -1e-12 * t_before);
        if (out.law_fallback) {
          ++fallbacks;
          EXPECT_EQ(out.theta_dot, paper.theta_dot);
          EXPECT_EQ(out.q_dot, paper.q_dot);
          continue;
        }
        // the modal velocities are continuous
        EXPECT_EQ(out.q_dot, qd);
        if (out.both_edges) continue;
        ++rigid;
        // the moment of momentum about the landing point, summed mass by mass, is conserved
        EXPECT_NEAR(h_after, h_before, 1e-11 * (std::abs(h_before) + 1.0)) << "seed " << seed;
      }
    }
  }
  EXPECT_GE(rigid, 20);
  // fast modes against theta_dot make the rigid law add energy: the paper's law takes them
  if (n > 0) {
    EXPECT_GE(fallbacks, 1);
  }
}

TEST(ImpactLaws, RigidBodyLawConvergesToHousnerLikeOneOverStiffness) {
  // a body at rest in its static deformation under gravity, landing: the rigid_body ratio differs
  // from Housner's by O(q_static) = O(1/stiffness), the paper's law by O(1)
  std::vector<double> err;
  double paper_err = 0.0;
  for (const double k : {2e5, 2e6, 2e7, 2e8}) {
    const Body body(test::random_lumped_body(2, 7, k));
    const DynX dyn(body);
    const double z2 = body.params().zeta2, a1 = body.alpha1(), a2 = body.alpha2();
    const double housner = (1.0 + z2 - a1 * a2) / (1.0 + z2 + a1 * a1);
    const VectorX& q = body.static_deformation();
    const VectorX qd = VectorX::Zero(2);
    const auto rigid = resolve_impact(dyn, 1, q, 0.5, qd, {.law = ImpactLaw::kRigidBody});
    const auto paper = resolve_impact(dyn, 1, q, 0.5, qd);
    err.push_back(std::abs(rigid.theta_dot / 0.5 - housner));
    paper_err = std::abs(paper.theta_dot / 0.5 - housner);
  }
  // first order: each tenfold stiffening divides the error by ten
  for (std::size_t i = 1; i < err.size(); ++i) EXPECT_NEAR(err[i - 1] / err[i], 10.0, 0.5);
  EXPECT_LT(err.back(), 1e-6);
  EXPECT_GT(paper_err, 0.05);
}

TEST(ImpactLaws, RegimeFromTheContactDurationAgainstTheModalPeriods) {
  const double two_pi = 2.0 * std::numbers::pi;
  const VectorX omega = two_pi * (VectorX(2) << 1.0, 50.0).finished();  // 1 s and 20 ms periods
  // 0.1 ms: 0.005 of the shortest period, every mode much slower than the contact
  const auto short_contact = impact_regime(omega, 1e-4);
  EXPECT_NEAR(short_contact.duration_over_fastest, 0.005, 1e-15);
  EXPECT_EQ(short_contact.closest, ImpactLaw::kPaper);
  EXPECT_FALSE(short_contact.between);
  // 20 s: 20 x the longest period, every mode much faster
  const auto long_contact = impact_regime(omega, 20.0);
  EXPECT_NEAR(long_contact.duration_over_slowest, 20.0, 1e-12);
  EXPECT_EQ(long_contact.closest, ImpactLaw::kRigidBody);
  // 0.1 s: 5 x the 20 ms period and 0.1 x the 1 s one: in between; the slowest mode, impulsive,
  // names the law
  const auto mixed = impact_regime(omega, 0.1);
  EXPECT_TRUE(mixed.between);
  EXPECT_EQ(mixed.closest, ImpactLaw::kPaper);
  EXPECT_EQ(impact_regime(VectorX(0), 0.002).closest, ImpactLaw::kPaper);
}

TEST(ImpactLaws, RestitutionThatWouldAddEnergyTakesTheElasticRatio) {
  // an asymmetric rigid block landing on its wide edge: S_post = 1 + zeta^2 + alpha1^2 is larger
  // than S_pre = 1 + zeta^2 + alpha2^2, so r = 0.99 would add energy; the elastic ratio
  // sqrt(S_pre/S_post) is taken and said
  const Body body(BodyParameters::rigid(300, 1.0, 0.5, 0.2, 0.3));
  const DynX dyn(body);
  const VectorX none(0);
  const ImpactRule rule{.law = ImpactLaw::kRestitution, .ratio_edge1 = 0.99, .ratio_edge2 = 0.99};
  const auto wide = resolve_impact(dyn, 1, none, 0.7, none, rule);
  EXPECT_TRUE(wide.law_fallback);
  EXPECT_NEAR(wide.theta_dot, std::sqrt((1.3 + 0.04) / (1.3 + 0.25)) * 0.7, 1e-15);
  EXPECT_EQ(wide.energy_loss, 0.0);
  // the same ratio landing on the narrow edge loses energy: taken as given
  const auto narrow = resolve_impact(dyn, 2, none, -0.7, none, rule);
  EXPECT_FALSE(narrow.law_fallback);
  EXPECT_EQ(narrow.theta_dot, 0.99 * -0.7);
  EXPECT_GT(narrow.energy_loss, 0.0);
}

TEST(ImpactLaws, RigidBodyEqualsPaperWhenTheModesCarryNoMomentum) {
  // psi = beta = gamma = 0: the modes carry no linear momentum and no moment of momentum, so the
  // paper's law leaves the modal velocities unchanged and both laws coincide
  BodyParameters p = BodyParameters::rigid(800, 1.2, 0.4, 0.5, 0.35);
  const int n = 3;
  MatrixX a = MatrixX::Random(n, n);
  p.mu = 0.1 * (a * a.transpose() + n * MatrixX::Identity(n, n));
  p.kappa = 50.0 * MatrixX::Identity(n, n);
  p.gamma = MatrixX::Zero(n, n);
  p.psi_x = p.psi_y = p.beta = VectorX::Zero(n);
  p.delta = 0.05 * VectorX::Random(n);
  const Body body(p);
  const DynX dyn(body);
  const VectorX q = 0.03 * VectorX::Random(n), qd = 2.0 * VectorX::Random(n);
  for (int landing : {1, 2}) {
    const double thd = landing == 1 ? 0.6 : -0.6;
    const auto paper = resolve_impact(dyn, landing, q, thd, qd);
    const auto rigid = resolve_impact(dyn, landing, q, thd, qd, {.law = ImpactLaw::kRigidBody});
    EXPECT_FALSE(rigid.law_fallback);
    EXPECT_NEAR(rigid.theta_dot, paper.theta_dot, 1e-14);
    EXPECT_LT((rigid.q_dot - paper.q_dot).norm(), 1e-14);
    EXPECT_NEAR(rigid.energy_loss, paper.energy_loss, 1e-10 * paper.energy_loss);
  }
}

TEST(ImpactLaws, AbsoluteRestitutionGivesTheRatioPerEdge) {
  const auto lb = test::random_lumped(2, 4);
  const Body body(lb.params());
  const DynX dyn(body);
  const VectorX q = 0.01 * VectorX::Ones(2), qd = 0.2 * VectorX::Ones(2);
  // ratios below the elastic one of this asymmetric body (sqrt(S_pre/S_post) = 0.586 on edge 1)
  const ImpactRule rule{.law = ImpactLaw::kRestitution, .ratio_edge1 = 0.53, .ratio_edge2 = 0.61};
  const auto on1 = resolve_impact(dyn, 1, q, 0.7, qd, rule);
  const auto on2 = resolve_impact(dyn, 2, q, -0.7, qd, rule);
  EXPECT_EQ(on1.theta_dot, 0.53 * 0.7);
  EXPECT_FALSE(on1.law_fallback);
  EXPECT_EQ(on2.theta_dot, 0.61 * -0.7);
  // the modal momenta are conserved: mu q_dot+ + b_post theta_dot+ = mu q_dot- + b_pre theta_dot-
  for (const auto& [out, e] : {std::pair{on1, 1}, std::pair{on2, 2}}) {
    const VectorX p_after = dyn.mu() * out.q_dot + dyn.coupling(dyn.alpha(e), q) * out.theta_dot;
    const VectorX p_before =
        dyn.mu() * qd + dyn.coupling(dyn.alpha(e == 1 ? 2 : 1), q) * (e == 1 ? 0.7 : -0.7);
    EXPECT_LT((p_after - p_before).norm(), 1e-13);
  }
  // a ratio of zero ends rocking
  const auto stop =
      resolve_impact(dyn, 1, q, 0.7, qd, {.law = ImpactLaw::kRestitution, .ratio_edge1 = 0.0});
  EXPECT_TRUE(stop.both_edges);
}

INSTANTIATE_TEST_SUITE_P(Modes, FlexibleImpact, ::testing::Values(1, 2, 3, 5));

}  // namespace
}  // namespace flexrock
