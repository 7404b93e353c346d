// SPDX-License-Identifier: BSD-3-Clause
// Housner's (1963) linearized closed forms against the nonlinear engine: the free-rocking period
// and the minimum overturning accelerations of rectangular and half-sine pulses. The linearized
// forms replace sin(alpha - theta) by alpha - theta and cos by 1, so they differ from the exact
// equation by O(alpha^2); each test states the expected difference and its order.
#include <gtest/gtest.h>

#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <functional>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

constexpr double g = kStandardGravity;

// uniform rectangular block of slenderness alpha, half-diagonal R [m]
Body block(double alpha, double R = 1.0) {
  return Body(BodyParameters::rectangular_block(1000.0, R * std::sin(alpha), R * std::cos(alpha)));
}

SimulationOptions tight(double p, double t_end) {
  SimulationOptions o;
  o.rtol = 1e-11;
  o.atol = 1e-13;
  o.max_step = 0.05 / p;
  o.t_end = t_end;
  return o;
}

// the smallest x in [lo, hi] where pred turns true (pred(lo) false, pred(hi) true)
double bisect(const std::function<bool(double)>& pred, double lo, double hi, double rel = 1e-7) {
  EXPECT_FALSE(pred(lo));
  EXPECT_TRUE(pred(hi));
  while (hi - lo > rel * hi) {
    const double mid = 0.5 * (lo + hi);
    (pred(mid) ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// Quarter period of free rocking from theta0 = x alpha: (1/p) U (1 + delta) + O(alpha^4), with
// U = arccosh(1/(1 - x)) Housner's linearized value and delta the second-order correction from
// cos(phi0) - cos(phi) = (phi^2 - phi0^2)/2 (1 - (phi^2 + phi0^2)/12 + ...), phi = alpha - theta:
//   delta = phi0^2 (3U/2 + sinh U cosh U/2) / (24 U),   phi0 = alpha (1 - x).
// The next term of the integrand is bounded by (3/8 (4/144) + 3/720) alpha^4 < 0.015 alpha^4.
TEST(HousnerClosedForm, FreeRockingPeriodApproachesLinearizedAtSecondOrder) {
  for (double alpha : {0.2, 0.1, 0.05}) {
    const Body body = block(alpha);
    const double p = body.rocking_frequency();
    ASSERT_NEAR(p, std::sqrt(3 * g / 4.0), 1e-12);  // p = sqrt(3g/(4R)), R = 1
    for (double x : {0.02, 0.5, 0.9}) {
      InitialState init;
      init.theta = x * alpha;
      auto o = tight(p, 60.0 / p);
      o.rtol = 1e-13;
      o.atol = 1e-15;
      o.max_impacts = 1;
      const auto r = simulate(body, GroundMotion::none(o.t_end), init, o);
      double t_impact = -1;
      for (const auto& e : r.events)
        if (e.kind == EventKind::kImpact && t_impact < 0) t_impact = e.time;
      ASSERT_GT(t_impact, 0.0);
      const double T = 4 * t_impact;
      const double U = std::acosh(1 / (1 - x));
      const double T_lin = 4 / p * U;
      const double phi0 = alpha * (1 - x);
      const double delta = phi0 * phi0 * (1.5 * U + 0.5 * std::sinh(U) * std::cosh(U)) / (24 * U);
      EXPECT_NEAR(T / T_lin - 1, delta, 0.015 * std::pow(alpha, 4) + 1e-10)
          << "alpha = " << alpha << ", theta0/alpha = " << x;
      // and the linearized period alone is off by the second order only
      EXPECT_GT(T / T_lin - 1, 0.0);
      EXPECT_LT(T / T_lin - 1, 0.1 * alpha * alpha);
    }
  }
}

// A release from a tilt far below atol (1e-15 rad against atol = 1e-11) once stopped at t = 0
// with "integration step collapsed": the integrator's starting step scales with |theta| /
// |theta''|. At the default tolerances the block must fall back, impact and go on rocking or
// settle. The small-angle forms hold to O(theta0) relative: the fall lasts t = sqrt(2 theta0 / (p^2
// sin alpha)) (theta'' = -p^2 sin(alpha - theta)), theta_dot^2 = 2 p^2 (cos(alpha - theta0) - cos
// alpha) at the impact, and the rectangular block's impact law (r = 1 - 3/2 sin^2 alpha on the
// angular velocity) gives a peak of r^2 theta0 on edge 2.
TEST(HousnerClosedForm, ReleaseFromATinyTiltFallsBackAndRocks) {
  const double alpha = 0.2;
  const Body body = block(alpha);
  const double p = body.rocking_frequency();
  const double r = 1.0 - 1.5 * std::sin(alpha) * std::sin(alpha);
  for (double theta0 : {1e-15, 1e-12, 1e-9}) {
    InitialState init;
    init.theta = theta0;
    SimulationOptions o;  // the defaults, as a user runs it
    o.t_end = 2.0;
    const auto r_run = simulate(body, GroundMotion::none(o.t_end), init, o);
    ASSERT_EQ(r_run.status, Status::kCompleted) << "theta0 = " << theta0 << ": " << r_run.message;
    EXPECT_DOUBLE_EQ(r_run.t_end, 2.0);
    const Event* impact = nullptr;
    for (const auto& e : r_run.events)
      if (e.kind == EventKind::kImpact && !impact) impact = &e;
    ASSERT_NE(impact, nullptr) << "theta0 = " << theta0;
    const double t_fall = std::sqrt(2.0 * theta0 / (p * p * std::sin(alpha)));
    // cos(alpha - theta0) - cos(alpha) without cancellation
    const double w_fall =
        p * std::sqrt(4.0 * std::sin(alpha - 0.5 * theta0) * std::sin(0.5 * theta0));
    EXPECT_NEAR(impact->time / t_fall, 1.0, 1e-6) << "theta0 = " << theta0;
    EXPECT_NEAR(-impact->theta_dot_before / w_fall, 1.0, 1e-6) << "theta0 = " << theta0;
    EXPECT_NEAR(impact->theta_dot_after / impact->theta_dot_before, r, 1e-9);
    EXPECT_EQ(impact->edge, 2);
    EXPECT_NEAR(r_run.extremes.max_theta_edge1, theta0, 1e-9 * theta0);
    EXPECT_NEAR(r_run.extremes.max_theta_edge2 / (r * r * theta0), 1.0, 1e-6)
        << "theta0 = " << theta0;
    EXPECT_FALSE(r_run.energy_unbalanced);
  }
}

// the nonlinear single-degree equation of a rigid block rocking on edge 1 (theta > 0),
// integrated by odeint independently of the engine: theta'' = p^2 (a/g cos(alpha - theta) -
// sin(alpha - theta)). Returns true if theta reaches alpha before it returns to 0.
bool overturns_without_impact(double alpha, double p, const std::function<double(double)>& a_over_g,
                              double t_uplift, double t_end) {
  using State = std::array<double, 2>;
  namespace ode = boost::numeric::odeint;
  auto rhs = [&](const State& x, State& dx, double t) {
    dx[0] = x[1];
    dx[1] = p * p * (a_over_g(t) * std::cos(alpha - x[0]) - std::sin(alpha - x[0]));
  };
  auto stepper = ode::make_dense_output(1e-12, 1e-12, ode::runge_kutta_dopri5<State>());
  stepper.initialize(State{0.0, 0.0}, t_uplift, 1e-3 / p);
  while (stepper.current_time() < t_end) {
    stepper.do_step(rhs);
    const auto& x = stepper.current_state();
    if (x[0] >= alpha) return true;
    if (x[0] < -1e-14 * alpha) return false;
  }
  return false;
}

// Rectangular pulse of duration t1: linearized threshold a/(g alpha) = 1/(1 - exp(-p t1)).
// A pulse that does not overturn leaves free rocking, which only loses energy, so the
// threshold is the overturning-without-impact one. The engine must match the independent
// nonlinear integration to the bisection tolerance, and the linearized form must be off by
// c alpha^2 (uplift at tan(alpha) instead of alpha gives alpha^2/3 of it): halving alpha
// divides the difference by 4.
TEST(HousnerClosedForm, RectangularPulseThresholdApproachesLinearized) {
  for (double pt1 : {0.3, 2.0}) {
    double diff[2];
    int i = 0;
    for (double alpha : {0.02, 0.01}) {
      const Body body = block(alpha);
      const double p = body.rocking_frequency(), t1 = pt1 / p;
      const double a_lin = 1 / (1 - std::exp(-pt1));
      const double a_engine = bisect(
          [&](double A) {
            const auto o = tight(p, t1 + 30 / p);
            return simulate(body, rectangular_pulse(A * g * alpha, t1, o.t_end), {}, o).status ==
                   Status::kOverturned;
          },
          0.9 * a_lin, 1.1 * a_lin);
      const double a_ode = bisect(
          [&](double A) {
            const double t_up = 0.0;  // A alpha > tan(alpha): uplift at once
            return overturns_without_impact(
                alpha, p, [&](double t) { return t <= t1 ? A * alpha : 0.0; }, t_up, t1 + 30 / p);
          },
          0.9 * a_lin, 1.1 * a_lin);
      EXPECT_NEAR(a_engine / a_ode, 1.0, 1e-5) << "alpha = " << alpha << ", p t1 = " << pt1;
      diff[i++] = a_engine / a_lin - 1;
      EXPECT_GT(diff[i - 1], 0.0);
      EXPECT_LT(diff[i - 1], alpha * alpha);
    }
    EXPECT_NEAR(diff[1] / diff[0], 0.25, 0.02) << "p t1 = " << pt1;
  }
}

// Half-sine pulse a_p sin(omega_p t), overturning without impact, linearized (A = a_p/(g tan
// alpha), Omega = omega_p/p, psi = asin(1/A)):
//   sqrt(A^2 - 1) + A exp(-(pi - psi)/Omega) = Omega.
// Same checks as for the rectangular pulse.
double half_sine_linear(double Omega) {
  auto f = [&](double A) {
    const double psi = std::asin(1 / A);
    return std::sqrt(A * A - 1) + A * std::exp(-(M_PI - psi) / Omega) - Omega;
  };
  double lo = 1.0 + 1e-14, hi = 1e3;
  while (hi - lo > 1e-14 * hi) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(HousnerClosedForm, HalfSinePulseThresholdApproachesLinearized) {
  for (double Omega : {1.0, 4.0}) {
    const double A_lin = half_sine_linear(Omega);
    double diff[2];
    int i = 0;
    for (double alpha : {0.04, 0.02}) {
      const Body body = block(alpha);
      const double p = body.rocking_frequency(), wp = Omega * p;
      const double ta = std::tan(alpha);
      const double A_engine = bisect(
          [&](double A) {
            const auto o = tight(p, M_PI / wp + 30 / p);
            return simulate(body, half_sine_pulse(A * g * ta, wp, o.t_end), {}, o).status ==
                   Status::kOverturned;
          },
          0.9 * A_lin, 1.1 * A_lin);
      const double A_ode = bisect(
          [&](double A) {
            return overturns_without_impact(
                alpha, p,
                [&](double t) { return t <= M_PI / wp ? A * ta * std::sin(wp * t) : 0.0; },
                std::asin(1 / A) / wp, M_PI / wp + 30 / p);
          },
          0.9 * A_lin, 1.1 * A_lin);
      EXPECT_NEAR(A_engine / A_ode, 1.0, 1e-5) << "alpha = " << alpha << ", Omega = " << Omega;
      diff[i++] = A_engine / A_lin - 1;
      EXPECT_LT(std::abs(diff[i - 1]), alpha * alpha);
    }
    EXPECT_NEAR(diff[1] / diff[0], 0.25, 0.03) << "Omega = " << Omega;
  }
}

}  // namespace
}  // namespace flexrock
