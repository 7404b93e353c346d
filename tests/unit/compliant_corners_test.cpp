// SPDX-License-Identifier: BSD-3-Clause
// The compliant contact's corners acting together (docs/theory.md, "Compliant contact"): a level
// body's two corners lift off and land at one instant, each with its own force. Checked against
// symmetry (a level block under vertical shaking stays level), the one-degree-of-freedom drop on
// two springs (closed forms, and an independent quadrature where the dashpot acts) and the
// impulsive floor's lift-off and landing counts as the springs stiffen.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

long count(const SimulationResult& r, EventKind k) {
  return std::count_if(r.events.begin(), r.events.end(),
                       [k](const Event& e) { return e.kind == k; });
}

// a contact setting: the springs for omega_v = ratio p (omega_v the bounce on both springs at the
// static load), with the linear law's damping ratio or the Hunt-Crossley law's restitution
struct Setting {
  ContactForceLaw law;
  double ratio;    // omega_v / p
  double damping;  // linear: zeta; Hunt-Crossley: e
};

SimulationOptions compliant(const Body& body, const Setting& s) {
  SimulationOptions o;
  o.contact_model = ContactModel::kCompliant;
  const double m = body.params().mass, wv = s.ratio * body.rocking_frequency();
  const double k_secant = 0.5 * m * wv * wv;  // per corner
  o.contact_force_law = s.law;
  if (s.law == ContactForceLaw::kLinear) {
    o.contact_stiffness = k_secant;
    o.contact_damping_ratio = s.damping;
  } else {
    // the same secant stiffness under half the weight: k delta_st^1.5 = M g / 2 = k_secant delta_st
    const double delta_st = 0.5 * m * body.g() / k_secant;
    o.contact_exponent = 1.5;
    o.contact_stiffness = 0.5 * m * body.g() / std::pow(delta_st, 1.5);
    o.contact_restitution = s.damping;
  }
  return o;
}

// pure vertical harmonic shaking, 1.5 g at 2 Hz: the floor drops faster than g twice a second
GroundMotion vertical_shaking(double g, double duration) {
  return GroundMotion::analytic(
      [g](double t) {
        return BaseAcceleration{0.0, 1.5 * g * std::sin(2.0 * std::numbers::pi * 2.0 * t)};
      },
      duration);
}

std::vector<Setting> grid() {
  std::vector<Setting> v;
  for (const double ratio : {300.0, 1000.0, 3000.0}) {
    for (const double zeta : {0.05, 1.0}) v.push_back({ContactForceLaw::kLinear, ratio, zeta});
    for (const double e : {0.3, 0.9}) v.push_back({ContactForceLaw::kHuntCrossley, ratio, e});
  }
  return v;
}

TEST(CompliantCorners, LevelBlockUnderVerticalShakingStaysLevel) {
  // a symmetric block with no horizontal motion has nothing to tilt it: its two corners lift off
  // and land together, every time, with equal forces (theta = 0 to rounding), and the lift-offs
  // are seen (the floor drops faster than g for 0.13 s of each 0.5 s cycle)
  const Body body(rigid_block(0.6, 1.8, 1000.0));
  for (const Setting& s : grid()) {
    SimulationOptions o = compliant(body, s);
    o.output_dt = 0.002;
    const auto r = simulate(body, vertical_shaking(body.g(), 2.0), {}, o);
    ASSERT_EQ(r.status, Status::kCompleted) << r.message;
    double max_theta = 0.0;
    for (const double th : r.history.theta) max_theta = std::max(max_theta, std::abs(th));
    const char* law = to_string(s.law);
    EXPECT_LT(max_theta, 1e-12) << law << " ratio " << s.ratio << " damping " << s.damping;
    EXPECT_LT(std::abs(r.final_theta), 1e-12) << law << " ratio " << s.ratio;
    EXPECT_GE(r.extremes.lift_offs, 4) << law << " ratio " << s.ratio << " damping " << s.damping;
    EXPECT_EQ(count(r, EventKind::kLiftOff), r.extremes.lift_offs);
    EXPECT_GT(r.extremes.flight_time, 4 * 0.05) << law << " ratio " << s.ratio;
    // every touch after a flight is on both corners (edge 0), and nothing uplifts one corner
    for (const Event& e : r.events) {
      if (e.kind == EventKind::kLanding) {
        EXPECT_EQ(e.edge, 0) << "landing at t = " << e.time;
      }
      EXPECT_NE(e.kind, EventKind::kUplift) << "t = " << e.time;
      EXPECT_NE(e.kind, EventKind::kImpact) << "t = " << e.time;
    }
  }
}

// The flat drop: the block rests on its springs until t0 = 0.05 s, is thrown up by the floor
// dropping at 2 g until t1 = 0.2 s and lands flat on both corners. In flight its corners' height
// over the floor is ballistic in the floor's frame (upward acceleration g while the floor drops at
// 2 g, -g after), so the lift-off and landing times alone give the landing speed v0, whatever
// the springs did before.
constexpr double kDropStart = 0.05, kDropEnd = 0.2;

