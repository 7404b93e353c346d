// SPDX-License-Identifier: BSD-3-Clause
// The reset maps of contact/ (lift-off, landing, Moreau's impact with Coulomb friction, stick or
// slip) against the machine-checked derivation (tools/derive/derive.py), which computes each map
// mass by mass from the point-mass bodies, at rigid (n = 0) and flexible (n = 1, 2, 3) states,
// under the paper's and the rigid_body law, and the whole map's choice at theta = 0;
// then the laws' own properties: no energy gained, the impulse in the friction cone, a sticking
// corner at rest after, and the limits mu -> infinity (the sticking map) and mu -> 0 (no friction).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "flexrock/contact/flight_maps.hpp"
#include "flexrock/contact/friction_impact.hpp"
#include "flexrock/contact/impact.hpp"
#include "flexrock/model/dynamics.hpp"
#include "sympy_reference.hpp"

namespace flexrock {
namespace {

using json = nlohmann::json;
using sympy_reference::params_of;
using sympy_reference::vec;
using DynX = Dynamics<Eigen::Dynamic, Eigen::Dynamic>;
using State = ImpactState<VectorX>;
constexpr double kInf = std::numeric_limits<double>::infinity();

Eigen::Vector2d vec2(const json& j) { return {j[0].get<double>(), j[1].get<double>()}; }
// the reference (tools/derive/derive.py, run by the ctest fixture)
const json& reference() {
  static const json ref = [] {
    std::ifstream in(FLEXROCK_BINARY_DIR "/sympy_reference.json");
    return in ? json::parse(in) : json();
  }();
  return ref;
}

void expect_close(double got, double want, double scale, const std::string& what) {
  EXPECT_NEAR(got, want, 1e-12 * std::max(1.0, std::abs(scale))) << what;
}
void expect_vec(const VectorX& got, const json& want, double scale, const std::string& what) {
  ASSERT_EQ(got.size(), static_cast<Eigen::Index>(want.size())) << what;
  for (Eigen::Index i = 0; i < got.size(); ++i)
    expect_close(got(i), want[static_cast<std::size_t>(i)].get<double>(), scale, what);
}
// an impulse against the reference's [I_x, I_y], on the scale |I_x| + |I_y|
void expect_impulse(const Eigen::Vector2d& got, const json& want, const std::string& what) {
  const Eigen::Vector2d w = vec2(want);
  const double scale = w.lpNorm<1>();
  expect_close(got(0), w(0), scale, what + " I_x");
  expect_close(got(1), w(1), scale, what + " I_y");
}

// each body of the reference with its dynamics
template <class F>
void for_each_body(F&& f) {
  const json& ref = reference();
  ASSERT_FALSE(ref.is_null()) << "run tools/derive/derive.py (the ctest fixture does)";
  const double g = ref["g"];
  for (const auto& c : ref["cases"]) {
    const Body body(params_of(c, g));
    const DynX dyn(body);
    f(c, body, dyn);
  }
}

TEST(ContactMapsReference, LiftOffMapAgainstPointMassMechanics) {
  // the c.g.'s place and velocity about the pivot, and whether the pivot would dive in flight
  std::set<int> ns;
  int checked = 0, pulls = 0;
  for_each_body([&](const json& c, const Body& body, const DynX& dyn) {
    for (const auto& s : c["liftoff"]) {
      const int e = s["edge"];
      const VectorX q = vec(s["q"]), qd = vec(s["q_dot"]);
      const double h = body.params().height;
      const LiftOffState<VectorX> at{.pivot = e,
                                     .theta = s["theta"],
                                     .q = q,
                                     .theta_dot = s["theta_dot"],
                                     .q_dot = qd,
                                     .offset = s["pivot_x"].get<double>() - h * dyn.alpha(e),
                                     .sliding = false};
      const FlightStart f = lift_off_map(dyn, at);
      expect_close(f.r_c(0), s["cg"][0].get<double>(), h, "x_c");
      expect_close(f.r_c(1), s["cg"][1].get<double>(), h, "y_c");
      const Eigen::Vector2d v = vec2(s["cg_velocity"]);
      expect_close(f.v_c(0), v(0), v.norm(), "xc_dot");
      expect_close(f.v_c(1), v(1), v.norm(), "yc_dot");
      // the pivot dives if its vertical acceleration in flight (from the masses) is negative
      const BaseAcceleration a{s["base_acc"][0].get<double>(), s["base_acc"][1].get<double>()};
      const double corner_ydd = s["flight_corner_acceleration"][1];
      EXPECT_EQ(lift_off_pulls(dyn, at, a), corner_ydd < 0.0) << corner_ydd;
      // a sliding pivot never does, and its slip carries the c.g.
      LiftOffState<VectorX> sliding = at;
      sliding.sliding = true;
      sliding.slip_velocity = 0.3;
      EXPECT_FALSE(lift_off_pulls(dyn, sliding, a));
      EXPECT_EQ(lift_off_map(dyn, sliding).v_c(0), f.v_c(0) + 0.3);
      pulls += corner_ydd < 0.0;
      ns.insert(static_cast<int>(q.size()));
      ++checked;
    }
  });
  EXPECT_GE(checked, 26);
  EXPECT_GE(pulls, 1);
  EXPECT_EQ(ns, (std::set<int>{0, 1, 2, 3}));
}

TEST(ContactMapsReference, LandingMapAgainstPointMassMechanics) {
  // the sticking corner conserves the modal momenta and the moment of momentum about it; the
  // reference solves that balance mass by mass. At theta = 0 the map may hand the floor to the
  // other corner or land flat: those states are checked against the flat landings below.
  int single = 0, flat = 0;
  std::set<int> ns;
  for_each_body([&](const json& c, const Body& body, const DynX& dyn) {
    const double mgh = body.params().mass * body.g() * body.params().height;
    for (const auto& s : c["landings"]) {
      const int e = s["edge"];
      const VectorX q = vec(s["q"]), qd = vec(s["q_dot_minus"]);
      const Eigen::Vector2d v_c = vec2(s["cg_velocity"]);
      const double thd = s["theta_dot_minus"];
      const auto out = landing_map(dyn, e, State{s["theta"], q, thd, qd, v_c}, ImpactRule{});
      EXPECT_FALSE(out.law_fallback);
      if (out.flat || out.edge != e) {
        EXPECT_EQ(s["theta"].get<double>(), 0.0);
        continue;
      }
      const double scale = std::abs(thd) + qd.norm();
      expect_close(out.theta_dot, s["theta_dot_plus"].get<double>(), scale, "theta_dot+");
      expect_vec(out.q_dot, s["q_dot_plus"], scale, "q_dot+");
      expect_impulse(out.impulse, s["impulse"], "landing");
      expect_close(out.energy_loss, s["energy_loss"].get<double>(), mgh, "landing loss");
      ns.insert(static_cast<int>(q.size()));
      ++single;
    }
    for (const auto& s : c["flat_landings"]) {
      // both corners press after (H^_1 <= 0 <= H^_2): from either corner the map lands flat
      const double h1 = s["H_hat"][0], h2 = s["H_hat"][1];
      if (!(h1 <= 0.0 && 0.0 <= h2)) continue;
      const VectorX q = vec(s["q"]), qd = vec(s["q_dot_minus"]);
      const Eigen::Vector2d v_c = vec2(s["cg_velocity"]);
      const double thd = s["theta_dot_minus"];
      for (int e : {1, 2}) {
        const auto out = landing_map(dyn, e, State{0.0, q, thd, qd, v_c}, ImpactRule{});
        ASSERT_TRUE(out.flat) << "H^ = " << h1 << ", " << h2;
        EXPECT_EQ(out.theta_dot, 0.0);
        expect_vec(out.q_dot, s["q_dot_plus"], std::abs(thd) + qd.norm(), "flat q_dot+");
        expect_impulse(out.impulse, s["impulse"], "flat landing");
        expect_close(out.energy_loss, s["energy_loss"].get<double>(), mgh, "flat landing loss");
        ++flat;
      }
    }
  });
  EXPECT_GE(single, 45);
  EXPECT_GE(flat, 20);
  EXPECT_EQ(ns, (std::set<int>{0, 1, 2, 3}));
}

// one impact with friction of the reference: its state and the floor's coefficients
struct FrictionCase {
  VectorX q, qd;
  Eigen::Vector2d v_c;
  double theta = 0.0, thd = 0.0;
  CoulombFriction f;
  State state() const { return {theta, q, thd, qd, v_c}; }
};
FrictionCase friction_case(const json& s) {
  FrictionCase k;
  k.q = vec(s["q"]);
  k.qd = vec(s["q_dot_minus"]);
  k.v_c = vec2(s["cg_velocity"]);
  k.theta = s.contains("theta") ? s["theta"].get<double>() : 0.0;
  k.thd = s["theta_dot_minus"];
  k.f = {s["mu_s"].get<double>(), s["mu_k"].get<double>()};
  return k;
}

TEST(ContactMapsReference, FrictionImpactAgainstPointMassMechanics) {
  // Moreau's law with Coulomb friction: for each d_dot+ the post state follows from the moment of
  // momentum about the corner and the modal momenta, the impulse is the change of momentum summed
  // mass by mass, and Coulomb's law picks d_dot+ (the reference's stick / slip branch)
  int stick = 0, slip = 0, inconsistent = 0, whole = 0;
  std::set<int> ns;
  for_each_body([&](const json& c, const Body& body, const DynX& dyn) {
    const double m = body.params().mass, mgh = m * body.g() * body.params().height;
    for (const auto& s : c["friction"]["friction_landings"]) {
      const FrictionCase k = friction_case(s);
      const int e = s["edge"];
      const bool slips = s["mode"] == "slip";
      const double scale = std::abs(k.thd) + k.qd.norm();
      // the corner's outcome, affine in d_dot+, and Coulomb's law on it
      ImpactCandidate<VectorX> cand;
      corner_candidate(dyn, e, k.state(), ModesInImpact::kMomentaConserved, cand);
      const CoulombResolution z = coulomb_resolution(cand, k.v_c, m, k.f);
      const Eigen::Vector2d l0 = m * (cand.vc0 - k.v_c);
      expect_impulse(l0, s["stick_impulse"], "sticking impulse");
      EXPECT_EQ(z.slid, slips);
      if (!z.ok) {
        // k_s <= 0: no slide fits; the reference's slide then moves the wrong way or pulls
        EXPECT_TRUE(slips);
        EXPECT_FALSE(s["slip_sign"].get<int>() * s["d_dot_plus"].get<double>() > 0.0 &&
                     s["impulse"][1].get<double>() > 0.0);
        ++inconsistent;
        continue;
      }
      expect_close(z.v, s["d_dot_plus"].get<double>(), std::sqrt(body.g() * body.params().height),
                   "d_dot+");
      expect_close(cand.thd0 + z.v * cand.thd1, s["theta_dot_plus"].get<double>(), scale, "thd+");
      expect_vec(cand.qd0 + z.v * cand.qd1, s["q_dot_plus"], scale, "q_dot+");
      expect_impulse(m * (cand.vc0 + z.v * cand.vc1 - k.v_c), s["impulse"], "impulse");
      // the whole map, where it lands on this corner (away from theta = 0 it always does)
      const auto out =
          friction_impact(dyn, k.state(), {.edge = e, .from_flight = true}, ImpactRule{}, k.f);
      if (k.theta != 0.0) {
        EXPECT_TRUE(out.consistent && out.edge == e && !out.flat);
      }
      if (out.consistent && out.edge == e && !out.flat) {
        EXPECT_EQ(out.slip, slips ? s["slip_sign"].get<int>() : 0);
        expect_close(out.slip_velocity, s["d_dot_plus"].get<double>(), 1.0, "slip velocity");
        expect_close(out.theta_dot, s["theta_dot_plus"].get<double>(), scale, "map thd+");
        expect_vec(out.q_dot, s["q_dot_plus"], scale, "map q_dot+");
        expect_impulse(out.impulse, s["impulse"], "map impulse");
        expect_close(out.energy_loss, s["energy_loss"].get<double>(), mgh, "map loss");
        // the friction the sticking impulse needs (infinite where it would pull)
        const double demand = friction_ratio(l0(0), l0(1));
        if (std::isinf(demand)) {
          EXPECT_EQ(out.sticking_demand, demand);
        } else {
          expect_close(out.sticking_demand, demand, demand, "demand");
        }
        ++whole;
      }
      ns.insert(static_cast<int>(k.q.size()));
      (slips ? slip : stick) += 1;
    }
  });
  EXPECT_GE(stick, 20);
  EXPECT_GE(slip, 40);
  EXPECT_GE(whole, 50);
  EXPECT_LE(inconsistent, 4);
  EXPECT_EQ(ns, (std::set<int>{0, 1, 2, 3}));
}

TEST(ContactMapsReference, FlatFrictionImpactAgainstPointMassMechanics) {
  // both edges land (theta_dot+ = 0), the base sticking or sliding at d_dot+: the modal momenta
  // mu q_dot+ + psi_x d_dot+ / h conserved, Coulomb's law on the whole impulse
  int stick = 0, slip = 0;
  for_each_body([&](const json& c, const Body& body, const DynX& dyn) {
    const double mgh = body.params().mass * body.g() * body.params().height;
    for (const auto& s : c["friction"]["flat_friction_landings"]) {
      const FrictionCase k = friction_case(s);
      const bool slips = s["mode"] == "slip";
      const double scale = std::abs(k.thd) + k.qd.norm();
      for (int e : {1, 2}) {
        const auto out =
            friction_impact(dyn, k.state(), {.edge = e, .flat = true}, ImpactRule{}, k.f);
        ASSERT_TRUE(out.consistent);
        EXPECT_TRUE(out.flat);
        EXPECT_EQ(out.theta_dot, 0.0);
        EXPECT_EQ(out.slid, slips);
        EXPECT_EQ(out.slip, slips ? s["slip_sign"].get<int>() : 0);
        expect_close(out.slip_velocity, s["d_dot_plus"].get<double>(), 1.0, "flat d_dot+");
        expect_vec(out.q_dot, s["q_dot_plus"], scale, "flat q_dot+");
        expect_impulse(out.impulse, s["impulse"], "flat impulse");
        expect_close(out.energy_loss, s["energy_loss"].get<double>(), mgh, "flat loss");
      }
      (slips ? slip : stick) += 1;
    }
  });
  EXPECT_GE(stick, 2);
  EXPECT_GE(slip, 20);
}

TEST(ContactMapsReference, SlipDirectionOpposesKineticFriction) {
  // a sliding state's floor force is F_I = -sg mu_k F_J: the slip the floor cannot hold is sg
  int checked = 0;
  for_each_body([&](const json& c, const Body&, const DynX&) {
    for (const char* kind : {"sliding_rocking", "sliding_full_contact"}) {
      for (const auto& s : c["friction"][kind]) {
        const double fi = s["reaction"][0], fj = s["reaction"][1];
        if (!(fj > 0.0)) continue;
        EXPECT_EQ(slip_direction(fi), s["slip_sign"].get<int>());
        EXPECT_NEAR(friction_ratio(fi, fj), s["mu_k"].get<double>(), 1e-12);
        ++checked;
      }
    }
  });
  EXPECT_GE(checked, 20);
}

TEST(ContactMapsReference, RigidBodyLawWithFrictionAgainstPointMassMechanics) {
  // rigid_body: the body rigid during the impact (q_dot+ = q_dot-), the moment of momentum about
  // the corner summed mass by mass, Coulomb's law on the impulse; where it would add energy the
  // engine takes the paper's law and says so
  int stick = 0, slip = 0, fallback = 0;
  std::set<int> ns;
  const ImpactRule rigid{.law = ImpactLaw::kRigidBody};
  for_each_body([&](const json& c, const Body& body, const DynX& dyn) {
    const double m = body.params().mass;
    for (const auto& s : c["friction"]["friction_landings"]) {
      const FrictionCase k = friction_case(s);
      const json& r = s["rigid_body"];
      const int e = s["edge"];
      const bool slips = r["mode"] == "slip";
      const double scale = std::abs(k.thd) + k.qd.norm();
      ImpactCandidate<VectorX> cand;
      corner_candidate(dyn, e, k.state(), impact_law_info(ImpactLaw::kRigidBody).modes, cand);
      expect_impulse(m * (cand.vc0 - k.v_c), r["stick_impulse"], "rigid_body sticking impulse");
      const CoulombResolution z = coulomb_resolution(cand, k.v_c, m, k.f);
      EXPECT_EQ(z.slid, slips);
      EXPECT_EQ(z.ok, r["consistent"].get<int>() != 0);
      if (!z.ok) continue;
      expect_close(z.v, r["d_dot_plus"].get<double>(), 1.0, "rigid_body d_dot+");
      expect_close(cand.thd0 + z.v * cand.thd1, r["theta_dot_plus"].get<double>(), scale,
                   "rigid_body thd+");
      EXPECT_EQ(VectorX(cand.qd0 + z.v * cand.qd1), k.qd);  // the modal velocities are kept
      expect_impulse(m * (cand.vc0 + z.v * cand.vc1 - k.v_c), r["impulse"], "rigid_body impulse");
      if (k.theta == 0.0) continue;  // the whole map may take another outcome there
      const double loss = r["energy_loss"];
      const double before = dyn.flight_kinetic_energy(k.q, k.thd, k.qd, k.v_c);
      if (std::abs(loss) < 1e-9 * before) continue;  // a gain or a loss within rounding of zero
      const auto out =
          friction_impact(dyn, k.state(), {.edge = e, .from_flight = true}, rigid, k.f);
      ASSERT_TRUE(out.consistent);
      EXPECT_EQ(out.law_fallback, loss < 0.0) << loss;
      if (out.law_fallback) {
        // the paper's law: the same as the map with the paper's rule
        const auto paper =
            friction_impact(dyn, k.state(), {.edge = e, .from_flight = true}, ImpactRule{}, k.f);
        EXPECT_EQ(out.theta_dot, paper.theta_dot);
        EXPECT_EQ(out.impulse, paper.impulse);
        ++fallback;
        continue;
      }
      expect_close(out.theta_dot, r["theta_dot_plus"].get<double>(), scale, "rigid_body map thd+");
      expect_impulse(out.impulse, r["impulse"], "rigid_body map impulse");
      expect_close(out.energy_loss, loss, std::abs(loss), "rigid_body map loss");
      ns.insert(static_cast<int>(k.q.size()));
      (slips ? slip : stick) += 1;
    }
  });
  EXPECT_GE(stick, 10);
  EXPECT_GE(slip, 20);
  EXPECT_EQ(ns, (std::set<int>{0, 1, 2, 3}));
  std::printf("rigid_body with friction: %d stick, %d slip, %d took the paper's law\n", stick, slip,
              fallback);
}

TEST(ContactMapsReference, LevelImpactWithFrictionTakesTheConsistentOutcome) {
  // theta = 0 from flight: corner 1, corner 2 and flat, each resolved by Coulomb's law; the
  // derivation's consistency of each and the outcome the stated rule takes, for the whole map
  const json& ref = reference();
  ASSERT_TRUE(ref.contains("friction_theta0"));
  const double g = ref["g"];
  std::map<std::string, int> taken;
  for (const auto& s : ref["friction_theta0"]) {
    const Body body(params_of(s, g));
    const DynX dyn(body);
    const FrictionCase k = friction_case(s);
    const int e = s["edge"];
    const json& want = s["outcome"];
    const auto out =
        friction_impact(dyn, k.state(), {.edge = e, .from_flight = true}, ImpactRule{}, k.f);
    ASSERT_EQ(out.consistent, want["fits"].get<int>() != 0);
    if (!out.consistent) continue;
    const std::string kind = want["outcome"];
    EXPECT_EQ(out.flat, kind == "flat");
    if (!out.flat) {
      EXPECT_EQ(out.edge, kind == "corner1" ? 1 : 2);
    }
    EXPECT_EQ(out.slid, want["mode"] == "slip");
    EXPECT_EQ(out.slip, want["slip_sign"].get<int>());
    const double scale = std::abs(k.thd) + k.qd.norm();
    expect_close(out.slip_velocity, want["d_dot_plus"].get<double>(), 1.0, "d_dot+");
    expect_close(out.theta_dot, want["theta_dot_plus"].get<double>(), scale, "theta_dot+");
    expect_vec(out.q_dot, want["q_dot_plus"], scale, "q_dot+");
    expect_impulse(out.impulse, want["impulse"], "impulse");
    const double mgh = body.params().mass * g * body.params().height;
    expect_close(out.energy_loss, want["energy_loss"].get<double>(), mgh, "loss");
    ++taken[kind];
  }
  // each outcome is exercised
  EXPECT_GE(taken["corner1"], 2);
  EXPECT_GE(taken["corner2"], 2);
  EXPECT_GE(taken["flat"], 10);
}

// ---- the laws' own properties, at the reference's states over a range of coefficients

TEST(ContactMapsProperties, FrictionImpactNeverGainsEnergyAndKeepsTheImpulseInTheCone) {
  int stick = 0, slip = 0;
  for_each_body([&](const json& c, const Body& body, const DynX& dyn) {
    const double mgh = body.params().mass * body.g() * body.params().height;
    for (const auto& s : c["friction"]["friction_landings"]) {
      FrictionCase k = friction_case(s);
      for (double mu : {0.0, 0.05, 0.2, 0.5, 1.0, 3.0}) {
        for (double ratio : {1.0, 0.7}) {
          k.f = {mu, mu * ratio};
          const int e = s["edge"];
          const auto out =
              friction_impact(dyn, k.state(), {.edge = e, .from_flight = true}, ImpactRule{}, k.f);
          if (!out.consistent) continue;
          EXPECT_GE(out.energy_loss, -1e-12 * mgh) << "mu " << mu;
          const double ix = out.impulse(0), iy = out.impulse(1);
          if (out.slid) {
            // on the edge of the kinetic cone, against the slip, pressing
            EXPECT_GT(iy, 0.0);
            EXPECT_NEAR(std::abs(ix), k.f.mu_k * iy, 1e-12 * (std::abs(ix) + iy));
            if (out.slip != 0) {
              EXPECT_LE(out.slip * ix, 1e-12 * (std::abs(ix) + iy));  // (mu = 0: I_x is rounding)
            }
            ++slip;
          } else {
            EXPECT_TRUE(inside_friction_cone(ix, iy, k.f.mu_s));
            ++stick;
          }
          // the corner after: at rest when it sticks, sliding along the floor at d_dot+ when not
          if (out.flat) continue;
          const double th = k.theta, sn = std::sin(th), cs = std::cos(th);
          const Eigen::Vector2d v_corner =
              dyn.corner_velocity_body(out.edge, sn, cs, k.q, out.theta_dot, out.q_dot, out.v_c);
          const Eigen::Vector2d want = out.slip_velocity * Eigen::Vector2d(cs, -sn);
          const double v_scale = k.v_c.norm() + out.v_c.norm();
          EXPECT_NEAR(v_corner(0), want(0), 1e-12 * v_scale) << "mu " << mu;
          EXPECT_NEAR(v_corner(1), want(1), 1e-12 * v_scale) << "mu " << mu;
        }
      }
    }
  });
  EXPECT_GE(stick, 50);
  EXPECT_GE(slip, 200);
}

TEST(ContactMapsProperties, FrictionLimitsAreTheStickingAndTheFrictionlessMaps) {
  // mu -> infinity: the sticking landing of theory §16 wherever its impulse presses;
  // mu = 0: no horizontal impulse, so the c.g.'s horizontal velocity is kept; and the map is
  // continuous there (mu = 1e-9 is within 1e-8 of it)
  int sticking = 0, frictionless = 0;
  for_each_body([&](const json& c, const Body& body, const DynX& dyn) {
    const double m = body.params().mass, mgh = m * body.g() * body.params().height;
    for (const auto& s : c["friction"]["friction_landings"]) {
      FrictionCase k = friction_case(s);
      const int e = s["edge"];
      const CornerImpactCase ic{.edge = e, .from_flight = true};
      const auto stuck = landing_map(dyn, e, k.state(), ImpactRule{});
      k.f = {1e12, 1e12};
      const auto big = friction_impact(dyn, k.state(), ic, ImpactRule{}, k.f);
      if (stuck.impulse(1) > 0.0 && big.consistent) {
        EXPECT_FALSE(big.slid);
        EXPECT_EQ(big.edge, stuck.edge);
        EXPECT_EQ(big.flat, stuck.flat);
        const double scale = std::abs(k.thd) + k.qd.norm();
        expect_close(big.theta_dot, stuck.theta_dot, scale, "mu = inf thd+");
        for (Eigen::Index i = 0; i < k.q.size(); ++i)
          expect_close(big.q_dot(i), stuck.q_dot(i), scale, "mu = inf q_dot+");
        expect_close(big.impulse(0), stuck.impulse(0), stuck.impulse.norm(), "mu = inf I_x");
        expect_close(big.impulse(1), stuck.impulse(1), stuck.impulse.norm(), "mu = inf I_y");
        expect_close(big.energy_loss, stuck.energy_loss, mgh, "mu = inf loss");
        ++sticking;
      }
      k.f = {0.0, 0.0};
      const auto free = friction_impact(dyn, k.state(), ic, ImpactRule{}, k.f);
      if (!free.consistent) continue;
      EXPECT_NEAR(free.impulse(0), 0.0, 1e-12 * free.impulse.norm());
      EXPECT_NEAR(free.v_c(0), k.v_c(0), 1e-12 * (k.v_c.norm() + 1.0));
      EXPECT_GE(free.energy_loss, -1e-12 * mgh);
      k.f = {1e-9, 1e-9};
      const auto near = friction_impact(dyn, k.state(), ic, ImpactRule{}, k.f);
      ASSERT_TRUE(near.consistent);
      EXPECT_EQ(near.edge, free.edge);
      EXPECT_NEAR(near.theta_dot, free.theta_dot, 1e-8 * (std::abs(free.theta_dot) + 1.0));
      EXPECT_NEAR(near.impulse(1), free.impulse(1), 1e-8 * std::abs(free.impulse(1)));
      ++frictionless;
    }
  });
  EXPECT_GE(sticking, 20);
  EXPECT_GE(frictionless, 60);
}

TEST(ContactMapsProperties, EachImpactLawDoesWhatItsRowSays) {
  // whatever rows kImpactLaws holds: the rocking impact and the landing keep the modal velocities
  // or conserve the modal momenta as the row's `modes` says, and a measured ratio gives
  // theta_dot+ = r theta_dot-
  int checked = 0;
  for_each_body([&](const json& c, const Body&, const DynX& dyn) {
    if (c["n"].get<int>() == 0) return;
    for (const ImpactLawInfo& law : kImpactLaws) {
      const ImpactRule rule{.law = law.law, .ratio_edge1 = 0.5, .ratio_edge2 = 0.5};
      for (const auto& s : c["impacts"]) {
        const int landing = s["landing_edge"];
        const VectorX q = vec(s["q"]), qd = vec(s["q_dot_minus"]);
        const double thd = s["theta_dot_minus"];
        const auto out = resolve_impact(dyn, landing, q, thd, qd, rule);
        if (out.law_fallback) continue;
        const VectorX p_before = dyn.mu() * qd + dyn.coupling(dyn.alpha(3 - landing), q) * thd;
        const VectorX p_after =
            dyn.mu() * out.q_dot + dyn.coupling(dyn.alpha(landing), q) * out.theta_dot;
        for (Eigen::Index i = 0; i < q.size(); ++i) {
          if (law.modes == ModesInImpact::kVelocitiesKept) {
            EXPECT_EQ(out.q_dot(i), qd(i)) << law.name;
          } else {
            EXPECT_NEAR(p_after(i), p_before(i), 1e-12 * (p_before.norm() + 1.0)) << law.name;
          }
        }
        if (law.rebound == Rebound::kMeasuredRatio && !out.both_edges) {
          EXPECT_NEAR(out.theta_dot, 0.5 * thd, 1e-15 * std::abs(thd)) << law.name;
        }
        ++checked;
      }
      for (const auto& s : c["landings"]) {
        const int e = s["edge"];
        const VectorX q = vec(s["q"]), qd = vec(s["q_dot_minus"]);
        const Eigen::Vector2d v_c = vec2(s["cg_velocity"]);
        const double th = s["theta"], thd = s["theta_dot_minus"];
        const auto out = landing_map(dyn, e, State{th, q, thd, qd, v_c}, rule);
        if (out.law_fallback) continue;
        const double sn = std::sin(th), cs = std::cos(th);
        const VectorX p_before = dyn.flight_modal_momenta(
            e, q, thd, qd, dyn.corner_velocity_body(e, sn, cs, q, thd, qd, v_c));
        const VectorX p_after =
            dyn.mu() * out.q_dot + dyn.coupling(dyn.alpha(out.edge), q) * out.theta_dot;
        for (Eigen::Index i = 0; i < q.size(); ++i) {
          if (law.modes == ModesInImpact::kVelocitiesKept) {
            EXPECT_EQ(out.q_dot(i), qd(i)) << law.name;
          } else {
            EXPECT_NEAR(p_after(i), p_before(i), 1e-12 * (p_before.norm() + 1.0)) << law.name;
          }
        }
        ++checked;
      }
    }
  });
  EXPECT_GE(checked, 180);  // 9 flexible bodies, 8 impacts and landings each, 3 laws
}

TEST(ContactMapsProperties, StickOrSlipNeedsAStrictlyPositiveMargin) {
  EXPECT_TRUE(stick_or_slip(0.3, 1e-300).sticks);
  EXPECT_EQ(stick_or_slip(0.3, 1e-300).slip, 0);
  EXPECT_FALSE(stick_or_slip(0.3, 0.0).sticks);
  EXPECT_EQ(stick_or_slip(0.3, 0.0).slip, -1);  // the floor pushes along I: the base slides back
  EXPECT_EQ(stick_or_slip(-0.3, -0.1).slip, 1);
  EXPECT_EQ(friction_ratio(1.0, 0.0), kInf);
  EXPECT_FALSE(inside_friction_cone(0.0, 0.0, kInf));
  EXPECT_TRUE(inside_friction_cone(5.0, 1.0, kInf));
}

}  // namespace
}  // namespace flexrock
