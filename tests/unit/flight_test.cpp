// SPDX-License-Identifier: BSD-3-Clause
// Flight and landing (docs/theory.md, "Flight", "Landing"), each checked against something
// computed differently: point masses summed one by one, closed-form ballistics, a fixed-step
// integration of the flight equations, and the paper's impact map.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flexrock/contact/impact.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "flexrock/model/dynamics.hpp"
#include "flexrock/sim/simulate.hpp"
#include "support/bodies.hpp"

namespace flexrock {
namespace {

using DynX = Dynamics<Eigen::Dynamic, Eigen::Dynamic>;
constexpr double kG = kStandardGravity;

// A flight state of a lumped body and its point-mass kinematics, independent of the engine's
// formulas: positions r_k = r_O + R(theta) rho_k(q), rho_k measured from the base point below the
// undeformed c.g.
struct PointKinematics {
  const test::LumpedBody& lb;
  double xg = 0.0;  // [m] undeformed c.g. abscissa in the lumped model's frame
  double mass = 0.0;

  explicit PointKinematics(const test::LumpedBody& body) : lb(body) {
    for (const auto& p : lb.pts) {
      mass += p.m;
      xg += p.m * p.x;
    }
    xg /= mass;
  }
  Eigen::Vector2d rho(const test::PointMass& p, const VectorX& q) const {
    Eigen::Vector2d r(p.x - xg, p.y);
    for (int i = 0; i < q.size(); ++i) r += q(i) * Eigen::Vector2d(p.phix[i], p.phiy[i]);
    return r;
  }
  Eigen::Vector2d phi_qd(const test::PointMass& p, const VectorX& qd) const {
    Eigen::Vector2d r(0, 0);
    for (int i = 0; i < qd.size(); ++i) r += qd(i) * Eigen::Vector2d(p.phix[i], p.phiy[i]);
    return r;
  }
  static Eigen::Matrix2d rot(double th) {
    Eigen::Matrix2d r;
    r << std::cos(th), -std::sin(th), std::sin(th), std::cos(th);
    return r;
  }
  static Eigen::Vector2d perp(const Eigen::Vector2d& a) { return {-a(1), a(0)}; }  // k x a
  // body-frame c.g. and its rate
  Eigen::Vector2d rho_cg(const VectorX& q) const {
    Eigen::Vector2d s(0, 0);
    for (const auto& p : lb.pts) s += p.m * rho(p, q);
    return s / mass;
  }
  Eigen::Vector2d rho_cg_dot(const VectorX& qd) const {
    Eigen::Vector2d s(0, 0);
    for (const auto& p : lb.pts) s += p.m * phi_qd(p, qd);
    return s / mass;
  }
  // velocities of every mass in flight, from the c.g. position and velocity
  std::vector<Eigen::Vector2d> velocities(double th, const VectorX& q, double thd,
                                          const VectorX& qd, const Eigen::Vector2d& vc) const {
    const Eigen::Matrix2d R = rot(th);
    const Eigen::Vector2d c = rho_cg(q), cd = rho_cg_dot(qd);
    std::vector<Eigen::Vector2d> v;
    for (const auto& p : lb.pts) {
      const Eigen::Vector2d d = R * (rho(p, q) - c);
      v.push_back(vc + thd * perp(d) + R * (phi_qd(p, qd) - cd));
    }
    return v;
  }
  std::vector<Eigen::Vector2d> positions(double th, const VectorX& q,
                                         const Eigen::Vector2d& rc) const {
    const Eigen::Matrix2d R = rot(th);
    const Eigen::Vector2d c = rho_cg(q);
    std::vector<Eigen::Vector2d> r;
    for (const auto& p : lb.pts) r.push_back(rc + R * (rho(p, q) - c));
    return r;
  }
  Eigen::Vector2d corner(int edge, double th, const VectorX& q, const Eigen::Vector2d& rc) const {
    const double xe = edge == 1 ? lb.x1 : lb.x2;
    return rc + rot(th) * (Eigen::Vector2d(xe - xg, 0.0) - rho_cg(q));
  }
};

class FlightMaps : public ::testing::TestWithParam<int> {};

TEST_P(FlightMaps, KineticEnergyAboutTheCentreOfMassEqualsThePointMassSum) {
  const int n = GetParam();
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const auto lb = test::random_lumped(n, seed);
    const Body body(lb.params());
    const DynX dyn(body);
    const PointKinematics pk(lb);
    const VectorX q = 0.03 * VectorX::Random(n), qd = 0.7 * VectorX::Random(n);
    const double th = 0.3, thd = -1.1;
    const Eigen::Vector2d vc(0.4, -0.9);
    double t = 0;
    const auto v = pk.velocities(th, q, thd, qd, vc);
    for (std::size_t k = 0; k < v.size(); ++k) t += 0.5 * lb.pts[k].m * v[k].squaredNorm();
    EXPECT_NEAR(dyn.flight_kinetic_energy(q, thd, qd, vc), t, 1e-11 * t) << "seed " << seed;
  }
}

TEST_P(FlightMaps, CornerHeightAndVelocityMatchThePointKinematics) {
  const int n = GetParam();
  const auto lb = test::random_lumped(n, 7);
  const Body body(lb.params());
  const DynX dyn(body);
  const PointKinematics pk(lb);
  const VectorX q = 0.03 * VectorX::Random(n), qd = 0.7 * VectorX::Random(n);
  const double th = -0.2, thd = 0.8, eps = 1e-6;
  const Eigen::Vector2d rc(0.1, 1.7), vc(-0.3, 0.5);
  for (int e : {1, 2}) {
    const Eigen::Vector2d p = pk.corner(e, th, q, rc);
    EXPECT_NEAR(dyn.corner_height(e, std::sin(th), std::cos(th), q, rc(1)), p(1), 1e-13);
    EXPECT_NEAR(dyn.corner_x(e, std::sin(th), std::cos(th), q, rc(0)), p(0), 1e-13);
    // the velocity by central differences of the corner's path
    const Eigen::Vector2d pp = pk.corner(e, th + eps * thd, q + eps * qd, rc + eps * vc);
    const Eigen::Vector2d pm = pk.corner(e, th - eps * thd, q - eps * qd, rc - eps * vc);
    const Eigen::Vector2d v = (pp - pm) / (2 * eps);
    const Eigen::Vector2d vb =
        dyn.corner_velocity_body(e, std::sin(th), std::cos(th), q, thd, qd, vc);
    EXPECT_LT((PointKinematics::rot(th) * vb - v).norm(), 1e-8);
  }
}

TEST_P(FlightMaps, LandingConservesModalMomentaAndMomentOfMomentumMassByMass) {
  const int n = GetParam();
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto lb = test::random_lumped(n, seed);
    const Body body(lb.params());
    const DynX dyn(body);
    const PointKinematics pk(lb);
    const VectorX q = 0.02 * VectorX::Random(n), qd = 0.5 * VectorX::Random(n);
    for (int e : {1, 2}) {
      // tipping point e is the lower one: theta has its edge's sign
      const double th = e == 1 ? 0.15 : -0.15, thd = e == 1 ? -0.9 : 0.9;
      const Eigen::Vector2d rc(0.05, 1.2), vc(0.3, -0.8);
      const double s = std::sin(th), c = std::cos(th);
      const Eigen::Vector2d vcorner = dyn.corner_velocity_body(e, s, c, q, thd, qd, vc);
      double thp = 0;
      VectorX qdp(n);
      dyn.corner_impact(e, q, thd, qd, vcorner, thp, qdp);
      // after: rocking about the stuck tipping point
      const Eigen::Vector2d rp = pk.corner(e, th, q, rc);
      const auto pos = pk.positions(th, q, rc);
      const auto before = pk.velocities(th, q, thd, qd, vc);
      std::vector<Eigen::Vector2d> after;
      const Eigen::Matrix2d R = PointKinematics::rot(th);
      for (std::size_t k = 0; k < pos.size(); ++k)
        after.push_back(thp * PointKinematics::perp(pos[k] - rp) + R * pk.phi_qd(lb.pts[k], qdp));
      double hb = 0, ha = 0, tb = 0, ta = 0, carnot = 0;
      VectorX pb = VectorX::Zero(n), pa = VectorX::Zero(n);
      for (std::size_t k = 0; k < pos.size(); ++k) {
        const auto& p = lb.pts[k];
        const Eigen::Vector2d d = pos[k] - rp;
        hb += p.m * (d(0) * before[k](1) - d(1) * before[k](0));
        ha += p.m * (d(0) * after[k](1) - d(1) * after[k](0));
        for (int i = 0; i < n; ++i) {
          const Eigen::Vector2d phi = R * Eigen::Vector2d(p.phix[i], p.phiy[i]);
          pb(i) += p.m * phi.dot(before[k]);
          pa(i) += p.m * phi.dot(after[k]);
        }
        tb += 0.5 * p.m * before[k].squaredNorm();
        ta += 0.5 * p.m * after[k].squaredNorm();
        carnot += 0.5 * p.m * (after[k] - before[k]).squaredNorm();
      }
      EXPECT_NEAR(ha, hb, 1e-12 * (std::abs(hb) + 1.0)) << "seed " << seed << " edge " << e;
      EXPECT_LT((pa - pb).norm(), 1e-12 * (pb.norm() + 1.0));
      // a plastic impact loses the kinetic energy of the velocity jump, never gains
      EXPECT_NEAR(tb - ta, carnot, 1e-10 * (carnot + 1.0));
      EXPECT_GE(tb - ta, 0.0);
      // the rocking kinetic energy after is the engine's
      EXPECT_NEAR(dyn.kinetic_energy(dyn.alpha(e), q, thp, qdp), ta, 1e-10 * (ta + 1.0));
    }
  }
}

