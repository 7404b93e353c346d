// SPDX-License-Identifier: BSD-3-Clause
// Rocking frames and stacked blocks (docs/theory.md §25): the frame's closed forms against the
// sympy derivation, its run against an independently built single block, its limits and its
// refusals; the stack's uplift bands against a brute-force Newton-Euler enumeration of every
// contact pattern.
#include "flexrock/model/assemblies.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "flexrock/io/records.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/rocking_frame.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

constexpr double kG = kStandardGravity;

RockingFrame bent(int count, double beam_mass) {
  RockingFrame f;
  f.column_width = 0.4;
  f.column_height = 4.0;
  f.column_mass = 2000.0;
  f.count = count;
  f.beam_mass = beam_mass;
  return f;
}

GroundMotion one_sine(double amplitude_g, double period, double duration) {
  return one_sine_pulse(amplitude_g * kG, 2.0 * std::numbers::pi / period, duration);
}

GroundMotion elcentro(double scale) {
  return io::read_single_column(FLEXROCK_SOURCE_DIR "/../shared/data/elcentro_1940_ns.dat", 0.02,
                                io::AccelUnit::kG)
      .to_motion(scale);
}

// a uniform block with the frame's slenderness and frequency parameter (R = 3 g / (4 p^2)) whose
// impacts take the frame's ratio as a measured one: built from p, alpha and r alone
BodyParameters block_of(const FrameConstants& k, double mass) {
  const double R = 0.75 * kG / (k.p * k.p);
  return rigid_block(2.0 * R * std::sin(k.alpha), 2.0 * R * std::cos(k.alpha), mass);
}

SimulationOptions history_options() {
  SimulationOptions o;
  o.output_dt = 0.01;
  o.rtol = 1e-12;
  o.atol = 1e-14;
  return o;
}

// over the samples both runs have (a frame's run may stop earlier: compare_lengths false)
double max_theta_difference(const SimulationResult& a, const SimulationResult& b,
                            bool compare_lengths = true) {
  if (compare_lengths) {
    EXPECT_EQ(a.history.size(), b.history.size());
  }
  double d = 0.0;
  for (std::size_t i = 0; i < std::min(a.history.size(), b.history.size()); ++i) {
    // a stopped run's last row is at its stop, between the other's rows
    if (a.history.time[i] != b.history.time[i]) {
      EXPECT_TRUE(i + 1 == a.history.size() || i + 1 == b.history.size());
      continue;
    }
    d = std::max(d, std::abs(a.history.theta[i] - b.history.theta[i]));
    d = std::max(d, std::abs(a.history.theta_dot[i] - b.history.theta_dot[i]) /
                        std::max(1.0, std::abs(a.history.theta_dot[i])));
  }
  return d;
}

TEST(RockingFrame, ClosedFormsMatchTheSympyDerivation) {
  std::ifstream in(FLEXROCK_BINARY_DIR "/assemblies_reference.json");
  ASSERT_TRUE(in) << "run tools/derive/derive.py --out " FLEXROCK_BINARY_DIR
                     "/sympy_reference.json first";
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_GE(j.at("frames").size(), 4u);
  for (const auto& r : j.at("frames")) {
    RockingFrame f;
    f.column_width = r.at("column_width");
    f.column_height = r.at("column_height");
    f.column_mass = r.at("column_mass");
    f.count = r.at("count");
    f.beam_mass = r.at("beam_mass");
    const FrameConstants k = frame_constants(f);
    auto rel = [](double a, double b) { return std::abs(a - b) / std::abs(b); };
    EXPECT_LT(rel(k.p, r.at("p")), 1e-13);
    EXPECT_LT(rel(k.r, r.at("r")), 1e-13);
    EXPECT_LT(rel(k.alpha, r.at("alpha")), 1e-13);
    EXPECT_LT(rel(k.height_eq, r.at("height_eq")), 1e-13);
    EXPECT_LT(rel(k.zeta2_eq, r.at("zeta2_eq")), 1e-13);
    EXPECT_LT(rel(k.mass_eq, r.at("mass_eq")), 1e-13);
    // the equivalent body's own frequency parameter is the frame's
    const Body body(frame_equivalent_body(f));
    EXPECT_LT(rel(body.rocking_frequency(), k.p), 1e-13);
    EXPECT_DOUBLE_EQ(body.alpha1(), std::tan(k.alpha));
  }
}

