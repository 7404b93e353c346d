// SPDX-License-Identifier: BSD-3-Clause
// The compliant contact (docs/theory.md, "Compliant contact"): as its springs stiffen with a
// plastic dashpot it tends to the impulsive model with the matching law (Housner's for a rigid
// block, the paper's for a flexible body) at second order in the contact's period; its energy
// balance closes with the springs' and dashpots' work; a body at rest stays at rest; sliding on
// it tends to Coulomb's closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

std::vector<const Event*> of_kind(const SimulationResult& r, EventKind k) {
  std::vector<const Event*> v;
  for (const Event& e : r.events)
    if (e.kind == k) v.push_back(&e);
  return v;
}

// the springs for omega_v = ratio p, omega_v = sqrt(2 k / M) the body's bounce on both
SimulationOptions compliant(const Body& body, double ratio, double zeta) {
  SimulationOptions o;
  o.contact_model = ContactModel::kCompliant;
  const double wv = ratio * body.rocking_frequency();
  o.contact_stiffness = 0.5 * body.params().mass * wv * wv;
  o.contact_damping_ratio = zeta;
  return o;
}

TEST(CompliantContact, RigidBlockTendsToHousnerAtSecondOrder) {
  // free rocking from half the tipping angle: the second impact's time and speed, against the
  // impulsive model (Housner's law); a dashpot four times critical makes the corner plastic
  const Body body(rigid_block(0.3, 1.5, 1000.0));
  InitialState init;
  init.theta = 0.5 * body.tipping_angle(1);
  SimulationOptions o;
  o.t_end = 3.0;
  o.rtol = 1e-11;
  o.atol = 1e-13;
  const auto ref = simulate(body, GroundMotion::none(3.0), init, o);
  const auto ri = of_kind(ref, EventKind::kImpact);
  ASSERT_GE(ri.size(), 2u);
  std::vector<double> ratios = {300.0, 1000.0, 3000.0}, err;
  for (const double ratio : ratios) {
    SimulationOptions c = compliant(body, ratio, 4.0);
    c.t_end = o.t_end;
    c.rtol = o.rtol;
    c.atol = o.atol;
    const auto r = simulate(body, GroundMotion::none(3.0), init, c);
    ASSERT_EQ(r.status, Status::kCompleted) << r.message;
    const auto ci = of_kind(r, EventKind::kImpact);
    ASSERT_GE(ci.size(), 2u);
    EXPECT_NEAR(ci[1]->time, ri[1]->time, 2e-3);
    err.push_back(std::abs(ci[1]->theta_dot_before / ri[1]->theta_dot_before - 1.0));
    EXPECT_LT(std::abs(r.energy.residual), energy_residual_bound(body, r.energy.scale));
  }
  // the order in omega_v: log(e_i / e_i+1) / log(omega_i+1 / omega_i), about 2
  for (std::size_t i = 0; i + 1 < err.size(); ++i) {
    const double order = std::log(err[i] / err[i + 1]) / std::log(ratios[i + 1] / ratios[i]);
    RecordProperty("order_" + std::to_string(i), std::to_string(order));
    std::printf("omega_v/p %g -> %g: error %.3e -> %.3e, order %.2f\n", ratios[i], ratios[i + 1],
                err[i], err[i + 1], order);
    EXPECT_GT(order, 1.8);
    EXPECT_LT(order, 2.5);
  }
  EXPECT_LT(err.back(), 3e-5);
}

