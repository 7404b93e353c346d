// SPDX-License-Identifier: BSD-3-Clause
// Deformable bodies against closed forms and conservation laws.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "flexrock/sim/simulate.hpp"
#include "support/bodies.hpp"

namespace flexrock {
namespace {

constexpr double g = kStandardGravity;
using cd = std::complex<double>;

test::Oscillator tuned_oscillator(double f_hz = 2.0, double zeta = 0.05) {
  test::Oscillator o;
  o.k = o.m * std::pow(2 * M_PI * f_hz, 2);
  o.zeta = zeta;
  return o;
}

// steady-state complex amplitude of u (top-mass displacement) under Xdd = A sin(w t)
cd steady_amplitude(const test::Oscillator& o, double A, double w) {
  const double c = 2 * o.zeta * o.omega() * o.m;
  return -o.m * A / cd(o.k - o.m * w * w, c * w);
}

TEST(FlexibleBody, NoUpliftFollowsFixedBaseClosedForm) {
  // below the uplift threshold the oscillator is an SDOF system on a fixed base:
  // m u'' + c u' + k u = -m A sin(w t), from rest
  const auto o = tuned_oscillator(2.0, 0.05);
  const Body body(o.params());
  const double A = 0.02 * g, w = 0.8 * o.omega();
  const auto motion = GroundMotion::analytic(
      [&](double t) {
        return BaseAcceleration{A * std::sin(w * t), 0.0};
      },
      5.0);
  SimulationOptions opt;
  opt.output_dt = 0.05;
  opt.rtol = 1e-11;
  opt.atol = 1e-13;
  const auto res = simulate(body, motion, {}, opt);
  ASSERT_EQ(res.extremes.first_uplift_time, -1.0);
  const cd U = steady_amplitude(o, A, w);
  const double wn = o.omega(), z = o.zeta, wd = wn * std::sqrt(1 - z * z);
  const double up0 = U.imag(), vp0 = (cd(0, w) * U).imag();
  const double c1 = -up0, c2 = (-vp0 + z * wn * c1) / wd;
  double umax = 0;
  for (std::size_t i = 0; i < res.history.size(); ++i) {
    const double t = res.history.time[i];
    const double u = (U * std::exp(cd(0, w * t))).imag() +
                     std::exp(-z * wn * t) * (c1 * std::cos(wd * t) + c2 * std::sin(wd * t));
    umax = std::max(umax, std::abs(u));
    EXPECT_NEAR(res.history.q[i] * o.h(), u, 1e-9 * std::abs(U)) << "t = " << t;
  }
  EXPECT_GT(umax, 0.5 * std::abs(U));
}

// Exact response of m u'' + c u' + k u = -m a(t) with a(t) linear between samples (the
// piecewise-exact recurrence of Nigam & Jennings): on each interval the forcing is f0 + f1 s.
std::vector<double> exact_piecewise_linear(const test::Oscillator& o, const std::vector<double>& t,
                                           const std::vector<double>& a) {
  const double wn = o.omega(), z = o.zeta, wd = wn * std::sqrt(1 - z * z);
  const double c = 2 * z * wn * o.m;
  std::vector<double> u(t.size(), 0.0);
  double u0 = 0, v0 = 0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double dt = t[i + 1] - t[i];
    const double f0 = -o.m * a[i], f1 = -o.m * (a[i + 1] - a[i]) / dt;
    // particular solution of the linear forcing: up = p0 + p1 s
    const double p1 = f1 / o.k, p0 = (f0 - c * p1) / o.k;
    const double c1 = u0 - p0, c2 = (v0 - p1 + z * wn * c1) / wd;
    const double e = std::exp(-z * wn * dt), co = std::cos(wd * dt), si = std::sin(wd * dt);
    const double uh = e * (c1 * co + c2 * si);
    const double vh = e * (-z * wn * (c1 * co + c2 * si) + wd * (-c1 * si + c2 * co));
    u0 = uh + p0 + p1 * dt;
    v0 = vh + p1;
    u[i + 1] = u0;
  }
  return u;
}

TEST(FlexibleBody, SampledRecordKeepsFullAccuracyAcrossKinks) {
  // a random record with uneven sample spacing, below uplift: the fixed-base response is exact.
  // (Steps end on the samples; without that the step control still recovers the accuracy by
  // rejecting steps at the kinks, at about 1.6 times the steps.)
  const auto o = tuned_oscillator(3.0, 0.03);
  const Body body(o.params());
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> t{0.0}, a{0.0};
  while (t.back() < 4.0) {
    t.push_back(t.back() + 0.005 + 0.02 * u(rng));
    a.push_back(0.03 * g * (2 * u(rng) - 1));
  }
  const auto motion = GroundMotion::sampled(t, a);
  SimulationOptions opt;
  opt.rtol = 1e-11;
  opt.atol = 1e-14;
  opt.max_step = 1.0;
  opt.output_dt = 0.0;
  // compare at the samples themselves, where the exact recurrence is defined
  const auto exact = exact_piecewise_linear(o, t, a);
  double umax = 0;
  for (double v : exact) umax = std::max(umax, std::abs(v));
  for (std::size_t k : {t.size() / 4, t.size() / 2, t.size() - 1}) {
    opt.t_end = t[k];
    // integrated by DOPRI5, and propagated exactly between the samples (the default): the
    // latter is the same recurrence as the reference, so it agrees to rounding
    opt.methods.exact_full_contact = false;
    const auto res = simulate(body, motion, {}, opt);
    ASSERT_EQ(res.extremes.first_uplift_time, -1.0);
    EXPECT_NEAR(res.final_q(0) * o.h(), exact[k], 1e-8 * umax) << "at t = " << t[k];
    opt.methods.exact_full_contact = true;
    const auto ex = simulate(body, motion, {}, opt);
    ASSERT_EQ(ex.extremes.first_uplift_time, -1.0);
    EXPECT_NEAR(ex.final_q(0) * o.h(), exact[k], 1e-12 * umax) << "at t = " << t[k];
    EXPECT_EQ(ex.rhs_evaluations, 0);
  }
}

// the linear steady-state base moment about an edge: M g b + m g u - m H (u'' + Xdd); its
// oscillating part is -(k H + m g) u - c H u'. Uplift when its amplitude reaches M g b.
double uplift_amplitude(const test::Oscillator& o, double w) {
  const double c = 2 * o.zeta * o.omega() * o.m;
  const cd per_unit_A = steady_amplitude(o, 1.0, w);
  const double moment_per_A = std::abs(per_unit_A * cd(o.k * o.H + o.m * g, c * o.H * w));
  return o.M() * g * o.b / moment_per_A;
}

TEST(FlexibleBody, ResonantOscillatorUpliftsAtLinearPrediction) {
  const auto o = tuned_oscillator(2.0, 0.05);
  const Body body(o.params());
  const double w = o.omega();
  const double a_crit = uplift_amplitude(o, w);
  // the paper's central point: far below the rigid threshold g b/h
  EXPECT_LT(a_crit, 0.15 * g * o.b / o.h());
  for (double factor : {0.99, 1.01}) {
    const double A = factor * a_crit;
    // start on the steady state, so no transient blurs the threshold
    const cd U = steady_amplitude(o, A, w);
    InitialState init;
    init.q = VectorX::Constant(1, U.imag() / o.h());
    init.q_dot = VectorX::Constant(1, (cd(0, w) * U).imag() / o.h());
    const double periods = 10;
    const auto motion = GroundMotion::analytic(
        [&](double t) {
          return BaseAcceleration{A * std::sin(w * t), 0.0};
        },
        periods * 2 * M_PI / w);
    const auto res = simulate(body, motion, init);
    if (factor < 1) {
      EXPECT_EQ(res.extremes.first_uplift_time, -1.0) << "uplift below the predicted amplitude";
    } else {
      EXPECT_GE(res.extremes.first_uplift_time, 0.0) << "no uplift above the predicted amplitude";
      EXPECT_LT(res.extremes.first_uplift_time, 2 * M_PI / w);
    }
  }
}

class FlexibleEnergy : public ::testing::TestWithParam<int> {};

TEST_P(FlexibleEnergy, ConservedBetweenImpactsWithoutDampingOrBaseMotion) {
  const int n = GetParam();
  // mostly horizontal modes: a body that keeps contact while it rocks
  const auto p = test::random_lumped_body(n, 40u + static_cast<unsigned>(n), 5e4, 0.002);
  const Body body(p);
  InitialState init;
  init.theta = 0.4 * std::min(body.tipping_angle(1), body.tipping_angle(2));
  init.q_dot = VectorX::Constant(n, 0.02);
  SimulationOptions opt;
  opt.t_end = 3.0;
  opt.output_dt = 0.005;
  opt.rtol = 1e-11;
  opt.atol = 1e-13;
  const auto res = simulate(body, GroundMotion::none(opt.t_end), init, opt);
  // after an impact the modes keep their momenta and can pull the pivot up: the body then flies;
  // the balance must hold throughout
  ASSERT_EQ(res.status, Status::kCompleted) << res.message;
  const auto& h = res.history;
  const double e0 = h.kinetic[0] + h.potential[0];
  const double scale = std::max(h.kinetic[0], 1e-3 * e0);
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double e = h.kinetic[i] + h.potential[i] + h.impact_loss[i];
    EXPECT_NEAR(e, e0, 1e-9 * e0) << "n = " << n << ", t = " << h.time[i];
  }
  long impacts = 0;
  for (const auto& e : res.events) {
    if (e.kind == EventKind::kImpact || e.kind == EventKind::kRockingEnded) {
      ++impacts;
      EXPECT_GE(e.energy_loss, 0.0) << "an impact gained energy at t = " << e.time;
    }
  }
  EXPECT_GT(impacts, 0);
  EXPECT_LT(std::abs(res.energy.residual), 1e-9 * (e0 + scale));
}