TEST_P(FlightMaps, LandingFromRockingOnTheOtherEdgeIsThePapersImpactMap) {
  // a body rocking on one edge at theta = 0 moves its other tipping point at theta_dot k x
  // (P_new - P_old): the landing map must then be the paper's map (theory §8)
  const int n = GetParam();
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto lb = test::random_lumped(n, seed);
    const Body body(lb.params());
    const DynX dyn(body);
    const VectorX q = 0.02 * VectorX::Random(n), qd = 0.5 * VectorX::Random(n);
    for (int landing : {1, 2}) {
      const int pre = landing == 1 ? 2 : 1;
      const double thd = landing == 1 ? 0.8 : -0.8;
      // the c.g. velocity while rocking on `pre`, then the landing tipping point's velocity
      Eigen::Vector2d r, vc;
      dyn.cg_from_pivot(pre, 0.0, 1.0, q, thd, qd, r, vc);
      const Eigen::Vector2d vcorner = dyn.corner_velocity_body(landing, 0.0, 1.0, q, thd, qd, vc);
      double thp = 0, paper = 0;
      VectorX qdp(n), qd_paper(n);
      dyn.corner_impact(landing, q, thd, qd, vcorner, thp, qdp);
      single_edge_impact(dyn, landing, q, thd, qd, paper, qd_paper);
      EXPECT_NEAR(thp, paper, 1e-13) << "seed " << seed;
      EXPECT_LT((qdp - qd_paper).norm(), 1e-12);
    }
  }
}