GroundMotion drop(double g) {
  return GroundMotion::analytic(
      [g](double t) {
        return BaseAcceleration{0.0, t >= kDropStart && t < kDropEnd ? -2.0 * g : 0.0};
      },
      1.2, {kDropStart, kDropEnd});
}

double landing_speed(double g, double t_off, double t_land) {
  const double a1 = g, a2 = -g, d1 = kDropEnd - t_off, d2 = t_land - kDropEnd;
  // 0 = v (d1 + d2) + a1 d1^2 / 2 + a1 d1 d2 + a2 d2^2 / 2 for the speed v at lift-off
  const double v = -(0.5 * a1 * d1 * d1 + a1 * d1 * d2 + 0.5 * a2 * d2 * d2) / (d1 + d2);
  return -(v + a1 * d1 + a2 * d2);  // downward, at the landing
}

// the peak of the total normal force of two corners carrying mass M landing flat at v0, by an
// independent fixed-step RK4 integration of M delta'' = M g - 2 F_n(delta, delta') (refined
// where F peaks by a parabola through the three largest samples)
template <class Force>
double peak_by_quadrature(double m, double g, double v0, double period, Force force) {
  const int steps_per_period = 200000;
  const double dt = period / steps_per_period;
  double d = 0.0, v = v0, best = 0.0, f_prev2 = 0.0, f_prev = 0.0;
  auto acc = [&](double dd, double vv) { return g - 2.0 * force(dd, vv) / m; };
  for (int i = 0; i < 2 * steps_per_period; ++i) {
    const double k1d = v, k1v = acc(d, v);
    const double k2d = v + 0.5 * dt * k1v, k2v = acc(d + 0.5 * dt * k1d, v + 0.5 * dt * k1v);
    const double k3d = v + 0.5 * dt * k2v, k3v = acc(d + 0.5 * dt * k2d, v + 0.5 * dt * k2v);
    const double k4d = v + dt * k3v, k4v = acc(d + dt * k3d, v + dt * k3v);
    d += dt / 6.0 * (k1d + 2.0 * k2d + 2.0 * k3d + k4d);
    v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    const double f = 2.0 * force(d, v);
    if (i >= 2 && f_prev > f && f_prev >= f_prev2) {
      // the vertex of the parabola through the last three samples
      const double curv = f_prev2 - 2.0 * f_prev + f;
      best = f_prev - 0.125 * (f_prev2 - f) * (f_prev2 - f) / curv;
      break;
    }
    f_prev2 = f_prev;
    f_prev = f;
    if (d < 0.0) break;
  }
  return best;
}

TEST(CompliantCorners, FlatDropPeakForceIsTheMassOnTwoSprings) {
  // both corners land together: the total force is that of the mass M on two springs. Linear and
  // undamped: M g + sqrt((M g)^2 + 2 k M v0^2) (energy: k delta^2 - M g delta = M v0^2 / 2 with
  // k per corner); Hunt-Crossley and elastic: 2 k delta^p at the root of
  // 2 k delta^(p+1) / (p+1) - M g delta = M v0^2 / 2; with a dashpot, an independent quadrature
  const Body body(rigid_block(0.6, 1.8, 1000.0));
  const double m = body.params().mass, g = body.g(), mg = m * g;
  for (const Setting& s : {Setting{ContactForceLaw::kLinear, 1000.0, 0.0},
                           Setting{ContactForceLaw::kLinear, 1000.0, 0.3},
                           Setting{ContactForceLaw::kHuntCrossley, 1000.0, 1.0},
                           Setting{ContactForceLaw::kHuntCrossley, 1000.0, 0.5}}) {
    SimulationOptions o = compliant(body, s);
    o.rtol = 1e-11;
    o.atol = 1e-13;
    const auto r = simulate(body, drop(g), {}, o);
    ASSERT_EQ(r.status, Status::kCompleted) << r.message;
    const Event *off = nullptr, *land = nullptr;
    for (const Event& e : r.events) {
      if (e.kind == EventKind::kLiftOff && !off) off = &e;
      if (e.kind == EventKind::kLanding && off && !land) land = &e;
    }
    ASSERT_TRUE(off && land) << "the block must lift off and land";
    EXPECT_EQ(land->edge, 0);
    const double v0 = landing_speed(g, off->time, land->time);
    ASSERT_GT(v0, 0.5);
    const double k = o.contact_stiffness, p = s.law == ContactForceLaw::kLinear ? 1.0 : 1.5;
    double want = 0.0;
    if (s.law == ContactForceLaw::kLinear && s.damping == 0.0) {
      want = mg + std::sqrt(mg * mg + 2.0 * k * m * v0 * v0);
    } else if (s.law == ContactForceLaw::kHuntCrossley && s.damping == 1.0) {
      // the root by bisection: the stored energy less gravity's work is monotone past delta_st
      double lo = 0.0, hi = 1.0;
      for (int i = 0; i < 200; ++i) {
        const double d = 0.5 * (lo + hi);
        const double e = 2.0 * k * std::pow(d, p + 1.0) / (p + 1.0) - mg * d - 0.5 * m * v0 * v0;
        (e > 0.0 ? hi : lo) = d;
      }
      want = 2.0 * k * std::pow(0.5 * (lo + hi), p);
    } else {
      const double wv = s.ratio * body.rocking_frequency(), period = 2.0 * std::numbers::pi / wv;
      const double zeta = s.damping, e = s.damping;
      const double c = 2.0 * zeta * std::sqrt(0.5 * k * m);
      const double delta_st =
          s.law == ContactForceLaw::kLinear ? 0.5 * mg / k : std::pow(0.5 * mg / k, 1.0 / p);
      const double v_in = std::max(v0, std::sqrt(g * delta_st));
      want = peak_by_quadrature(m, g, v0, period, [&](double d, double dd) {
        if (s.law == ContactForceLaw::kLinear) return std::max(k * d + c * dd, 0.0);
        return std::max(k * std::pow(d, p) * (1.0 + 0.75 * (1.0 - e * e) * dd / v_in), 0.0);
      });
    }
    const char* law = to_string(s.law);
    std::printf("%s, damping %.2g: v0 = %.6f m/s, peak %.10g N, expected %.10g N (%.2e)\n", law,
                s.damping, v0, 2.0 * r.extremes.max_contact_force, want,
                2.0 * r.extremes.max_contact_force / want - 1.0);
    // each corner carries half of it; the landing event's estimate is the larger corner's peak
    EXPECT_NEAR(r.extremes.max_contact_force, 0.5 * want, 1e-8 * want)
        << law << " damping " << s.damping << " v0 " << v0;
    EXPECT_NEAR(land->force_estimate, 0.5 * want, 1e-8 * want) << law << " damping " << s.damping;
    EXPECT_LT(std::abs(r.final_theta), 1e-12) << law;
  }
}

