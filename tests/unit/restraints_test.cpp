// SPDX-License-Identifier: BSD-3-Clause
// Restraints (docs/theory.md §26): the statics against the closed forms of
// tools/derive/restraints.py, the engine's uplift under a slow ramp against the threshold, the
// limits (no stiffness: the free body; stiff anchors: no uplift), and the energy balance with
// yield and fracture.
#include "flexrock/sim/restraints.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "flexrock/core/error.hpp"

namespace flexrock {
namespace {

using json = nlohmann::json;

json references() {
  std::ifstream in(FLEXROCK_SOURCE_DIR "/tests/data/restraints_reference.json");
  EXPECT_TRUE(in.good());
  return json::parse(in);
}

Body body_of(const json& c) {
  const double h = c["h"], b1 = c["b1"], b2 = c["b2"];
  return Body(BodyParameters::rigid(c["M"], h, b1, b2, (b1 * b1 + h * h) / (3.0 * h * h)));
}

Restraint tie_of(const json& c) {
  Restraint r;
  r.kind = c["s"].get<double>() > 0.0 ? RestraintKind::kAnchor : RestraintKind::kTendon;
  r.body_x = c["xb"];
  r.body_y = c["yb"];
  r.floor_x = c["xf"];
  r.floor_y = c["yf"];
  r.stiffness = c["k"];
  r.prestress = c["P0"];
  r.slack = c["s"];
  return r;
}

double rel(double got, double want) {
  return std::abs(got - want) / std::max(std::abs(want), 1e-300);
}

// the tie's elongation, the restoring moment and the pushover acceleration at sample rotations,
// and the uplift threshold, against sympy's exact forms (30 digits)
TEST(RestraintStatics, MatchTheDerivedClosedForms) {
  const json ref = references();
  ASSERT_EQ(ref["cases"].size(), 3u);
  for (const json& c : ref["cases"]) {
    SCOPED_TRACE(c["name"].get<std::string>());
    const Body body = body_of(c);
    const std::vector<Restraint> ties{tie_of(c)};
    for (const json& pt : c["points"]) {
      const double th = pt["theta"];
      const TieGeometry g = tie_geometry(body, ties[0], 1, th);
      EXPECT_LT(std::abs(g.e - pt["elongation"].get<double>()), 1e-15 + 1e-12 * std::abs(g.e));
      EXPECT_LT(rel(g.de, pt["elongation_rate"]), 1e-12);
      EXPECT_LT(rel(restoring_moment(body, ties, 1, th), pt["restoring_moment"]), 1e-9);
      EXPECT_LT(rel(pushover_acceleration(body, ties, 1, th), pt["pushover_acceleration"]), 1e-9);
    }
    EXPECT_LT(rel(uplift_acceleration(body, ties, 1), c["uplift_acceleration"]), 1e-12);
    if (c.contains("critical_stiffness")) {
      EXPECT_LT(rel(critical_stiffness(body, ties, 0, 1), c["critical_stiffness"]), 1e-12);
    }
  }
}

// the engine's rocking equation holds the body still at the pushover's acceleration: a static
// solve through the engine's equations (its generalised force from the ties' geometry)
TEST(RestraintStatics, EngineEquationIsInEquilibriumOnThePushover) {
  const json ref = references();
  for (const json& c : ref["cases"]) {
    SCOPED_TRACE(c["name"].get<std::string>());
    const Body body = body_of(c);
    const std::vector<Restraint> ties{tie_of(c)};
    const double gh = body.g_over_h();
    for (const json& pt : c["points"]) {
      const double th = pt["theta"];
      const double a = pt["pushover_acceleration"];
      EXPECT_LT(std::abs(restrained_rocking_acceleration(body, ties, 1, th, {a, 0.0})), 1e-9 * gh);
      // and off it the body moves: 1 % more acceleration tips it further
      EXPECT_GT(restrained_rocking_acceleration(body, ties, 1, th, {1.01 * a, 0.0}), 1e-5 * gh);
    }
  }
}

// the critical stiffness: the post-uplift branch neither softens nor stiffens there, softens below
TEST(RestraintStatics, CriticalStiffnessEndsTheSoftening) {
  const json ref = references();
  const json& c = ref["cases"][0];
  const Body body = body_of(c);
  std::vector<Restraint> ties{tie_of(c)};
  ties[0].stiffness = c["critical_stiffness"];
  EXPECT_LT(std::abs(self_centring_stiffness(body, ties, 1)),
            1e-9 * body.params().mass * body.g() * body.params().height);
  ties[0].stiffness *= 0.9;
  EXPECT_LT(self_centring_stiffness(body, ties, 1), 0.0);
  // a free block's branch: -M g h
  EXPECT_NEAR(self_centring_stiffness(body, {}, 1),
              -body.params().mass * body.g() * body.params().height, 1e-9);
}

// the engine under a slow ramp of base acceleration lifts the body off when the ramp reaches the
// closed-form threshold (the uplift event located on the guard)
TEST(RestrainedRun, UpliftUnderASlowRampMatchesTheThreshold) {
  const json ref = references();
  for (const json& c : ref["cases"]) {
    SCOPED_TRACE(c["name"].get<std::string>());
    const Body body = body_of(c);
    const std::vector<Restraint> ties{tie_of(c)};
    const double a_up = c["uplift_acceleration"];
    const double rate = 0.5;  // [m/s^3]
    const double t_max = 3.0 * a_up / rate;
    const GroundMotion ramp = GroundMotion::sampled({0.0, t_max}, {0.0, rate * t_max});
    SimulationOptions opt;
    opt.t_end = 1.2 * a_up / rate;
    const RestrainedResult r = simulate_restrained(body, ties, ramp, {}, opt);
    ASSERT_GT(r.result.extremes.first_uplift_time, 0.0);
    EXPECT_EQ(r.result.extremes.first_uplift_edge, 1);
    EXPECT_LT(rel(rate * r.result.extremes.first_uplift_time, a_up), 1e-9);
  }
}

Body uniform_block() { return Body(BodyParameters::rectangular_block(1000.0, 0.25, 1.0)); }

// a one-sine pulse: amplitude A [m/s^2], period T [s]
GroundMotion sine_pulse(double amp, double period, double duration) {
  return GroundMotion::analytic(
      [=](double t) -> BaseAcceleration {
        return {t < period ? amp * std::sin(2.0 * std::numbers::pi * t / period) : 0.0, 0.0};
      },
      duration, {period});
}

// zero stiffness and prestress: the run is the free body's (the Simulator's own paths)
TEST(RestrainedRun, TiesWithoutStiffnessAreTheFreeBody) {
  const Body body = uniform_block();
  const GroundMotion pulse = sine_pulse(0.35 * body.g(), 0.6, 4.0);
  Restraint tendon;
  tendon.body_y = 2.0;
  tendon.floor_y = -1.0;
  Restraint anchor;
  anchor.kind = RestraintKind::kAnchor;
  anchor.body_x = 0.25;
  anchor.floor_x = 0.25;
  anchor.floor_y = -0.1;
  SimulationOptions opt;
  const SimulationResult free = simulate(body, pulse, {}, opt);
  const RestrainedResult tied = simulate_restrained(body, {tendon, anchor}, pulse, {}, opt);
  ASSERT_EQ(free.status, tied.result.status);
  EXPECT_EQ(free.extremes.impacts, tied.result.extremes.impacts);
  EXPECT_LT(rel(tied.result.extremes.max_theta_edge1, free.extremes.max_theta_edge1), 1e-7);
  EXPECT_LT(rel(tied.result.extremes.max_theta_edge2, free.extremes.max_theta_edge2), 1e-7);
  EXPECT_LT(rel(tied.result.extremes.first_uplift_time, free.extremes.first_uplift_time), 1e-9);
  EXPECT_NEAR(tied.result.final_theta, free.final_theta, 1e-7 * free.extremes.max_theta_edge1);
  EXPECT_LT(rel(tied.result.energy.impact_loss, free.energy.impact_loss), 1e-6);
  EXPECT_EQ(tied.restraints[0].max_force, 0.0);
}

// anchors at both corners ever stiffer: the uplift shrinks as 1/k (the body cannot uplift in
// the limit), and without them the same pulse rocks the body
TEST(RestrainedRun, StiffStrongAnchorsPreventUplift) {
  const Body body = uniform_block();
  const GroundMotion pulse = sine_pulse(0.6 * body.g(), 0.5, 1.5);
  auto anchors = [](double k) {
    std::vector<Restraint> v(2);
    for (int i = 0; i < 2; ++i) {
      v[i].kind = RestraintKind::kAnchor;
      v[i].body_x = v[i].floor_x = i == 0 ? -0.25 : 0.25;
      v[i].floor_y = -0.2;
      v[i].stiffness = k;
    }
    return v;
  };
  SimulationOptions opt;
  const RestrainedResult soft = simulate_restrained(body, anchors(1e9), pulse, {}, opt);
  const RestrainedResult stiff = simulate_restrained(body, anchors(1e10), pulse, {}, opt);
  const SimulationResult free = simulate(body, pulse, {}, opt);
  EXPECT_GT(free.extremes.max_uplift, 1e-2);
  EXPECT_LT(soft.result.extremes.max_uplift, 1e-4);
  const double ratio = soft.result.extremes.max_uplift / stiff.result.extremes.max_uplift;
  EXPECT_GT(ratio, 8.0);
  EXPECT_LT(ratio, 12.0);
}

// an elastic tendon without impacts: kinetic + gravity + the tendon's energy is constant
TEST(RestrainedRun, TendonEnergyIsConservedBetweenImpacts) {
  const Body body = uniform_block();
  Restraint tendon;
  tendon.body_y = 2.0;
  tendon.floor_y = -3.0;
  tendon.stiffness = 2e6;
  tendon.prestress = 2e4;
  SimulationOptions opt;
  opt.output_dt = 0.001;
  opt.t_end = 0.3;
  InitialState init;
  init.theta = 0.05;
  const RestrainedResult r =
      simulate_restrained(body, {tendon}, GroundMotion::none(1.0), init, opt);
  ASSERT_GT(r.result.history.size(), 100u);
  const History& h = r.result.history;
  const double e0 = h.kinetic[0] + h.potential[0];
  double worst = 0.0, peak_u = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (r.result.extremes.impacts > 0 && h.time[i] >= r.result.events.front().time) break;
    worst = std::max(worst, std::abs(h.kinetic[i] + h.potential[i] - e0));
    peak_u = std::max(peak_u, std::abs(r.energy[i]));
  }
  EXPECT_GT(peak_u, 100.0);  // the tendon stores energy worth conserving
  EXPECT_LT(worst, 1e-7 * peak_u);
  EXPECT_LT(std::abs(r.result.energy.residual), 1e-7 * r.result.energy.scale);
}

// a tendon anchored at the top goes slack at a large rotation (the top swings down toward its
// floor point) and taut again on the way back: the kink is located both ways and the energy of
// T + V_g + U holds through it (a slack guard that never fired kept the tendon slack or pushing)
TEST(RestrainedRun, TendonSlackAtLargeRotationKeepsTheEnergy) {
  const Body body(BodyParameters::rectangular_block(1000.0, 0.2, 1.0));
  Restraint tendon;
  tendon.body_y = 2.0;
  tendon.floor_y = -1.0;
  tendon.stiffness = 2e5;
  tendon.prestress = 0.5 * 1000.0 * body.g();
  SimulationOptions opt;
  opt.output_dt = 0.0005;
  opt.t_end = 0.6;
  InitialState init;
  init.theta = 0.8;       // slack: e = -0.056 m, P_0/k = 0.025 m
  init.theta_dot = -3.0;  // on its way back
  const RestrainedResult r =
      simulate_restrained(body, {tendon}, GroundMotion::none(1.0), init, opt);
  const History& h = r.result.history;
  ASSERT_GT(h.size(), 100u);
  EXPECT_EQ(r.force[0], 0.0);
  const double t_impact = r.result.extremes.impacts > 0 ? r.result.events.front().time : 1e9;
  const double e0 = h.kinetic[0] + h.potential[0];
  double worst = 0.0, peak_force = 0.0;
  for (std::size_t i = 0; i < h.size() && h.time[i] < t_impact; ++i) {
    worst = std::max(worst, std::abs(h.kinetic[i] + h.potential[i] - e0));
    peak_force = std::max(peak_force, r.force[i]);
    EXPECT_GE(r.force[i], 0.0) << "a tendon never pushes, t = " << h.time[i];
  }
  EXPECT_GT(peak_force, tendon.prestress);  // taut again before the impact
  EXPECT_LT(worst, 1e-7 * e0);
  EXPECT_LT(std::abs(r.result.energy.residual), 1e-7 * r.result.energy.scale);
}

// anchors that yield and break under a strong pulse: yield, unloading and fracture events, the
// plastic and fracture work in the balance (without them it would not close), no event gaining
TEST(RestrainedRun, YieldAndFractureWorkCloseTheBalance) {
  const Body body = uniform_block();
  const GroundMotion pulse = sine_pulse(0.9 * body.g(), 0.6, 3.0);
  std::vector<Restraint> v(2);
  for (int i = 0; i < 2; ++i) {
    v[i].kind = RestraintKind::kAnchor;
    v[i].body_x = v[i].floor_x = i == 0 ? -0.25 : 0.25;
    v[i].floor_y = -0.2;
    v[i].stiffness = 5e7;
    v[i].yield_force = 1.0e4;
    v[i].slack = 2e-4;
    v[i].fracture_elongation = 0.01;
  }
  SimulationOptions opt;
  const RestrainedResult r = simulate_restrained(body, v, pulse, {}, opt);
  int yields = 0, fractures = 0;
  for (const RestraintEvent& ev : r.events) {
    yields += ev.kind == RestraintEventKind::kYield;
    fractures += ev.kind == RestraintEventKind::kFracture;
  }
  EXPECT_GE(yields, 1);
  EXPECT_GE(fractures, 1);
  EXPECT_TRUE(r.restraints[1].yielded);
  EXPECT_GT(r.plastic_work, 10.0);
  EXPECT_GT(r.fracture_work, 0.0);
  const EnergyBalance& e = r.result.energy;
  EXPECT_FALSE(r.result.energy_unbalanced) << e.residual;
  EXPECT_LT(std::abs(e.residual), 1e-6 * e.scale);
  EXPECT_GT(r.plastic_work, 1e3 * std::abs(e.residual));
  for (const Event& ev : r.result.events) EXPECT_GE(ev.energy_loss, 0.0) << to_string(ev.kind);
  for (const RestraintEvent& ev : r.events) EXPECT_GE(ev.energy, 0.0) << to_string(ev.kind);
}

TEST(RestraintInput, RefusedWithTheRestraintAndTheKey) {
  const Body body = uniform_block();
  Restraint bad;
  bad.body_y = 1.0;
  bad.floor_y = -1.0;
  bad.prestress = 100.0;
  bad.slack = 1e-3;
  try {
    (void)simulate_restrained(body, {Restraint{.body_y = 1.0, .floor_y = -1.0}, bad},
                              GroundMotion::none(1.0));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("restraint 2: a slack and a prestress"), std::string::npos)
        << e.what();
  }
  SimulationOptions opt;
  opt.friction_coefficient = 0.5;
  EXPECT_THROW((void)simulate_restrained(body, {}, GroundMotion::none(1.0), {}, opt), InputError);
}

}  // namespace
}  // namespace flexrock
