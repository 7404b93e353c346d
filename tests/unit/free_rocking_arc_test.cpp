// SPDX-License-Identifier: BSD-3-Clause
// A rigid body's free rocking on a floor at rest in closed form (closed_form_free_rocking, the
// default) against the Taylor series that steps it otherwise (= false): bodies slender and squat,
// symmetric and not, started on either edge and after pulses, compared event by event, in their
// extremes and in their time history; the peaks against the energy the impact law leaves; mirror
// symmetry.
#include "sim/free_rocking_arc.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/model/dynamics.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

constexpr double g = kStandardGravity;

SimulationResult run(const Body& body, const GroundMotion& motion, const InitialState& init,
                     bool closed_form, double output_dt = 0.0) {
  SimulationOptions opt;
  opt.t_end = motion.duration();
  opt.rtol = 1e-13;
  opt.atol = 1e-15;
  opt.output_dt = output_dt;
  opt.methods.closed_form_free_rocking = closed_form;
  return simulate(body, motion, init, opt);
}

double rel(double a, double b) {
  return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-300});
}

// every event, extreme and history sample of the closed form against the series; the run rocks
// freely to its end (no overturn). Adds the steps of each to `steps_arc` and `steps_series`.
void expect_same_motion(const Body& body, const GroundMotion& motion, const InitialState& init,
                        const std::string& where, long& steps_arc, long& steps_series) {
  const auto a = run(body, motion, init, true, 0.01);
  const auto s = run(body, motion, init, false, 0.01);
  ASSERT_EQ(a.status, Status::kCompleted) << where;
  ASSERT_EQ(s.status, Status::kCompleted) << where;
  EXPECT_GE(a.extremes.impacts, 10) << where;
  // one step per arc: never more than the series takes
  EXPECT_LE(a.steps, s.steps) << where;
  steps_arc += a.steps;
  steps_series += s.steps;
  ASSERT_EQ(a.events.size(), s.events.size()) << where;
  for (std::size_t k = 0; k < a.events.size(); ++k) {
    const Event &ea = a.events[k], &es = s.events[k];
    ASSERT_EQ(ea.kind, es.kind) << where << " event " << k;
    EXPECT_EQ(ea.edge, es.edge) << where << " event " << k;
    EXPECT_NEAR(ea.time, es.time, 1e-10 * std::max(1.0, es.time)) << where << " event " << k;
    EXPECT_NEAR(ea.theta, es.theta, 1e-11) << where << " event " << k;
    EXPECT_NEAR(ea.theta_dot_before, es.theta_dot_before, 1e-9) << where << " event " << k;
    EXPECT_NEAR(ea.theta_dot_after, es.theta_dot_after, 1e-9) << where << " event " << k;
  }
  const Extremes &xa = a.extremes, &xs = s.extremes;
  EXPECT_EQ(xa.impacts, xs.impacts) << where;
  EXPECT_LT(rel(xa.max_theta_edge1, xs.max_theta_edge1), 1e-10) << where;
  EXPECT_LT(rel(xa.max_theta_edge2, xs.max_theta_edge2), 1e-10) << where;
  EXPECT_LT(rel(xa.max_uplift, xs.max_uplift), 1e-10) << where;
  EXPECT_LT(rel(xa.max_impulse, xs.max_impulse), 1e-9) << where;
  // the series locates these on its polynomial to 1e-6 of a step (a curvature's 1e-12)
  EXPECT_LT(rel(xa.max_base_shear, xs.max_base_shear), 1e-9) << where;
  EXPECT_LT(rel(xa.max_overturning_moment, xs.max_overturning_moment), 1e-9) << where;
  EXPECT_LT(rel(xa.max_friction_demand, xs.max_friction_demand), 1e-9) << where;
  EXPECT_LT(rel(a.energy.impact_loss, s.energy.impact_loss), 1e-9) << where;
  EXPECT_LT(std::abs(a.energy.residual), 1e-9 * a.energy.scale) << where;
  ASSERT_EQ(a.history.time.size(), s.history.time.size()) << where;
  for (std::size_t k = 0; k < a.history.time.size(); ++k) {
    ASSERT_EQ(a.history.phase[k], s.history.phase[k]) << where << " row " << k;
    EXPECT_NEAR(a.history.theta[k], s.history.theta[k], 1e-10) << where << " row " << k;
    EXPECT_NEAR(a.history.theta_dot[k], s.history.theta_dot[k], 1e-9) << where << " row " << k;
    EXPECT_NEAR(a.history.reaction_x[k], s.history.reaction_x[k], 1e-9 * body.params().mass * g)
        << where << " row " << k;
  }
}