TEST(CompliantCorners, LiftOffsAndLandingsTendToTheImpulsiveFloors) {
  // with a plastic dashpot (zeta = 4: no rebound) the compliant floor's lift-offs and landings
  // under vertical shaking are the impulsive floor's, at every stiffness of the sequence
  const Body body(rigid_block(0.6, 1.8, 1000.0));
  const GroundMotion shake = vertical_shaking(body.g(), 3.0);
  const auto ref = simulate(body, shake, {}, SimulationOptions{});
  ASSERT_EQ(ref.status, Status::kCompleted) << ref.message;
  ASSERT_GE(ref.extremes.lift_offs, 5);
  const long ref_landings = count(ref, EventKind::kLanding);
  for (const double ratio : {100.0, 300.0, 1000.0, 3000.0}) {
    const auto r =
        simulate(body, shake, {}, compliant(body, {ContactForceLaw::kLinear, ratio, 4.0}));
    ASSERT_EQ(r.status, Status::kCompleted) << r.message;
    std::printf(
        "omega_v/p = %6.0f: lift-offs %ld, landings %ld, flight time %.6f s "
        "(impulsive floor: %ld, %ld, %.6f s)\n",
        ratio, r.extremes.lift_offs, count(r, EventKind::kLanding), r.extremes.flight_time,
        ref.extremes.lift_offs, ref_landings, ref.extremes.flight_time);
    EXPECT_EQ(r.extremes.lift_offs, ref.extremes.lift_offs) << "ratio " << ratio;
    EXPECT_EQ(count(r, EventKind::kLanding), ref_landings) << "ratio " << ratio;
    EXPECT_EQ(r.extremes.impacts, ref.extremes.impacts) << "ratio " << ratio;
  }
}

TEST(CompliantOptions, ImpulsiveKeysAndAZeroTangentialSpringAreRefused) {
  // the compliant contact has no impact law, restitution or assumed impact duration: a value it
  // would ignore is refused, naming the key; a tangential stiffness of 0 is no default
  const Body body(rigid_block(0.6, 1.8, 1000.0));
  const GroundMotion none = GroundMotion::none(0.1);
  auto refused = [&](const SimulationOptions& o, const std::string& key) {
    try {
      simulate(body, none, {}, o);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << key << " was not refused";
  };
  const SimulationOptions base = compliant(body, {ContactForceLaw::kLinear, 300.0, 1.0});
  EXPECT_EQ(simulate(body, none, {}, base).status, Status::kCompleted);
  SimulationOptions o = base;
  o.impact_law = ImpactLaw::kRigidBody;
  refused(o, "impact_law");
  o = base;
  o.restitution_factor = 0.9;
  refused(o, "restitution_factor");
  o = base;
  o.restitution_ratio_edge2 = 0.8;
  refused(o, "restitution_ratio_edge2");
  o = base;
  o.impact_duration = 0.005;
  refused(o, "impact_duration");
  o = base;
  o.contact_tangential_stiffness = 0.0;
  refused(o, "contact_tangential_stiffness");
  o.contact_tangential_stiffness = -3.0;
  refused(o, "contact_tangential_stiffness");
}

}  // namespace
}  // namespace flexrock