TEST(CompliantContact, FlexibleBodyTendsToThePapersLaw) {
  // an oscillator on a slab rocking freely: the energy its impacts take, with a stiffening
  // plastic contact, tends to the paper's law (not to the rigid_body law, 4x larger here): the
  // contact becomes short against the modal period
  const Body body(oscillator_on_slab(1000.0, 2.0, 500.0, 3.0, 0.6, 0.05));
  InitialState init;
  init.theta = 0.5 * body.tipping_angle(1);
  SimulationOptions o;
  o.t_end = 6.0;
  auto lost = [](const SimulationResult& r) {
    return r.energy.impact_loss + r.energy.chatter_loss;
  };
  const double paper = lost(simulate(body, GroundMotion::none(6.0), init, o));
  SimulationOptions rb = o;
  rb.impact_law = ImpactLaw::kRigidBody;
  const double rigid = lost(simulate(body, GroundMotion::none(6.0), init, rb));
  std::vector<double> err;
  for (const double ratio : {300.0, 1000.0, 3000.0}) {
    SimulationOptions c = compliant(body, ratio, 4.0);
    c.t_end = o.t_end;
    const auto r = simulate(body, GroundMotion::none(6.0), init, c);
    ASSERT_EQ(r.status, Status::kCompleted) << r.message;
    err.push_back(std::abs(lost(r) / paper - 1.0));
    EXPECT_LT(std::abs(r.energy.residual), energy_residual_bound(body, r.energy.scale));
  }
  EXPECT_GT(err[0], err[1]);
  EXPECT_GT(err[1], err[2]);
  EXPECT_LT(err[2], 0.005);
  EXPECT_GT(rigid / paper, 3.0);
}

TEST(CompliantContact, ABodyAtRestStaysAtRest) {
  // the statics place the body on its springs: nothing moves, nothing happens, and the springs
  // carry the weight split by the lever rule (b2/(b1+b2) on corner 1)
  const Body body(rigid_body(800.0, 50.0, 1.0, 0.3, 0.5));
  SimulationOptions o = compliant(body, 500.0, 1.0);
  o.output_dt = 0.1;
  const auto r = simulate(body, GroundMotion::none(2.0), {}, o);
  ASSERT_EQ(r.status, Status::kCompleted) << r.message;
  EXPECT_TRUE(r.events.empty());
  const double mg = 800.0 * body.g();
  // (the lever rule of the untilted base: the statics tilt it by (delta1 - delta2)/(b1 + b2),
  // about 1e-5 here, which moves the corners' lever arms by as much)
  EXPECT_NEAR(r.extremes.max_contact_force, mg * 0.5 / 0.8, 1e-4 * mg);
  for (std::size_t i = 0; i < r.history.size(); ++i) {
    EXPECT_NEAR(r.history.reaction_y[i], mg, 1e-9 * mg);
    EXPECT_NEAR(r.history.theta[i], r.history.theta[0], 1e-12);
  }
}

TEST(CompliantContact, EnergyBalanceClosesWithTheContactsWork) {
  // every force law, with and without friction, under a pulse that uplifts and a vertical pulse
  // that throws the body off the floor: the balance closes with the springs' and dashpots' work
  const Body body(oscillator_on_slab(1000.0, 3.0, 500.0, 2.0, 0.8, 0.02));
  const double g = body.g();
  const GroundMotion rock = GroundMotion::analytic(
      [g](double t) {
        return BaseAcceleration{
            t < 0.5 ? 0.6 * g * std::sin(2.0 * std::numbers::pi * t / 0.5) : 0.0, 0.0};
      },
      3.0, {0.5});
  const GroundMotion jump = GroundMotion::analytic(
      [g](double t) {
        return BaseAcceleration{0.2 * g, t > 0.2 && t < 0.3 ? -1.8 * g : 0.0};
      },
      2.0, {0.2, 0.3});
  for (const auto law : {ContactForceLaw::kLinear, ContactForceLaw::kHuntCrossley}) {
    for (const double mu : {std::numeric_limits<double>::infinity(), 0.25}) {
      for (const GroundMotion* m : {&rock, &jump}) {
        SimulationOptions o = compliant(body, 300.0, 1.0);
        o.contact_force_law = law;
        if (law == ContactForceLaw::kHuntCrossley) {
          o.contact_exponent = 1.5;
          o.contact_restitution = 0.5;
          o.contact_damping_ratio = 1.0;
        }
        o.friction_coefficient = mu;
        const auto r = simulate(body, *m, {}, o);
        ASSERT_EQ(r.status, Status::kCompleted) << r.message;
        EXPECT_LT(std::abs(r.energy.residual), energy_residual_bound(body, r.energy.scale))
            << to_string(law) << " mu " << mu;
        EXPECT_GT(r.energy.impact_loss, 0.0);
        EXPECT_GT(r.extremes.max_contact_force, 0.0);
        if (m == &jump) {
          EXPECT_GT(r.extremes.flight_time, 0.0) << to_string(law) << " mu " << mu;
        }
        if (std::isfinite(mu)) {
          EXPECT_GT(r.energy.friction_loss, 0.0) << to_string(law);
          EXPECT_GT(r.extremes.slips, 0);
        }
      }
    }
  }
}

