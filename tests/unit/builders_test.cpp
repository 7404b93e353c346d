// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/model/builders.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "flexrock/core/error.hpp"
#include "support/bodies.hpp"

namespace flexrock {
namespace {

using ::testing::HasSubstr;

constexpr double kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// expects the builder call to throw InputError whose message contains every fragment
template <class... S>
void expect_rejected(const std::function<void()>& build, S... fragments) {
  try {
    build();
    FAIL() << "accepted invalid input";
  } catch (const InputError& e) {
    for (const char* f : {fragments...}) EXPECT_THAT(e.what(), HasSubstr(f));
  }
}

void expect_near_rel(double got, double want, double rel, const char* what = "") {
  EXPECT_NEAR(got, want, rel * std::max(1.0, std::abs(want))) << what;
}

void expect_same(const BodyParameters& a, const BodyParameters& b, double tol) {
  EXPECT_NEAR(a.mass, b.mass, tol * b.mass);
  EXPECT_NEAR(a.height, b.height, tol * b.height);
  EXPECT_NEAR(a.b1, b.b1, tol * b.height);
  EXPECT_NEAR(a.b2, b.b2, tol * b.height);
  EXPECT_NEAR(a.zeta2, b.zeta2, tol * b.zeta2);
  EXPECT_EQ(a.gravity, b.gravity);
  ASSERT_EQ(a.mu.rows(), b.mu.rows());
  EXPECT_LE((a.mu - b.mu).cwiseAbs().maxCoeff(), tol * b.mu.cwiseAbs().maxCoeff());
  EXPECT_LE((a.kappa - b.kappa).cwiseAbs().maxCoeff(), tol * b.kappa.cwiseAbs().maxCoeff());
  EXPECT_LE((a.gamma - b.gamma).cwiseAbs().maxCoeff(), tol);
  EXPECT_LE((a.psi_x - b.psi_x).cwiseAbs().maxCoeff(), tol);
  EXPECT_LE((a.psi_y - b.psi_y).cwiseAbs().maxCoeff(), tol);
  EXPECT_LE((a.delta - b.delta).cwiseAbs().maxCoeff(), tol);
  EXPECT_LE((a.beta - b.beta).cwiseAbs().maxCoeff(), tol);
}

// ---------------------------------------------------------------------------------------------
// rigid bodies

TEST(RigidBlockBuilder, RadiusOfGyrationOfUniformRectangle) {
  // 0.6 m x 2 m, 300 kg: h = 1, I = M (0.36 + 4)/12, zeta2 = 4.36/12
  const auto p = rigid_block(0.6, 2.0, 300.0);
  EXPECT_DOUBLE_EQ(p.mass, 300.0);
  EXPECT_DOUBLE_EQ(p.height, 1.0);
  EXPECT_DOUBLE_EQ(p.b1, 0.3);
  EXPECT_DOUBLE_EQ(p.b2, 0.3);
  EXPECT_NEAR(p.zeta2, 4.36 / 12.0, 1e-15);
  EXPECT_EQ(p.mu.rows(), 0);
  // Housner: zeta2 = (1 + alpha^2)/3 with alpha = b/h
  EXPECT_NEAR(p.zeta2, BodyParameters::rectangular_block(300.0, 0.3, 1.0).zeta2, 1e-15);
  const Body body(p);
  EXPECT_EQ(body.modes(), 0);
  EXPECT_NEAR(body.tipping_angle(1), std::atan(0.3), 1e-9);
}

TEST(RigidBlockBuilder, RejectsNonPositiveSizes) {
  expect_rejected([] { rigid_block(0.0, 2.0, 1.0); }, "rigid_block", "width", "> 0", "got 0");
  expect_rejected([] { rigid_block(1.0, -2.0, 1.0); }, "height", "got -2");
  expect_rejected([] { rigid_block(1.0, 2.0, kNaN); }, "mass", "nan");
}

TEST(RigidBodyBuilder, RadiusOfGyrationFromInertia) {
  // M = 50, I = 12, h = 0.8: zeta2 = 12/(50 0.64) = 0.375; asymmetric base
  const auto p = rigid_body(50.0, 12.0, 0.8, 0.2, 0.35);
  EXPECT_NEAR(p.zeta2, 0.375, 1e-15);
  EXPECT_DOUBLE_EQ(p.b1, 0.2);
  EXPECT_DOUBLE_EQ(p.b2, 0.35);
  EXPECT_DOUBLE_EQ(p.height, 0.8);
  const Body body(p);
  EXPECT_NEAR(body.alpha2(), 0.35 / 0.8, 1e-15);
}

TEST(RigidBodyBuilder, RejectsBadArguments) {
  expect_rejected([] { rigid_body(50, 0, 0.8, 0.2, 0.3); }, "rigid_body", "inertia_cg", "got 0");
  expect_rejected([] { rigid_body(50, 1, 0.8, -0.2, 0.3); }, "b1", "got -0.2");
  expect_rejected([] { rigid_body(50, 1, 0.8, 0.2, INFINITY); }, "b2", "inf");
}

// ---------------------------------------------------------------------------------------------
// lumped-mass models

// two nodes, tipping points at x = -1 and 1:
//   node 1 (0, 1), m = 3, J = 0.5; node 2 (0.5, 3), m = 1
//   M = 4, c.g. (0.125, 1.5): h = 1.5, b1 = 1.125, b2 = 0.875, M h^2 = 9, M h = 6
//   rho0: node 1 (-0.125, -0.5), node 2 (0.375, 1.5)
//   mode 1 as given: node 1 (0.1, 0), node 2 (0.3, -0.4) -> max |phi| = 0.5, scale 3
//     scaled: node 1 (0.3, 0), node 2 (0.9, -1.2)
//   mode 2 as given: node 1 (0, 0.2), node 2 (-0.1, 0) -> max |phi| = 0.2, scale 7.5
//     scaled: node 1 (0, 1.5), node 2 (-0.75, 0)
LumpedModel two_node_model(int modes) {
  LumpedModel m;
  m.nodes = {{0.0, 1.0, 3.0, 0.5}, {0.5, 3.0, 1.0, 0.0}};
  m.tip1_x = -1.0;
  m.tip2_x = 1.0;
  m.phi_x.resize(2, modes);
  m.phi_y.resize(2, modes);
  m.phi_x.col(0) << 0.1, 0.3;
  m.phi_y.col(0) << 0.0, -0.4;
  if (modes > 1) {
    m.phi_x.col(1) << 0.0, -0.1;
    m.phi_y.col(1) << 0.2, 0.0;
  }
  return m;
}

TEST(LumpedModelBuilder, TwoNodesOneModeByHand) {
  auto model = two_node_model(1);
  model.frequencies = VectorX::Constant(1, 10.0);
  const auto p = from_lumped_model(model);
  const double g = kStandardGravity;
  EXPECT_DOUBLE_EQ(p.mass, 4.0);
  EXPECT_DOUBLE_EQ(p.height, 1.5);
  EXPECT_DOUBLE_EQ(p.b1, 1.125);
  EXPECT_DOUBLE_EQ(p.b2, 0.875);
  // 3 (0.125^2 + 0.5^2) + 1 (0.375^2 + 1.5^2) + 0.5 = 3.6875
  EXPECT_NEAR(p.zeta2, 3.6875 / 9.0, 1e-15);
  // 3 (0.3^2) + (0.9^2 + 1.2^2) = 2.52
  EXPECT_NEAR(p.mu(0, 0), 2.52 / 9.0, 1e-15);
  // k = omega^2 m_11 = 100 * 2.52, kappa = k/(M g h)
  EXPECT_NEAR(p.kappa(0, 0), 252.0 / (6.0 * g), 1e-13);
  EXPECT_NEAR(p.psi_x(0), (3 * 0.3 + 0.9) / 6.0, 1e-15);
  EXPECT_NEAR(p.psi_y(0), -1.2 / 6.0, 1e-15);
  // 3 (-0.125 * 0.3) + (0.375 * 0.9 + 1.5 * (-1.2)) = -1.575
  EXPECT_NEAR(p.delta(0), -1.575 / 9.0, 1e-15);
  // 3 (0 - (-0.5)(0.3)) + (0.375 (-1.2) - 1.5 (0.9)) = 0.45 - 1.8
  EXPECT_NEAR(p.beta(0), -1.35 / 9.0, 1e-15);
  EXPECT_EQ(p.gamma(0, 0), 0.0);
  const Body body(p);
  EXPECT_NEAR(body.natural_frequencies()(0), 10.0, 1e-12);
}

TEST(LumpedModelBuilder, StiffnessForShapesAsGivenMatchesFrequencies) {
  // as given m_11 = 3 (0.01) + 0.25 = 0.28, so omega = 10 means k = 28 for those shapes
  auto by_freq = two_node_model(1);
  by_freq.frequencies = VectorX::Constant(1, 10.0);
  auto by_stiff = two_node_model(1);
  by_stiff.stiffness = MatrixX::Constant(1, 1, 28.0);
  expect_same(from_lumped_model(by_stiff), from_lumped_model(by_freq), 1e-14);
}

TEST(LumpedModelBuilder, TwoNodesTwoModesByHand) {
  auto model = two_node_model(2);
  model.stiffness.resize(2, 2);
  model.stiffness << 28.0, 2.0, 2.0, 10.0;
  model.damping.kind = DampingKind::kModal;
  model.damping.modal_ratios = VectorX::Constant(2, 0.03);
  model.gravity = 9.81;
  const auto p = from_lumped_model(model);
  const double mgh = 4.0 * 9.81 * 1.5;
  // mu_12: 3 (0.3 * 0 + 0 * 1.5) + (0.9 (-0.75) + (-1.2) 0) = -0.675; mu_22: 3 (2.25) + 0.5625
  EXPECT_NEAR(p.mu(0, 1), -0.675 / 9.0, 1e-15);
  EXPECT_NEAR(p.mu(1, 0), -0.675 / 9.0, 1e-15);
  EXPECT_NEAR(p.mu(1, 1), 7.3125 / 9.0, 1e-15);
  // k' = s_i s_j k: 9 * 28, 3 * 7.5 * 2, 56.25 * 10
  EXPECT_NEAR(p.kappa(0, 0), 252.0 / mgh, 1e-13);
  EXPECT_NEAR(p.kappa(0, 1), 45.0 / mgh, 1e-13);
  EXPECT_NEAR(p.kappa(1, 1), 562.5 / mgh, 1e-13);
  // gamma_12: 3 (0.3 * 1.5 - 0 * 0) + (0.9 * 0 - (-1.2)(-0.75)) = 1.35 - 0.9
  EXPECT_NEAR(p.gamma(0, 1), 0.45 / 9.0, 1e-15);
  EXPECT_NEAR(p.gamma(1, 0), -0.45 / 9.0, 1e-15);
  EXPECT_NEAR(p.psi_x(1), -0.75 / 6.0, 1e-15);
  EXPECT_NEAR(p.psi_y(1), 4.5 / 6.0, 1e-15);
  // delta_2: 3 (-0.5 * 1.5) + 0.375 (-0.75) = -2.53125
  EXPECT_NEAR(p.delta(1), -2.53125 / 9.0, 1e-15);
  // beta_2: 3 (-0.125 * 1.5) + (0 - 1.5 (-0.75)) = -0.5625 + 1.125
  EXPECT_NEAR(p.beta(1), 0.5625 / 9.0, 1e-15);
  EXPECT_EQ(p.damping.kind, DampingKind::kModal);
  EXPECT_EQ(p.damping.modal_ratios, model.damping.modal_ratios);
  EXPECT_DOUBLE_EQ(p.gravity, 9.81);
  const Body body(p);
  EXPECT_EQ(body.modes(), 2);
}

TEST(LumpedModelBuilder, RandomBodiesMatchIndependentSums) {
  for (int n = 1; n <= 3; ++n) {
    auto lb = test::random_lumped(n, 11u + static_cast<unsigned>(n));
    // normalise the test shapes to max |phi| = h first, so the builder's scale is 1
    double M = 0, ym = 0;
    for (const auto& pt : lb.pts) {
      M += pt.m;
      ym += pt.m * pt.y;
    }
    const double h = ym / M;
    for (int i = 0; i < n; ++i) {
      double big = 0;
      for (const auto& pt : lb.pts) big = std::max(big, std::hypot(pt.phix[i], pt.phiy[i]));
      for (auto& pt : lb.pts) {
        pt.phix[i] *= h / big;
        pt.phiy[i] *= h / big;
      }
      lb.k.row(i) *= h / big;
      lb.k.col(i) *= h / big;
    }
    LumpedModel model;
    model.tip1_x = lb.x1;
    model.tip2_x = lb.x2;
    model.phi_x.resize(static_cast<Eigen::Index>(lb.pts.size()), n);
    model.phi_y.resize(static_cast<Eigen::Index>(lb.pts.size()), n);
    for (std::size_t k = 0; k < lb.pts.size(); ++k) {
      const auto& pt = lb.pts[k];
      model.nodes.push_back({pt.x, pt.y, pt.m, 0.0});
      for (int i = 0; i < n; ++i) {
        model.phi_x(static_cast<Eigen::Index>(k), i) = pt.phix[static_cast<std::size_t>(i)];
        model.phi_y(static_cast<Eigen::Index>(k), i) = pt.phiy[static_cast<std::size_t>(i)];
      }
    }
    model.stiffness = lb.k;
    const auto p = from_lumped_model(model);
    expect_same(p, lb.params(), 1e-12);
    EXPECT_NO_THROW(Body{p});
  }
}

TEST(LumpedModelBuilder, RotaryInertiaAddsToZeta2Only) {
  auto a = two_node_model(1);
  a.frequencies = VectorX::Constant(1, 10.0);
  auto b = a;
  b.nodes[1].rotary_inertia = 0.9;
  const auto pa = from_lumped_model(a), pb = from_lumped_model(b);
  EXPECT_NEAR(pb.zeta2 - pa.zeta2, 0.9 / 9.0, 1e-15);
  EXPECT_EQ(pa.mu, pb.mu);
  EXPECT_EQ(pa.beta, pb.beta);
  EXPECT_EQ(pa.delta, pb.delta);
}

TEST(LumpedModelBuilder, NoModesGivesRigidBody) {
  LumpedModel model;
  model.nodes = {{-0.5, 0.0, 2.0, 0.0}, {0.5, 0.0, 2.0, 0.0}, {0.0, 2.0, 4.0, 0.0}};
  model.tip1_x = -0.5;
  model.tip2_x = 0.5;
  const auto p = from_lumped_model(model);
  EXPECT_EQ(p.mu.rows(), 0);
  EXPECT_DOUBLE_EQ(p.height, 1.0);
  // 2 (0.25 + 1) * 2 + 4 * 1 = 9, M h^2 = 8
  EXPECT_NEAR(p.zeta2, 9.0 / 8.0, 1e-15);
  EXPECT_NO_THROW(Body{p});
}

TEST(LumpedModelBuilder, NodesAtTippingPointsMustNotMove) {
  LumpedModel model;
  model.nodes = {{-0.5, 0.0, 2.0, 0.0}, {0.5, 0.0, 2.0, 0.0}, {0.0, 2.0, 4.0, 0.0}};
  model.tip1_x = -0.5;
  model.tip2_x = 0.5;
  model.phi_x = MatrixX::Zero(3, 1);
  model.phi_y = MatrixX::Zero(3, 1);
  model.phi_x(2, 0) = 1.0;
  model.frequencies = VectorX::Constant(1, 5.0);
  EXPECT_NO_THROW(Body{from_lumped_model(model)});
  // a round-off displacement is tolerated, a real one is not
  model.phi_x(0, 0) = 1e-8;
  EXPECT_NO_THROW(from_lumped_model(model));
  model.phi_x(0, 0) = 1e-3;
  expect_rejected([&] { from_lumped_model(model); }, "lumped model", "mode 1", "node 1",
                  "tipping point", "pinned-base modes");
  model.phi_x(0, 0) = 0.0;
  model.phi_y(1, 0) = -0.01;
  expect_rejected([&] { from_lumped_model(model); }, "node 2", "x = 0.5", "pinned-base");
}

TEST(LumpedModelBuilder, RejectsBadNodes) {
  auto model = two_node_model(1);
  model.frequencies = VectorX::Constant(1, 10.0);
  auto bad = model;
  bad.nodes[1].mass = -2.0;
  expect_rejected([&] { from_lumped_model(bad); },
                  "lumped model: node 2 mass must be >= 0, got -2");
  bad = model;
  for (auto& nd : bad.nodes) nd.mass = 0.0;
  expect_rejected([&] { from_lumped_model(bad); }, "every node is massless");
  bad = model;
  bad.nodes[0].rotary_inertia = -1.0;
  expect_rejected([&] { from_lumped_model(bad); }, "node 1 rotary_inertia", ">= 0", "got -1");
  bad = model;
  bad.nodes[0].y = -0.5;
  expect_rejected([&] { from_lumped_model(bad); }, "node 1 y", "base line", "got -0.5");
  bad = model;
  bad.nodes.clear();
  expect_rejected([&] { from_lumped_model(bad); }, "nodes must not be empty");
  bad = model;
  bad.gravity = 0.0;
  expect_rejected([&] { from_lumped_model(bad); }, "gravity", "got 0");
}

TEST(LumpedModelBuilder, RejectsTippingPointsNotStraddlingTheCg) {
  auto model = two_node_model(1);
  model.frequencies = VectorX::Constant(1, 10.0);
  model.tip1_x = 0.2;  // c.g. at x = 0.125
  expect_rejected([&] { from_lumped_model(model); }, "straddle", "0.125", "tip1_x = 0.2");
}

TEST(LumpedModelBuilder, RejectsInconsistentSizes) {
  auto model = two_node_model(2);
  model.frequencies = VectorX::Constant(1, 10.0);
  expect_rejected([&] { from_lumped_model(model); }, "frequencies", "2 entries", "got 1");
  model = two_node_model(2);
  model.stiffness = MatrixX::Identity(3, 3);
  expect_rejected([&] { from_lumped_model(model); }, "stiffness", "2x2", "got 3x3");
  model = two_node_model(2);
  model.phi_y.resize(3, 2);
  model.stiffness = MatrixX::Identity(2, 2);
  expect_rejected([&] { from_lumped_model(model); }, "phi_x and phi_y", "got phi_x 2x2",
                  "phi_y 3x2");
  model = two_node_model(1);
  expect_rejected([&] { from_lumped_model(model); }, "exactly one of", "neither");
  model.frequencies = VectorX::Constant(1, 10.0);
  model.stiffness = MatrixX::Identity(1, 1);
  expect_rejected([&] { from_lumped_model(model); }, "exactly one of", "both");
  model = two_node_model(1);
  model.frequencies = VectorX::Constant(1, 10.0);
  model.damping.kind = DampingKind::kModal;
  model.damping.modal_ratios = VectorX::Constant(2, 0.05);
  expect_rejected([&] { from_lumped_model(model); }, "one ratio per mode (1)", "got 2");
}

// a massless node adds nothing: the body is the one without it
TEST(LumpedModelBuilder, MasslessNodesAddNothing) {
  auto model = two_node_model(1);
  model.frequencies = VectorX::Constant(1, 10.0);
  auto with = model;
  with.nodes.push_back({0.7, 2.0, 0.0, 0.0});
  with.phi_x.conservativeResize(3, 1);
  with.phi_y.conservativeResize(3, 1);
  with.phi_x(2, 0) = 0.3;  // moves, but carries no mass and stays below the largest motion
  with.phi_y(2, 0) = -0.2;
  expect_same(from_lumped_model(with), from_lumped_model(model), 1e-15);
}

TEST(LumpedModelBuilder, RejectsBadModesAndStiffness) {
  auto model = two_node_model(2);
  model.frequencies = VectorX::Constant(2, 10.0);
  // these two shapes are not mass-orthogonal: m_12 = -0.675, m_11 = 2.52, m_22 = 7.3125 for the
  // rescaled shapes (see two_node_model), 0.675 / sqrt(2.52 * 7.3125) = 0.157243 relative
  expect_rejected([&] { from_lumped_model(model); }, "modes 1 and 2", "mass-orthogonal",
                  "|m_ij| / sqrt(m_ii m_jj) = 0.15724", "give stiffness");
  // within 1e-2 (printed shapes): re-orthogonalised, with a note
  model.phi_x(0, 1) = 0.1007;  // m_12 = 0.3 (0.0007) of sqrt(0.28 * 0.0448): 1e-3 relative
  std::vector<std::string> notes;
  const auto p = from_lumped_model(model, notes);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("re-orthogonalised"), std::string::npos) << notes[0];
  EXPECT_LT(std::abs(p.mu(0, 1)), 1e-14 * p.mu(0, 0));
  model = two_node_model(2);
  model = two_node_model(2);
  model.stiffness.resize(2, 2);
  model.stiffness << 28.0, 2.0, 2.5, 10.0;
  expect_rejected([&] { from_lumped_model(model); }, "stiffness must be symmetric");
  model.stiffness << 1.0, 2.0, 2.0, 1.0;
  expect_rejected([&] { from_lumped_model(model); }, "positive definite");
  model = two_node_model(2);
  model.phi_x.col(1).setZero();
  model.phi_y.col(1).setZero();
  model.stiffness = MatrixX::Identity(2, 2);
  expect_rejected([&] { from_lumped_model(model); }, "mode 2 shape is zero");
  model = two_node_model(1);
  model.frequencies = VectorX::Constant(1, -3.0);
  expect_rejected([&] { from_lumped_model(model); }, "frequency 1", "> 0", "got -3");
}

// ---------------------------------------------------------------------------------------------
// oscillator on a slab

TEST(OscillatorOnSlabBuilder, MatchesClosedForm) {
  test::Oscillator o;
  o.m = 1000;
  o.H = 2.0;
  o.m0 = 500;
  o.b = 0.5;
  const double f = 3.0;
  o.k = o.m * std::pow(2 * kPi * f, 2);
  o.zeta = 0.05;
  const auto p = oscillator_on_slab(o.m, f, o.m0, o.H, 2 * o.b, o.zeta);
  expect_same(p, o.params(), 1e-14);
  EXPECT_EQ(p.damping.kind, DampingKind::kModal);
  EXPECT_DOUBLE_EQ(p.damping.modal_ratios(0), 0.05);
  // h = m H / M = 4/3
  EXPECT_NEAR(p.height, 4.0 / 3.0, 1e-15);
}

TEST(OscillatorOnSlabBuilder, BodyVibratesAtTheGivenFrequency) {
  for (double f : {0.5, 2.0, 12.0}) {
    const Body body(oscillator_on_slab(800, f, 1200, 3.0, 1.2, 0.02));
    EXPECT_NEAR(body.natural_frequencies()(0), 2 * kPi * f, 1e-10 * f);
    EXPECT_NEAR(body.damping_ratios()(0), 0.02, 1e-15);
  }
}

TEST(OscillatorOnSlabBuilder, EqualsLumpedModelWithSlabAsRotaryInertia) {
  // top node at (0, H); the slab as one node at its centre (0, 0) carrying I = m0 B^2/12
  const double m = 700, f = 1.7, m0 = 300, H = 2.5, B = 1.4;
  LumpedModel model;
  model.nodes = {{0.0, H, m, 0.0}, {0.0, 0.0, m0, m0 * B * B / 12.0}};
  model.tip1_x = -B / 2;
  model.tip2_x = B / 2;
  model.phi_x = MatrixX::Zero(2, 1);
  model.phi_y = MatrixX::Zero(2, 1);
  model.phi_x(0, 0) = 0.04;  // any normalisation
  model.frequencies = VectorX::Constant(1, 2 * kPi * f);
  model.damping.kind = DampingKind::kModal;
  model.damping.modal_ratios = VectorX::Constant(1, 0.1);
  expect_same(oscillator_on_slab(m, f, m0, H, B, 0.1), from_lumped_model(model), 1e-13);
}

TEST(OscillatorOnSlabBuilder, RejectsBadArguments) {
  expect_rejected([] { oscillator_on_slab(0, 1, 1, 1, 1); }, "oscillator_on_slab", "top_mass",
                  "got 0");
  expect_rejected([] { oscillator_on_slab(1, -1, 1, 1, 1); }, "frequency_hz", "got -1");
  expect_rejected([] { oscillator_on_slab(1, 1, 0, 1, 1); }, "base_mass", "> 0", "got 0");
  expect_rejected([] { oscillator_on_slab(1, 1, 1, kNaN, 1); }, "height", "nan");
  expect_rejected([] { oscillator_on_slab(1, 1, 1, 1, 0); }, "base_width", "got 0");
  expect_rejected([] { oscillator_on_slab(1, 1, 1, 1, 1, 1.0); }, "damping_ratio", "[0, 1)",
                  "got 1");
  expect_rejected([] { oscillator_on_slab(1, 1, 1, 1, 1, -0.1); }, "damping_ratio", "got -0.1");
}

// ---------------------------------------------------------------------------------------------
// uniform cantilever

// b_i L, roots of cos x cosh x = -1 (Blevins, Formulas for Natural Frequency and Mode Shape)
constexpr double kRoots[] = {1.87510406871196, 4.69409113297418, 7.85475743823761, 10.9955407348755,
                             14.1371683910465, 17.2787595320882, 20.4203522510413, 23.5619449018064,
                             26.7035375555183, 29.8451302091028};

// b_i L by bisection of cos x cosh x + 1 in long double (independent of the builder's solver)
double root_by_bisection(int i) {
  long double lo = (i - 0.5L) * std::numbers::pi_v<long double> - 0.5L;
  long double hi = lo + 1.0L;
  auto f = [](long double x) { return std::cos(x) * std::cosh(x) + 1.0L; };
  const long double flo = f(lo);
  for (int k = 0; k < 200; ++k) {
    const long double mid = 0.5L * (lo + hi);
    if ((f(mid) > 0) == (flo > 0))
      lo = mid;
    else
      hi = mid;
  }
  return static_cast<double>(0.5L * (lo + hi));
}

// textbook mode shape, naive form (fine in long double for low modes), normalised to phi(L) = h
struct NaiveMode {
  long double X, s;
  explicit NaiveMode(double root) : X(root) {
    s = (std::cosh(X) + std::cos(X)) / (std::sinh(X) + std::sin(X));
  }
  long double shape(long double x) const {
    return std::cosh(x) - std::cos(x) - s * (std::sinh(x) - std::sin(x));
  }
};

// Simpson's rule of f on [0, L] with `n` (even) intervals
double simpson(const std::function<long double(long double)>& f, double L, int n) {
  const long double dx = static_cast<long double>(L) / n;
  long double sum = f(0) + f(static_cast<long double>(L));
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0L : 2.0L) * f(k * dx);
  return static_cast<double>(sum * dx / 3.0L);
}