TEST(RockingFrame, EquivalentBodysImpactRatioIsTheFramesUnderTheBodysOwnLaw) {
  // free rocking from a tilt: the engine's impact map (Housner's, the moment of momentum about
  // the landing corner) on the equivalent body gives the frame's r, for the paper's and the
  // rigid-body law, with and without a beam
  for (double beam : {0.0, 1500.0, 9000.0, 60000.0}) {
    const RockingFrame f = bent(3, beam);
    const FrameConstants k = frame_constants(f);
    for (ImpactLaw law : {ImpactLaw::kPaper, ImpactLaw::kRigidBody}) {
      SimulationOptions o;
      o.t_end = 3.0;
      o.impact_law = law;
      InitialState s;
      s.theta = 0.5 * k.alpha;
      const SimulationResult r = simulate_frame(f, GroundMotion::none(3.0), s, o);
      int impacts = 0;
      for (const Event& e : r.events) {
        if (e.kind != EventKind::kImpact) continue;
        ++impacts;
        EXPECT_NEAR(e.theta_dot_after / e.theta_dot_before, k.r, 1e-12) << beam;
        EXPECT_GE(e.energy_loss, 0.0);
      }
      EXPECT_GE(impacts, 2) << beam;
    }
  }
}

TEST(RockingFrame, RunEqualsItsEquivalentSingleBlockOnAPulse) {
  // the frame run against a uniform block built from p, alpha and r only, its impacts by the
  // measured-ratio law: the same motion to 1e-10
  for (double beam : {1500.0, 9000.0}) {
    const RockingFrame f = bent(3, beam);
    const FrameConstants k = frame_constants(f);
    const GroundMotion m = one_sine(0.15, 1.0, 8.0);
    const SimulationOptions o = history_options();
    const SimulationResult frame = simulate_frame(f, m, {}, o);
    SimulationOptions ob = o;
    ob.impact_law = ImpactLaw::kRestitution;
    ob.restitution_ratio_edge1 = ob.restitution_ratio_edge2 = k.r;
    const SimulationResult block = simulate(Body(block_of(k, 1.0)), m, {}, ob);
    ASSERT_EQ(frame.status, Status::kCompleted) << frame.message;
    ASSERT_EQ(block.status, frame.status);
    EXPECT_GE(frame.extremes.impacts, 3);
    EXPECT_EQ(frame.extremes.impacts, block.extremes.impacts);
    EXPECT_LT(max_theta_difference(frame, block), 1e-10) << beam;
  }
}

TEST(RockingFrame, RunEqualsItsEquivalentSingleBlockOnElCentro) {
  const RockingFrame f = bent(4, 12000.0);
  const FrameConstants k = frame_constants(f);
  const GroundMotion m = elcentro(1.0);
  const SimulationOptions o = history_options();
  const SimulationResult frame = simulate_frame(f, m, {}, o);
  SimulationOptions ob = o;
  ob.impact_law = ImpactLaw::kRestitution;
  ob.restitution_ratio_edge1 = ob.restitution_ratio_edge2 = k.r;
  const SimulationResult block = simulate(Body(block_of(k, 7.0)), m, {}, ob);
  ASSERT_EQ(frame.status, block.status);
  EXPECT_GT(frame.extremes.max_theta_edge1 + frame.extremes.max_theta_edge2, 1e-3);
  EXPECT_EQ(frame.extremes.impacts, block.extremes.impacts);
  EXPECT_LT(max_theta_difference(frame, block), 1e-10);
}

TEST(RockingFrame, WithoutBeamMassItIsOneColumn) {
  // beam mass 0: the equivalent body is the columns side by side, bit for bit a rigid_block; the
  // motion is one column's (the mass scales out)
  const RockingFrame f = bent(5, 0.0);
  const BodyParameters eq = frame_equivalent_body(f);
  const BodyParameters col5 = rigid_block(0.4, 4.0, 5 * 2000.0);
  EXPECT_EQ(eq.mass, col5.mass);
  EXPECT_EQ(eq.height, col5.height);
  EXPECT_EQ(eq.b1, col5.b1);
  EXPECT_EQ(eq.b2, col5.b2);
  EXPECT_EQ(eq.zeta2, col5.zeta2);
  const GroundMotion m = elcentro(1.0);
  const SimulationOptions o = history_options();
  const SimulationResult frame = simulate_frame(f, m, {}, o);
  const SimulationResult column = simulate(Body(rigid_block(0.4, 4.0, 2000.0)), m, {}, o);
  EXPECT_GT(frame.history.size(), 500u);
  EXPECT_LT(max_theta_difference(frame, column, false), 1e-12);
  if (frame.status == Status::kStopped) {
    // without a beam the frame's floor reaction is the column's: the frame stops where the floor
    // would pull on the column (the column's run lets it pull, pivot_tension)
    double tension = -1.0;
    for (const Event& e : column.events) {
      if (e.kind == EventKind::kPivotTension || e.kind == EventKind::kLiftOff) {
        tension = e.time;
        break;
      }
    }
    EXPECT_NEAR(tension, frame.t_end, 1e-7) << frame.message;
  } else {
    EXPECT_EQ(frame.extremes.impacts, column.extremes.impacts);
    EXPECT_EQ(frame.history.size(), column.history.size());
  }
  const FrameConstants k = frame_constants(f);
  EXPECT_DOUBLE_EQ(k.p, k.column_p);
  EXPECT_DOUBLE_EQ(k.r, k.column_r);
  EXPECT_EQ(k.reaction_mass, 0.0);
}

