// SPDX-License-Identifier: BSD-3-Clause
// The series step's guards by bounds (series_guards.hpp): the Bernstein form against the
// polynomial, first crossings of polynomials with known roots (dips far narrower than a step,
// zero starts, a guard that turns positive later, a second crossing after a first), and whole runs:
// the located reaction extremes bound a dense history of the same run, and the outcome, impacts
// and largest tilt do not depend on max_step, which the series step no longer takes.
#include "sim/series_guards.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "flexrock/excitation/pulses.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

using detail::BernsteinPiece;
using detail::CrossingBracket;
using detail::GuardStart;
using detail::StepPolynomial;

constexpr double g = kStandardGravity;

// the polynomial sign * prod (tau - r_i), times (1 + tau^2) (no further real roots), in tau
StepPolynomial from_roots(const std::vector<double>& roots, double sign) {
  StepPolynomial p;
  p.degree = 0;
  p.c[0] = sign;
  auto times = [&](double a0, double a1, double a2) {  // p *= a0 + a1 tau + a2 tau^2
    StepPolynomial q;
    q.degree = p.degree + (a2 != 0.0 ? 2 : 1);
    for (int k = 0; k <= q.degree; ++k) q.c[static_cast<std::size_t>(k)] = 0.0;
    for (int k = 0; k <= p.degree; ++k) {
      const double ck = p.c[static_cast<std::size_t>(k)];
      q.c[static_cast<std::size_t>(k)] += a0 * ck;
      q.c[static_cast<std::size_t>(k + 1)] += a1 * ck;
      if (a2 != 0.0) q.c[static_cast<std::size_t>(k + 2)] += a2 * ck;
    }
    p = q;
  };
  for (double r : roots) times(-r, 1.0, 0.0);
  times(1.0, 0.0, 1.0);
  return p;
}

double bernstein_value(const BernsteinPiece& b, double tau) {
  const double s = (tau - b.lo) / (b.hi - b.lo);
  // de Casteljau at s
  std::vector<double> w(b.b.begin(), b.b.begin() + b.degree + 1);
  for (int r = 1; r <= b.degree; ++r)
    for (int i = 0; i + r <= b.degree; ++i)
      w[static_cast<std::size_t>(i)] =
          (1 - s) * w[static_cast<std::size_t>(i)] + s * w[static_cast<std::size_t>(i + 1)];
  return w[0];
}

TEST(SeriesGuards, BernsteinFormIsThePolynomialAndBoundsIt) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    StepPolynomial p;
    p.degree = 1 + trial % 20;
    for (int k = 0; k <= p.degree; ++k) p.c[static_cast<std::size_t>(k)] = u(rng) / (1 + k);
    const double lo = trial % 3 == 0 ? 0.0 : 0.3 * (1 + u(rng)),
                 hi = lo + 0.05 + 0.5 * (1 + u(rng));
    const BernsteinPiece b = detail::bernstein_piece(p, lo, hi, p.value(lo));
    double lowest = 1e300, highest = -1e300;
    for (int i = 0; i <= 400; ++i) {
      const double tau = lo + (hi - lo) * i / 400.0;
      const double v = p.value(tau);
      EXPECT_NEAR(bernstein_value(b, tau), v, 1e-12) << trial << " " << tau;
      lowest = std::min(lowest, v);
      highest = std::max(highest, v);
    }
    // the convex hull property: the coefficients enclose the polynomial on the piece
    EXPECT_LE(b.min(), lowest + 1e-12) << trial;
    EXPECT_GE(b.max(), highest - 1e-12) << trial;
    EXPECT_GE(b.max_abs(), std::max(std::abs(lowest), std::abs(highest)) - 1e-12) << trial;
    // and its halves are the same polynomial
    BernsteinPiece left, right;
    b.split(left, right);
    for (double s : {0.1, 0.37, 0.9}) {
      EXPECT_NEAR(bernstein_value(left, left.lo + s * (left.hi - left.lo)),
                  p.value(left.lo + s * (left.hi - left.lo)), 1e-12);
      EXPECT_NEAR(bernstein_value(right, right.lo + s * (right.hi - right.lo)),
                  p.value(right.lo + s * (right.hi - right.lo)), 1e-12);
    }
  }
}

// the bracket holds the expected root, and the guard's values at its ends have the right signs
void expect_bracket(const StepPolynomial& p, double a, double b, GuardStart start, double root) {
  CrossingBracket br;
  ASSERT_EQ(detail::polynomial_bracket(p, a, b, start, br), 1) << root;
  EXPECT_LE(br.tl, root) << root;
  EXPECT_GE(br.tr, root) << root;
  EXPECT_GT(br.gl, 0.0) << root;
  EXPECT_LE(br.gr, 0.0) << root;
}