constexpr double kL = 10.0, kW = 2.0, kMbar = 1000.0, kEI = 1e9;

TEST(UniformCantileverBuilder, RootsAreTheClampedFreeEigenvalues) {
  for (int i = 1; i <= 10; ++i)
    EXPECT_NEAR(root_by_bisection(i), kRoots[i - 1], 1e-12) << "root " << i;
}

TEST(UniformCantileverBuilder, BodyFrequenciesAreTheBeamFrequencies) {
  const double scale = std::sqrt(kEI / (kMbar * std::pow(kL, 4)));
  for (int n = 1; n <= 10; ++n) {
    const Body body(uniform_cantilever(kL, kW, kMbar, kEI, n));
    ASSERT_EQ(body.modes(), n);
    for (int i = 0; i < n; ++i) {
      const double want = std::pow(root_by_bisection(i + 1), 2) * scale;
      EXPECT_NEAR(body.natural_frequencies()(i), want, 1e-8 * want)
          << "mode " << i + 1 << " of " << n;
    }
  }
}

TEST(UniformCantileverBuilder, ModesAreOrthogonalAndStiffnessDiagonal) {
  const int n = 10;
  const double base = 2000.0;
  const auto p = uniform_cantilever(kL, kW, kMbar, kEI, n, base);
  const double M = kMbar * kL + base, h = kMbar * kL * kL / 2 / M;
  const double scale = std::sqrt(kEI / (kMbar * std::pow(kL, 4)));
  for (int i = 0; i < n; ++i) {
    // int phi^2 dy = L phi(L)^2/4 for the textbook shapes: mu_ii = mbar L/(4 M)
    EXPECT_NEAR(p.mu(i, i), kMbar * kL / (4 * M), 1e-10) << i;
    // kappa = k/(M g h) with k_ii = omega_i^2 m_ii, m_ii = mu_ii M h^2
    const double w = std::pow(kRoots[i], 2) * scale;
    expect_near_rel(p.kappa(i, i), w * w * p.mu(i, i) * h / p.gravity, 1e-9, "kappa_ii");
    for (int j = 0; j < n; ++j) {
      if (i == j) continue;
      EXPECT_LE(std::abs(p.mu(i, j)), 1e-10 * p.mu(i, i)) << i << "," << j;
      EXPECT_LE(std::abs(p.kappa(i, j)), 1e-10 * std::sqrt(p.kappa(i, i) * p.kappa(j, j)))
          << i << "," << j;
    }
  }
  EXPECT_TRUE(p.gamma.isZero(0.0));
  EXPECT_TRUE(p.psi_y.isZero(0.0));
  EXPECT_TRUE(p.delta.isZero(0.0));
}

