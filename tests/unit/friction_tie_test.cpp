// SPDX-License-Identifier: BSD-3-Clause
// A base acceleration that touches the friction limit exactly (docs/theory.md, "Sliding", the tie
// at m_s = 0): a sampled record whose peak sample is mu_s g. Coulomb's law holds the contact up to
// and including |F_I| = mu_s F_J, so with mu_k = mu_s nothing slides (the offset stays zero, the
// run completes); with mu_k < mu_s the slide that starts there grows, and its distance is the
// closed form below.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "flexrock/contact/friction_impact.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

constexpr double g = kStandardGravity;

// a squat block (b/h = 2): it cannot uplift below 2 g, so it only slides
Body squat_block() { return Body(BodyParameters::rectangular_block(100.0, 1.0, 0.5)); }

// a triangle sampled every 0.02 s over 2 s whose peak sample, at t = 1 s, is `peak` exactly
GroundMotion triangle(double peak) {
  std::vector<double> t, a;
  for (int i = 0; i <= 100; ++i) {
    t.push_back(0.02 * i);
    a.push_back(i == 50 ? peak : peak * (1.0 - std::abs(i - 50) / 50.0));
  }
  return GroundMotion::sampled(t, a, {});
}

SimulationOptions with_friction(double mu_s, double mu_k, double rtol = 1e-9) {
  SimulationOptions o;
  o.friction_coefficient = mu_s;
  o.kinetic_friction_coefficient = mu_k;
  o.rtol = rtol;
  return o;
}

// the decision itself: a slide that never grew sticks at a margin that rounding left at or below
// zero; one that moved slides on there (a margin of zero holds nothing)
TEST(FrictionTie, StickOrSlipDecidesTheTieByTheSlide) {
  for (double margin : {0.0, -5.5e-17}) {
    const StickOrSlip held = stick_or_slip(0.3, margin, true);
    EXPECT_TRUE(held.sticks);
    EXPECT_TRUE(held.tie);
    EXPECT_EQ(held.slip, 0);
    const StickOrSlip moved = stick_or_slip(0.3, margin, false);
    EXPECT_FALSE(moved.sticks);
    EXPECT_EQ(moved.slip, -1);
  }
  EXPECT_FALSE(stick_or_slip(0.3, 1e-300, true).tie);  // a positive margin is no tie
}

// |a| <= mu_s g throughout and mu_k = mu_s: the floor holds the block, whatever rounding does to
// the margin at the peak (these coefficients include ties that round either way)
TEST(FrictionTie, PeakSampleAtTheLimitHoldsTheBlock) {
  for (double mu : {0.1, 0.2, 0.25, 0.3, 0.35, 0.5, 0.7}) {
    for (double sign : {1.0, -1.0}) {
      for (double rtol : {1e-9, 1e-10}) {
        std::ostringstream what;
        what << "mu " << mu << " sign " << sign << " rtol " << rtol;
        const auto r =
            simulate(squat_block(), triangle(sign * (mu * g)), {}, with_friction(mu, mu, rtol));
        ASSERT_EQ(r.status, Status::kCompleted) << what.str() << ": " << r.message;
        EXPECT_EQ(r.final_offset, 0.0) << what.str();
        EXPECT_EQ(r.extremes.max_offset, 0.0) << what.str();
        EXPECT_EQ(r.extremes.sliding_time, 0.0) << what.str();
        EXPECT_EQ(r.final_phase, ContactMode::kFullContact) << what.str();
        EXPECT_EQ(r.energy.friction_loss, 0.0) << what.str();
      }
    }
  }
}

// mu_k < mu_s: at the peak the slide starts with s d'' = (mu_s - mu_k) g > 0 and grows. With
// tau = t - 1 s and a = mu_s g (1 - tau) after the peak, s d' = g tau (mu_s - mu_k - mu_s tau / 2)
// stops at tau* = 2 (mu_s - mu_k) / mu_s (< 1 here), where |a| < mu_s g holds it:
// |d| = g ((mu_s - mu_k) tau*^2 / 2 - mu_s tau*^3 / 6), against the floor's acceleration.
TEST(FrictionTie, PeakSampleAtTheLimitSlidesWhenKineticFrictionIsLower) {
  for (auto [mu_s, mu_k] : {std::pair{0.3, 0.2}, std::pair{0.25, 0.2}, std::pair{0.5, 0.4}}) {
    for (double sign : {1.0, -1.0}) {
      const auto r =
          simulate(squat_block(), triangle(sign * (mu_s * g)), {}, with_friction(mu_s, mu_k));
      ASSERT_EQ(r.status, Status::kCompleted) << r.message;
      const double ts = 2.0 * (mu_s - mu_k) / mu_s;
      const double d = g * ((mu_s - mu_k) * ts * ts / 2.0 - mu_s * ts * ts * ts / 6.0);
      EXPECT_NEAR(r.final_offset, -sign * d, 1e-9 * d) << mu_s << " " << mu_k << " " << sign;
      EXPECT_NEAR(r.extremes.sliding_time, ts, 1e-9) << mu_s << " " << mu_k << " " << sign;
      EXPECT_EQ(r.extremes.slips, 1);
      EXPECT_EQ(r.final_phase, ContactMode::kFullContact);
    }
  }
}

}  // namespace
}  // namespace flexrock