// The arc's reaction as a function of phi (signed F_I, F_J, the signed moment about the c.g.'s
// projection), which the loop takes at the peak and on the floor without a sincos of theta,
// against the rocking equations' reaction from (theta, theta_dot) (Dynamics), on either edge of a
// symmetric and of an asymmetric body, along the arc and at its peak and impact
TEST(FreeRockingArc, ReactionOnTheArcIsTheRockingEquations) {
  using Arc = detail::FreeRockingArc<Eigen::Vector4d>;
  const Eigen::Matrix<double, 0, 1> none;
  for (const BodyParameters& p : {BodyParameters::rectangular_block(1000, 0.2, 1.0),
                                  BodyParameters::rigid(2000, 1.5, 0.3, 0.5, 0.4)}) {
    const Body body(p);
    const Dynamics<0, 0> dyn(body);
    for (int e : {1, 2}) {
      const double sg = edge_sign(e), a = dyn.alpha(e);
      Arc arc;
      arc.set_pivot(a, dyn.inertia(a, none), dyn.g_over_h());
      Eigen::Vector4d x0 = Eigen::Vector4d::Zero();
      x0(0) = sg * 0.4 * arc.alpha_t();
      x0(1) = sg * 0.1;
      ASSERT_TRUE(arc.start(0.0, x0, sg)) << "edge " << e;
      const double alpha_t = arc.alpha_t();
      // the reaction and moment over M g (h) from the rocking equations at (theta, theta_dot)
      auto expect_same = [&](const Eigen::Vector4d& x, double sp, double cp, const char* where) {
        double thdd = 0.0;
        Eigen::Matrix<double, 0, 1> qdd;
        dyn.rocking_acceleration(e, x(0), none, x(1), none, BaseAcceleration{}, thdd, qdd);
        const Eigen::Vector2d r =
            dyn.rocking_reaction(e, x(0), none, x(1), none, thdd, qdd, BaseAcceleration{});
        const double moment = a * (-r(0) * std::sin(x(0)) + r(1) * std::cos(x(0)));
        EXPECT_NEAR(arc.fi(sp, cp), r(0), 1e-12) << where << ", edge " << e;
        EXPECT_NEAR(arc.press(cp), r(1), 1e-12) << where << ", edge " << e;
        EXPECT_NEAR(arc.signed_moment(sp, cp), moment, 1e-12) << where << ", edge " << e;
      };
      Eigen::Vector4d x = x0;
      for (int i = 0; i <= 8; ++i) {
        const double t = arc.impact_time() * i / 8.0;
        arc.dense(t, x);
        const double phi = alpha_t - sg * x(0);
        expect_same(x, std::sin(phi), std::cos(phi), "along the arc");
      }
      // the peak and the impact, with the sin(phi) and cos(phi) the loop takes there
      arc.dense(arc.peak_time(), x);
      EXPECT_EQ(x(1), 0.0);
      expect_same(x, arc.sin_phi_m(), arc.energy_cosine(), "at the peak");
      arc.dense(arc.impact_time(), x);
      EXPECT_EQ(x(0), 0.0);
      expect_same(x, arc.floor_sin(), arc.floor_cos(), "at the impact");
    }
  }
}

TEST(FreeRockingArc, AgreesWithTheSeriesFromRest) {
  struct Case {
    const char* name;
    BodyParameters body;
    double theta, theta_dot;
  };
  const std::vector<Case> cases{
      {"slender block, edge 1", BodyParameters::rectangular_block(1000, 0.2, 1.0), 0.15, 0.0},
      {"slender block, edge 2 rising", BodyParameters::rectangular_block(1000, 0.2, 1.0), -0.05,
       -0.15},
      {"squat block", BodyParameters::rectangular_block(500, 0.6, 1.0), 0.3, 0.0},
      {"asymmetric body, falling", BodyParameters::rigid(2000, 1.5, 0.3, 0.5, 0.4), 0.12, -0.2},
      {"from the floor", BodyParameters::rigid(800, 1.2, 0.25, 0.25, 0.2), 0.0, 0.3},
      // 1e-4 rad short of its tipping angle: s^2 = sin^2(phi_m/2) is 2.5e-9, K(k) large
      {"near upright", BodyParameters::rectangular_block(1000, 0.2, 1.0), std::atan(0.2) - 1e-4,
       0.0},
  };
  long steps_arc = 0, steps_series = 0;
  for (const auto& c : cases) {
    InitialState init;
    init.theta = c.theta;
    init.theta_dot = c.theta_dot;
    expect_same_motion(Body(c.body), GroundMotion::none(12.0), init, c.name, steps_arc,
                       steps_series);
  }
  // the closed form took the free rocking (the series takes several steps on a long arc)
  EXPECT_LT(steps_arc, steps_series);
}