TEST(RockingFrame, MirroredInputGivesTheMirroredResponse) {
  // a symmetric frame under the record and under its negative: theta -> -theta, edges swapped
  const RockingFrame f = bent(3, 9000.0);
  const SimulationResult a = simulate_frame(f, elcentro(1.0), {}, history_options());
  const SimulationResult b = simulate_frame(f, elcentro(-1.0), {}, history_options());
  ASSERT_EQ(a.history.size(), b.history.size());
  EXPECT_GT(a.extremes.impacts, 0);
  for (std::size_t i = 0; i < a.history.size(); ++i) {
    EXPECT_NEAR(a.history.theta[i], -b.history.theta[i], 1e-12);
  }
  EXPECT_DOUBLE_EQ(a.extremes.max_theta_edge1, b.extremes.max_theta_edge2);
  EXPECT_EQ(a.status, b.status);
}

TEST(RockingFrame, NoImpactGainsEnergyAndAHeavierBeamSteadiesTheFrame) {
  // over slenderness and beam mass: 0 < ... r <= 1 with (1 - r^2) the loss of the kinetic energy;
  // the uplift acceleration g tan(alpha) does not depend on the beam, p falls as the beam grows
  // (the published findings: uplift independent of the cap beam, a heavier cap beam more stable)
  for (double w : {0.1, 0.4, 1.0, 2.0, 3.9}) {
    double last_p = std::numeric_limits<double>::infinity();
    for (double beam : {0.0, 100.0, 2000.0, 2e4, 2e6}) {
      RockingFrame f = bent(2, beam);
      f.column_width = w;
      const FrameConstants k = frame_constants(f);
      EXPECT_LE(k.r, 1.0);
      EXPECT_GT(1.0 + k.r, 0.0);
      EXPECT_LT(k.p, last_p);
      last_p = k.p;
      const Body b(frame_equivalent_body(f));
      EXPECT_NEAR(kG * b.alpha1(), kG * w / 4.0, 1e-12);
      EXPECT_NEAR(std::atan(b.alpha1()), std::atan2(w, 4.0), 1e-14);
    }
  }
  // and a run's energy balance closes, impacts losing
  const SimulationResult r = simulate_frame(bent(3, 9000.0), elcentro(1.5), {}, history_options());
  EXPECT_FALSE(r.energy_unbalanced);
  EXPECT_GE(r.energy.impact_loss, 0.0);
  for (const Event& e : r.events) {
    if (e.kind == EventKind::kImpact) {
      EXPECT_GE(e.energy_loss, 0.0);
    }
  }
}