TEST(CompliantContact, SlidingTendsToCoulombsClosedForm) {
  // a squat block (no uplift) under a constant acceleration a > mu g for T, then still: it slides
  // (a - mu g) T^2 / 2 while pushed and v^2 / (2 mu g) after, v = (a - mu g) T
  const Body body(rigid_block(2.0, 1.0, 1000.0));
  const double g = body.g(), mu = 0.2, a = 0.4 * g, T = 0.5;
  const GroundMotion push = GroundMotion::analytic(
      [=](double t) {
        return BaseAcceleration{t < T ? a : 0.0, 0.0};
      },
      2.0, {T});
  const double v = (a - mu * g) * T;
  const double want = 0.5 * (a - mu * g) * T * T + v * v / (2.0 * mu * g);
  std::vector<double> err;
  for (const double ratio : {100.0, 1000.0}) {
    SimulationOptions o = compliant(body, ratio, 1.0);
    o.friction_coefficient = mu;
    const auto r = simulate(body, push, {}, o);
    ASSERT_EQ(r.status, Status::kCompleted) << r.message;
    // the ground pushes along +I: the body lags, its offset is negative
    err.push_back(std::abs(-r.final_offset / want - 1.0));
    EXPECT_EQ(r.extremes.first_uplift_time, -1.0);
  }
  EXPECT_LT(err[1], err[0]);
  EXPECT_LT(err[1], 2e-3);
}

TEST(CompliantContact, TheIntegratorsAgreeAndTheSwitchSavesWork) {
  // a rigid block under a one-sine pulse on plastic springs (it rocks, lands and overturns as the
  // impulsive model says): DOPRI5 alone, the Rosenbrock method alone and the automatic switch
  // give the same motion to the tolerance; at a loose tolerance the explicit method is held by
  // the springs' stability and the switch does the run with fewer right-hand sides. (The counts
  // of touches and the time of overturning differ by a few ms: the toppling block's pivot skips
  // on its spring past 75 degrees, thousands of touches that no two integrations place alike.)
  const Body body(rigid_block(0.4, 1.8, 800.0));
  const double g = body.g();
  const GroundMotion pulse = GroundMotion::analytic(
      [g](double t) {
        return BaseAcceleration{t < 1.0 ? 0.4 * g * std::sin(2.0 * std::numbers::pi * t) : 0.0,
                                0.0};
      },
      6.0, {1.0});
  for (const double rtol : {1e-9, 1e-6}) {
    std::vector<SimulationResult> rs;
    for (const auto how :
         {ContactIntegrator::kExplicit, ContactIntegrator::kImplicit, ContactIntegrator::kAuto}) {
      SimulationOptions o = compliant(body, 1000.0, 4.0);
      o.rtol = rtol;
      o.atol = 1e-3 * rtol;
      o.methods.contact_integrator = how;
      rs.push_back(simulate(body, pulse, {}, o));
      ASSERT_EQ(rs.back().status, Status::kOverturned) << rs.back().message;
    }
    for (std::size_t i = 1; i < rs.size(); ++i) {
      EXPECT_NEAR(rs[i].extremes.max_theta_edge1, rs[0].extremes.max_theta_edge1,
                  2e3 * rtol * rs[0].extremes.max_theta_edge1)
          << "rtol " << rtol << " integrator " << i;
    }
    std::printf("rtol %g: right-hand sides explicit %ld, Rosenbrock %ld, switching %ld\n", rtol,
                rs[0].rhs_evaluations, rs[1].rhs_evaluations, rs[2].rhs_evaluations);
    // the switch never costs much more than the better of the two
    const double best = static_cast<double>(std::min(rs[0].rhs_evaluations, rs[1].rhs_evaluations));
    EXPECT_LT(static_cast<double>(rs[2].rhs_evaluations), 1.3 * best);
    if (rtol > 1e-8) {
      EXPECT_LT(2 * rs[2].rhs_evaluations, rs[0].rhs_evaluations);
    }
  }
}

}  // namespace
}  // namespace flexrock
