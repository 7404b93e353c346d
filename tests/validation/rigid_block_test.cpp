// SPDX-License-Identifier: BSD-3-Clause
// Housner's rigid block against closed forms.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <vector>

#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

constexpr double g = kStandardGravity;

std::vector<Event> of_kind(const SimulationResult& r, EventKind k) {
  std::vector<Event> out;
  for (const auto& e : r.events)
    if (e.kind == k) out.push_back(e);
  return out;
}

// Exact free rocking of a symmetric rigid block (no base motion), by quadrature of the energy
// integral: time to fall from a peak theta0 to theta = 0.
struct ExactFreeRocking {
  double alpha, zeta2, h;
  double m() const { return 1 + zeta2 + alpha * alpha; }
  // V(theta0) - V(theta0 - d) over M g h, from the difference d itself (no cancellation)
  double dv(double th0, double d) const {
    return 2 * std::sin(0.5 * d) * (alpha * std::cos(th0 - 0.5 * d) - std::sin(th0 - 0.5 * d));
  }
  double fall_time(double th0) const {
    // theta = th0 (1 - v^2) removes the square-root singularity at the peak
    auto f = [&](double v) {
      if (v == 0.0) {
        const double dvdth = alpha * std::cos(th0) - std::sin(th0);
        return 2.0 * std::sqrt(th0) / std::sqrt(2 * g / (h * m()) * dvdth);
      }
      return 2 * th0 * v / std::sqrt(2 * g / (h * m()) * dv(th0, th0 * v * v));
    };
    return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, 0.0, 1.0, 15, 1e-15);
  }
  // next peak from the energy left after an impact with angular velocity ratio r
  double next_peak(double th, double r) const {
    const double aH = std::atan(alpha);
    return aH - std::acos(std::cos(aH) + r * r * (std::cos(aH - th) - std::cos(aH)));
  }
};

TEST(RigidBlock, FreeRockingMatchesExactSolution) {
  const double b = 0.2, h = 1.0;
  const Body body(BodyParameters::rectangular_block(1000, b, h));
  const ExactFreeRocking ex{b / h, (1 + b * b / (h * h)) / 3, h};
  const double r = 1 - 1.5 * std::pow(std::sin(std::atan(b / h)), 2);
  SimulationOptions opt;
  opt.t_end = 8.0;
  opt.rtol = 1e-12;
  opt.atol = 1e-14;
  InitialState init;
  init.theta = 0.8 * b / h;
  const auto res = simulate(body, GroundMotion::none(opt.t_end), init, opt);
  const auto impacts = of_kind(res, EventKind::kImpact);
  const auto peaks = of_kind(res, EventKind::kPeak);
  ASSERT_GE(impacts.size(), 6u);
  double th = init.theta, t = ex.fall_time(th);
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_NEAR(impacts[k].time, t, 1e-8 * t) << "impact " << k;
    th = ex.next_peak(th, r);
    const double tf = ex.fall_time(th);
    ASSERT_GT(peaks.size(), k);
    EXPECT_NEAR(std::abs(peaks[k].theta), th, 1e-8 * th) << "peak " << k;
    EXPECT_NEAR(peaks[k].time, t + tf, 1e-8 * (t + tf)) << "peak time " << k;
    EXPECT_NEAR(impacts[k].theta_dot_after / impacts[k].theta_dot_before, r, 1e-12);
    t += 2 * tf;
  }
}

TEST(RigidBlock, EnergyConstantBetweenImpactsAndLostAtThem) {
  const Body body(BodyParameters::rectangular_block(500, 0.3, 1.2));
  SimulationOptions opt;
  opt.t_end = 6.0;
  opt.output_dt = 0.01;
  InitialState init;
  init.theta = 0.15;
  const auto res = simulate(body, GroundMotion::none(opt.t_end), init, opt);
  const auto& hist = res.history;
  const double e0 = hist.kinetic[0] + hist.potential[0];
  for (std::size_t i = 0; i < hist.size(); ++i) {
    // mechanical energy plus what impacts took is the initial energy
    const double e = hist.kinetic[i] + hist.potential[i] + hist.impact_loss[i];
    EXPECT_NEAR(e, e0, 1e-9 * e0) << "t = " << hist.time[i];
  }
  for (const auto& e : res.events) {
    if (e.kind == EventKind::kImpact) {
      EXPECT_GT(e.energy_loss, 0.0);
    }
  }
  EXPECT_LT(std::abs(res.energy.residual), 1e-9 * e0);
}