TEST(UniformCantileverBuilder, FirstModeParticipation) {
  const auto p = uniform_cantilever(kL, kW, kMbar, kEI, 3);
  // no base mass: psi_x = int (phi/h) dy / L = s_1/(b_1 L) for tip-normalised phi
  const NaiveMode m1(kRoots[0]);
  EXPECT_NEAR(p.psi_x(0), static_cast<double>(m1.s) / kRoots[0], 1e-12);
  EXPECT_NEAR(p.psi_x(0), 0.391496, 1e-6);
  // classical effective mass of mode 1: (int m phi)^2/(int m phi^2)/(mbar L) = 0.6131
  const double M = kMbar * kL;
  const double effective = p.psi_x(0) * p.psi_x(0) * M / (p.mu(0, 0) * kMbar * kL);
  EXPECT_NEAR(effective, 0.6131, 1e-4);
  // and the effective masses of all modes sum towards 1 (0.6131 + 0.1883 + 0.0647 = 0.8661)
  double sum = 0;
  for (int i = 0; i < 3; ++i) sum += p.psi_x(i) * p.psi_x(i) / p.mu(i, i);
  EXPECT_NEAR(sum, 0.8661, 1e-4);
}

TEST(UniformCantileverBuilder, IntegralsMatchNaiveShapesBySimpson) {
  const double base = 500.0;
  const int n = 5;
  const auto p = uniform_cantilever(kL, kW, kMbar, kEI, n, base);
  const double M = kMbar * kL + base, h = kMbar * kL * kL / 2 / M;
  EXPECT_DOUBLE_EQ(p.mass, M);
  EXPECT_NEAR(p.height, h, 1e-14);
  EXPECT_DOUBLE_EQ(p.b1, 1.0);
  EXPECT_DOUBLE_EQ(p.b2, 1.0);
  // beam: mbar L (L^2 + w^2)/12 + mbar L (L/2 - h)^2; plate: mb (w^2/12 + h^2)
  const double inertia = kMbar * kL * (kL * kL + kW * kW) / 12 +
                         kMbar * kL * std::pow(kL / 2 - h, 2) + base * (kW * kW / 12 + h * h);
  EXPECT_NEAR(p.zeta2, inertia / (M * h * h), 1e-12);
  for (int i = 0; i < n; ++i) {
    const NaiveMode mode(kRoots[i]);
    const long double b = mode.X / kL, c = h / mode.shape(mode.X);
    auto phi = [&](long double y) { return c * mode.shape(b * y); };
    const double psi = simpson([&](long double y) { return kMbar * phi(y); }, kL, 4000) / (M * h);
    const double beta =
        -simpson([&](long double y) { return kMbar * (y - h) * phi(y); }, kL, 4000) / (M * h * h);
    const double mu =
        simpson([&](long double y) { return kMbar * phi(y) * phi(y); }, kL, 4000) / (M * h * h);
    EXPECT_NEAR(p.psi_x(i), psi, 1e-9) << "mode " << i + 1;
    EXPECT_NEAR(p.beta(i), beta, 1e-9) << "mode " << i + 1;
    EXPECT_NEAR(p.mu(i, i), mu, 1e-9) << "mode " << i + 1;
  }
}

