// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/model/body.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <random>

#include "flexrock/core/error.hpp"
#include "flexrock/model/dynamics.hpp"
#include "support/bodies.hpp"

namespace flexrock {
namespace {

using ::testing::HasSubstr;

// expects construction to throw InputError whose message contains every fragment
template <class... S>
void expect_rejected(const BodyParameters& p, S... fragments) {
  try {
    Body b(p);
    FAIL() << "accepted invalid parameters";
  } catch (const InputError& e) {
    for (const char* f : {fragments...}) EXPECT_THAT(e.what(), HasSubstr(f));
  }
}

BodyParameters two_modes() { return test::random_lumped_body(2, 7); }

TEST(BodyValidation, RejectsNonPositiveGeometry) {
  auto p = BodyParameters::rectangular_block(100, 0.2, 1.0);
  p.height = 0;
  expect_rejected(p, "h", "positive", "got 0");
  p = BodyParameters::rectangular_block(100, 0.2, 1.0);
  p.b1 = -0.1;
  expect_rejected(p, "b1", "got -0.1");
  p = BodyParameters::rectangular_block(100, 0.2, 1.0);
  p.b2 = 0;
  expect_rejected(p, "b2");
  p = BodyParameters::rectangular_block(100, 0.2, 1.0);
  p.mass = std::numeric_limits<double>::quiet_NaN();
  expect_rejected(p, "M", "nan");
}

TEST(BodyValidation, RejectsFiniteInputsWhoseDerivedQuantitiesOverflow) {
  // each input is finite and positive; M g h or the inertia is not a normal double
  auto p = BodyParameters::rectangular_block(1e308, 0.2, 1.0);
  expect_rejected(p, "M g h", "inf", "M = 1e+308", "physical sizes");
  p = BodyParameters::rectangular_block(5e-324, 0.2, 1.0);
  expect_rejected(p, "M g h", "not a finite normal number", "4.94066e-324");
  p = BodyParameters::rectangular_block(1e300, 0.2, 1e5);
  expect_rejected(p, "rotary inertia");
  p = two_modes();
  p.kappa *= 1e306;
  expect_rejected(p, "kappa", "overflows");
  // physical extremes still pass: 1 g and 1e9 kg
  EXPECT_NO_THROW(Body(BodyParameters::rectangular_block(1e-3, 0.01, 0.05)));
  EXPECT_NO_THROW(Body(BodyParameters::rectangular_block(1e9, 5.0, 20.0)));
}

TEST(BodyValidation, RejectsWrongSizes) {
  auto p = two_modes();
  p.kappa = MatrixX::Identity(3, 3);
  expect_rejected(p, "kappa", "2x2", "got 3x3");
  p = two_modes();
  p.psi_x = VectorX::Zero(1);
  expect_rejected(p, "psi_x", "2 entries", "got 1");
}

TEST(BodyValidation, RejectsMassMatrixNotPositiveDefinite) {
  auto p = two_modes();
  p.mu(1, 1) = -p.mu(1, 1);
  expect_rejected(p, "mu", "positive definite", "smallest eigenvalue");
}

TEST(BodyValidation, RejectsAsymmetricStiffness) {
  auto p = two_modes();
  p.kappa(0, 1) += 1.0;
  expect_rejected(p, "kappa", "symmetric", "(2,1)");
}

TEST(BodyValidation, RejectsGammaNotAntisymmetric) {
  auto p = two_modes();
  p.gamma(0, 1) = p.gamma(1, 0) = 0.1;
  expect_rejected(p, "gamma", "antisymmetric");
}

TEST(BodyValidation, RejectsNaNInModalData) {
  auto p = two_modes();
  p.beta(1) = std::numeric_limits<double>::infinity();
  expect_rejected(p, "beta", "NaN or inf");
}

TEST(BodyValidation, RejectsNegativeDampingRatio) {
  auto p = two_modes();
  p.damping.kind = DampingKind::kModal;
  p.damping.modal_ratios = VectorX::Constant(2, -0.01);
  expect_rejected(p, "damping ratio", ">= 0");
}

TEST(BodyDerived, RigidTippingAngleIsArctanAlpha) {
  const Body b(BodyParameters::rigid(10, 1.0, 0.25, 0.4, 0.3));
  EXPECT_NEAR(b.tipping_angle(1), std::atan(0.25), 1e-14);
  EXPECT_NEAR(b.tipping_angle(2), std::atan(0.4), 1e-14);
}

TEST(BodyDerived, OscillatorFrequencyAndModalDamping) {
  test::Oscillator o;
  o.k = 1000 * std::pow(2 * M_PI * 2.0, 2);
  const Body b(o.params());
  ASSERT_EQ(b.modes(), 1);
  EXPECT_NEAR(b.natural_frequencies()(0), o.omega(), 1e-12 * o.omega());
  // C = 2 zeta omega mu for one mode
  EXPECT_NEAR(b.damping_matrix()(0, 0), 2 * 0.05 * o.omega() * o.m / o.M(), 1e-12);
}

TEST(BodyDerived, ModalDampingGivesRequestedRatios) {
  auto p = test::random_lumped_body(3, 11);
  p.damping.kind = DampingKind::kModal;
  p.damping.modal_ratios = VectorX::LinSpaced(3, 0.02, 0.05);
  const Body b(p);
  // the damping matrix is diagonal in the mass-normalised modes with entries 2 zeta omega
  Eigen::GeneralizedSelfAdjointEigenSolver<MatrixX> ges(b.stiffness(), p.mu);
  const MatrixX c = ges.eigenvectors().transpose() * b.damping_matrix() * ges.eigenvectors();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(c(i, i), 2 * p.damping.modal_ratios(i) * b.natural_frequencies()(i), 1e-9);
    for (int j = 0; j < 3; ++j) {
      if (i != j) {
        EXPECT_NEAR(c(i, j), 0.0, 1e-9);
      }
    }
  }
}

TEST(BodyDerived, RayleighRatiosFollowTheFormula) {
  auto p = test::random_lumped_body(2, 5);
  p.damping.kind = DampingKind::kRayleigh;
  p.damping.rayleigh_mass = 0.3;
  p.damping.rayleigh_stiffness = 0.002;
  const Body b(p);
  for (int i = 0; i < 2; ++i) {
    const double w = b.natural_frequencies()(i);
    EXPECT_NEAR(b.damping_ratios()(i), 0.3 / (2 * w) + 0.002 * w / 2, 1e-14);
  }
}

TEST(BodyDerived, StaticDeformationBalancesGravity) {
  const auto p = test::random_lumped_body(3, 3);
  const Body b(p);
  // kappa q = -psi_y at rest
  EXPECT_LT((p.kappa * b.static_deformation() + p.psi_y).norm(), 1e-14);
}

TEST(BodyDerived, FlexibleTippingAngleSatisfiesStaticEquilibrium) {
  const auto p = test::random_lumped_body(2, 9, 2e4);
  const Body b(p);
  for (int edge : {1, 2}) {
    const double th = (edge == 1 ? 1.0 : -1.0) * b.tipping_angle(edge);
    const double a = edge == 1 ? -b.alpha1() : b.alpha2();
    const VectorX q = -p.kappa.llt().solve(p.psi_x * std::sin(th) + p.psi_y * std::cos(th));
    // tan(theta) = (psi_x.q - alpha)/(1 + psi_y.q)   (paper, above eq. 5)
    EXPECT_NEAR(std::tan(th), (p.psi_x.dot(q) - a) / (1 + p.psi_y.dot(q)), 1e-12);
  }
}

// The body in its pinned-base modal coordinates (docs/theory.md, "Modal coordinates") is the
// congruence of the given one by Phi, with mu = I and kappa, C diagonal to the last bit, and its
// equations (the modal fast path of Dynamics) give the given body's accelerations, reaction and
// energies (the general path) at q = Phi eta
template <int N>
void expect_modal_coordinates_map_the_motion(const BodyParameters& p) {
  const Body b(p);
  const Body m = b.in_modal_coordinates();
  const int n = b.modes();
  const MatrixX& phi = b.pinned_base_modes();
  const MatrixX id = MatrixX::Identity(n, n);
  EXPECT_LT((phi.transpose() * p.mu * phi - id).norm(), 1e-12);
  EXPECT_EQ(m.params().mu, id);
  EXPECT_EQ(m.pinned_base_modes(), id);
  auto off_diagonal = [](const MatrixX& a) {
    return (a - MatrixX(a.diagonal().asDiagonal())).norm();
  };
  EXPECT_EQ(off_diagonal(m.params().kappa), 0.0);
  EXPECT_EQ(off_diagonal(m.damping_matrix()), 0.0);
  auto near = [](const auto& got, const auto& want) {
    EXPECT_LT((got - want).norm(), 1e-11 * (1.0 + want.norm())) << got << "\nvs\n" << want;
  };
  near(m.params().kappa, MatrixX(phi.transpose() * p.kappa * phi));
  near(m.params().gamma, MatrixX(phi.transpose() * p.gamma * phi));
  EXPECT_EQ(m.params().gamma + m.params().gamma.transpose(), MatrixX::Zero(n, n));
  near(m.damping_matrix(), MatrixX(phi.transpose() * b.damping_matrix() * phi));
  near(m.params().psi_x, VectorX(phi.transpose() * p.psi_x));
  near(m.params().psi_y, VectorX(phi.transpose() * p.psi_y));
  near(m.params().delta, VectorX(phi.transpose() * p.delta));
  near(m.params().beta, VectorX(phi.transpose() * p.beta));
  near(VectorX(phi * m.static_deformation()), b.static_deformation());
  near(m.natural_frequencies(), b.natural_frequencies());
  near(m.damping_ratios(), b.damping_ratios());
  EXPECT_EQ(m.tipping_angle(1), b.tipping_angle(1));
  EXPECT_EQ(m.rocking_frequency(), b.rocking_frequency());

  using Dyn = Dynamics<N>;
  const Dyn dq(b), de(m);
  typename Dyn::Vec eta(n), etad(n), q(n), qd(n), qdd(n), etadd(n);
  for (int i = 0; i < n; ++i) {
    eta(i) = 0.01 * std::sin(1.0 + i) + m.static_deformation()(i);
    etad(i) = 0.3 * std::cos(2.0 + 3.0 * i);
  }
  q = phi * eta;
  qd = phi * etad;
  const BaseAcceleration base{2.1, -1.3};
  for (int edge : {1, 2}) {
    const double theta = edge == 1 ? 0.07 : -0.05, thd = edge == 1 ? -0.4 : 0.3;
    double thdd_q = 0.0, thdd_e = 0.0;
    dq.rocking_acceleration(edge, theta, q, thd, qd, base, thdd_q, qdd);
    de.rocking_acceleration(edge, theta, eta, thd, etad, base, thdd_e, etadd);
    EXPECT_NEAR(thdd_e, thdd_q, 1e-11 * (1.0 + std::abs(thdd_q)));
    near(VectorX(phi * etadd), VectorX(qdd));
    near(de.rocking_reaction(edge, theta, eta, thd, etad, thdd_e, etadd, base),
         dq.rocking_reaction(edge, theta, q, thd, qd, thdd_q, qdd, base));
    const double a = dq.alpha(edge);
    EXPECT_NEAR(de.kinetic_energy(a, eta, thd, etad), dq.kinetic_energy(a, q, thd, qd),
                1e-11 * dq.kinetic_energy(a, q, thd, qd));
    EXPECT_NEAR(de.potential_energy(a, theta, eta), dq.potential_energy(a, theta, q),
                1e-11 * b.params().mass * b.g() * b.params().height);
    // an impact onto the other edge: the same velocities after it
    const Eigen::Vector2d v_corner{0.2, -0.15};
    double thp_q = 0.0, thp_e = 0.0;
    typename Dyn::Vec qdp(n), etadp(n);
    dq.corner_impact(3 - edge, q, thd, qd, v_corner, thp_q, qdp);
    de.corner_impact(3 - edge, eta, thd, etad, v_corner, thp_e, etadp);
    EXPECT_NEAR(thp_e, thp_q, 1e-11 * (1.0 + std::abs(thp_q)));
    near(VectorX(phi * etadp), VectorX(qdp));
  }
  dq.full_contact_acceleration(q, qd, base, qdd);
  de.full_contact_acceleration(eta, etad, base, etadd);
  near(VectorX(phi * etadd), VectorX(qdd));
  EXPECT_NEAR(de.damping_power(etad), dq.damping_power(qd), 1e-11 * (1.0 + dq.damping_power(qd)));
}

TEST(BodyDerived, ModalCoordinatesMapTheMotion) {
  auto p = test::random_lumped_body(3, 11);
  p.damping.kind = DampingKind::kRayleigh;
  p.damping.rayleigh_mass = 0.3;
  p.damping.rayleigh_stiffness = 0.002;
  expect_modal_coordinates_map_the_motion<3>(p);
  expect_modal_coordinates_map_the_motion<Eigen::Dynamic>(p);
  // full modal mass and stiffness, modal damping, five modes (Eigen's product kernel path)
  auto c = test::random_coupled({0.7, 2.0, 5.5, 13.0, 31.0}, 4).params();
  c.damping.kind = DampingKind::kModal;
  c.damping.modal_ratios = VectorX::Constant(5, 0.03);
  expect_modal_coordinates_map_the_motion<5>(c);
}

// The rocking right-hand side's fused sums (Dynamics::rocking_rates_sc) give what the
// accelerations, input power and damping power of the general path (full mu, K, C) give apart:
// on the general body itself, and on its modal coordinates (phi: q = Phi eta) with and without
// damping and with and without the coupling gamma, whose accelerations (rocking_acceleration_sc
// shares the modal pass) are compared through Phi
template <int N>
void expect_rocking_rates_match(const Body& general, const Body& b, const MatrixX& phi) {
  using Dyn = Dynamics<N>;
  const Dyn ref(general), dyn(b);
  const int n = b.modes();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  typename Dyn::Vec eta(n), etad(n), etadd(n), q(n), qd(n), qdd(n), fused(n);
  for (int trial = 0; trial < 20; ++trial) {
    for (int i = 0; i < n; ++i) {
      eta(i) = 0.02 * u(rng) + b.static_deformation()(i);
      etad(i) = 0.5 * u(rng);
    }
    q = phi * eta;
    qd = phi * etad;
    const double theta = 0.3 * u(rng), thd = 2.0 * u(rng);
    const BaseAcceleration base{4.0 * u(rng), 3.0 * u(rng)};
    const double s = std::sin(theta), c = std::cos(theta);
    for (int edge : {1, 2}) {
      double thdd = 0.0, thdd_sc = 0.0;
      ref.rocking_acceleration_sc(edge, s, c, q, thd, qd, base, thdd, qdd);
      typename Dyn::RockingRates r{};
      dyn.rocking_rates_sc(edge, s, c, eta.data(), thd, etad.data(), base, fused.data(), r);
      const double scale = 1.0 + std::abs(thdd) + qdd.cwiseAbs().maxCoeff();
      EXPECT_NEAR(r.theta_ddot, thdd, 1e-13 * scale);
      EXPECT_LT((phi * fused - qdd).cwiseAbs().maxCoeff(), 1e-13 * scale);
      dyn.rocking_acceleration_sc(edge, s, c, eta, thd, etad, base, thdd_sc, etadd);
      EXPECT_NEAR(thdd_sc, thdd, 1e-13 * scale);
      EXPECT_LT((phi * etadd - qdd).cwiseAbs().maxCoeff(), 1e-13 * scale);
      const double power = ref.input_power_sc(ref.alpha(edge), s, c, q, thd, qd, base);
      EXPECT_NEAR(r.input_power, power, 1e-13 * (1.0 + std::abs(power)));
      const double damping = ref.damping_power(qd);
      EXPECT_NEAR(r.damping_power, damping, 1e-13 * (1.0 + damping));
    }
  }
}

TEST(BodyDerived, RockingRatesAreTheAccelerationsAndPowers) {
  for (const bool damped : {false, true}) {
    for (const bool coupled : {false, true}) {
      BodyParameters p = test::random_coupled({0.7, 2.0, 5.5, 13.0, 31.0}, 4).params();
      if (damped) {
        p.damping.kind = DampingKind::kRayleigh;
        p.damping.rayleigh_mass = 0.3;
        p.damping.rayleigh_stiffness = 0.002;
      }
      if (!coupled) p.gamma.setZero();
      const Body general(p);
      const Body modal = general.in_modal_coordinates();
      ASSERT_EQ(modal.params().gamma.isZero(0.0), !coupled);
      const MatrixX& phi = general.pinned_base_modes();
      expect_rocking_rates_match<5>(general, general, MatrixX::Identity(5, 5));
      expect_rocking_rates_match<5>(general, modal, phi);
      expect_rocking_rates_match<Eigen::Dynamic>(general, modal, phi);
    }
  }
}

}  // namespace
}  // namespace flexrock