TEST(RockingFrame, StopsWhereTheBeamWouldLiftOff) {
  // stocky columns rocking under a strong pulse with a vertical motion of 0.7 g: the light beam's
  // contact force on the columns turns negative; the run stops there, saying so with the force
  RockingFrame f;
  f.column_width = 1.5;
  f.column_height = 3.0;
  f.column_mass = 2000.0;
  f.count = 2;
  f.beam_mass = 300.0;
  const double wh = 2.0 * std::numbers::pi / 0.6, wv = 2.0 * std::numbers::pi * 4.0;
  const GroundMotion m = GroundMotion::analytic(
      [&](double t) {
        return BaseAcceleration{t <= 0.6 ? 1.2 * kG * std::sin(wh * t) : 0.0,
                                0.7 * kG * std::sin(wv * t)};
      },
      4.0, {0.6});
  SimulationOptions o;
  o.output_dt = 0.005;
  const SimulationResult r = simulate_frame(f, m, {}, o);
  ASSERT_EQ(r.status, Status::kStopped) << to_string(r.status);
  EXPECT_NE(r.message.find("beam's contact force"), std::string::npos) << r.message;
  // at the stop the beam's force is zero: the frame's own, from the equations of theory §25
  {
    const FrameConstants k = frame_constants(f);
    const double R = std::hypot(0.75, 1.5), s = r.final_theta >= 0.0 ? 1.0 : -1.0;
    const double phi = k.alpha - s * r.final_theta, thd = r.final_theta_dot;
    const BaseAcceleration a = m.at(r.t_end);
    const double thdd = k.p * k.p / kG * (s * a.x * std::cos(phi) - (kG + a.y) * std::sin(phi));
    const double ycdd = R * (s * std::sin(phi) * thdd - std::cos(phi) * thd * thd);
    EXPECT_NEAR(kG + a.y + 2.0 * ycdd, 0.0, 1e-6 * kG);
  }
  EXPECT_NE(r.message.find("not modelled"), std::string::npos) << r.message;
  EXPECT_GT(r.extremes.max_theta_edge1 + r.extremes.max_theta_edge2, 0.01);
  // the equivalent body alone runs past that instant
  const SimulationResult eq = simulate(Body(frame_equivalent_body(f)), m, {}, o);
  EXPECT_GT(eq.t_end, r.t_end);
  // located between the samples: a ten times finer sampling, or none asked for, gives the same
  // instant
  o.output_dt = 0.0005;
  const SimulationResult fine = simulate_frame(f, m, {}, o);
  EXPECT_NEAR(fine.t_end, r.t_end, 1e-9);
  o.output_dt = 0.0;
  const SimulationResult none = simulate_frame(f, m, {}, o);
  EXPECT_NEAR(none.t_end, r.t_end, 1e-9);
  EXPECT_EQ(none.history.size(), 0u);
  EXPECT_EQ(none.status, Status::kStopped);
}

TEST(RockingFrame, RefusesWhatItsModelDoesNotCover) {
  SimulationOptions o;
  o.friction_coefficient = 0.5;
  try {
    simulate_frame(bent(3, 100.0), GroundMotion::none(3.0), {}, o);
    FAIL() << "a finite friction coefficient was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("friction_coefficient"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("sliding"), std::string::npos);
  }
  SimulationOptions c;
  c.contact_model = ContactModel::kCompliant;
  c.contact_stiffness = 1e9;
  EXPECT_THROW(simulate_frame(bent(3, 100.0), GroundMotion::none(3.0), {}, c), InputError);
  EXPECT_THROW(frame_constants(bent(1, 100.0)), InputError);
  EXPECT_THROW(frame_constants(bent(3, -1.0)), InputError);
  // through the table of body types, as case files and Python make it
  BodyArgs a;
  a.keys = {{"column_width", 0.4}, {"column_height", 4.0}, {"column_mass", 2000.0}, {"count", 1.0}};
  EXPECT_THROW(make_body(body_kind("rocking_frame"), a), InputError);
  a.keys["count"] = 3.0;
  a.keys["beam_mass"] = 9000.0;
  const BodyParameters p = make_body(body_kind("rocking_frame"), a);
  const BodyParameters q = frame_equivalent_body(bent(3, 9000.0));
  EXPECT_EQ(p.mass, q.mass);
  EXPECT_EQ(p.zeta2, q.zeta2);
}

// ---------------------------------------------------------------------------------------------
// the stack: brute force by Newton-Euler for every contact pattern

