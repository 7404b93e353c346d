// SPDX-License-Identifier: BSD-3-Clause
// The 3D engine of a rigid body of revolution (docs/theory.md §27) against independent references:
// the sympy derivation (tools/derive/axisymmetric3d.py, Lagrange-Kane and Newton-Euler in Euler
// angles), the planar engine, conservation laws and the symmetry of the floor's plane.
#include "flexrock/sim/axisymmetric.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>

#include "flexrock/contact/rim_landing.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "flexrock/model/axisymmetric_body.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

using json = nlohmann::json;

json references() {
  std::ifstream in(std::string(FLEXROCK_BINARY_DIR) + "/sympy_reference_axisymmetric3d.json");
  EXPECT_TRUE(in.good()) << "run tools/derive/derive.py --out sympy_reference.json first";
  json j;
  in >> j;
  return j;
}

Vector3 vec3(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

// the cask-like cylinder of the measurements: diameter 3.4 m, height 5.9 m
AxisymmetricBody cask() { return uniform_cylinder(1.7, 5.9, 1.2e5); }

TEST(AxisymmetricRolling, MatchesTheSympyDerivationInEulerAngles) {
  const json refs = references();
  ASSERT_GE(refs["references"].size(), 6u);
  for (const json& c : refs["references"]) {
    AxisymmetricBody b;
    b.mass = c["mass"];
    b.height = c["height"];
    b.radius = c["radius"];
    b.inertia_diameter = c["inertia_diameter"];
    b.inertia_axis = c["inertia_axis"];
    b.gravity = 9.80665;
    const Eigen::Quaterniond q = Eigen::AngleAxisd(c["phi"].get<double>(), Vector3::UnitZ()) *
                                 Eigen::AngleAxisd(c["theta"].get<double>(), Vector3::UnitY()) *
                                 Eigen::AngleAxisd(c["psi"].get<double>(), Vector3::UnitZ());
    const RimRates r = rim_rates(b, {q, vec3(c["omega"])}, vec3(c["acc"]), Vector3::UnitX());
    const Vector3 wd = vec3(c["omega_dot"]), f = vec3(c["force"]);
    EXPECT_LT((r.omega_dot - wd).norm(), 1e-11 * std::max(1.0, wd.norm())) << c.dump();
    EXPECT_LT((r.force - f).norm(), 1e-11 * f.norm()) << c.dump();
  }
}

// the planar engine's signed tilt from a 3D history: theta > 0 rocks on edge 1, at -x
double signed_tilt(const RimHistory& h, std::size_t i) {
  return std::cos(h.azimuth[i]) < 0.0 ? h.tilt[i] : -h.tilt[i];
}

void expect_planar_limit(const AxisymmetricBody& cyl, const GroundMotion& m, double theta0,
                         double t_end, int min_landings) {
  SimulationOptions po;
  po.rtol = 1e-13;
  po.atol = 1e-15;
  po.output_dt = 0.01;
  po.t_end = t_end;
  InitialState pi;
  pi.theta = theta0;
  const SimulationResult p = simulate(Body(planar_equivalent(cyl)), m, pi, po);
  RimOptions o;
  o.rtol = 1e-13;
  o.atol = 1e-15;
  o.output_dt = 0.01;
  o.t_end = t_end;
  RimInitialState ri;
  ri.tilt = std::abs(theta0);
  ri.azimuth_deg = theta0 > 0.0 ? 180.0 : 0.0;
  const RimResult r = simulate_axisymmetric(cyl, {&m, nullptr}, ri, o);
  ASSERT_EQ(r.status, RimStatus::kCompleted) << r.message;
  EXPECT_GE(r.landings, min_landings);
  ASSERT_EQ(p.history.size(), r.history.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < r.history.size(); ++i) {
    ASSERT_DOUBLE_EQ(p.history.time[i], r.history.time[i]);
    worst = std::max(worst, std::abs(p.history.theta[i] - signed_tilt(r.history, i)));
    // in the plane: the base moves along x only
    EXPECT_EQ(r.history.y[i], 0.0);
    EXPECT_EQ(r.history.reaction_y[i], 0.0);
  }
  EXPECT_LT(worst, 1e-10 * std::atan2(cyl.radius, cyl.height));
  long impacts = 0;
  for (const Event& e : p.events)
    impacts += e.kind == EventKind::kImpact || e.kind == EventKind::kChatterCutoff;
  EXPECT_EQ(impacts, r.landings);
}

TEST(AxisymmetricPlanarLimit, FreeRockingEqualsThePlanarEngineWithTheCylindersInertia) {
  // a hollow cylinder: its inertia is not a rectangle's
  const AxisymmetricBody cyl = uniform_cylinder(0.6, 2.5, 900.0, 0.45);
  expect_planar_limit(cyl, GroundMotion::none(4.0), 0.15, 4.0, 4);
}

TEST(AxisymmetricPlanarLimit, ExcitedInItsPlaneEqualsThePlanarEngine) {
  const AxisymmetricBody cyl = uniform_cylinder(0.5, 3.0, 1500.0);
  const GroundMotion m = one_sine_pulse(0.5 * 9.80665, 2.0 * std::numbers::pi * 1.5, 4.0);
  expect_planar_limit(cyl, m, 0.0, 4.0, 1);
}

TEST(AxisymmetricPlanarLimit, LandingRatioIsHousnersWithTheBodysInertia) {
  const AxisymmetricBody b = cask();
  const Vector3 w(0.0, -0.3, 0.0);  // rolling about +y: tilting toward +x... before: contact +x
  const RimLanding l = rim_landing(b, Vector3::UnitZ(), Vector3::UnitX(), w);
  EXPECT_NEAR(l.omega_after.y() / w.y(), planar_landing_ratio(b), 1e-15);
  EXPECT_EQ(l.omega_after.x(), 0.0);
  EXPECT_EQ(l.omega_after.z(), 0.0);
  // and the planar engine's ratio for the equivalent body
  const double a = b.radius / b.height;
  const Body pb(planar_equivalent(b));
  const double r2 = b.inertia_diameter / (b.mass * b.height * b.height);
  EXPECT_NEAR(planar_landing_ratio(b), (r2 + 1.0 - a * a) / (r2 + 1.0 + a * a), 1e-15);
  EXPECT_NEAR(rocking_frequency(b), pb.rocking_frequency(), 1e-14 * pb.rocking_frequency());
}

TEST(AxisymmetricLanding, ConservesTheMomentOfMomentumAboutTheLandingPoint) {
  const AxisymmetricBody b = uniform_cylinder(0.8, 2.0, 3000.0, 0.3);
  const Vector3 c = Vector3(std::cos(0.7), std::sin(0.7), 0.0);
  for (const Vector3& w : {Vector3(0.2, -0.5, 0.3), Vector3(-0.1, 0.4, -1.2)}) {
    const RimLanding l = rim_landing(b, Vector3::UnitZ(), c, w);
    const Vector3 r_old = b.height * Vector3::UnitZ() - b.radius * c;
    const Vector3 r_new = b.height * Vector3::UnitZ() + b.radius * c;
    const Matrix3 iw = Vector3(b.inertia_diameter, b.inertia_diameter, b.inertia_axis).asDiagonal();
    const Vector3 h_before = iw * w + b.mass * r_new.cross(w.cross(r_old));
    const Vector3 h_after = iw * l.omega_after + b.mass * r_new.cross(l.omega_after.cross(r_new));
    EXPECT_LT((h_after - h_before).norm(), 1e-13 * h_before.norm());
    EXPECT_GE(l.energy_loss, 0.0);
  }
}

// the precession rate of the steady wobble with the c.g. at rest (omega parallel to r_PG,
// theta_dot = 0): the root of theta_ddot(phi_dot) = 0 by the engine's own equations, found by
// bisection (the sympy closed form is the independent value it is compared with)
double steady_precession(const AxisymmetricBody& b, double theta) {
  auto thdd = [&](double w) {
    const double psd = w * (b.height * std::sin(theta) / b.radius - std::cos(theta));
    const Eigen::Quaterniond q(Eigen::AngleAxisd(theta, Vector3::UnitY()));
    const Vector3 om = w * Vector3::UnitZ() + psd * (q * Vector3::UnitZ());
    const RimRates rr = rim_rates(b, {q, om}, Vector3::Zero(), Vector3::UnitX());
    // omega_dot . e2 = theta_ddot + psi_dot phi_dot sin(theta) at theta_dot = 0 (e2 = y, phi = 0)
    return rr.omega_dot.y() - psd * w * std::sin(theta);
  };
  double lo = 1e-3, hi = 1e3;
  const bool slo = thdd(lo) > 0;
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(lo * hi);
    ((thdd(mid) > 0) == slo ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(AxisymmetricSteadyWobble, HoldsItsTiltOverManyPrecessions) {
  const json refs = references();
  for (const json& c : refs["steady_wobble"]) {
    AxisymmetricBody b = uniform_cylinder(c["radius"], c["full_height"], c["mass"]);
    const double theta = c["theta"], w = c["phi_dot"];
    // the sympy closed form and the engine's own equations agree on the rate
    EXPECT_NEAR(steady_precession(b, theta), w, 1e-9 * w);
    RimInitialState init;
    init.tilt = theta;
    init.precession = w;
    init.spin = w * (b.height * std::sin(theta) / b.radius - std::cos(theta));
    const double period = 2.0 * std::numbers::pi / w;
    RimOptions o;
    o.rtol = 1e-12;
    o.atol = 1e-14;
    o.output_dt = period / 8.0;
    o.t_end = 20.0 * period;
    const GroundMotion none = GroundMotion::none(o.t_end);
    const RimResult r = simulate_axisymmetric(b, {&none, nullptr}, init, o);
    ASSERT_EQ(r.status, RimStatus::kCompleted) << r.message;
    double worst = 0.0, cg = 0.0;
    // c.g. = base centre + h k: at rest where it started
    auto cg_at = [&](std::size_t i) {
      const double kx = std::sin(r.history.tilt[i]) * std::cos(r.history.azimuth[i]);
      const double ky = std::sin(r.history.tilt[i]) * std::sin(r.history.azimuth[i]);
      return std::array<double, 2>{r.history.x[i] + b.height * kx, r.history.y[i] + b.height * ky};
    };
    const auto cg0 = cg_at(0);
    for (std::size_t i = 0; i < r.history.size(); ++i) {
      worst = std::max(worst, std::abs(r.history.tilt[i] - theta));
      const auto gi = cg_at(i);
      cg = std::max(cg, std::hypot(gi[0] - cg0[0], gi[1] - cg0[1]));
    }
    EXPECT_LT(worst, 1e-8) << c.dump();
    EXPECT_LT(cg, 1e-8 * b.radius) << c.dump();
    // the azimuth advanced by 20 turns
    EXPECT_NEAR(r.history.azimuth.back() - r.history.azimuth.front(), w * r.history.time.back(),
                1e-7 * w * r.history.time.back());
  }
}

TEST(AxisymmetricConservation, EnergyInRollingWithoutBaseMotion) {
  const AxisymmetricBody b = uniform_cylinder(0.7, 2.2, 2000.0, 0.2);
  RimInitialState init;
  init.tilt = 0.2;
  init.azimuth_deg = 23.0;
  init.tilt_rate = 0.3;
  init.precession = 1.7;
  init.spin = -0.9;
  RimOptions o;
  o.rtol = 1e-12;
  o.atol = 1e-14;
  o.output_dt = 0.05;
  o.t_end = 6.0;
  const GroundMotion none = GroundMotion::none(o.t_end);
  const RimResult r = simulate_axisymmetric(b, {&none, nullptr}, init, o);
  ASSERT_EQ(r.status, RimStatus::kCompleted) << r.message;
  ASSERT_EQ(r.landings, 0);
  const double e0 = r.history.kinetic[0] + r.history.potential[0];
  double worst = 0.0;
  for (std::size_t i = 0; i < r.history.size(); ++i)
    worst = std::max(worst, std::abs(r.history.kinetic[i] + r.history.potential[i] - e0));
  EXPECT_LT(worst, 1e-9 * e0);
  // it wobbles out of any plane
  double az_lo = 1e9, az_hi = -1e9;
  for (double a : r.history.azimuth) az_lo = std::min(az_lo, a), az_hi = std::max(az_hi, a);
  EXPECT_GT(az_hi - az_lo, 1.0);
}

TEST(AxisymmetricConservation, VerticalMomentOfMomentumAboutTheContactInTheSteadyWobble) {
  // c.g. at rest: the contact force is M g e_z, no moment about the vertical through P, and P's
  // motion adds no term (v_G = 0): H_P . e_z stays at its start value
  const AxisymmetricBody b = uniform_cylinder(0.5, 0.6, 100.0);
  const double theta = 0.3, w = steady_precession(b, theta);
  const double psd = w * (b.height * std::sin(theta) / b.radius - std::cos(theta));
  double hz0 = std::numeric_limits<double>::quiet_NaN();
  for (double phi : {0.0, 1.0, 2.5}) {
    const Eigen::Quaterniond q =
        Eigen::AngleAxisd(phi, Vector3::UnitZ()) * Eigen::AngleAxisd(theta, Vector3::UnitY());
    const Vector3 k = q * Vector3::UnitZ();
    const Vector3 om = w * Vector3::UnitZ() + psd * k;
    const Matrix3 iw = b.inertia_diameter * Matrix3::Identity() +
                       (b.inertia_axis - b.inertia_diameter) * k * k.transpose();
    const RimRates r = rim_rates(b, {q, om}, Vector3::Zero(), Vector3::UnitX());
    EXPECT_LT(r.v_cg.norm(), 1e-14);
    const double hz = (iw * om).z();
    if (std::isnan(hz0)) hz0 = hz;
    EXPECT_NEAR(hz, hz0, 1e-12 * std::abs(hz0));
    // and its rate is zero: d/dt (I om) = I om_dot + om x I om
    const Vector3 hd = iw * r.omega_dot + om.cross(iw * om);
    EXPECT_LT(std::abs(hd.z()), 1e-12 * (iw * om).norm());
  }
}

TEST(AxisymmetricSymmetry, RotatingTheInputPairRotatesTheResponse) {
  const AxisymmetricBody b = uniform_cylinder(0.4, 2.4, 800.0);
  const double dt = 0.005;
  const int n = 600;
  std::vector<double> h1(n), h2(n);
  for (int i = 0; i < n; ++i) {
    const double t = i * dt;
    const double env = std::sin(std::numbers::pi * t / (n * dt));
    h1[static_cast<std::size_t>(i)] = 4.0 * env * std::sin(2.0 * std::numbers::pi * 1.3 * t);
    h2[static_cast<std::size_t>(i)] = 3.0 * env * std::sin(2.0 * std::numbers::pi * 1.7 * t + 0.5);
  }
  RimOptions o;
  o.output_dt = 0.01;
  o.rtol = 1e-12;
  o.atol = 1e-14;
  const GroundMotion m1 = GroundMotion::uniform(dt, h1), m2 = GroundMotion::uniform(dt, h2);
  const RimResult r0 = simulate_axisymmetric(b, {&m1, &m2}, {}, o);
  ASSERT_GE(r0.uplifts, 1);
  ASSERT_GT(r0.max_tilt, 0.01);
  const double beta = 0.6;
  std::vector<double> g1(n), g2(n);
  for (std::size_t i = 0; i < h1.size(); ++i) {
    g1[i] = std::cos(beta) * h1[i] - std::sin(beta) * h2[i];
    g2[i] = std::sin(beta) * h1[i] + std::cos(beta) * h2[i];
  }
  const GroundMotion n1 = GroundMotion::uniform(dt, g1), n2 = GroundMotion::uniform(dt, g2);
  const RimResult r1 = simulate_axisymmetric(b, {&n1, &n2}, {}, o);
  ASSERT_EQ(r0.history.size(), r1.history.size());
  ASSERT_EQ(r0.status, r1.status);
  double worst = 0.0, worst_az = 0.0, worst_xy = 0.0;
  for (std::size_t i = 0; i < r0.history.size(); ++i) {
    worst = std::max(worst, std::abs(r0.history.tilt[i] - r1.history.tilt[i]));
    if (r0.history.tilt[i] > 1e-6)
      worst_az = std::max(
          worst_az, std::abs(std::remainder(r1.history.azimuth[i] - r0.history.azimuth[i] - beta,
                                            2.0 * std::numbers::pi)));
    const double x = std::cos(beta) * r0.history.x[i] - std::sin(beta) * r0.history.y[i];
    const double y = std::sin(beta) * r0.history.x[i] + std::cos(beta) * r0.history.y[i];
    worst_xy = std::max(worst_xy, std::hypot(x - r1.history.x[i], y - r1.history.y[i]));
  }
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(worst_az, 1e-6);
  EXPECT_LT(worst_xy, 1e-8);
}

TEST(AxisymmetricPivotZone, AnswersConvergeAsItShrinks) {
  // a 3D response under a pair, with the zone round upright 10 and 100 times smaller: the
  // differences shrink about 2.5 times a decade (docs/theory.md §27); at the default they are
  // below 1e-4 of the largest tilt
  const AxisymmetricBody b = uniform_cylinder(0.3, 2.4, 800.0);
  const double dt = 0.005;
  const int n = 800;
  std::vector<double> h1(n), h2(n);
  for (int i = 0; i < n; ++i) {
    const double t = i * dt;
    const double env = std::sin(std::numbers::pi * t / (n * dt));
    h1[static_cast<std::size_t>(i)] = 3.5 * env * std::sin(2.0 * std::numbers::pi * 1.1 * t);
    h2[static_cast<std::size_t>(i)] = 2.5 * env * std::sin(2.0 * std::numbers::pi * 0.8 * t + 1.0);
  }
  const GroundMotion m1 = GroundMotion::uniform(dt, h1), m2 = GroundMotion::uniform(dt, h2);
  RimOptions o;
  o.rtol = 1e-12;
  o.atol = 1e-14;
  o.output_dt = 0.01;
  const RimResult r0 = simulate_axisymmetric(b, {&m1, &m2}, {}, o);
  ASSERT_GT(r0.max_tilt, 0.02);
  double last = 0.0;
  for (double zone : {1e-13, 1e-14}) {
    o.pivot_zone = zone;
    const RimResult r = simulate_axisymmetric(b, {&m1, &m2}, {}, o);
    ASSERT_EQ(r.status, r0.status);
    ASSERT_EQ(r.history.size(), r0.history.size());
    EXPECT_EQ(r.landings, r0.landings);
    double worst = 0.0;
    for (std::size_t i = 0; i < r.history.size(); ++i)
      worst = std::max(worst, std::abs(r.history.tilt[i] - r0.history.tilt[i]));
    EXPECT_LT(worst, 1e-4 * r0.max_tilt) << zone;
    // and the difference from the default does not grow as the zone shrinks further
    EXPECT_GE(worst, last);
    EXPECT_LT(worst, 1.5e-4 * r0.max_tilt);
    last = worst;
  }
}

TEST(AxisymmetricModes, UnmodelledModesEndTheRunWithTheirMagnitude) {
  const AxisymmetricBody b = uniform_cylinder(0.4, 2.4, 800.0);
  const GroundMotion m = one_sine_pulse(0.6 * 9.80665, 2.0 * std::numbers::pi * 2.0, 2.0);
  RimOptions o;
  o.friction_coefficient = 0.2;  // below the uplift ratio R/h = 1/3: the base slides first
  const RimResult r = simulate_axisymmetric(b, {&m, nullptr}, {}, o);
  EXPECT_EQ(r.status, RimStatus::kUnmodelled);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.back().kind, RimEventKind::kFullSliding);
  EXPECT_NEAR(r.events.back().value, 0.2, 1e-9);
  EXPECT_NE(r.message.find("0.2"), std::string::npos) << r.message;
  // a vertical floor dropping faster than g: flight
  const GroundMotion down =
      GroundMotion::uniform(0.01, {0.0, 0.0, 0.0, 0.0}, {0.0, -5.0, -15.0, -15.0});
  const RimResult f = simulate_axisymmetric(b, {&down, nullptr}, {}, {});
  EXPECT_EQ(f.status, RimStatus::kUnmodelled);
  EXPECT_EQ(f.events.back().kind, RimEventKind::kLiftOff);
}

TEST(AxisymmetricModes, OverturnsUnderAStrongPulse) {
  const AxisymmetricBody b = uniform_cylinder(0.2, 2.0, 300.0);
  const GroundMotion m = one_sine_pulse(0.5 * 9.80665, 2.0 * std::numbers::pi * 0.7, 4.0);
  const RimResult r = simulate_axisymmetric(b, {&m, nullptr}, {}, {});
  EXPECT_EQ(r.status, RimStatus::kOverturned);
  EXPECT_EQ(r.events.back().kind, RimEventKind::kOverturn);
  // the planar engine agrees on the outcome
  const SimulationResult p = simulate(Body(planar_equivalent(b)), m, {}, {});
  EXPECT_EQ(p.status, Status::kOverturned);
}

}  // namespace
}  // namespace flexrock
