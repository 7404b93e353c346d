// SPDX-License-Identifier: BSD-3-Clause
// The hand estimates of a qualification (study/hand_estimates.hpp) against what they claim to
// be: the closed forms against the engine where they are exact (sliding and uplift thresholds,
// Newmark's block under a rectangular pulse), the linearized Housner forms against the engine
// with their error falling at the stated order, and the exact Newmark integration against the
// engine's sliding of a block that cannot uplift under a sampled record.
#include "flexrock/study/hand_estimates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock::study {
namespace {

constexpr double g = kStandardGravity;

SimulationOptions tight(double mu = std::numeric_limits<double>::infinity()) {
  SimulationOptions o;
  o.rtol = 1e-11;
  o.atol = 1e-13;
  o.friction_coefficient = mu;
  return o;
}

// smallest x in [lo, hi] for which fails(x), by bisection to a relative 1e-9
double threshold(double lo, double hi, const std::function<bool(double)>& fails) {
  EXPECT_FALSE(fails(lo));
  EXPECT_TRUE(fails(hi));
  while (hi - lo > 1e-9 * hi) {
    const double mid = 0.5 * (lo + hi);
    (fails(mid) ? hi : lo) = mid;
  }
  return hi;
}

TEST(HandEstimates, UpliftThresholdIsWhereTheEngineLeavesFullContactOnEitherEdge) {
  // an asymmetric rigid body: g b1/h lifts onto edge 1 (a > 0), g b2/h onto edge 2 (a < 0)
  const BodyParameters p = BodyParameters::rigid(300.0, 0.9, 0.2, 0.35, 0.44);
  const Body body(p);
  for (int edge : {1, 2}) {
    const double a_up = uplift_threshold(p, edge);
    EXPECT_DOUBLE_EQ(a_up, g * (edge == 1 ? 0.2 : 0.35) / 0.9);
    const double sign = edge == 1 ? 1.0 : -1.0;
    for (double f : {0.999, 1.001}) {
      const auto r = simulate(body, rectangular_pulse(sign * f * a_up, 0.5, 1.0), {}, tight());
      EXPECT_EQ(r.extremes.first_uplift_time >= 0.0, f > 1.0) << "edge " << edge << " x" << f;
      if (f > 1.0) {
        EXPECT_EQ(r.extremes.first_uplift_edge, edge);
      }
    }
  }
}

TEST(HandEstimates, SlidingThresholdIsWhereTheEngineSlips) {
  const Body squat(BodyParameters::rectangular_block(100.0, 1.0, 0.5));  // b/h = 2: no uplift
  for (double mu : {0.2, 0.5}) {
    const double a_s = sliding_threshold(mu, g);
    for (double f : {0.999, 1.001}) {
      const auto r = simulate(squat, rectangular_pulse(f * a_s, 0.5, 1.0), {}, tight(mu));
      EXPECT_EQ(r.extremes.slips > 0, f > 1.0) << "mu " << mu << " x" << f;
    }
  }
}

TEST(HandEstimates, NewmarkRectangularPulseIsTheEnginesSlidingDistance) {
  const Body squat(BodyParameters::rectangular_block(100.0, 1.0, 0.5));
  for (double mu : {0.1, 0.3}) {
    for (double A_over_g : {0.35, 0.6, 1.2}) {
      const double A = A_over_g * g, t1 = 0.2;
      const double d = newmark_rectangular_displacement(A, t1, mu, g);
      if (A <= mu * g) {
        EXPECT_EQ(d, 0.0);
        continue;
      }
      const auto r = simulate(squat, rectangular_pulse(A, t1, 3.0), {}, tight(mu));
      EXPECT_NEAR(r.extremes.max_offset, d, 1e-10 * d) << mu << " " << A_over_g;
      // the exact integration of samples with a jump: the same closed form
      const std::vector<double> t = {0.0, t1, t1, 3.0}, a = {A, A, 0.0, 0.0};
      const NewmarkResult n = newmark_sliding(t, a, mu, mu, g);
      EXPECT_NEAR(n.max_offset, d, 1e-12 * d);
      EXPECT_NEAR(n.final_offset, -d, 1e-12 * d);  // the block lags the floor
      EXPECT_NEAR(n.sliding_time, t1 * A / (mu * g), 1e-12);
      EXPECT_EQ(n.slips, 1);
    }
  }
}

TEST(HandEstimates, NewmarkBlockUnderASampledRecordIsTheEnginesSquatBlock) {
  // a record of three sines with a jump-free envelope, sampled at 0.01 s: the engine's squat
  // block (it cannot uplift below 2 g) and the exact two-way Newmark block see the same
  // piecewise-linear acceleration
  std::vector<double> t, a;
  for (int i = 0; i <= 800; ++i) {
    const double ti = 0.01 * i, env = std::sin(M_PI * ti / 8.0);
    t.push_back(ti);
    a.push_back(g * env *
                (0.35 * std::sin(2.0 * M_PI * 1.3 * ti) + 0.2 * std::sin(2.0 * M_PI * 3.1 * ti) +
                 0.1 * std::sin(2.0 * M_PI * 0.7 * ti + 1.0)));
  }
  const Body squat(BodyParameters::rectangular_block(100.0, 1.0, 0.5));
  for (double mu : {0.15, 0.3}) {
    const NewmarkResult n = newmark_sliding(t, a, mu, mu, g);
    const auto r = simulate(squat, GroundMotion::sampled(t, a), {}, tight(mu));
    ASSERT_GT(n.slips, 1) << "the record must make the block slide both ways";
    EXPECT_NEAR(n.max_offset, r.extremes.max_offset, 1e-9) << mu;
    EXPECT_NEAR(n.final_offset, r.final_offset, 1e-9) << mu;
    EXPECT_NEAR(n.sliding_time, r.extremes.sliding_time, 1e-9) << mu;
    EXPECT_EQ(n.slips, r.extremes.slips) << mu;
  }
}

// the engine's smallest overturning amplitude of a rectangular pulse of duration t1
double engine_rectangular_threshold(const Body& body, double t1, double lo, double hi) {
  const double free = 60.0 / body.rocking_frequency();
  return threshold(lo, hi, [&](double a) {
    return overturned(simulate(body, rectangular_pulse(a, t1, t1 + free), {}, tight()));
  });
}

TEST(HandEstimates, HousnerRectangularPulseIsTheEnginesThresholdToSecondOrderInAlpha) {
  // uniform blocks of half-diagonal 1 m: the linearized closed form's error falls as alpha^2
  double previous = 0.0;
  for (double alpha : {0.08, 0.04, 0.02}) {
    const BodyParameters p =
        BodyParameters::rectangular_block(100.0, std::sin(alpha), std::cos(alpha));
    const RockingConstants c = rocking_constants(p, 1);
    EXPECT_NEAR(c.alpha, alpha, 1e-15);
    EXPECT_NEAR(c.p, std::sqrt(3.0 * g / 4.0), 1e-12);  // Housner's p of a block, R = 1 m
    const double t1 = 1.0 / c.p;
    const double hand = housner_rectangular_min_amplitude(c, g, t1);
    EXPECT_NEAR(housner_rectangular_min_duration(c, g, hand), t1, 1e-12 * t1);  // the inverse
    const double engine = engine_rectangular_threshold(Body(p), t1, 0.9 * hand, 1.2 * hand);
    const double err = std::abs(engine / hand - 1.0);
    EXPECT_LT(err, 0.6 * alpha * alpha) << alpha;
    if (previous > 0.0) {
      EXPECT_NEAR(previous / err, 4.0, 0.6) << alpha;
    }
    previous = err;
  }
}

TEST(HandEstimates, HousnerCriticalVelocityIsTheEnginesImpulseThresholdToFirstOrderInPulseLength) {
  // a velocity change V delivered by ever shorter rectangular pulses (V/tau over tau): the
  // engine's smallest overturning V tends to the energy criterion's, the gap ~ p tau
  const BodyParameters p = BodyParameters::rigid(300.0, 0.9, 0.2, 0.35, 0.44);
  const Body body(p);
  const RockingConstants c = rocking_constants(p, 1);
  const double V = housner_critical_velocity(c, p.mass, p.height, g);
  // the closed form by hand for this body: I_O = I_cg + M R^2, barrier M g (R - h)
  const double I_O = 0.44 * 300.0 * 0.81 + 300.0 * (0.04 + 0.81);
  EXPECT_NEAR(V, std::sqrt(2.0 * 300.0 * g * (std::hypot(0.2, 0.9) - 0.9) * I_O) / (300.0 * 0.9),
              1e-12);
  double previous = 0.0;
  for (double ptau : {0.02, 0.01, 0.005}) {
    const double tau = ptau / c.p;
    const double free = 10.0 / c.p;
    const double v_engine = threshold(0.8 * V, 1.5 * V, [&](double v) {
      return overturned(simulate(body, rectangular_pulse(v / tau, tau, tau + free), {}, tight()));
    });
    const double err = v_engine / V - 1.0;
    EXPECT_GT(err, 0.0) << "a finite pulse needs more than the impulse";
    EXPECT_LT(err, 2.0 * ptau) << ptau;
    if (previous > 0.0) {
      EXPECT_NEAR(previous / err, 2.0, 0.3) << ptau;
    }
    previous = err;
  }
}

}  // namespace
}  // namespace flexrock::study