// each interface closed (0), pivoting on its left corner (1) or on its right corner (2); the
// acceleration lambda g points to +x (the inertial load to -x). Unknowns: per closed interface
// the shear and the two corner normal forces, per pivoting one the two pivot force components
// and the relative angular acceleration. Returns whether the pattern is consistent: normal forces
// >= 0, each pivoting interface opening.
bool consistent(const BlockStack& s, double lambda, int floor_c, int iface_c) {
  const double b1 = 0.5 * s.bottom_width, h1 = 0.5 * s.bottom_height, m1 = s.bottom_mass;
  const double b2 = 0.5 * s.top_width, h2 = 0.5 * s.top_height, m2 = s.top_mass;
  const double I1 = m1 * (b1 * b1 + h1 * h1) / 3.0, I2 = m2 * (b2 * b2 + h2 * h2) / 3.0;
  const double g = 1.0, a = lambda;
  // unknowns: x = [floor forces (3: Fx, N_L, N_R or Fx, Fy, w1), interface (3 likewise)]
  // positions, origin at the bottom's base centre
  const Eigen::Vector2d G1(0.0, h1), G2(0.0, 2.0 * h1 + h2);
  auto cross = [](const Eigen::Vector2d& r, const Eigen::Vector2d& f) {
    return r(0) * f(1) - r(1) * f(0);
  };
  // accelerations at rest are linear in the angular accelerations w1 (bottom) and w2 (top
  // relative): a point at r rotating about pivot P accelerates w k x (r - P)
  auto kx = [](const Eigen::Vector2d& v) { return Eigen::Vector2d(-v(1), v(0)); };
  const Eigen::Vector2d P1 = floor_c == 2 ? Eigen::Vector2d(b1, 0) : Eigen::Vector2d(-b1, 0);
  const Eigen::Vector2d P2 =
      iface_c == 2 ? Eigen::Vector2d(b2, 2 * h1) : Eigen::Vector2d(-b2, 2 * h1);
  // columns of the 6 x 6 system, rows: bottom Fx, Fy, moment about G1; top Fx, Fy, moment about G2
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs;
  // external loads: gravity and the inertial load of the base's acceleration
  rhs << m1 * a, m1 * g, 0.0, m2 * a, m2 * g, 0.0;
  // m a_G = sum of forces + (-m a, -m g): write sum of forces - m a_G = (m a, m g)
  // floor contact on the bottom
  if (floor_c == 0) {
    const Eigen::Vector2d L(-b1, 0), R(b1, 0);
    A(0, 0) = 1;  // shear
    A(1, 1) = 1;
    A(1, 2) = 1;  // N_L, N_R
    A(2, 0) = cross(Eigen::Vector2d(0, 0) - G1, Eigen::Vector2d(1, 0));
    A(2, 1) = cross(L - G1, Eigen::Vector2d(0, 1));
    A(2, 2) = cross(R - G1, Eigen::Vector2d(0, 1));
  } else {
    A(0, 0) = 1;
    A(1, 1) = 1;  // pivot force (Fx, Fy)
    A(2, 0) = cross(P1 - G1, Eigen::Vector2d(1, 0));
    A(2, 1) = cross(P1 - G1, Eigen::Vector2d(0, 1));
    // w1 as unknown 2: its inertia terms on both bodies
    const Eigen::Vector2d aG1 = kx(G1 - P1), aG2 = kx(G2 - P1);
    A(0, 2) = -m1 * aG1(0);
    A(1, 2) = -m1 * aG1(1);
    A(2, 2) = -I1;
    A(3, 2) = -m2 * aG2(0);
    A(4, 2) = -m2 * aG2(1);
    A(5, 2) = -I2;
  }
  // interface: forces on the top (+), on the bottom (-)
  auto add_iface_force = [&](int col, const Eigen::Vector2d& at, const Eigen::Vector2d& dir) {
    A(3, col) += dir(0);
    A(4, col) += dir(1);
    A(5, col) += cross(at - G2, dir);
    A(0, col) -= dir(0);
    A(1, col) -= dir(1);
    A(2, col) -= cross(at - G1, dir);
  };
  const Eigen::Vector2d C(0, 2 * h1), L2(-b2, 2 * h1), R2(b2, 2 * h1);
  if (iface_c == 0) {
    add_iface_force(3, C, Eigen::Vector2d(1, 0));
    add_iface_force(4, L2, Eigen::Vector2d(0, 1));
    add_iface_force(5, R2, Eigen::Vector2d(0, 1));
  } else {
    add_iface_force(3, P2, Eigen::Vector2d(1, 0));
    add_iface_force(4, P2, Eigen::Vector2d(0, 1));
    const Eigen::Vector2d aG2 = kx(G2 - P2);
    A(3, 5) = -m2 * aG2(0);
    A(4, 5) = -m2 * aG2(1);
    A(5, 5) = -I2;
  }
  const Eigen::Matrix<double, 6, 1> x = A.fullPivLu().solve(rhs);
  const double tol = 1e-12 * (m1 + m2);
  // floor: normal forces >= 0 (closed) or pivot pressing and the bottom opening
  if (floor_c == 0) {
    if (x(1) < -tol || x(2) < -tol) return false;
  } else {
    const double w1 = x(2);
    if (x(1) < -tol) return false;
    if (!(floor_c == 1 ? w1 > 1e-12 : w1 < -1e-12)) return false;
  }
  if (iface_c == 0) {
    if (x(4) < -tol || x(5) < -tol) return false;
  } else {
    const double w2 = x(5);
    if (x(4) < -tol) return false;
    if (!(iface_c == 1 ? w2 > 1e-12 : w2 < -1e-12)) return false;
  }
  return true;
}