TEST(FreeRockingArc, AgreesWithTheSeriesAfterPulses) {
  const Body body(BodyParameters::rectangular_block(1000, 0.2, 1.0));
  const double p = body.rocking_frequency();
  long steps_arc = 0, steps_series = 0;
  // amplitudes and frequencies that rock without overturning (the block's uplift is at 0.2 g)
  for (const auto& [a, f] : {std::pair{0.25, 3.0}, std::pair{0.4, 5.0}}) {
    expect_same_motion(body, one_sine_pulse(a * g, f * p, 10.0), InitialState{},
                       "one-sine " + std::to_string(a) + " g", steps_arc, steps_series);
  }
  for (const auto& [a, f] : {std::pair{0.3, 3.0}, std::pair{0.6, 5.0}}) {
    expect_same_motion(body, cycloidal_pulse_b(a * g, f * p, 10.0), InitialState{},
                       "cycloidal " + std::to_string(a) + " g", steps_arc, steps_series);
  }
  EXPECT_LT(steps_arc, steps_series);
}

// Between impacts the energy is kept, and at each the law scales theta_dot by the event's ratio
// r: the next peak follows from the last, cos(a - th') - cos(a) = r^2 (cos(a - th) - cos(a))
// (docs/theory.md, §11), independently of how the arcs were propagated
TEST(FreeRockingArc, PeaksFollowTheEnergyTheImpactsLeave) {
  const double b = 0.25, h = 1.1;
  const Body body(BodyParameters::rectangular_block(1000, b, h));
  const double at = std::atan(b / h);
  InitialState init;
  init.theta = 0.7 * at;
  SimulationOptions opt;
  opt.t_end = 15.0;
  const auto r = simulate(body, GroundMotion::none(opt.t_end), init, opt);
  double peak = init.theta;
  int checked = 0;
  for (std::size_t k = 0; k + 1 < r.events.size() && checked < 20; ++k) {
    const Event& e = r.events[k];
    if (e.kind != EventKind::kImpact) continue;
    const Event& next = r.events[k + 1];
    if (next.kind != EventKind::kPeak) break;
    const double ratio = e.theta_dot_after / e.theta_dot_before;
    const double expected =
        at -
        std::acos(std::cos(at) + ratio * ratio * (std::cos(at - std::abs(peak)) - std::cos(at)));
    EXPECT_NEAR(std::abs(next.theta), expected, 1e-9 * at) << "peak after impact at " << e.time;
    peak = next.theta;
    ++checked;
  }
  EXPECT_GE(checked, 10);
}

TEST(FreeRockingArc, MirroredStartMirrorsTheMotion) {
  const Body body(BodyParameters::rectangular_block(1000, 0.3, 1.2));
  InitialState up, down;
  up.theta = 0.12;
  up.theta_dot = 0.2;
  down.theta = -0.12;
  down.theta_dot = -0.2;
  SimulationOptions opt;
  opt.t_end = 10.0;
  const auto a = simulate(body, GroundMotion::none(opt.t_end), up, opt);
  const auto b = simulate(body, GroundMotion::none(opt.t_end), down, opt);
  ASSERT_EQ(a.events.size(), b.events.size());
  ASSERT_GT(a.events.size(), 10u);
  for (std::size_t k = 0; k < a.events.size(); ++k) {
    EXPECT_EQ(a.events[k].kind, b.events[k].kind) << k;
    EXPECT_EQ(a.events[k].time, b.events[k].time) << k;
    EXPECT_EQ(a.events[k].theta, -b.events[k].theta) << k;
  }
  EXPECT_EQ(a.extremes.max_theta_edge1, b.extremes.max_theta_edge2);
  EXPECT_EQ(a.extremes.max_base_shear, b.extremes.max_base_shear);
}

}  // namespace
}  // namespace flexrock
