// SPDX-License-Identifier: BSD-3-Clause
// The impact laws in whole runs (docs/theory.md, "Impact laws"): the rigid_body law tends to
// Housner's ratio as a flexible body stiffens, the restitution law gives its measured ratios
// exactly, and every law closes the energy balance with flight, sliding and landings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"
#include "support/bodies.hpp"

namespace flexrock {
namespace {

const Event* first(const SimulationResult& r, EventKind k) {
  for (const Event& e : r.events)
    if (e.kind == k) return &e;
  return nullptr;
}

// Housner's ratio theta_dot+/theta_dot- of the body taken rigid (its own zeta^2 and alphas)
double housner_ratio(const Body& body, int landing) {
  const double z2 = body.params().zeta2, a1 = body.alpha1(), a2 = body.alpha2();
  const double a_post = landing == 1 ? a1 : a2;
  return (1.0 + z2 - a1 * a2) / (1.0 + z2 + a_post * a_post);
}

// free rocking of a lumped body released at half its tipping angle: the first impact's ratio
double first_ratio(const Body& body, ImpactLaw law) {
  SimulationOptions o;
  o.impact_law = law;
  o.t_end = 3.0;
  o.rtol = 1e-12;
  o.atol = 1e-14;
  InitialState init;
  init.theta = 0.5 * body.tipping_angle(1);
  const auto r = simulate(body, GroundMotion::none(3.0), init, o);
  const Event* e = first(r, EventKind::kImpact);
  if (!e) e = first(r, EventKind::kRockingEnded);
  EXPECT_NE(e, nullptr);
  return e ? e->theta_dot_after / e->theta_dot_before : NAN;
}

TEST(ImpactLawRuns, RigidBodyLawTendsToHousnerAsTheBodyStiffens) {
  // the same masses and mode shapes, the stiffness 10x up at each level: the rigid_body ratio
  // approaches Housner's (the static deformation and the modal rates fall like 1/stiffness),
  // while the paper's law stays 0.17 away from it
  std::vector<double> err_rigid, err_paper;
  for (const double k : {2e5, 2e6, 2e7}) {
    const Body body(test::random_lumped_body(2, 7, k));
    const double want = housner_ratio(body, 2);
    err_rigid.push_back(std::abs(first_ratio(body, ImpactLaw::kRigidBody) - want));
    err_paper.push_back(std::abs(first_ratio(body, ImpactLaw::kPaper) - want));
  }
  // the modal state at the first impact depends on the phase of the modes there, so the error
  // is bounded by, not proportional to, 1/stiffness (the closed-form order is in impact_test)
  for (const double e : err_rigid) EXPECT_LT(e, 5e-6);
  EXPECT_LT(std::max(err_rigid[1], err_rigid[2]), 1e-6);
  EXPECT_GT(err_paper.back(), 1e-2);
}

TEST(ImpactLawRuns, RestitutionGivesTheMeasuredRatioAtEveryImpact) {
  const Body body(BodyParameters::rectangular_block(400, 0.2, 1.0));
  SimulationOptions o;
  o.impact_law = ImpactLaw::kRestitution;
  o.restitution_ratio_edge1 = 0.9;
  o.restitution_ratio_edge2 = 0.75;
  InitialState init;
  init.theta = 0.15;
  const auto r = simulate(body, GroundMotion::none(8.0), init, o);
  int impacts = 0;
  for (const Event& e : r.events) {
    if (e.kind != EventKind::kImpact) continue;
    const double want = e.edge == 1 ? 0.9 : 0.75;
    EXPECT_NEAR(e.theta_dot_after / e.theta_dot_before, want, 1e-15) << e.time;
    ++impacts;
  }
  EXPECT_GE(impacts, 6);
}

TEST(ImpactLawRuns, EveryLawClosesTheEnergyBalanceWithFlightAndSliding) {
  // a flexible body under strong horizontal and vertical pulses lifts off, lands, rocks and
  // slides: every law runs to the end and its energy balance closes, the impacts' loss included
  const Body body(test::random_lumped_body(2, 3, 2e6));
  for (const ImpactLaw law : {ImpactLaw::kPaper, ImpactLaw::kRigidBody, ImpactLaw::kRestitution}) {
    for (const double mu : {std::numeric_limits<double>::infinity(), 0.4}) {
      SimulationOptions o;
      o.impact_law = law;
      o.restitution_ratio_edge1 = o.restitution_ratio_edge2 = 0.85;
      o.friction_coefficient = mu;
      // a horizontal half-sine that uplifts, then a downward vertical pulse beyond g that lifts off
      const double g = kStandardGravity, pi = std::numbers::pi;
      const auto motion = GroundMotion::analytic(
          [&](double t) {
            BaseAcceleration a;
            if (t < pi / 6.0) a.x = 0.45 * g * std::sin(6.0 * t);
            if (t > 0.6 && t < 0.6 + pi / 20.0) a.y = -1.3 * g * std::sin(20.0 * (t - 0.6));
            return a;
          },
          3.0, {pi / 6.0, 0.6, 0.6 + pi / 20.0});
      const auto r = simulate(body, motion, {}, o);
      EXPECT_NE(r.status, Status::kStopped) << to_string(law) << " " << r.message;
      EXPECT_GT(r.extremes.impacts, 0) << to_string(law) << " " << to_string(r.status);
      EXPECT_GT(r.extremes.lift_offs, 0) << to_string(law);
      EXPECT_FALSE(r.energy_unbalanced) << to_string(law) << " mu " << mu;
      EXPECT_LE(std::abs(r.energy.residual), 1e-5 * r.energy.scale) << to_string(law);
    }
  }
}

}  // namespace
}  // namespace flexrock