// ramp Xdd = rate t with a constant Ydd: uplift when Xdd/g reaches alpha1 (1 + Ydd/g)
TEST(RigidBlock, VerticalAccelerationScalesUpliftThreshold) {
  const double a1 = 0.25;
  const Body body(BodyParameters::rigid(100, 1.0, a1, 0.4, 0.4));
  for (double a0 : {-0.5 * g, 0.0, 0.7 * g}) {
    const double rate = 2.0;  // [m/s^3]
    const auto motion = GroundMotion::analytic(
        [&](double t) {
          return BaseAcceleration{rate * t, a0};
        },
        3.0);
    SimulationOptions opt;
    opt.t_end = 3.0;
    const auto res = simulate(body, motion, {}, opt);
    const double expected = a1 * (g + a0) / rate;
    EXPECT_NEAR(res.extremes.first_uplift_time, expected, 1e-10 * expected) << "a0 = " << a0;
    EXPECT_EQ(res.extremes.first_uplift_edge, 1);
  }
}

TEST(RigidBlock, BaseFallingFasterThanGravityLetsTheBlockFly) {
  // Ydd = -rate t: the floor stops pressing at t = g/rate and falls away for good; the block
  // flies level (theta = 0) until the end, its lower edge at height int int (-g + rate t)
  const Body body(BodyParameters::rectangular_block(100, 0.3, 1.0));
  const double rate = 5.0;
  const auto motion = GroundMotion::analytic(
      [&](double t) {
        return BaseAcceleration{0.0, -rate * t};
      },
      4.0);
  SimulationOptions opt;
  opt.output_dt = 0.5;
  const auto res = simulate(body, motion, {}, opt);
  EXPECT_EQ(res.status, Status::kCompleted) << res.message;
  ASSERT_FALSE(res.events.empty());
  EXPECT_EQ(res.events.front().kind, EventKind::kLiftOff);
  EXPECT_NEAR(res.events.front().time, g / rate, 1e-10);
  EXPECT_EQ(res.final_phase, ContactMode::kFlight);
  // relative height: y'' = -g + rate t from t0 = g/rate with y = y' = 0 there
  const double t0 = g / rate, tau = 4.0 - t0;
  const double expected =
      -0.5 * g * tau * tau + rate * (tau * tau * tau / 6.0 + 0.5 * t0 * tau * tau);
  EXPECT_NEAR(res.history.lift.back(), expected, 1e-9 * expected);
  EXPECT_NEAR(res.energy.residual, 0.0, 1e-9 * res.energy.scale);
}

TEST(RigidBlock, AsymmetricBlockTipsAboutTheNearerEdge) {
  // b1 = 0.2 h < b2 = 0.4 h; Xdd = -A sin(w t): the first half cycle (toward edge 2) stays below
  // g b2/h, the second exceeds g b1/h and tips the body about edge 1 at a known time
  const Body body(BodyParameters::rigid(100, 1.0, 0.2, 0.4, 0.4));
  const double A = 0.3 * g, w = 2 * M_PI;
  const auto motion = GroundMotion::analytic(
      [&](double t) {
        return BaseAcceleration{-A * std::sin(w * t), 0.0};
      },
      2.0);
  const auto res = simulate(body, motion);
  ASSERT_GE(res.extremes.first_uplift_time, 0.0);
  EXPECT_EQ(res.extremes.first_uplift_edge, 1);
  const double expected = (M_PI + std::asin(0.2 / 0.3)) / w;
  EXPECT_NEAR(res.extremes.first_uplift_time, expected, 1e-9);
}

TEST(RigidBlock, MirroredExcitationMirrorsResponse) {
  const Body body(BodyParameters::rectangular_block(100, 0.25, 1.0));
  auto motion = [](double s) {
    return GroundMotion::analytic(
        [s](double t) {
          return BaseAcceleration{s * 0.5 * g * std::sin(8 * t), 0.1 * g * std::cos(3 * t)};
        },
        4.0);
  };
  SimulationOptions opt;
  opt.output_dt = 0.01;
  const auto a = simulate(body, motion(1.0), {}, opt);
  const auto b = simulate(body, motion(-1.0), {}, opt);
  ASSERT_EQ(a.history.size(), b.history.size());
  ASSERT_GT(a.extremes.impacts, 2);
  for (std::size_t i = 0; i < a.history.size(); ++i) {
    EXPECT_NEAR(a.history.theta[i], -b.history.theta[i], 1e-10);
  }
  EXPECT_EQ(a.extremes.first_uplift_edge, 3 - b.extremes.first_uplift_edge);
}

TEST(RigidBlock, UpliftStartsWithoutAFalseImpact) {
  // a half-sine pulse just above the threshold: uplift, one excursion, then an impact much later
  const Body body(BodyParameters::rectangular_block(100, 0.2, 1.0));
  const double ap = 1.02 * 0.2 * g, wp = 4.0;
  const auto motion = GroundMotion::analytic(
      [&](double t) {
        return BaseAcceleration{t < M_PI / wp ? ap * std::sin(wp * t) : 0.0, 0.0};
      },
      6.0, {M_PI / wp});
  const auto res = simulate(body, motion);
  std::vector<Event> changes;
  for (const auto& e : res.events)
    if (e.kind != EventKind::kPeak) changes.push_back(e);
  ASSERT_GE(changes.size(), 2u);
  EXPECT_EQ(changes[0].kind, EventKind::kUplift);
  EXPECT_NE(changes[1].kind, EventKind::kUplift);
  EXPECT_GT(changes[1].time - changes[0].time, 0.05);
}

