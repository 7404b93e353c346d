// SPDX-License-Identifier: BSD-3-Clause
// A flexible body in full contact under a sampled record: the exact propagation between samples
// against the integrator at a tight tolerance, on random bodies, damping and records.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/sim/simulate.hpp"
#include "support/bodies.hpp"

namespace flexrock {
namespace {

constexpr double g = kStandardGravity;

// a random record with uneven spacing, both components, amplitude in g
GroundMotion random_record(unsigned seed, double amplitude, double duration, bool uniform) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> t{0.0}, ax{0.0}, ay{0.0};
  while (t.back() < duration) {
    t.push_back(t.back() + (uniform ? 0.01 : 0.004 + 0.016 * u(rng)));
    ax.push_back(amplitude * g * (2 * u(rng) - 1));
    ay.push_back(0.5 * amplitude * g * (2 * u(rng) - 1));
  }
  if (uniform) {
    ax.pop_back();
    ay.pop_back();
    return GroundMotion::uniform(0.01, ax, ay);
  }
  return GroundMotion::sampled(t, ax, ay);
}

Body damped_body(int n, unsigned seed, int damping) {
  // softer than the default random body (modes of 20-200 rad/s): the reference integration then
  // converges to 1e-11 in 1e4-1e5 steps, before its rounding accumulates
  BodyParameters p = test::random_lumped_body(n, seed, 1e4);
  if (damping == 1) {
    p.damping.kind = DampingKind::kModal;
    p.damping.modal_ratios = VectorX::LinSpaced(n, 0.02, 0.08);
  } else if (damping == 2) {
    p.damping.kind = DampingKind::kRayleigh;
    p.damping.rayleigh_mass = 0.3;
    p.damping.rayleigh_stiffness = 2e-4;
  }
  return Body(p);
}

SimulationResult run(const Body& body, const GroundMotion& m, bool exact, double t_end = -1.0) {
  SimulationOptions opt;
  opt.exact_full_contact = exact;
  // the reference: the integrator at its tightest, with short steps (its input work and damping
  // loss are not error-controlled); the exact path does not depend on rtol in contact
  opt.rtol = exact ? 1e-9 : 1e-13;
  opt.atol = exact ? 1e-11 : 1e-16;
  opt.max_step = exact ? 0.01 : 0.001;
  opt.t_end = t_end;
  opt.output_dt = 0.0137;  // rows between the samples: the exact path's dense output
  return simulate(body, m, {}, opt);
}

TEST(ExactFullContact, MatchesTightIntegrationBelowUplift) {
  for (int n : {1, 2, 3, 5}) {
    for (int damping : {0, 1, 2}) {
      for (bool uniform : {true, false}) {
        const unsigned seed = 100u * static_cast<unsigned>(n) +
                              10u * static_cast<unsigned>(damping) + (uniform ? 1u : 0u);
        const Body body = damped_body(n, seed, damping);
        const GroundMotion m = random_record(seed, 0.01, 3.0, uniform);
        const SimulationResult ex = run(body, m, true), in = run(body, m, false);
        SCOPED_TRACE("n = " + std::to_string(n) + ", damping " + std::to_string(damping) +
                     (uniform ? ", uniform" : ", uneven"));
        ASSERT_EQ(ex.status, Status::kCompleted);
        ASSERT_EQ(in.status, Status::kCompleted);
        ASSERT_EQ(ex.extremes.first_uplift_time, -1.0) << "the record must stay below uplift";
        // the exact path takes one step per sample interval and evaluates no right-hand side
        EXPECT_EQ(ex.rhs_evaluations, 0);
        EXPECT_LT(ex.steps, in.steps);
        const double qs = in.extremes.max_abs_q.maxCoeff();
        for (int i = 0; i < n; ++i) EXPECT_NEAR(ex.final_q(i), in.final_q(i), 1e-9 * qs);
        // the time histories, between samples too (extremes are not compared: they are taken
        // at each step's event samples, and the integrator's steps are 30-50 times more)
        ASSERT_EQ(ex.history.size(), in.history.size());
        double worst = 0.0;
        for (std::size_t k = 0; k < ex.history.q.size(); ++k)
          worst = std::max(worst, std::abs(ex.history.q[k] - in.history.q[k]));
        EXPECT_LT(worst, 1e-9 * qs);
        double vs = 0.0;
        for (double v : in.history.q_dot) vs = std::max(vs, std::abs(v));
        for (int i = 0; i < n; ++i) EXPECT_NEAR(ex.final_q_dot(i), in.final_q_dot(i), 1e-9 * vs);
        // the energies: Gauss-Legendre on the exact integrands against the integrated ones
        const double es = in.energy.scale;
        EXPECT_NEAR(ex.energy.input_work, in.energy.input_work, 1e-9 * es);
        EXPECT_NEAR(ex.energy.damping_loss, in.energy.damping_loss, 1e-9 * es);
        if (damping > 0) {
          EXPECT_GT(ex.energy.damping_loss, 0.0);
        }
        // the balance closes on its own, independently of the integrator, down to the rounding
        // of the potential energy (M g h (1 + psi_y.q) differenced)
        const double mgh = body.params().mass * g * body.params().height;
        EXPECT_LT(std::abs(ex.energy.residual), 1e-9 * ex.energy.scale + 1e-14 * mgh);
      }
    }
  }
}

TEST(ExactFullContact, FindsTheSameUpliftAndContinues) {
  for (int n : {1, 2, 4}) {
    const Body body = damped_body(n, 7u + static_cast<unsigned>(n), 1);
    // strong enough to uplift within the record, but the first seconds decide it
    const GroundMotion m = random_record(40u + static_cast<unsigned>(n), 0.6, 6.0, true);
    const SimulationResult ex = run(body, m, true), in = run(body, m, false);
    SCOPED_TRACE("n = " + std::to_string(n));
    ASSERT_GT(in.extremes.first_uplift_time, 0.0);
    EXPECT_NEAR(ex.extremes.first_uplift_time, in.extremes.first_uplift_time, 1e-9);
    EXPECT_EQ(ex.extremes.first_uplift_edge, in.extremes.first_uplift_edge);
    // the state at uplift is the same: stop both just before and compare
    const double t_before = in.extremes.first_uplift_time - 1e-6;
    const SimulationResult exb = run(body, m, true, t_before), inb = run(body, m, false, t_before);
    const double qs = inb.extremes.max_abs_q.maxCoeff();
    for (int i = 0; i < n; ++i) EXPECT_NEAR(exb.final_q(i), inb.final_q(i), 1e-9 * qs);
    // and every run that rocks closes its energy balance
    EXPECT_LT(std::abs(ex.energy.residual), 1e-6 * ex.energy.scale);
  }
}

// A body whose modes are coupled (every mode moves every mass; full modal mass and stiffness) and
// widely spread (0.1 Hz .. top_hz). Damping: 0 none, 1 modal 2-8 %, 2 Rayleigh, 3 modal with the
// top modes damped critically and three times critically.
Body coupled_body(int n, unsigned seed, int damping, double top_hz) {
  // bodies that cannot stand (a soft mode sagging too far) are drawn again
  BodyParameters p;
  for (unsigned s = seed;; s += 7919u) {
    p = test::random_coupled(test::spread_frequencies(n, s, 0.1, top_hz), s, 0.002).params();
    try {
      const Body check(p);
      break;
    } catch (const InputError&) {
    }
  }
  if (damping == 1) {
    p.damping.kind = DampingKind::kModal;
    p.damping.modal_ratios = VectorX::LinSpaced(n, 0.02, 0.08);
  } else if (damping == 2) {
    p.damping.kind = DampingKind::kRayleigh;
    p.damping.rayleigh_mass = 0.05;
    p.damping.rayleigh_stiffness = 2e-5;
  } else if (damping == 3) {
    p.damping.kind = DampingKind::kModal;
    p.damping.modal_ratios = VectorX::Constant(n, 0.05);
    p.damping.modal_ratios(n - 1) = 3.0;
    p.damping.modal_ratios(n - 2) = 1.0;
  }
  return Body(p);
}

TEST(ExactFullContact, CoupledWidelySpreadModesMatchTightIntegration) {
  // 0.1 Hz .. 1 kHz over a short window: the reference (rtol 1e-12, a few 1e4 steps) is converged
  // there (it agrees with itself at rtol 1e-13 to 1e-13 of max|q|); the former propagator
  // (V e^{Lambda tau} V^-1 with a particular solution c0 + c1 tau) was off by up to 7e-8 here
  for (int n : {2, 3, 4}) {
    for (int damping : {0, 1, 2, 3}) {
      for (bool uniform : {true, false}) {
        const unsigned seed = 2000u + 10u * static_cast<unsigned>(n) +
                              3u * static_cast<unsigned>(damping) + (uniform ? 1u : 0u);
        const Body body = coupled_body(n, seed, damping, 1000.0);
        const GroundMotion m = random_record(seed, 0.02, 0.2, uniform);
        SimulationOptions opt;
        opt.output_dt = 0.0137;
        opt.exact_full_contact = true;
        const SimulationResult ex = simulate(body, m, {}, opt);
        opt.exact_full_contact = false;
        opt.rtol = 1e-12;
        opt.atol = 1e-15;
        opt.max_step = 1e-4;
        const SimulationResult in = simulate(body, m, {}, opt);
        SCOPED_TRACE("n = " + std::to_string(n) + ", damping " + std::to_string(damping) +
                     (uniform ? ", uniform" : ", uneven"));
        ASSERT_EQ(ex.status, Status::kCompleted);
        ASSERT_EQ(in.status, Status::kCompleted);
        ASSERT_EQ(ex.extremes.first_uplift_time, -1.0) << "the record must stay below uplift";
        EXPECT_EQ(ex.rhs_evaluations, 0);
        const double qs = in.extremes.max_abs_q.maxCoeff();
        // velocities on the scale of the fastest mode's (omega_max max|q|): the energy norm
        const double vs = body.natural_frequencies().maxCoeff() * qs;
        for (int i = 0; i < n; ++i) {
          EXPECT_NEAR(ex.final_q(i), in.final_q(i), 1e-9 * qs);
          EXPECT_NEAR(ex.final_q_dot(i), in.final_q_dot(i), 1e-9 * vs);
        }
        ASSERT_EQ(ex.history.size(), in.history.size());
        double worst = 0.0, worst_v = 0.0;
        for (std::size_t k = 0; k < ex.history.q.size(); ++k) {
          worst = std::max(worst, std::abs(ex.history.q[k] - in.history.q[k]));
          worst_v = std::max(worst_v, std::abs(ex.history.q_dot[k] - in.history.q_dot[k]));
        }
        EXPECT_LT(worst, 1e-9 * qs);
        EXPECT_LT(worst_v, 1e-9 * vs);
        if (damping > 0) {
          EXPECT_GT(ex.energy.damping_loss, 0.0);
          EXPECT_NEAR(ex.energy.damping_loss, in.energy.damping_loss,
                      1e-6 * in.energy.damping_loss);
        }
      }
    }
  }
}

TEST(ExactFullContact, CoupledModesAgreeWithTheRecordUpsampled) {
  // the same piecewise-linear function sampled twice as often is the same input: the exact path
  // must not depend on where the samples are (it agrees to ~2e-14 of max|q|; the former
  // propagator differed by up to 3e-9 here)
  for (int n : {3, 4}) {
    for (unsigned seed = 3000u; seed < 3006u; ++seed) {
      const Body body = coupled_body(n, seed, 1, 1000.0);
      const GroundMotion m = random_record(seed, 0.1, 2.0, true);
      std::vector<double> ax, ay;
      for (std::size_t k = 0; k + 1 < m.samples(); ++k) {
        const BaseAcceleration a = m.at(0.01 * static_cast<double>(k));
        const BaseAcceleration b = m.at(0.01 * (static_cast<double>(k) + 0.5));
        ax.insert(ax.end(), {a.x, b.x});
        ay.insert(ay.end(), {a.y, b.y});
      }
      const BaseAcceleration last = m.at(0.01 * static_cast<double>(m.samples() - 1));
      ax.push_back(last.x);
      ay.push_back(last.y);
      const GroundMotion up = GroundMotion::uniform(0.005, ax, ay);
      SimulationOptions opt;
      opt.output_dt = 0.0137;
      const SimulationResult a = simulate(body, m, {}, opt), b = simulate(body, up, {}, opt);
      SCOPED_TRACE("n = " + std::to_string(n) + ", seed " + std::to_string(seed));
      ASSERT_EQ(a.status, Status::kCompleted);
      ASSERT_EQ(a.extremes.first_uplift_time, -1.0);
      const double qs = a.extremes.max_abs_q.maxCoeff();
      ASSERT_EQ(a.history.size(), b.history.size());
      double worst = 0.0;
      for (std::size_t k = 0; k < a.history.q.size(); ++k)
        worst = std::max(worst, std::abs(a.history.q[k] - b.history.q[k]));
      EXPECT_LT(worst, 1e-12 * qs);
    }
  }
}

TEST(ExactFullContact, AnalyticMotionStillIntegrates) {
  // a pulse is not piecewise linear: the integrator keeps it
  const Body body = damped_body(2, 3u, 1);
  const auto m = GroundMotion::analytic(
      [](double t) {
        return BaseAcceleration{0.05 * g * std::sin(9.0 * t), 0.0};
      },
      2.0);
  SimulationOptions opt;
  const SimulationResult r = simulate(body, m, {}, opt);
  EXPECT_GT(r.rhs_evaluations, 0);
}

}  // namespace
}  // namespace flexrock