TEST_P(FlightMaps, FlightEquationsKeepTheMomentOfMomentumAboutTheCentreOfMassAndTheEnergy) {
  // RK4 with small fixed steps on the engine's flight accelerations; the moment of momentum
  // about the c.g. is summed mass by mass, the energy is T_int + strain
  const int n = GetParam();
  const auto lb = test::random_lumped(n, 11, 2e4);
  const Body body(lb.params());
  const DynX dyn(body);
  const PointKinematics pk(lb);
  VectorX y(2 * n + 2);
  y(0) = 0.1;
  y.segment(1, n) = 0.02 * VectorX::Random(n);
  y(n + 1) = 1.3;
  y.segment(n + 2, n) = 0.8 * VectorX::Random(n);
  auto f = [&](const VectorX& s) {
    VectorX d(2 * n + 2);
    double thdd = 0;
    VectorX qdd(n);
    dyn.flight_acceleration(s.segment(1, n), s(n + 1), s.segment(n + 2, n), thdd, qdd);
    d(0) = s(n + 1);
    d.segment(1, n) = s.segment(n + 2, n);
    d(n + 1) = thdd;
    d.segment(n + 2, n) = qdd;
    return d;
  };
  auto invariants = [&](const VectorX& s, double& h, double& e) {
    const VectorX q = s.segment(1, n), qd = s.segment(n + 2, n);
    const auto pos = pk.positions(s(0), q, Eigen::Vector2d::Zero());
    const auto v = pk.velocities(s(0), q, s(n + 1), qd, Eigen::Vector2d::Zero());
    h = 0;
    for (std::size_t k = 0; k < pos.size(); ++k)
      h += lb.pts[k].m * (pos[k](0) * v[k](1) - pos[k](1) * v[k](0));
    e = dyn.flight_kinetic_energy(q, s(n + 1), qd, Eigen::Vector2d::Zero()) +
        dyn.flight_potential_energy(0.0, q);
  };
  double h0, e0;
  invariants(y, h0, e0);
  const double dt = 2e-5;
  for (int k = 0; k < 20000; ++k) {
    const VectorX k1 = f(y), k2 = f(y + 0.5 * dt * k1), k3 = f(y + 0.5 * dt * k2),
                  k4 = f(y + dt * k3);
    y += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  double h1, e1;
  invariants(y, h1, e1);
  EXPECT_NEAR(h1, h0, 1e-9 * std::abs(h0));
  EXPECT_NEAR(e1, e0, 1e-9 * std::abs(e0));
  EXPECT_GT(std::abs(y(0) - 0.1), 0.3);  // it did turn
}

INSTANTIATE_TEST_SUITE_P(Modes, FlightMaps, ::testing::Values(1, 2, 3, 5));

// --- whole runs ----------------------------------------------------------------------------------

TEST(Flight, RigidBlockThrownUpByTheFloorFliesBallisticallyAndLandsFlat) {
  // the floor accelerates down at 2 g for 0.1 s: the block leaves it at once (F_J = -M g) with
  // theta = 0, rises relative to the floor at +g, then falls at -g and lands on both edges at
  // t = 0.6 + (0.1 + sqrt(0.02)) s, losing all its kinetic energy M (g sqrt(0.02))^2 / 2
  const Body body(BodyParameters::rectangular_block(200.0, 0.3, 1.0));
  SimulationOptions opt;
  opt.t_end = 1.5;
  opt.output_dt = 0.01;
  const SimulationResult r =
      simulate(body, rectangular_pulse(-2 * kG, 0.1, 1.5, Component::kVertical), {}, opt);
  ASSERT_EQ(r.status, Status::kCompleted) << r.message;
  int lift = 0, land = 0;
  double t_land = -1, loss = 0;
  for (const Event& e : r.events) {
    if (e.kind == EventKind::kLiftOff) ++lift;
    if (e.kind == EventKind::kLanding) {
      ++land;
      t_land = e.time;
      loss = e.energy_loss;
      EXPECT_EQ(e.edge, 0);  // flat
    }
  }
  EXPECT_EQ(lift, 1);
  EXPECT_EQ(land, 1);
  const double t_expected = 0.1 + 0.1 + std::sqrt(0.02);
  EXPECT_NEAR(t_land, t_expected, 1e-12);
  const double v = kG * std::sqrt(0.02);
  EXPECT_NEAR(loss, 0.5 * 200.0 * v * v, 1e-9 * 0.5 * 200.0 * v * v);
  EXPECT_NEAR(r.extremes.flight_time, t_expected, 1e-12);
  EXPECT_NEAR(r.extremes.max_flight_height, 0.5 * kG * 0.01 + (0.1 * kG) * (0.1 * kG) / (2 * kG),
              1e-9);
  EXPECT_EQ(r.final_phase, ContactMode::kFullContact);
  EXPECT_EQ(r.final_offset, 0.0);
  EXPECT_NEAR(r.energy.residual, 0.0, 1e-9 * r.energy.scale);
  // the rows in flight follow the parabola of the lower tipping point
  for (std::size_t k = 0; k < r.history.size(); ++k) {
    const double t = r.history.time[k];
    double y = 0;
    if (t <= 0.1) {
      y = 0.5 * kG * t * t;
    } else if (t < t_expected) {
      const double tau = t - 0.1;
      y = 0.5 * kG * 0.01 + 0.1 * kG * tau - 0.5 * kG * tau * tau;
    }
    EXPECT_NEAR(r.history.lift[k], y, 1e-12) << "t = " << t;
    EXPECT_EQ(r.history.phase[k], t < t_expected ? 3 : 0) << "t = " << t;
  }
}

TEST(Flight, RigidBlockTurnsAtConstantSpeedInFlightWhileItsCentreIsBallistic) {
  // rocking on edge 1 from theta = 0.05 with theta_dot = 0.4, the floor drops at 3 g for 0.05 s
  // from t = 0: the block flies at once, turning at constant speed about its c.g.
  const double b = 0.25, h = 1.0;
  const Body body(BodyParameters::rectangular_block(100.0, b, h));
  SimulationOptions opt;
  opt.t_end = 0.05;
  opt.output_dt = 0.005;
  InitialState init;
  init.theta = 0.05;
  init.theta_dot = 0.4;
  const SimulationResult r =
      simulate(body, rectangular_pulse(-3 * kG, 0.05, 0.05, Component::kVertical), init, opt);
  ASSERT_EQ(r.status, Status::kCompleted) << r.message;
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.front().kind, EventKind::kLiftOff);
  EXPECT_EQ(r.events.front().time, 0.0);
  // c.g. at lift-off relative to the pivot (edge 1 at x = -b): R(theta) (b, h)
  const double th0 = 0.05, s0 = std::sin(th0), c0 = std::cos(th0);
  const double yc0 = b * s0 + h * c0;
  const double vy0 = 0.4 * (b * c0 - h * s0);
  for (std::size_t k = 0; k < r.history.size(); ++k) {
    const double t = r.history.time[k];
    EXPECT_EQ(r.history.phase[k], 3);
    const double th = th0 + 0.4 * t;
    EXPECT_NEAR(r.history.theta[k], th, 1e-12);
    EXPECT_NEAR(r.history.theta_dot[k], 0.4, 1e-12);
    // relative to the floor the c.g. accelerates at -g + 3 g
    const double yc = yc0 + vy0 * t + 0.5 * (2 * kG) * t * t;
    // lower tipping point (edge 1, theta > 0): y_c - (b sin + h cos)... at (-b, -h) from the c.g.
    const double lift = yc + (-b) * std::sin(th) - h * std::cos(th);
    EXPECT_NEAR(r.history.lift[k], lift, 1e-12) << "t = " << t;
  }
  EXPECT_NEAR(r.energy.residual, 0.0, 1e-10 * r.energy.scale);
}