TEST(RigidBlock, ShortExcursionAboveThresholdBetweenSamplesIsFound) {
  // a narrow bump that exceeds g alpha by 0.05% for under a millisecond, inside a long step
  const Body body(BodyParameters::rectangular_block(100, 0.2, 1.0));
  const double peak = 1.0005 * 0.2 * g, tc = 0.50123, width = 0.01;
  const auto motion = GroundMotion::analytic(
      [&](double t) {
        const double s = (t - tc) / width;
        return BaseAcceleration{peak * std::exp(-s * s), 0.0};
      },
      1.0);
  SimulationOptions opt;
  opt.max_step = 0.01;
  const auto res = simulate(body, motion, {}, opt);
  ASSERT_GE(res.extremes.first_uplift_time, 0.0);
  // the closed-form crossing time: peak exp(-s^2) = g alpha
  const double s = std::sqrt(std::log(1.0005));
  EXPECT_NEAR(res.extremes.first_uplift_time, tc - s * width, 1e-9);
}

TEST(RigidBlock, LargeLongPulseOverturnsAndCriterionOptionGoesFurther) {
  const Body body(BodyParameters::rectangular_block(100, 0.2, 1.0));
  const double ap = 3 * 0.2 * g, wp = 2 * M_PI;
  const auto motion = GroundMotion::analytic(
      [&](double t) {
        return BaseAcceleration{t < 2 * M_PI / wp ? ap * std::sin(wp * t) : 0.0, 0.0};
      },
      10.0, {2 * M_PI / wp});
  SimulationOptions at_static;
  at_static.overturn = OverturnCriterion::kStaticInstability;
  const auto res = simulate(body, motion, {}, at_static);
  EXPECT_EQ(res.status, Status::kOverturned);
  const double theta_c = std::atan(0.2);
  EXPECT_NEAR(std::max(res.extremes.max_theta_edge1, res.extremes.max_theta_edge2), theta_c, 1e-9);
  // the extremes include the overturning instant: the lifted corner of the 0.4 m base is then
  // 0.4 sin(theta) high
  EXPECT_NEAR(res.extremes.max_uplift, 0.4 * std::sin(theta_c), 1e-9);
  SimulationOptions opt;
  opt.overturn = OverturnCriterion::kHalfPi;
  const auto further = simulate(body, motion, {}, opt);
  EXPECT_EQ(further.status, Status::kOverturned);
  EXPECT_GT(further.extremes.overturn_time, res.extremes.overturn_time);
  // the default is pi/2: the one rule of every entry point
  EXPECT_EQ(simulate(body, motion).extremes.overturn_time, further.extremes.overturn_time);
  EXPECT_NEAR(std::max(further.extremes.max_theta_edge1, further.extremes.max_theta_edge2),
              M_PI / 2, 1e-9);
  EXPECT_NEAR(further.extremes.max_uplift, 0.4, 1e-9);
}

TEST(RigidBlock, SquatBlockStopsOnBothEdgesAtFirstImpact) {
  // b/h = 1.6 > sqrt(2): the single-edge map would reverse theta_dot, so rocking ends
  const Body body(BodyParameters::rectangular_block(100, 1.6, 1.0));
  InitialState init;
  init.theta = 0.3;
  SimulationOptions opt;
  opt.t_end = 3.0;
  const auto res = simulate(body, GroundMotion::none(opt.t_end), init, opt);
  ASSERT_EQ(res.extremes.impacts, 1);
  EXPECT_EQ(of_kind(res, EventKind::kRockingEnded).size(), 1u);
  EXPECT_EQ(res.final_phase, Phase::kFullContact);
  EXPECT_EQ(res.final_theta_dot, 0.0);
  // all the kinetic energy at impact is lost: the loss equals the potential energy released
  EXPECT_NEAR(res.energy.impact_loss, -res.energy.potential_change, 1e-9 * res.energy.impact_loss);
}

TEST(RigidBlock, ChatterCutoffEndsFreeRocking) {
  const Body body(BodyParameters::rectangular_block(100, 0.2, 1.0));
  InitialState init;
  init.theta = 0.1;
  SimulationOptions opt;
  opt.t_end = 60.0;
  const auto res = simulate(body, GroundMotion::none(opt.t_end), init, opt);
  EXPECT_EQ(res.status, Status::kCompleted);
  EXPECT_TRUE(res.chatter_cut_off);
  EXPECT_EQ(res.final_phase, Phase::kFullContact);
  EXPECT_EQ(res.final_theta, 0.0);
  // everything was lost to impacts and the cut-off
  EXPECT_NEAR(res.energy.impact_loss + res.energy.chatter_loss, -res.energy.potential_change,
              1e-8 * res.energy.impact_loss);
}

}  // namespace
}  // namespace flexrock