TEST(SeriesGuards, FindsTheFirstCrossingWhereverItLies) {
  // a clean crossing, and a dip 1e-6 of the step wide before a later crossing: the sampled
  // guards of a step (4 samples, a parabola's vertex) see only the later one
  expect_bracket(from_roots({0.6}, -1.0), 0.0, 1.0, GuardStart::kArmed, 0.6);
  expect_bracket(from_roots({0.3141, 0.3141 + 1e-6, 0.8}, -1.0), 0.0, 1.0, GuardStart::kArmed,
                 0.3141);
  // positive throughout, and a double root (a touch) that does not cross: none
  CrossingBracket br;
  EXPECT_EQ(detail::polynomial_bracket(from_roots({}, 1.0), 0.0, 1.0, GuardStart::kArmed, br), 0);
  EXPECT_EQ(
      detail::polynomial_bracket(from_roots({1.5, 1.7}, 1.0), 0.0, 1.0, GuardStart::kArmed, br), 0);
  // starting at exactly zero, known to turn positive: the crossing after it, not the start
  expect_bracket(from_roots({0.0, 0.45}, -1.0), 0.0, 1.0, GuardStart::kZero, 0.45);
  // at zero and turning negative: unresolved
  EXPECT_EQ(
      detail::polynomial_bracket(from_roots({0.0, 0.45}, 1.0), 0.0, 1.0, GuardStart::kZero, br),
      -1);
  // at zero with a leading term at rounding of the wrong sign (theta'' at an uplift): armed
  expect_bracket(from_roots({0.0, 0.0, 1e-16, 0.8}, -1.0), 0.0, 1.0, GuardStart::kZero, 0.8);
  // negative at the start (disarmed): it counts once it has turned positive
  expect_bracket(from_roots({0.2, 0.7}, -1.0), 0.0, 1.0, GuardStart::kDisarmed, 0.7);
  EXPECT_EQ(detail::polynomial_bracket(from_roots({0.2}, 1.0), 0.0, 1.0, GuardStart::kDisarmed, br),
            0);
  // after a crossing at 0.25 (a peak), the next one at 0.75 once it has been positive again
  const StepPolynomial three = from_roots({0.25, 0.5, 0.75}, -1.0);
  expect_bracket(three, 0.0, 1.0, GuardStart::kArmed, 0.25);
  expect_bracket(three, 0.25, 1.0, GuardStart::kCrossed, 0.75);
  EXPECT_EQ(detail::polynomial_bracket(three, 0.75, 1.0, GuardStart::kCrossed, br), 0);
}

TEST(SeriesGuards, ArgmaxFindsTheLargestValue) {
  const StepPolynomial p = from_roots({0.2, 0.9}, -1.0);  // a hump, largest near 0.55
  const double t =
      detail::polynomial_argmax([&](double tau) { return std::abs(p.value(tau)); }, 1.0);
  double best = 0.0, at = 0.0;
  for (int i = 0; i <= 100000; ++i) {
    const double tau = i / 100000.0;
    if (std::abs(p.value(tau)) > best) {
      best = std::abs(p.value(tau));
      at = tau;
    }
  }
  EXPECT_NEAR(t, at, 2e-5);
  EXPECT_NEAR(std::abs(p.value(t)), best, 1e-12 * best);
}

// a rigid block under a one-sine pulse that rocks with impacts (the bench's case b family)
struct Rocking {
  Body body = Body(BodyParameters::rectangular_block(1000.0, 0.2, 1.0));
  GroundMotion pulse() const {
    return one_sine_pulse(3.0 * g * std::tan(body.tipping_angle(1)), 6.0 * M_PI, 6.0);
  }
};

TEST(SeriesGuards, LocatedReactionExtremesBoundADenseHistory) {
  const Rocking c;
  SimulationOptions opt;
  opt.output_dt = 2e-4;
  const SimulationResult r = simulate(c.body, c.pulse(), {}, opt);
  ASSERT_EQ(r.status, Status::kCompleted);
  ASSERT_GT(r.extremes.impacts, 5);
  const double mg = c.body.params().mass * c.body.g();
  double shear = 0.0;
  for (std::size_t i = 0; i < r.history.size(); ++i)
    shear = std::max(shear, std::abs(r.history.reaction_x[i]));
  // every row is a value the motion takes, so the located extreme is at least each; and the rows,
  // 0.2 ms apart, come within their spacing's variation of it
  EXPECT_GE(r.extremes.max_base_shear, shear * (1 - 1e-12));
  EXPECT_LE(r.extremes.max_base_shear, shear * (1 + 5e-3));
  EXPECT_GT(r.extremes.max_base_shear, 0.05 * mg);
}

TEST(SeriesGuards, TheAnswerDoesNotDependOnMaxStep) {
  const Rocking c;
  SimulationOptions coarse, fine;
  coarse.max_step = 0.01;
  fine.max_step = 0.001;
  const SimulationResult a = simulate(c.body, c.pulse(), {}, coarse);
  const SimulationResult b = simulate(c.body, c.pulse(), {}, fine);
  ASSERT_EQ(a.status, b.status);
  // the same motion to rounding: only the full contact before the uplift is checked per max_step
  // under a pulse
  ASSERT_EQ(a.extremes.impacts, b.extremes.impacts);
  for (double (*f)(const SimulationResult&) :
       {+[](const SimulationResult& r) { return r.extremes.max_theta_edge1; },
        +[](const SimulationResult& r) { return r.extremes.max_theta_edge2; },
        +[](const SimulationResult& r) { return r.extremes.max_base_shear; },
        +[](const SimulationResult& r) { return r.extremes.max_overturning_moment; },
        +[](const SimulationResult& r) { return r.extremes.max_friction_demand; }})
    EXPECT_NEAR(f(a), f(b), 1e-12 * std::abs(f(a)));
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i)
    EXPECT_NEAR(a.events[i].time, b.events[i].time, 1e-12);
  // a friction limit keeps the sampled steps (|F_I| is no polynomial): max_step caps them there
  SimulationOptions friction = coarse;
  friction.friction_coefficient = 5.0;  // far above the demand: the same motion
  const SimulationResult f = simulate(c.body, c.pulse(), {}, friction);
  EXPECT_GT(f.steps, 5 * a.steps);
  EXPECT_EQ(f.extremes.impacts, a.extremes.impacts);
  EXPECT_NEAR(f.extremes.max_theta_edge1, a.extremes.max_theta_edge1, 1e-9);
  // the sampled steps see the shear at their samples only: at most the located extreme
  EXPECT_LE(f.extremes.max_base_shear, a.extremes.max_base_shear * (1 + 1e-9));
}

}  // namespace
}  // namespace flexrock