INSTANTIATE_TEST_SUITE_P(Modes, FlexibleEnergy, ::testing::Values(1, 2, 3, 4, 6, 10));

TEST(FlexibleBody, EnergyBalanceClosesUnderDampedRecordLikeShaking) {
  auto p = test::random_lumped_body(3, 77, 5e4);
  p.damping.kind = DampingKind::kModal;
  p.damping.modal_ratios = VectorX::Constant(3, 0.05);
  const Body body(p);
  const double amp = 1.5 * g * std::min(body.alpha1(), body.alpha2());
  const auto motion = GroundMotion::analytic(
      [&](double t) {
        return BaseAcceleration{amp * std::sin(6 * t) * std::exp(-0.2 * t),
                                0.2 * g * std::sin(11 * t)};
      },
      8.0);
  SimulationOptions opt;
  opt.rtol = 1e-10;
  opt.atol = 1e-12;
  const auto res = simulate(body, motion, {}, opt);
  ASSERT_GT(res.extremes.impacts, 0);
  ASSERT_NE(res.status, Status::kStopped) << res.message;
  EXPECT_GT(res.energy.damping_loss, 0.0);
  // the base does work on the body (its sign depends on where the body ends: one that flew or
  // fell may end lower than it started)
  EXPECT_NE(res.energy.input_work, 0.0);
  EXPECT_LT(std::abs(res.energy.residual), 1e-7 * res.energy.scale)
      << to_string(res.status) << ", " << res.extremes.lift_offs << " lift-offs";
}

