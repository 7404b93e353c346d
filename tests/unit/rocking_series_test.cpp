// SPDX-License-Identifier: BSD-3-Clause
// A rigid body's rocking stepped by its Taylor series against DOPRI5 (series_rocking = false)
// under records and pulses, the closed-form free rocking, and mirror symmetry; one series step
// under a record and one under sinusoids against an independent integration of the equation.
#include "sim/rocking_series.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/integrate/dopri5.hpp"
#include "flexrock/sim/simulate.hpp"
#include "sim/event_location.hpp"

namespace flexrock {
namespace {

constexpr double g = kStandardGravity;

std::vector<double> impact_times(const SimulationResult& r) {
  std::vector<double> out;
  for (const Event& e : r.events)
    if (e.kind == EventKind::kImpact || e.kind == EventKind::kRockingEnded ||
        e.kind == EventKind::kChatterCutoff)
      out.push_back(e.time);
  return out;
}

// a random record with uneven spacing, both components, amplitude in g
GroundMotion random_record(unsigned seed, double amplitude, double duration, double sign = 1.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> t{0.0}, ax{0.0}, ay{0.0};
  while (t.back() < duration) {
    t.push_back(t.back() + 0.004 + 0.016 * u(rng));
    // a smooth-ish random ground motion: a few harmonics with random phases plus noise
    const double s = t.back();
    ax.push_back(sign * amplitude * g *
                 (std::sin(7.0 * s) + 0.6 * std::sin(17.0 * s + 1.0) + 0.3 * (2 * u(rng) - 1)));
    ay.push_back(0.3 * amplitude * g * (std::sin(11.0 * s + 0.5) + 0.3 * (2 * u(rng) - 1)));
  }
  return GroundMotion::sampled(t, ax, ay);
}

// the one-step tests' motions: a record whose interval [0.1, 0.14] has both components, and two
// sinusoids (one per component) on [0, 2] s
GroundMotion one_record_interval() {
  return GroundMotion::sampled({0.0, 0.1, 0.14, 0.2}, {0.0, 3.1, -4.7, 0.0}, {0.0, -1.9, 2.3, 0.0});
}
double pulse_x(double t) { return 3.1 * std::sin(9.0 * t + 0.3); }
double pulse_y(double t) { return -1.9 * std::sin(14.0 * t + 2.0); }
GroundMotion two_sinusoids() {
  return GroundMotion::analytic(
             [](double t) {
               return BaseAcceleration{pulse_x(t), pulse_y(t)};
             },
             2.0)
      .with_sinusoids({SinusoidPiece{0.0, 2.0, 3.1, 9.0, 0.3, false},
                       SinusoidPiece{0.0, 2.0, -1.9, 14.0, 2.0, true}});
}

// free rocking of a symmetric rigid block: the time to fall from a peak th0 to theta = 0 by
// quadrature of the energy integral (as in the validation tests and bench/peers/compare.py)
double fall_time(double alpha, double m, double h, double th0) {
  auto dv = [&](double d) {
    return 2 * std::sin(0.5 * d) * (alpha * std::cos(th0 - 0.5 * d) - std::sin(th0 - 0.5 * d));
  };
  auto f = [&](double v) {
    if (v == 0.0) {
      const double dvdth = alpha * std::cos(th0) - std::sin(th0);
      return 2.0 * std::sqrt(th0) / std::sqrt(2 * g / (h * m) * dvdth);
    }
    return 2 * th0 * v / std::sqrt(2 * g / (h * m) * dv(th0 * v * v));
  };
  return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, 0.0, 1.0, 15, 1e-15);
}

TEST(RockingSeries, FreeRockingImpactTimesMatchEnergyQuadrature) {
  const double b = 0.2, h = 1.0, alpha = b / h, m = 1 + (1 + alpha * alpha) / 3 + alpha * alpha;
  const Body body(BodyParameters::rectangular_block(1000, b, h));
  const double r = 1 - 1.5 * std::pow(std::sin(std::atan(alpha)), 2);
  const double aH = std::atan(alpha);
  InitialState init;
  init.theta = 0.8 * alpha;
  for (bool series : {true, false}) {
    SimulationOptions opt;
    opt.t_end = 20.0;
    opt.max_step = 1.0;
    opt.rtol = 1e-13;
    opt.atol = 1e-15;
    opt.methods.series_rocking = series;
    const auto res = simulate(body, GroundMotion::none(opt.t_end), init, opt);
    const auto times = impact_times(res);
    ASSERT_GE(times.size(), 12u);
    double th = init.theta, t = fall_time(alpha, m, h, th);
    for (std::size_t k = 0; k < 12; ++k) {
      EXPECT_NEAR(times[k], t, 2e-11 * t) << "impact " << k << (series ? " series" : " dopri5");
      th = aH - std::acos(std::cos(aH) + r * r * (std::cos(aH - th) - std::cos(aH)));
      t += 2 * fall_time(alpha, m, h, th);
    }
  }
}

SimulationResult run_record(const GroundMotion& motion, bool series, double rtol) {
  const Body body(BodyParameters::rectangular_block(1000, 0.2, 1.0));
  SimulationOptions opt;
  opt.rtol = rtol;
  opt.atol = 1e-2 * rtol;
  opt.methods.series_rocking = series;
  return simulate(body, motion, InitialState{}, opt);
}

// the series (series = true) against DOPRI5 under `motion`, both at rtol 1e-13: status, overturn
// side and time, first uplift, largest tilts, impact times and the energy balance; counts the
// runs that rocked and that overturned
void expect_series_agrees(const GroundMotion& motion, const std::string& where, int& rocked,
                          int& overturned) {
  const auto s = run_record(motion, true, 1e-13);
  const auto d = run_record(motion, false, 1e-13);
  ASSERT_EQ(s.status, d.status) << where;
  EXPECT_EQ(s.extremes.overturn_edge, d.extremes.overturn_edge) << where;
  if (s.status == Status::kOverturned) {
    ++overturned;
    EXPECT_NEAR(s.extremes.overturn_time, d.extremes.overturn_time, 1e-9) << where;
  }
  EXPECT_NEAR(s.extremes.first_uplift_time, d.extremes.first_uplift_time, 1e-12) << where;
  EXPECT_NEAR(s.extremes.max_theta_edge1, d.extremes.max_theta_edge1,
              1e-9 * std::max(1e-3, d.extremes.max_theta_edge1))
      << where;
  EXPECT_NEAR(s.extremes.max_theta_edge2, d.extremes.max_theta_edge2,
              1e-9 * std::max(1e-3, d.extremes.max_theta_edge2))
      << where;
  const auto ts = impact_times(s), td = impact_times(d);
  ASSERT_EQ(ts.size(), td.size()) << where;
  if (!ts.empty()) ++rocked;
  for (std::size_t k = 0; k < ts.size(); ++k) EXPECT_NEAR(ts[k], td[k], 1e-9) << where << k;
  // the series did the rocking: DOPRI5 evaluated the right-hand side only in the other run
  if (s.extremes.first_uplift_time >= 0.0) {
    EXPECT_LT(s.rhs_evaluations, d.rhs_evaluations / 10) << where;
  }
  // the input work, integrated with the series, closes the energy balance as tightly
  EXPECT_LT(std::abs(s.energy.residual), 1e-9 * s.energy.scale) << where;
}

TEST(RockingSeries, UnderARecordAgreesWithDopri5) {
  int overturned = 0, rocked = 0;
  for (unsigned seed : {1u, 2u, 3u, 4u}) {
    for (double amp : {0.25, 0.45}) {
      const std::string where = "seed " + std::to_string(seed) + ", " + std::to_string(amp) + " g";
      expect_series_agrees(random_record(seed, amp, 8.0), where, rocked, overturned);
    }
  }
  // the cases must exercise rocking with impacts and an overturn
  EXPECT_GT(rocked, 3);
  EXPECT_GT(overturned, 0);
}

TEST(RockingSeries, MirroredRecordMirrorsTheMotion) {
  for (unsigned seed : {5u, 6u}) {
    const auto p = run_record(random_record(seed, 0.35, 8.0, 1.0), true, 1e-10);
    const auto m = run_record(random_record(seed, 0.35, 8.0, -1.0), true, 1e-10);
    ASSERT_EQ(p.status, m.status);
    ASSERT_GT(p.extremes.max_theta_edge1 + p.extremes.max_theta_edge2, 0.0);
    EXPECT_EQ(p.extremes.first_uplift_edge, 3 - m.extremes.first_uplift_edge);
    EXPECT_NEAR(p.extremes.max_theta_edge1, m.extremes.max_theta_edge2, 1e-12);
    EXPECT_NEAR(p.extremes.max_theta_edge2, m.extremes.max_theta_edge1, 1e-12);
    const auto tp = impact_times(p), tm = impact_times(m);
    ASSERT_EQ(tp.size(), tm.size());
    for (std::size_t k = 0; k < tp.size(); ++k) EXPECT_NEAR(tp[k], tm[k], 1e-12) << k;
  }
}

// the step control of the one-step comparisons: rtol 1e-13 on theta and theta_dot
StepControl tight_control() {
  StepControl ctl;
  ctl.rtol = 1e-13;
  ctl.atol = 1e-15;
  ctl.controlled = 2;
  return ctl;
}

// the series' dense output on [t0, t1] against DOPRI5 at rtol 1e-13 (steps of at most 1e-3 s) on
// the equation `rhs`, at points inside the step and at its end
template <class Rhs>
void expect_dense_matches(const detail::RockingSeries<Eigen::Vector4d>& series, Rhs& rhs,
                          StepControl ctl, double t0, double t1, const Eigen::Vector4d& x0) {
  using State = Eigen::Vector4d;
  for (double f : {0.25, 0.5, 0.8, 1.0}) {
    const double tf = t0 + f * (t1 - t0);
    Dopri5<State> ref;
    ctl.max_step = 1e-3;
    ref.start(rhs, ctl, t0, x0);
    while (ref.t1() < tf) ref.step(rhs, tf);
    State xs;
    series.dense(tf, xs);
    EXPECT_NEAR(xs(0), ref.x1()(0), 1e-13) << f;
    EXPECT_NEAR(xs(1), ref.x1()(1), 1e-12) << f;
    EXPECT_NEAR(xs(2), ref.x1()(2), 1e-11 * std::abs(ref.x1()(2) - x0(2))) << f;
  }
}

// one step of the series across a record interval against DOPRI5 at rtol 1e-13 on the rocking
// equation written out here (theory §11), at points inside the step (the dense output)
TEST(RockingSeries, OneStepMatchesAnIndependentIntegration) {
  using State = Eigen::Vector4d;
  const double alpha = -0.25, zeta2 = 0.4, h = 1.3, mass = 800.0;
  const double m = 1 + zeta2 + alpha * alpha, k = g / h / m;
  // one record interval [0.1, 0.14] of both components
  const GroundMotion motion = one_record_interval();
  const double t0 = 0.1, t1 = 0.14;
  auto rhs = [&](double t, const State& x, State& dx) {
    const BaseAcceleration a = motion.at(t);
    const double ax = a.x / g, ay = 1 + a.y / g, s = std::sin(x(0)), c = std::cos(x(0));
    dx(0) = x(1);
    // (1 + zeta^2 + alpha^2) theta'' = g/h [a_y (sin + alpha cos) ... ] with alpha = -alpha_1
    dx(1) = k * (ay * (s + alpha * c) + ax * (c - alpha * s));
    // -M a_base . v_cm with v_cm = h theta' (-cos + alpha sin, -sin - alpha cos) in the inertial
    // axes of a pivot at alpha h
    const double vx = h * x(1) * (-c + alpha * s), vy = h * x(1) * (-s - alpha * c);
    dx(2) = -mass * (a.x * vx + a.y * vy);
    dx(3) = 0.0;
  };
  const State x0(0.05, -0.3, 1.5, 0.0);
  const StepControl ctl = tight_control();
  detail::RockingSeries<State> series(motion);
  series.set_pivot(alpha, k, mass * h * g, g);
  series.start(rhs, ctl, t0, x0);
  ASSERT_EQ(series.step(rhs, t1), detail::RockingSeries<State>::Status::kAccepted);
  EXPECT_EQ(series.t1(), t1);  // one step spans the interval
  expect_dense_matches(series, rhs, ctl, t0, t1, x0);
}

// a rigid block under the pulses made of sinusoids: the series (which expands the sinusoids)
// against DOPRI5 (which evaluates the pulse's function), both at rtol 1e-13, with impacts, an
// overturn and a motion of two components whose vertical piece starts after t = 0
TEST(RockingSeries, UnderSinusoidalPulsesAgreesWithDopri5) {
  const double wp = 2.2 * std::sqrt(3.0 * g / 4.0 / 1.0196);  // a few times the block's p
  const double tp = 2.0 * std::numbers::pi / wp;
  std::vector<std::pair<std::string, GroundMotion>> cases;
  for (double a : {0.35, 0.9}) {
    auto label = [a](const char* kind) {
      std::ostringstream o;
      o << kind << ' ' << a << " g";
      return o.str();
    };
    cases.emplace_back(label("one_sine"), one_sine_pulse(a * g, wp, 6.0));
    cases.emplace_back(label("cycloidal_b"), cycloidal_pulse_b(a * g, wp, 6.0));
    cases.emplace_back(label("cycloidal_c"), cycloidal_pulse_c(a * g, wp, 6.0, 2));
    cases.emplace_back(label("rectangular"), rectangular_pulse(-0.8 * a * g, 0.7 * tp, 6.0));
    cases.emplace_back(label("cycles"), harmonic_cycles(a * g, wp, 2.5, 6.0, 0.4));
  }
  // horizontal one-sine, vertical harmonic from t = 0.3 s to 2.1 s: two pieces by hand
  {
    const double a = 0.4 * g;
    auto f = [=](double t) {
      BaseAcceleration b;
      if (t <= tp) b.x = a * std::sin(wp * t);
      if (t >= 0.3 && t <= 2.1) b.y = 0.5 * a * std::sin(13.0 * t + 1.1);
      return b;
    };
    cases.emplace_back("two components",
                       GroundMotion::analytic(f, 6.0, {tp, 0.3, 2.1})
                           .with_sinusoids({SinusoidPiece{0.0, tp, a, wp, 0.0, false},
                                            SinusoidPiece{0.3, 2.1, 0.5 * a, 13.0, 1.1, true}}));
  }
  int overturned = 0, rocked = 0;
  for (const auto& [where, motion] : cases) {
    ASSERT_TRUE(motion.is_sinusoidal()) << where;
    expect_series_agrees(motion, where, rocked, overturned);
  }
  EXPECT_GT(rocked, 3);
  EXPECT_GT(overturned, 0);
}

// one series step under two sinusoids (one per component) against DOPRI5 at rtol 1e-13 on the
// rocking equation written out here, at points inside the step
TEST(RockingSeries, OneStepUnderSinusoidsMatchesAnIndependentIntegration) {
  using State = Eigen::Vector4d;
  const double alpha = 0.3, zeta2 = 0.4, h = 1.3, mass = 800.0;
  const double m = 1 + zeta2 + alpha * alpha, k = g / h / m;
  auto ax = pulse_x;
  auto ay = pulse_y;
  const GroundMotion motion = two_sinusoids();
  auto rhs = [&](double t, const State& x, State& dx) {
    const double u = ax(t) / g, v = 1 + ay(t) / g, s = std::sin(x(0)), c = std::cos(x(0));
    dx(0) = x(1);
    dx(1) = k * (v * (s + alpha * c) + u * (c - alpha * s));
    const double vx = h * x(1) * (-c + alpha * s), vy = h * x(1) * (-s - alpha * c);
    dx(2) = -mass * (ax(t) * vx + ay(t) * vy);
    dx(3) = 0.0;
  };
  const State x0(0.05, -0.3, 1.5, 0.0);
  const StepControl ctl = tight_control();
  detail::RockingSeries<State> series(motion);
  series.set_pivot(alpha, k, mass * h * g, g);
  const double t0 = 0.1;
  series.start(rhs, ctl, t0, x0);
  ASSERT_EQ(series.step(rhs, 0.5), detail::RockingSeries<State>::Status::kAccepted);
  const double t1 = series.t1();
  EXPECT_GT(t1 - t0, 0.02);  // a step of several hundredths over the sinusoids' periods
  expect_dense_matches(series, rhs, ctl, t0, t1, x0);
}

// the input work's terms of a step (RockingSeries::work_series forms them from W' = a sin' - b
// cos') against the integral of the power's own series, M h g theta' (a cos + b sin) by Cauchy
// products written out here, on the step's theta polynomial: every term to rounding, the last
// included (it needs sin and cos one power past the step's), under a record and under two sinusoids
TEST(RockingSeries, WorkTermsIntegrateThePowersSeries) {
  using State = Eigen::Vector4d;
  const double zeta2 = 0.4, h = 1.3, mass = 800.0, mhg = mass * h * g, t0 = 0.1;
  auto none = [](double, const State&, State&) {};
  const GroundMotion pulse = two_sinusoids();
  const GroundMotion record = one_record_interval();
  int checked = 0;
  for (const GroundMotion* motion : {&record, &pulse}) {
    const bool sampled = motion == &record;
    for (double alpha : {-0.25, 0.3}) {
      for (double rtol : {1e-6, 1e-13}) {
        const double k = g / h / (1 + zeta2 + alpha * alpha);
        StepControl ctl = tight_control();
        ctl.rtol = rtol;
        detail::RockingSeries<State> series(*motion);
        series.set_pivot(alpha, k, mhg, g);
        series.start(none, ctl, t0, State(0.05, -0.3, 1.5, 0.0));
        ASSERT_EQ(series.step(none, sampled ? 0.14 : 0.5),
                  detail::RockingSeries<State>::Status::kAccepted);
        const int p = series.order() - 1;  // the work's highest power
        const double* th = series.theta_coefficients();
        const double* w = series.work_coefficients();
        const auto n = static_cast<std::size_t>(p + 1);
        // u = a_x/g and v - 1 = a_y/g as Taylor series at t0: the record's interval is linear; a
        // sinusoid a sin(wt + phi) has the terms a w^j / j! sin(w t0 + phi + j pi/2)
        std::vector<double> u(n, 0.0), v(n, 0.0);
        if (sampled) {
          const BaseAcceleration a0 = motion->at(t0), a1 = motion->at(0.13);
          u[0] = a0.x / g;
          v[0] = a0.y / g;
          u[1] = (a1.x - a0.x) / 0.03 / g;
          v[1] = (a1.y - a0.y) / 0.03 / g;
        } else {
          double fu = 3.1 / g, fv = -1.9 / g;
          for (std::size_t j = 0; j < n; ++j) {
            const double turn = 0.5 * std::numbers::pi * static_cast<double>(j);
            u[j] = fu * std::sin(9.0 * t0 + 0.3 + turn);
            v[j] = fv * std::sin(14.0 * t0 + 2.0 + turn);
            fu *= 9.0 / static_cast<double>(j + 1);
            fv *= 14.0 / static_cast<double>(j + 1);
          }
        }
        // sin and cos of theta's polynomial, then the bracket a cos + b sin with its absolute sums
        std::vector<double> sn(n), cs(n), r(n), r_abs(n);
        sn[0] = std::sin(th[0]);
        cs[0] = std::cos(th[0]);
        for (std::size_t j = 1; j < n; ++j) {
          double a = 0.0, b = 0.0;
          for (std::size_t i = 1; i <= j; ++i) {
            a += static_cast<double>(i) * th[i] * cs[j - i];
            b -= static_cast<double>(i) * th[i] * sn[j - i];
          }
          sn[j] = a / static_cast<double>(j);
          cs[j] = b / static_cast<double>(j);
        }
        for (std::size_t j = 0; j < n; ++j) {
          r[j] = r_abs[j] = 0.0;
          for (std::size_t i = 0; i <= j; ++i) {
            const double a = mhg * (u[i] + alpha * v[i]), b = mhg * (v[i] - alpha * u[i]);
            r[j] += a * cs[j - i] + b * sn[j - i];
            r_abs[j] += std::abs(a * cs[j - i]) + std::abs(b * sn[j - i]);
          }
        }
        EXPECT_EQ(w[0], 1.5);
        for (std::size_t j = 0; j + 1 < n; ++j) {
          double power = 0.0, scale = 0.0;  // the power's term j and the sum of its products' sizes
          for (std::size_t i = 0; i <= j; ++i) {
            const double rate = static_cast<double>(i + 1) * th[i + 1];
            power += rate * r[j - i];
            scale += std::abs(rate) * r_abs[j - i];
          }
          const double term = power / static_cast<double>(j + 1);
          EXPECT_NEAR(w[j + 1], term, 1e-13 * scale)
              << (sampled ? "record" : "sinusoids") << " alpha " << alpha << " rtol " << rtol
              << " power " << j + 1 << " of " << p;
        }
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 8);
}

// the reaction's enclosure over a step (reaction_range, which spares the event loop the reaction's
// series on most steps) holds the reaction and the moment that the closed forms give on the step's
// dense states, theta'' from the equation written out here; and it is not wider than the step's
// own motion explains
TEST(RockingSeries, ReactionRangeEnclosesTheReactionAlongTheStep) {
  using State = Eigen::Vector4d;
  const double h = 1.3, mass = 800.0, zeta2 = 0.4;
  const GroundMotion pulse = two_sinusoids();
  const GroundMotion record = one_record_interval();
  int checked = 0;
  for (const GroundMotion* motion : {&pulse, &record}) {
    for (double alpha : {-0.25, 0.3}) {
      for (double theta_dot : {-0.3, 0.0, 0.8}) {
        const double m = 1 + zeta2 + alpha * alpha, k = g / h / m, gh = g / h;
        auto none = [](double, const State&, State&) {};
        const State x0(0.05, theta_dot, 0.0, 0.0);
        detail::RockingSeries<State> series(*motion);
        series.set_pivot(alpha, k, mass * h * g, g);
        series.start(none, tight_control(), 0.1, x0);
        ASSERT_EQ(series.step(none, motion == &record ? 0.14 : 0.4),
                  detail::RockingSeries<State>::Status::kAccepted);
        const double t0 = series.t0(), t1 = series.t1();
        const detail::ReactionRange r = series.reaction_range(gh, t1 - t0);
        double fi_lo = 1e300, fi_hi = -1e300, fj_lo = 1e300, fj_hi = -1e300, mo = 0.0;
        struct {
          double fi, fj, moment;
        } r0{};
        State x;
        for (int i = 0; i <= 400; ++i) {
          const double t = t0 + (t1 - t0) * i / 400;
          series.dense(t, x);
          const BaseAcceleration a = motion->at(t);
          const double u = a.x / g, v = 1 + a.y / g, s = std::sin(x(0)), c = std::cos(x(0));
          const double dd = k * ((alpha * v + u) * c + (v - alpha * u) * s);
          const double A = (alpha * x(1) * x(1) - dd) / gh, B = (alpha * dd + x(1) * x(1)) / gh;
          const double fi = u + A * c + B * s, fj = v + A * s - B * c;
          const double moment = alpha * (v * c - u * s - B);
          if (i == 0) r0 = {fi, fj, moment};
          fi_lo = std::min(fi_lo, fi);
          fi_hi = std::max(fi_hi, fi);
          fj_lo = std::min(fj_lo, fj);
          fj_hi = std::max(fj_hi, fj);
          mo = std::max(mo, std::abs(moment));
        }
        const double eps = 1e-9;
        EXPECT_LE(r.fi_lo, fi_lo + eps);
        EXPECT_GE(r.fi_hi, fi_hi - eps);
        EXPECT_LE(r.fj_lo, fj_lo + eps);
        EXPECT_GE(r.fj_hi, fj_hi - eps);
        EXPECT_GE(r.moment_abs, mo - eps);
        // and it closes on the reaction where the step starts as the step shrinks (the forms'
        // values there), and under a record's linear forcing is no wider than a few times the
        // quantity's own swing on the step (the interval arithmetic's dependency); a sinusoid's
        // range by its Taylor terms' sum may overshoot more
        const detail::ReactionRange at0 = series.reaction_range(gh, 1e-9);
        EXPECT_NEAR(at0.fi_lo, r0.fi, 1e-7);
        EXPECT_NEAR(at0.fi_hi, r0.fi, 1e-7);
        EXPECT_NEAR(at0.fj_lo, r0.fj, 1e-7);
        EXPECT_NEAR(at0.fj_hi, r0.fj, 1e-7);
        EXPECT_NEAR(at0.moment_abs, std::abs(r0.moment), 1e-7);
        if (motion == &record) {
          EXPECT_LE(r.fi_hi - r.fi_lo, 4.0 * (fi_hi - fi_lo) + 0.05);
          EXPECT_LE(r.fj_hi - r.fj_lo, 4.0 * (fj_hi - fj_lo) + 0.05);
          EXPECT_LE(r.moment_abs, 2.0 * mo + 0.05);
        }
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 12);
}

// the impact and peak guards' crossings are found on the series polynomial: against the known
// roots of a cubic, on both sides of its extremes, and the first time where the polynomial (as
// Horner's rule evaluates it) is <= 0
TEST(PolynomialCrossing, FindsTheRootsOfAKnownCubicToRounding) {
  const double t0 = 10.0;
  const double r1 = 0.1, r2 = 0.25, r3 = 0.4;  // roots in tau = t - t0
  // (tau - r1)(tau - r2)(tau - r3)
  const double c[4] = {-r1 * r2 * r3, r1 * r2 + r1 * r3 + r2 * r3, -(r1 + r2 + r3), 1.0};
  const double dc[4] = {0.0, c[1], 2.0 * c[2], 3.0 * c[3]};  // k c[k]
  auto poly = [&](double sign, double t) {
    const double tau = t - t0;
    return sign * (((c[3] * tau + c[2]) * tau + c[1]) * tau + c[0]);
  };
  struct Case {
    double sign, tl, tr, root;
  };
  // the first root from the left end, the second from a bracket that holds the first extreme
  // (Newton's first step leaves it), the third from far away
  for (const Case& k : {Case{-1.0, t0, t0 + 0.2, t0 + r1}, Case{1.0, t0 + 0.11, t0 + 0.3, t0 + r2},
                        Case{-1.0, t0 + 0.26, t0 + 5.0, t0 + r3}}) {
    const double gl = poly(k.sign, k.tl), gr = poly(k.sign, k.tr);
    ASSERT_GT(gl, 0.0);
    ASSERT_LE(gr, 0.0);
    const double t = detail::polynomial_crossing(c, dc, 3, k.sign, t0, k.tl, k.tr, gl, gr);
    EXPECT_NEAR(t, k.root, 4e-15 * k.root) << k.root;
    EXPECT_LE(poly(k.sign, t), 0.0) << k.root;
    EXPECT_GT(poly(k.sign, std::nextafter(t, k.tl)), 0.0) << k.root;
  }
}

}  // namespace
}  // namespace flexrock
