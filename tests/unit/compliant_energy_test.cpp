// SPDX-License-Identifier: BSD-3-Clause
// The compliant contact's energy (docs/theory.md, "Compliant contact"): its springs derive from a
// contact potential that vanishes with the penetration, so an undamped contact with no friction
// limit returns all it stores (free rocking conserves energy), and the loss it books is exactly
// its dashpots' work, integrated apart (CompliantAudit), whatever the friction.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"
#include "sim/compliant.hpp"

namespace flexrock {
namespace {

// the springs for omega_v = ratio p, omega_v = sqrt(2 k / M) the body's bounce on both
SimulationOptions compliant(const Body& body, double ratio, double zeta) {
  SimulationOptions o;
  o.contact_model = ContactModel::kCompliant;
  const double wv = ratio * body.rocking_frequency();
  o.contact_stiffness = 0.5 * body.params().mass * wv * wv;
  o.contact_damping_ratio = zeta;
  return o;
}

TEST(CompliantEnergy, UndampedFreeRockingConservesEnergy) {
  // a block let go at half its tipping angle on undamped springs with no friction limit: nothing
  // dissipates, at the default tangential stiffness and at 1/100 of it (where a sticking corner's
  // spring is still stretched when the corner leaves: its energy must come back, not vanish)
  const Body body(rigid_block(0.6, 1.8, 1000.0));
  InitialState init;
  init.theta = 0.5 * body.tipping_angle(1);
  const double mg = body.params().mass * body.g();
  for (const double tangential : {1.0, 0.01}) {
    SimulationOptions o = compliant(body, 300.0, 0.0);
    const double k_secant = o.contact_stiffness;  // linear: the secant stiffness is k
    o.contact_tangential_stiffness = tangential * k_secant;
    o.rtol = 1e-10;
    o.atol = 1e-12;
    o.t_end = 3.0;
    const auto r = simulate(body, GroundMotion::none(3.0), init, o);
    ASSERT_EQ(r.status, Status::kCompleted) << r.message;
    ASSERT_GT(r.extremes.impacts, 3);
    // the energy released from the tilt, against which the loss is measured
    const double e0 = mg * body.params().height *
                      (std::sqrt(1.0 + std::pow(std::tan(body.tipping_angle(1)), 2)) *
                           std::cos(body.tipping_angle(1) - init.theta) -
                       1.0);
    ASSERT_GT(e0, 0.0);
    std::printf("k_t / k = %g: released %.6f J, booked loss %.3e J, energy change %.3e J\n",
                tangential, e0, r.energy.impact_loss,
                r.energy.kinetic_change + r.energy.potential_change);
    EXPECT_LT(std::abs(r.energy.impact_loss), 1e-6 * e0) << "k_t / k = " << tangential;
    EXPECT_LT(std::abs(r.energy.kinetic_change + r.energy.potential_change), 1e-6 * e0)
        << "k_t / k = " << tangential;
  }
}

TEST(CompliantEnergy, BookedLossIsTheDashpotsWork) {
  // with dashpots, with and without friction, under a pulse that rocks the body and slides it:
  // the impact loss (the floor's work less what the springs hold) is the dashpots' work, and the
  // friction loss holds the slips' work with the tangential springs' energy let go as they slip
  const Body body(rigid_block(0.6, 1.8, 1000.0));
  const double g = body.g();
  const GroundMotion pulse = GroundMotion::analytic(
      [g](double t) {
        return BaseAcceleration{
            t < 0.5 ? 0.5 * g * std::sin(2.0 * std::numbers::pi * t / 0.5) : 0.0, 0.0};
      },
      2.5, {0.5});
  for (const auto law : {ContactForceLaw::kLinear, ContactForceLaw::kHuntCrossley}) {
    for (const double mu : {std::numeric_limits<double>::infinity(), 0.3}) {
      SimulationOptions o = compliant(body, 300.0, 0.3);
      o.contact_force_law = law;
      if (law == ContactForceLaw::kHuntCrossley) {
        o.contact_exponent = 1.5;
        o.contact_restitution = 0.5;
      }
      o.friction_coefficient = mu;
      o.rtol = 1e-10;
      o.atol = 1e-12;
      detail::CompliantAudit audit;
      const auto r = detail::simulate_compliant(body, pulse, {}, o, &audit);
      ASSERT_EQ(r.status, Status::kCompleted) << r.message;
      ASSERT_GT(r.extremes.impacts, 0) << to_string(law);
      std::printf(
          "%s, mu %g: impact_loss %.9g J, dashpots' work %.9g J; friction_loss %.6g J "
          "(of which released at slip starts %.6g J), %ld slips\n",
          to_string(law), mu, r.energy.impact_loss, audit.dashpot_work, r.energy.friction_loss,
          audit.released_at_slip, r.extremes.slips);
      EXPECT_GT(audit.dashpot_work, 0.0);
      EXPECT_NEAR(r.energy.impact_loss, audit.dashpot_work, 1e-6 * r.energy.scale)
          << to_string(law) << " mu " << mu;
      EXPECT_LT(std::abs(r.energy.residual), energy_residual_bound(body, r.energy.scale));
      if (std::isfinite(mu)) {
        EXPECT_GT(r.extremes.slips, 0) << to_string(law);
        EXPECT_GE(r.energy.friction_loss, audit.released_at_slip);
      } else {
        EXPECT_EQ(audit.released_at_slip, 0.0);
      }
    }
  }
}

}  // namespace
}  // namespace flexrock