TEST(UniformCantileverBuilder, EqualsFineLumpedModelOfTheBeam) {
  // trapezoidal lumping: N elements, half masses at the ends, the plate at the root node; each
  // node carries the rotary inertia of its slice across the width
  const int N = 4000, n = 3;
  const double base = 800.0, dy = kL / N;
  const double M = kMbar * kL + base, h = kMbar * kL * kL / 2 / M;
  LumpedModel model;
  model.tip1_x = -kW / 2;
  model.tip2_x = kW / 2;
  model.phi_x.resize(N + 1, n);
  model.phi_y = MatrixX::Zero(N + 1, n);
  for (int k = 0; k <= N; ++k) {
    const double mk = kMbar * dy * (k == 0 || k == N ? 0.5 : 1.0);
    const double jk = mk * kW * kW / 12 + (k == 0 ? base * kW * kW / 12 : 0.0);
    model.nodes.push_back({0.0, k * dy, mk + (k == 0 ? base : 0.0), jk});
    for (int i = 0; i < n; ++i) {
      const NaiveMode mode(kRoots[i]);
      // sign so that the tip moves in +x, as the builder's q_i = tip displacement/h
      const long double sign = mode.shape(mode.X) > 0 ? 1.0L : -1.0L;
      model.phi_x(k, i) = static_cast<double>(sign * mode.shape(mode.X * k / N));
    }
  }
  VectorX w(n);
  const double scale = std::sqrt(kEI / (kMbar * std::pow(kL, 4)));
  for (int i = 0; i < n; ++i) w(i) = std::pow(kRoots[i], 2) * scale;
  model.frequencies = w;
  model.damping.kind = DampingKind::kModal;
  model.damping.modal_ratios = VectorX::Constant(n, 0.02);
  const auto lumped = from_lumped_model(model);
  const auto beam = uniform_cantilever(kL, kW, kMbar, kEI, n, base, 0.02);
  EXPECT_NEAR(lumped.height, h, 1e-12);
  EXPECT_NEAR(beam.height, h, 1e-12);
  // trapezoidal error ~ dy^2: agree to ~1e-6
  EXPECT_NEAR(lumped.zeta2, beam.zeta2, 1e-6 * beam.zeta2);
  EXPECT_LE((lumped.mu - beam.mu).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LE((lumped.psi_x - beam.psi_x).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LE((lumped.beta - beam.beta).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LE((lumped.kappa - beam.kappa).cwiseAbs().maxCoeff(), 1e-5 * beam.kappa.maxCoeff());
  const Body lb(lumped), bb(beam);
  for (int i = 0; i < n; ++i)
    EXPECT_NEAR(lb.natural_frequencies()(i), bb.natural_frequencies()(i), 1e-5 * w(i));
}

TEST(UniformCantileverBuilder, HighModesStayFiniteAndValid) {
  const auto p = uniform_cantilever(30.0, 3.0, 5000.0, 5e10, 20, 1e4, 0.05);
  EXPECT_TRUE(p.mu.allFinite() && p.kappa.allFinite() && p.psi_x.allFinite() && p.beta.allFinite());
  const Body body(p);
  const double scale = std::sqrt(5e10 / (5000.0 * std::pow(30.0, 4)));
  for (int i = 0; i < 20; ++i) {
    const double want = std::pow(root_by_bisection(i + 1), 2) * scale;
    EXPECT_NEAR(body.natural_frequencies()(i), want, 1e-8 * want) << "mode " << i + 1;
  }
  EXPECT_EQ(body.damping_ratios(), VectorX::Constant(20, 0.05));
}

TEST(UniformCantileverBuilder, RejectsBadArguments) {
  expect_rejected([] { uniform_cantilever(0, 1, 1, 1, 1); }, "uniform_cantilever", "height",
                  "got 0");
  expect_rejected([] { uniform_cantilever(1, -1, 1, 1, 1); }, "width", "got -1");
  expect_rejected([] { uniform_cantilever(1, 1, 0, 1, 1); }, "mass_per_length", "got 0");
  expect_rejected([] { uniform_cantilever(1, 1, 1, kNaN, 1); }, "bending_stiffness", "nan");
  expect_rejected([] { uniform_cantilever(1, 1, 1, 1, 0); }, "modes", "[1, 20]", "got 0");
  expect_rejected([] { uniform_cantilever(1, 1, 1, 1, 21); }, "modes", "got 21");
  expect_rejected([] { uniform_cantilever(1, 1, 1, 1, 1, -5); }, "base_mass", ">= 0", "got -5");
  expect_rejected([] { uniform_cantilever(1, 1, 1, 1, 1, 0, 1.5); }, "damping_ratio", "got 1.5");
}

}  // namespace
}  // namespace flexrock