StackPattern pattern_of(int floor_c, int iface_c) {
  if (floor_c == 0) return iface_c == 0 ? StackPattern::kRest : StackPattern::kTopAlone;
  if (iface_c == 0) return StackPattern::kAsOne;
  return iface_c == 1 ? StackPattern::kSeparately : StackPattern::kSeparatelyOpposite;
}

TEST(BlockStack, BandsAreTheUniqueConsistentPatternByBruteForce) {
  std::mt19937 rng(48);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::array<int, 5> seen{};
  int checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    BlockStack s;
    s.bottom_width = 0.2 + 1.8 * U(rng);
    s.bottom_height = 0.4 + 5.6 * U(rng);
    s.bottom_mass = 0.1 + 10.0 * U(rng);
    s.top_width = s.bottom_width * (0.05 + 0.95 * U(rng));
    s.top_height = 0.4 + 5.6 * U(rng);
    s.top_mass = 0.1 + 10.0 * U(rng);
    const auto bands = stack_uplift_bands(s);
    // the bands partition lambda >= 0
    double covered = 0.0;
    for (const StackBand& b : bands)
      if (std::isfinite(b.lo))
        covered += std::max(0.0, std::min(b.hi, 50.0) - std::min(b.lo, 50.0));
    EXPECT_NEAR(covered, 50.0, 1e-9);
    for (int k = 1; k < 300; ++k) {
      const double lambda = 0.01 * k;
      bool near_boundary = false;
      for (const StackBand& b : bands)
        near_boundary |= std::abs(b.lo - lambda) < 1e-7 || std::abs(b.hi - lambda) < 1e-7;
      if (near_boundary) continue;
      std::vector<StackPattern> ok;
      for (int fc = 0; fc < 3; ++fc)
        for (int ic = 0; ic < 3; ++ic) {
          if (consistent(s, lambda, fc, ic)) {
            // the bottom never opens toward the acceleration, nor the top on a held bottom
            EXPECT_NE(fc, 2);
            EXPECT_FALSE(fc == 0 && ic == 2);
            ok.push_back(pattern_of(fc, ic));
          }
        }
      ASSERT_EQ(ok.size(), 1u) << "lambda " << lambda << " trial " << trial;
      EXPECT_EQ(ok[0], stack_pattern(s, lambda)) << "lambda " << lambda << " trial " << trial;
      ++seen[static_cast<int>(ok[0])];
      ++checked;
    }
  }
  for (int n : seen) EXPECT_GT(n, 0);  // every pattern occurs
  EXPECT_GT(checked, 50000);
}

TEST(BlockStack, ClosedFormLimits) {
  // identical blocks rocking as one: the single block of twice the height, b/(2h)
  BlockStack s{0.5, 2.0, 300.0, 0.5, 2.0, 300.0};
  const StackUplift u = stack_first_uplift(s);
  EXPECT_EQ(u.pattern, StackPattern::kAsOne);
  EXPECT_NEAR(u.lambda, 0.5 / 4.0, 1e-15);
  const Body twice(rigid_block(0.5, 4.0, 600.0));
  EXPECT_NEAR(u.lambda, twice.alpha1(), 1e-15);
  // a slender top on a squat bottom: the top alone first, at its own b/h
  BlockStack t{2.0, 1.0, 1000.0, 0.2, 2.0, 50.0};
  EXPECT_EQ(stack_first_uplift(t).pattern, StackPattern::kTopAlone);
  EXPECT_NEAR(stack_first_uplift(t).lambda, 0.1, 1e-15);
  // top mass -> 0: the bottom alone (b1/h1) for the as-one threshold
  BlockStack v{0.6, 2.0, 1000.0, 0.6, 0.3, 1e-9};
  EXPECT_EQ(stack_first_uplift(v).pattern, StackPattern::kAsOne);
  EXPECT_NEAR(stack_first_uplift(v).lambda, 0.3, 1e-9);
  // a top wider than the bottom's face is refused
  EXPECT_THROW(stack_uplift_bands(BlockStack{0.5, 1.0, 1.0, 0.6, 1.0, 1.0}), InputError);
}

}  // namespace
}  // namespace flexrock
