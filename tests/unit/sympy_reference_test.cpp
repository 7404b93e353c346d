// SPDX-License-Identifier: BSD-3-Clause
// The C++ equations against the machine-checked derivation (tools/derive/derive.py): mass matrix,
// forces, reaction, resultant, energies and impacts at random states of random point-mass bodies.
#include "sympy_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "flexrock/contact/corner_potential.hpp"
#include "flexrock/contact/impact.hpp"
#include "flexrock/model/dynamics.hpp"

namespace flexrock {
namespace {

using json = nlohmann::json;
using DynX = Dynamics<Eigen::Dynamic, Eigen::Dynamic>;
using sympy_reference::mat;
using sympy_reference::params_of;
using sympy_reference::vec;

json load() {
  std::ifstream in(FLEXROCK_BINARY_DIR "/sympy_reference.json");
  if (!in) return {};
  return json::parse(in);
}

void expect_close(double got, double want, double scale, const std::string& what) {
  EXPECT_NEAR(got, want, 1e-12 * std::max(1.0, std::abs(scale))) << what;
}

// an impulse against the reference's [I_x, I_y], on the scale |I_x| + |I_y|
void expect_impulse(const Eigen::Vector2d& got, const json& want, const std::string& what) {
  const double ix = want[0].get<double>(), iy = want[1].get<double>();
  const double scale = std::abs(ix) + std::abs(iy);
  expect_close(got(0), ix, scale, what + " I_x");
  expect_close(got(1), iy, scale, what + " I_y");
}

class SympyReference : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { ref_ = new json(load()); }
  static void TearDownTestSuite() { delete ref_; }
  static json* ref_;
};
json* SympyReference::ref_ = nullptr;

TEST_F(SympyReference, CoversEveryModeCount) {
  ASSERT_FALSE(ref_->is_null()) << "run tools/derive/derive.py (the ctest fixture does)";
  std::set<int> ns;
  for (const auto& c : (*ref_)["cases"]) ns.insert(c["n"].get<int>());
  EXPECT_EQ(ns, (std::set<int>{0, 1, 2, 3}));
}

TEST_F(SympyReference, RockingEquationsReactionAndEnergies) {
  ASSERT_FALSE(ref_->is_null());
  const double g = (*ref_)["g"];
  int checked = 0;
  for (const auto& c : (*ref_)["cases"]) {
    const Body body(params_of(c, g));
    const DynX dyn(body);
    const double mg = body.params().mass * g;
    EXPECT_NEAR(body.tipping_angle(1), c["tipping_angle"][0].get<double>(), 1e-12);
    EXPECT_NEAR(body.tipping_angle(2), c["tipping_angle"][1].get<double>(), 1e-12);
    for (const auto& s : c["rocking"]) {
      const int edge = s["edge"];
      const double a = dyn.alpha(edge), th = s["theta"], thd = s["theta_dot"];
      const VectorX q = vec(s["q"]), qd = vec(s["q_dot"]);
      const BaseAcceleration base{s["base_acc"][0].get<double>(), s["base_acc"][1].get<double>()};
      const std::string at = "n=" + std::to_string(q.size()) + " edge " + std::to_string(edge);
      // mass matrix A = [[m, b^T], [b, mu]]
      const MatrixX A = mat(s["mass_matrix"], q.size() + 1);
      expect_close(dyn.inertia(a, q), A(0, 0), A(0, 0), "m " + at);
      const VectorX b = dyn.coupling(a, q);
      for (Eigen::Index i = 0; i < q.size(); ++i)
        expect_close(b(i), A(i + 1, 0), A(0, 0), "b " + at);
      // accelerations from A x = f
      double thdd;
      VectorX qdd(q.size());
      dyn.rocking_acceleration(edge, th, q, thd, qd, base, thdd, qdd);
      const VectorX acc = vec(s["accelerations"]);
      expect_close(thdd, acc(0), acc.norm(), "theta_ddot " + at);
      for (Eigen::Index i = 0; i < q.size(); ++i)
        expect_close(qdd(i), acc(i + 1), acc.norm(), "q_ddot " + at);
      // forces: A (computed accelerations) reproduces the reference f
      VectorX nu(q.size() + 1);
      nu(0) = thdd;
      nu.tail(q.size()) = qdd;
      const VectorX f = vec(s["forces"]);
      const VectorX fa = A * nu;
      for (Eigen::Index i = 0; i < f.size(); ++i)
        expect_close(fa(i), f(i), f.norm(), "force " + at);
      const Eigen::Vector2d r = mg * dyn.rocking_reaction(edge, th, q, thd, qd, thdd, qdd, base);
      expect_close(r(0), s["reaction"][0].get<double>(), mg, "F_I " + at);
      expect_close(r(1), s["reaction"][1].get<double>(), mg, "F_J " + at);
      const double t_ref = s["kinetic_energy"], v_ref = s["potential_energy"];
      expect_close(dyn.kinetic_energy(a, q, thd, qd), t_ref, t_ref + std::abs(v_ref), "T " + at);
      expect_close(dyn.potential_energy(a, th, q), v_ref, std::abs(v_ref), "V " + at);
      expect_close(dyn.input_power(a, th, q, thd, qd, base), s["input_power"].get<double>(),
                   mg * body.params().height, "input power " + at);
      ++checked;
    }
  }
  EXPECT_GE(checked, 40);
}

TEST_F(SympyReference, FullContactAccelerationReactionAndResultant) {
  ASSERT_FALSE(ref_->is_null());
  const double g = (*ref_)["g"];
  int checked = 0;
  for (const auto& c : (*ref_)["cases"]) {
    const Body body(params_of(c, g));
    const DynX dyn(body);
    const double mg = body.params().mass * g;
    for (const auto& s : c["full_contact"]) {
      const VectorX q = vec(s["q"]), qd = vec(s["q_dot"]);
      const BaseAcceleration base{s["base_acc"][0].get<double>(), s["base_acc"][1].get<double>()};
      VectorX qdd(q.size());
      dyn.full_contact_acceleration(q, qd, base, qdd);
      const VectorX ref = vec(s["q_ddot"]);
      for (Eigen::Index i = 0; i < q.size(); ++i)
        expect_close(qdd(i), ref(i), ref.norm(), "q_ddot");
      const Eigen::Vector2d r = mg * dyn.full_contact_reaction(qdd, base);
      expect_close(r(0), s["reaction"][0].get<double>(), mg, "F_I");
      expect_close(r(1), s["reaction"][1].get<double>(), mg, "F_J");
      const double alpha_star = s["resultant"];
      expect_close(dyn.resultant_location(q, qdd, base), alpha_star, alpha_star, "resultant");
      // the uplift functions are the moments about the edges: (F_J/Mg)(alpha* + alpha1), ...
      const Eigen::Vector2d u = dyn.uplift_functions(q, qdd, base);
      const double fj = r(1) / mg;
      expect_close(u(0), fj * (alpha_star + body.alpha1()), fj * alpha_star, "U1");
      expect_close(u(1), fj * (body.alpha2() - alpha_star), fj * alpha_star, "U2");
      // the same three moments from the one product the event loop evaluates
      Eigen::Vector2d uc;
      const double r0 = dyn.contact_moments(q, qdd, base, uc);
      expect_close(r0, fj * alpha_star, fj * alpha_star, "R(0)");
      expect_close(uc(0), fj * (alpha_star + body.alpha1()), fj * alpha_star, "U1 (moments)");
      expect_close(uc(1), fj * (body.alpha2() - alpha_star), fj * alpha_star, "U2 (moments)");
      ++checked;
    }
  }
  EXPECT_GE(checked, 30);
}

TEST_F(SympyReference, ImpactMapImpulseAndEnergyLoss) {
  ASSERT_FALSE(ref_->is_null());
  const double g = (*ref_)["g"];
  int checked = 0, both = 0;
  for (const auto& c : (*ref_)["cases"]) {
    const Body body(params_of(c, g));
    const DynX dyn(body);
    for (const auto& s : c["impacts"]) {
      const int landing = s["landing_edge"];
      const VectorX q = vec(s["q"]), qdm = vec(s["q_dot_minus"]);
      const double thdm = s["theta_dot_minus"];
      double thdp;
      VectorX qdp(q.size());
      single_edge_impact(dyn, landing, q, thdm, qdm, thdp, qdp);
      const double scale = std::abs(thdm) + qdm.norm();
      expect_close(thdp, s["theta_dot_plus"].get<double>(), scale, "theta_dot+");
      const VectorX qref = vec(s["q_dot_plus"]);
      for (Eigen::Index i = 0; i < q.size(); ++i) expect_close(qdp(i), qref(i), scale, "q_dot+");
      const auto out = resolve_impact(dyn, landing, q, thdm, qdm);
      const json& want = out.both_edges ? s["both_edges"] : s;
      expect_impulse(out.impulse, want["impulse"], "impact");
      const double loss = want["energy_loss"];
      expect_close(out.energy_loss, loss, loss, "energy loss");
      if (out.both_edges) {
        ++both;
        const VectorX qb = vec(s["both_edges"]["q_dot_plus"]);
        for (Eigen::Index i = 0; i < q.size(); ++i)
          expect_close(out.q_dot(i), qb(i), scale, "both q_dot+");
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 40);
  EXPECT_GE(both, 1);  // the squat block exercises the both-edges rule
}

TEST_F(SympyReference, ImpactLawsAgainstPointMassMechanics) {
  // rigid_body (modal velocities kept, the moment of momentum about the landing point summed
  // mass by mass) and restitution (a given ratio, the modal momenta summed mass by mass), from
  // the derivation's direct point-mass computation
  ASSERT_FALSE(ref_->is_null());
  const double g = (*ref_)["g"];
  int rigid = 0, restitution = 0;
  for (const auto& c : (*ref_)["cases"]) {
    const Body body(params_of(c, g));
    const DynX dyn(body);
    for (const auto& s : c["impacts"]) {
      const int landing = s["landing_edge"];
      const VectorX q = vec(s["q"]), qdm = vec(s["q_dot_minus"]);
      const double thdm = s["theta_dot_minus"];
      const double scale = std::abs(thdm) + qdm.norm();
      const auto out = resolve_impact(dyn, landing, q, thdm, qdm, {.law = ImpactLaw::kRigidBody});
      const json& rb = s["rigid_body"];
      const double thr = rb["theta_dot_plus"];
      const bool turns = edge_sign(landing) * thr > 0.0;
      const json& want = turns ? rb : rb["both_edges"];
      const double loss = want["energy_loss"];
      if (loss < 0.0) {
        // the law would add energy: the engine takes the paper's law and says so
        EXPECT_TRUE(out.law_fallback);
      } else {
        EXPECT_FALSE(out.law_fallback);
        EXPECT_EQ(out.both_edges, !turns);
        expect_close(out.theta_dot, turns ? thr : 0.0, scale, "rigid_body theta_dot+");
        for (Eigen::Index i = 0; i < q.size(); ++i) EXPECT_EQ(out.q_dot(i), qdm(i));
        expect_impulse(out.impulse, want["impulse"], "rigid_body");
        expect_close(out.energy_loss, loss, std::abs(loss), "rigid_body loss");
        ++rigid;
      }
      const json& rs = s["restitution"];
      const double r = rs["ratio"];
      const auto res =
          resolve_impact(dyn, landing, q, thdm, qdm,
                         {.law = ImpactLaw::kRestitution, .ratio_edge1 = r, .ratio_edge2 = r});
      expect_close(res.theta_dot, rs["theta_dot_plus"].get<double>(), scale, "restitution");
      const VectorX qr = vec(rs["q_dot_plus"]);
      for (Eigen::Index i = 0; i < q.size(); ++i)
        expect_close(res.q_dot(i), qr(i), scale, "restitution q_dot+");
      expect_impulse(res.impulse, rs["impulse"], "restitution");
      const double rl = rs["energy_loss"];
      expect_close(res.energy_loss, rl, std::abs(rl), "restitution loss");
      ++restitution;
    }
  }
  EXPECT_GE(rigid, 30);
  EXPECT_GE(restitution, 40);
}

TEST_F(SympyReference, CompliantCornerPotentialAndForces) {
  // the sticking corner's stored energy and forces (with dashpots) against the contact potential
  // derived in tools/derive/derive.py (theory "Compliant contact"), for p = 1, 1.5 and 2.2
  int cases = 0;
  for (const auto& s : (*ref_)["compliant_potential"]) {
    CornerContact cc;
    cc.law = s["law"] == "linear" ? ContactForceLaw::kLinear : ContactForceLaw::kHuntCrossley;
    cc.p = s["p"];
    cc.k = s["k"];
    cc.k_t = s["k_t"];
    cc.c = s["c"];
    cc.c_t = s["c_t"];
    cc.hc = s["hc"];
    cc.v_floor = s["v_floor"];
    const double f_ref = s["f_ref"], delta = s["delta"], u = s["u"];
    const double v = s["potential"], ft = s["force_t"], fn = s["force_n"];
    EXPECT_NEAR(corner_potential(cc, f_ref, delta, u), v, 1e-13 * std::abs(v));
    const CornerForce f =
        sticking_corner_force(cc, f_ref, delta, s["delta_dot"], u, s["u_dot"], s["v_in"]);
    EXPECT_NEAR(f.t, ft, 1e-13 * (std::abs(ft) + std::abs(fn)));
    EXPECT_NEAR(f.n, fn, 1e-13 * (std::abs(ft) + std::abs(fn)));
    // at and above the floor the corner stores nothing and is held by nothing
    EXPECT_EQ(corner_potential(cc, f_ref, 0.0, u), 0.0);
    EXPECT_EQ(sticking_corner_force(cc, f_ref, 0.0, 0.0, u, 0.0, s["v_in"]).t, 0.0);
    ++cases;
  }
  EXPECT_EQ(cases, 9);
}

}  // namespace
}  // namespace flexrock