// F_J / M g of a rigid block rocking on edge 1 (theory §5 with q = 0): a_y + (h/g)(thdd (-s -
// alpha c) - thd^2 (c - alpha s)), thdd from §11; alpha = -alpha1
double rigid_pivot_reaction(double alpha1, double zeta2, double gh, double ax, double ay, double th,
                            double thd) {
  const double a = -alpha1, s = std::sin(th), c = std::cos(th);
  const double gx = ax * c + ay * s, gy = ay * c - ax * s;
  const double thdd = gh * (a * gy + gx) / (1 + zeta2 + a * a);
  return ay + (thdd * (-s - a * c) - thd * thd * (c - a * s)) / gh;
}

TEST(Flight, RockingBlockLeavesItsPivotWhereTheClosedFormPivotReactionVanishes) {
  // pushed at 0.5 g it rocks on edge 1; the push then reverses at 100 g/s. The pivot force falls
  // to zero at a_x* (linear in a_x): the engine's lift-off is checked against the closed form
  // and against a fixed-step RK4 of Housner's equation with its own bisection
  const double b = 0.2, h = 1.0;
  const Body body(BodyParameters::rectangular_block(300.0, b, h));
  const double alpha1 = b / h, zeta2 = (1 + alpha1 * alpha1) / 3, gh = kG / h;
  auto ax_of = [](double t) { return t < 0.3 ? 0.5 : 0.5 - 100.0 * (t - 0.3); };  // [g]
  const GroundMotion m = GroundMotion::analytic(
      [&](double t) {
        return BaseAcceleration{kG * ax_of(t), 0.0};
      },
      0.5, {0.3});
  SimulationOptions opt;
  opt.rtol = 1e-12;
  opt.atol = 1e-14;
  const SimulationResult r = simulate(body, m, {}, opt);
  // the pivot force vanishes: the block flies, or, pulled sideways at its pivot as here, could
  // leave it only by sliding (pivot_tension); either way this is where F_J reaches zero
  const Event* lift = nullptr;
  for (const Event& e : r.events)
    if ((e.kind == EventKind::kLiftOff || e.kind == EventKind::kPivotTension) && !lift) lift = &e;
  ASSERT_NE(lift, nullptr);
  EXPECT_EQ(lift->edge, 1);
  // closed form: the base acceleration at which the pivot force vanishes in this state
  const double th = lift->theta, thd = lift->theta_dot_before;
  const double f0 = rigid_pivot_reaction(alpha1, zeta2, gh, 0.0, 1.0, th, thd);
  const double f1 = rigid_pivot_reaction(alpha1, zeta2, gh, 1.0, 1.0, th, thd);
  const double ax_star = -f0 / (f1 - f0);
  EXPECT_NEAR(ax_of(lift->time), ax_star, 1e-9 * std::abs(ax_star));
  EXPECT_LT(ax_star, -1.0);  // a strong reversal is needed
  // RK4 from uplift (t = 0: 0.5 g > alpha1 g) with 1e-5 s steps, then bisection in the last step
  auto f = [&](double t, const Eigen::Vector2d& y) {
    const double ax = ax_of(t), s = std::sin(y(0)), c = std::cos(y(0));
    const double gx = ax * c + s, gy = c - ax * s;
    return Eigen::Vector2d(y(1), gh * (gx - alpha1 * gy) / (1 + zeta2 + alpha1 * alpha1));
  };
  auto rk4 = [&](double t, const Eigen::Vector2d& y, double dt) {
    const Eigen::Vector2d k1 = f(t, y), k2 = f(t + dt / 2, y + dt / 2 * k1),
                          k3 = f(t + dt / 2, y + dt / 2 * k2), k4 = f(t + dt, y + dt * k3);
    return Eigen::Vector2d(y + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4));
  };
  auto fj = [&](double t, const Eigen::Vector2d& y) {
    return rigid_pivot_reaction(alpha1, zeta2, gh, ax_of(t), 1.0, y(0), y(1));
  };
  Eigen::Vector2d y(0, 0);
  double t = 0, dt = 1e-5;
  while (true) {
    double dt_k = dt;
    if (t < 0.3 && t + dt > 0.3) dt_k = 0.3 - t;  // step onto the kink
    const Eigen::Vector2d yn = rk4(t, y, dt_k);
    if (fj(t + dt_k, yn) <= 0) {
      double lo = 0, hi = dt_k;
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (fj(t + mid, rk4(t, y, mid)) > 0 ? lo : hi) = mid;
      }
      const Eigen::Vector2d ye = rk4(t, y, hi);
      EXPECT_NEAR(lift->time, t + hi, 1e-9);
      EXPECT_NEAR(lift->theta, ye(0), 1e-9);
      EXPECT_NEAR(lift->theta_dot_before, ye(1), 1e-8);
      break;
    }
    y = yn;
    t += dt_k;
    ASSERT_LT(t, 0.5) << "the reference never lifted off";
  }
}

}  // namespace
}  // namespace flexrock