TEST(FlexibleBody, MirroredExcitationMirrorsSymmetricBody) {
  const auto o = tuned_oscillator(2.0, 0.05);
  const Body body(o.params());
  auto motion = [&](double s) {
    return GroundMotion::analytic(
        [s, &o](double t) {
          return BaseAcceleration{s * 0.08 * g * std::sin(o.omega() * t), 0.0};
        },
        6.0);
  };
  SimulationOptions opt;
  opt.output_dt = 0.01;
  const auto a = simulate(body, motion(1.0), {}, opt);
  const auto b = simulate(body, motion(-1.0), {}, opt);
  ASSERT_GT(a.extremes.impacts, 0);
  ASSERT_EQ(a.history.size(), b.history.size());
  for (std::size_t i = 0; i < a.history.size(); ++i) {
    EXPECT_NEAR(a.history.theta[i], -b.history.theta[i], 1e-9);
    EXPECT_NEAR(a.history.q[i], -b.history.q[i], 1e-9);
  }
}

TEST(FlexibleBody, ManyModesRunOnTheHeapPath) {
  // n = 20 goes beyond the stack-bounded sizes: same physics, same checks
  const auto p = test::random_lumped_body(20, 5, 5e4, 0.002);
  const Body body(p);
  InitialState init;
  init.theta = 0.05;
  SimulationOptions opt;
  opt.t_end = 1.0;
  const auto res = simulate(body, GroundMotion::none(opt.t_end), init, opt);
  EXPECT_EQ(res.status, Status::kCompleted) << res.message;
  EXPECT_GT(res.extremes.impacts, 0);
  EXPECT_LT(std::abs(res.energy.residual), 1e-7 * res.energy.scale);
}

}  // namespace
}  // namespace flexrock
