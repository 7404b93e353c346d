// SPDX-License-Identifier: BSD-3-Clause
// A flexible body in full contact under a sampled record: the exact propagation between samples
// against the integrator at a tight tolerance, on random bodies, damping and records.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"
#include "sim/contact_propagator.hpp"
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
  opt.methods.exact_full_contact = exact;
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
        opt.methods.exact_full_contact = true;
        const SimulationResult ex = simulate(body, m, {}, opt);
        opt.methods.exact_full_contact = false;
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

// The history q, q_dot of a body in full contact under a sampled record, from its engine
// initial state (the static sag, at rest), by a different method in long double: the first-order
// system x' = A x + b0 + b1 s on each sample interval, stepped by Van Loan's exponential of
// [A b1 b0; 0 0 1; 0 0 0] (Eigen's matrix exponential), with K = (g/h) kappa formed in long double
// and the engine's C and g/h (double) as the data. Its rounding is ~cond(K) 1e-19: 1e-11 at
// cond(K) = 1e8. (K rounded to double would be other data at that level: its soft mode's
// equilibrium lies cond(K) ulp, 1e-8 of the sag, from the static sag that kappa gives.)
struct Reference {
  std::vector<double> q, q_dot;  // at the history times, row-major like History
};
Reference long_double_reference(const Body& body, const GroundMotion& m,
                                const std::vector<double>& times) {
  using Ld = long double;
  using MatL = Eigen::Matrix<Ld, Eigen::Dynamic, Eigen::Dynamic>;
  using VecL = Eigen::Matrix<Ld, Eigen::Dynamic, 1>;
  const int n = body.modes(), size = 2 * n + 2;
  const MatL mu_inv = body.params().mu.cast<Ld>().inverse();
  const Ld gh = body.g_over_h(), gl = body.g();
  MatL a = MatL::Zero(size, size);
  a.block(0, n, n, n).setIdentity();
  a.block(n, 0, n, n) = -mu_inv * (gh * body.params().kappa.cast<Ld>());
  a.block(n, n, n, n) = -mu_inv * body.damping_matrix().cast<Ld>();
  a(2 * n, 2 * n + 1) = 1;  // s' = 1: the time within the interval
  const VecL px = body.params().psi_x.cast<Ld>(), py = body.params().psi_y.cast<Ld>();
  auto force = [&](Ld ax, Ld ay) -> VecL {
    return -gh * (mu_inv * (px * (ax / gl) + py * (1 + ay / gl)));
  };
  VecL z = VecL::Zero(size);
  z.head(n) = body.static_deformation().cast<Ld>();
  z(2 * n + 1) = 1;
  Reference out;
  const std::vector<double>&ts = m.times(), &xs = m.horizontal(), &ys = m.vertical();
  std::size_t row = 0;
  for (std::size_t k = 0; k + 1 < ts.size() && row < times.size(); ++k) {
    const Ld t0 = ts[k], t1 = ts[k + 1];
    const VecL b0 = force(xs[k], ys.empty() ? 0.0 : ys[k]);
    const VecL b1 = (force(xs[k + 1], ys.empty() ? 0.0 : ys[k + 1]) - b0) / (t1 - t0);
    MatL mk = a;
    mk.block(n, 2 * n, n, 1) = b1;
    mk.block(n, 2 * n + 1, n, 1) = b0;
    z(2 * n) = 0;
    Ld t = t0;
    for (; row < times.size() && static_cast<Ld>(times[row]) <= t1; ++row) {
      const MatL e = (mk * (static_cast<Ld>(times[row]) - t)).exp();
      z = e * z;
      t = times[row];
      for (int i = 0; i < n; ++i) {
        out.q.push_back(static_cast<double>(z(i)));
        out.q_dot.push_back(static_cast<double>(z(n + i)));
      }
    }
    const MatL e = (mk * (t1 - t)).exp();
    z = e * z;
  }
  return out;
}

TEST(ExactFullContact, ASoftModesLargeSagBesideAStiffModeMatchesALongDoubleReference) {
  // the harsh soak's bodies: a 0.1 Hz mode sagging tens of times h beside a mode near 1 kHz
  // (cond(K) ~ 1e8) under a small spiky record, 2.5 s. The equilibrium of such a body is
  // defined by its data only to ~cond(K) ulp (1e-8 of the sag): the soft mode's w^2 from the
  // eigensolver put the exact path's equilibrium there, so that the body at rest swung at
  // 0.1 Hz by 1e-8 of its sag (4e-5 of its whole motion, 1e-5 of max|q_dot| for the soak's
  // case 4093), as did a start from an unrefined static solve. Both paths must now follow the
  // long-double solution of the same data (kappa and psi; the engine's modal coordinates rest at
  // the refined sag of kappa) to 1e-9 of max|q| and 1e-9 of omega_max max|q|, and agree with
  // each other as closely.
  int bodies = 0;
  for (int n : {2, 3, 4}) {
    for (unsigned seed = 5000u; seed < 5003u; ++seed) {
      BodyParameters p;
      for (unsigned s = seed;; s += 7919u) {
        std::vector<double> hz = test::spread_frequencies(n, s, 0.1, 1000.0);
        p = test::random_coupled(hz, s, 0.05).params();
        try {
          const Body check(p);
          break;
        } catch (const InputError&) {
        }
      }
      p.damping.kind = DampingKind::kModal;
      p.damping.modal_ratios = VectorX::LinSpaced(n, 0.0, 0.1);
      const Body body(p);
      const GroundMotion m = random_record(seed, 0.02, 2.5, seed % 2 == 0);
      SimulationOptions opt;
      opt.output_dt = 0.0137;
      const SimulationResult ex = simulate(body, m, {}, opt);
      opt.methods.exact_full_contact = false;
      opt.rtol = 1e-12;
      opt.atol = 1e-14;
      opt.max_step = 1e-3;
      opt.max_steps = 100'000'000;
      const SimulationResult in = simulate(body, m, {}, opt);
      SCOPED_TRACE("n = " + std::to_string(n) + ", seed " + std::to_string(seed));
      ASSERT_EQ(ex.status, Status::kCompleted);
      ASSERT_EQ(in.status, Status::kCompleted);
      ASSERT_EQ(ex.extremes.first_uplift_time, -1.0) << "the record must stay below uplift";
      const Reference ref = long_double_reference(body, m, ex.history.time);
      ASSERT_EQ(ref.q.size(), ex.history.q.size());
      ASSERT_EQ(in.history.q.size(), ex.history.q.size());
      const double qs = ex.extremes.max_abs_q.maxCoeff();
      const double vs = body.natural_frequencies().maxCoeff() * qs;
      ASSERT_GT(qs, 1.0) << "a large static sag";
      double ex_q = 0, ex_v = 0, in_q = 0, in_v = 0, both_q = 0, both_v = 0;
      for (std::size_t k = 0; k < ref.q.size(); ++k) {
        ex_q = std::max(ex_q, std::abs(ex.history.q[k] - ref.q[k]));
        ex_v = std::max(ex_v, std::abs(ex.history.q_dot[k] - ref.q_dot[k]));
        in_q = std::max(in_q, std::abs(in.history.q[k] - ref.q[k]));
        in_v = std::max(in_v, std::abs(in.history.q_dot[k] - ref.q_dot[k]));
        both_q = std::max(both_q, std::abs(ex.history.q[k] - in.history.q[k]));
        both_v = std::max(both_v, std::abs(ex.history.q_dot[k] - in.history.q_dot[k]));
      }
      EXPECT_LT(ex_q, 1e-9 * qs);
      EXPECT_LT(ex_v, 1e-9 * vs);
      EXPECT_LT(in_q, 1e-9 * qs);
      EXPECT_LT(in_v, 1e-9 * vs);
      EXPECT_LT(both_q, 1e-9 * qs);
      EXPECT_LT(both_v, 1e-9 * vs);
      // the energy balance closes far inside its bound on both paths (at most 0.01 of it): the
      // potential energy is taken about the static sag (summed directly, psi_y.q + 1/2 q kappa q
      // lost ~1e-9 M g h to cancellation: 6.6 times the bound here on the exact path, 4.6 on
      // the integrated one)
      for (const SimulationResult* r : {&ex, &in}) {
        EXPECT_FALSE(r->energy_unbalanced);
        EXPECT_LT(std::abs(r->energy.residual),
                  5e-2 * energy_residual_bound(body, r->energy.scale));
      }
      ++bodies;
    }
  }
  EXPECT_EQ(bodies, 9);
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

// ---- the record walk: one exact update per piece, the guards bounded between the pieces' ends

namespace walk {

SimulationResult run(const Body& body, const GroundMotion& m, int path, double output_dt,
                     const InitialState& init = {}, double t_end = -1.0) {
  SimulationOptions opt;
  opt.output_dt = output_dt;
  opt.t_end = t_end;
  opt.methods.full_contact_walk = path == 0;  // path 1: the stepped, sampled propagation
  if (path == 2) {
    // the integrator at its tightest, with short steps
    opt.methods.exact_full_contact = false;
    opt.rtol = 1e-13;
    opt.atol = 1e-16;
    opt.max_step = 0.001;
  }
  return simulate(body, m, init, opt);
}

}  // namespace walk

// The floor's reaction at tau within the propagator's last walk piece (from the state x, under the
// base acceleration a0 + slope tau), formed as evaluate() forms it: q from the exact dense state,
// q'' from the equations of motion, then F_I, F_J, the uplift functions and R(0)
struct PieceReaction {
  VectorX q;
  Eigen::Vector2d r, uplift;
  double moment = 0.0;
};
template <class Dyn, class Prop, class State>
PieceReaction reaction_at(const Dyn& dyn, const Prop& prop, const State& x, int n,
                          BaseAcceleration a0, BaseAcceleration slope, double tau) {
  State xs = x;
  prop.walk_dense(tau, xs);
  const typename Dyn::Vec q = xs.segment(1, n), qd = xs.segment(n + 2, n);
  const BaseAcceleration a{a0.x + slope.x * tau, a0.y + slope.y * tau};
  typename Dyn::Vec qdd(n);
  dyn.full_contact_acceleration(q, qd, a, qdd);
  PieceReaction out;
  out.q = q;
  out.r = dyn.full_contact_reaction(qdd, a);
  out.moment = dyn.contact_moments(q, qdd, a, out.uplift);
  return out;
}

void compare_full_contact(const Body& body, const SimulationResult& wk, const SimulationResult& st,
                          const SimulationResult& in);
void compare_walk_with_steps(const Body& body, const SimulationResult& wk,
                             const SimulationResult& st);

TEST(FullContactWalk, MatchesTheSteppedPathAndTheTightIntegration) {
  // below uplift and through it; uniform records and uneven ones (more distinct intervals than
  // the walk keeps, so most pieces are computed afresh)
  for (int n : {1, 2, 3}) {
    for (double amplitude : {0.01, 0.6}) {
      for (bool uniform : {true, false}) {
        const unsigned seed = 300u + 10u * static_cast<unsigned>(n) + (uniform ? 1u : 0u) +
                              (amplitude > 0.1 ? 5u : 0u);
        const Body body = damped_body(n, seed, 1 + n % 2);
        const GroundMotion m = random_record(seed, amplitude, 4.0, uniform);
        const SimulationResult wk = walk::run(body, m, 0, 0.0137),
                               st = walk::run(body, m, 1, 0.0137),
                               in = walk::run(body, m, 2, 0.0137);
        SCOPED_TRACE("n = " + std::to_string(n) + ", amplitude " + std::to_string(amplitude) +
                     (uniform ? ", uniform" : ", uneven"));
        ASSERT_EQ(wk.status, in.status);
        ASSERT_EQ(st.status, in.status);
        EXPECT_EQ(wk.rhs_evaluations, st.rhs_evaluations);
        // the same uplift, on the same edge
        EXPECT_NEAR(wk.extremes.first_uplift_time, in.extremes.first_uplift_time, 1e-9);
        EXPECT_NEAR(wk.extremes.first_uplift_time, st.extremes.first_uplift_time, 1e-12);
        EXPECT_EQ(wk.extremes.first_uplift_edge, in.extremes.first_uplift_edge);
        EXPECT_LT(std::abs(wk.energy.residual), 1e-6 * wk.energy.scale);
        // the rest compares the full-contact phase alone (rocking after it is chaotic: rounding
        // differences grow there): the runs stop just before the first uplift
        const double t_end =
            in.extremes.first_uplift_time > 0.0 ? in.extremes.first_uplift_time - 1e-6 : -1.0;
        const SimulationResult wkc = walk::run(body, m, 0, 0.0137, {}, t_end),
                               stc = walk::run(body, m, 1, 0.0137, {}, t_end),
                               inc = walk::run(body, m, 2, 0.0137, {}, t_end);
        compare_full_contact(body, wkc, stc, inc);
      }
    }
  }
}

void compare_full_contact(const Body& body, const SimulationResult& wk, const SimulationResult& st,
                          const SimulationResult& in) {
  const int n = body.modes();
  ASSERT_EQ(wk.extremes.first_uplift_time, -1.0);
  EXPECT_LE(wk.steps, st.steps);
  // the extremes: located by the walk, sampled by the stepped path (so never above the walk's
  // beyond rounding); the integration's within its sampling's reach
  const double qs = in.extremes.max_abs_q.maxCoeff();
  for (int i = 0; i < n; ++i)
    EXPECT_NEAR(wk.extremes.max_abs_q(i), in.extremes.max_abs_q(i), 1e-3 * qs);
  compare_walk_with_steps(body, wk, st);
  const double es = in.energy.scale;
  EXPECT_NEAR(wk.energy.input_work, in.energy.input_work, 1e-6 * es);
  EXPECT_NEAR(wk.energy.damping_loss, in.energy.damping_loss, 1e-6 * es);
}

// the walk against the stepped path over a full-contact phase: the same located extremes, the
// same rows, the same energies. Both locate each peak of the exact solution, the walk by Newton's
// method to 2^-16 of its bracket, the stepped path by Brent's search to 2^-19 of three samples'
// span (Simulator::locate_step_extremes): equal to 1e-10 of their scale (1.8e-12 measured);
// sampled alone, the stepped path's fell short by up to 1e-4
void compare_walk_with_steps(const Body& body, const SimulationResult& wk,
                             const SimulationResult& st) {
  const double qs = st.extremes.max_abs_q.maxCoeff();
  for (int i = 0; i < body.modes(); ++i)
    EXPECT_NEAR(wk.extremes.max_abs_q(i), st.extremes.max_abs_q(i), 1e-10 * qs);
  EXPECT_NEAR(wk.extremes.max_base_shear, st.extremes.max_base_shear,
              1e-10 * st.extremes.max_base_shear);
  EXPECT_NEAR(wk.extremes.max_overturning_moment, st.extremes.max_overturning_moment,
              1e-10 * st.extremes.max_overturning_moment);
  EXPECT_NEAR(wk.extremes.max_friction_demand, st.extremes.max_friction_demand,
              1e-10 * st.extremes.max_friction_demand);
  ASSERT_EQ(wk.history.size(), st.history.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < wk.history.q.size(); ++k)
    worst = std::max(worst, std::abs(wk.history.q[k] - st.history.q[k]));
  EXPECT_LT(worst, 1e-9 * qs);
  const double es = st.energy.scale;
  EXPECT_NEAR(wk.energy.input_work, st.energy.input_work, 1e-9 * es);
  EXPECT_NEAR(wk.energy.damping_loss, st.energy.damping_loss, 1e-9 * es);
}

TEST(FullContactWalk, ClosedFormExponentialOfAModeIsTheTaylorStepsAndPadesOne) {
  // the walk's dense output between kept points takes e^{B tau} in closed form; the steps take it
  // by Taylor series and doubling, Eigen by Pade approximation and squaring. Under-, critically
  // and over-damped modes, phases from 1e-3 to 60 rad.
  for (const auto& [w, c] : std::vector<std::pair<double, double>>{
           {10.0, 0.0}, {10.0, 0.4}, {10.0, 20.0}, {10.0, 50.0}, {6000.0, 240.0}}) {
    for (double tau : {1e-4, 0.01, 0.3, 0.01 * 6000.0 / w}) {
      detail::ModeStep step;
      detail::mode_step(w, c, tau, step);
      Eigen::Matrix2d b;
      b << 0.0, w, -w, -c;
      const Eigen::Matrix2d pade = (b * tau).exp();
      const Eigen::Matrix2d closed = detail::mode_exponential(w, c, tau);
      SCOPED_TRACE("w = " + std::to_string(w) + ", c = " + std::to_string(c) +
                   ", tau = " + std::to_string(tau));
      EXPECT_LT((closed - step.e).cwiseAbs().maxCoeff(), 1e-13);
      EXPECT_LT((closed - pade).cwiseAbs().maxCoeff(), 1e-13);
    }
  }
}

// A random piece of the walk, for the tests of its bounds: a coupled body of n modes between 2 Hz
// and 500 Hz (random_coupled's, seeded by body_seed, its vertical mode shapes scaled by
// vertical_scale) with modal damping up to 10 %, a state about its static deflection, and a linear
// forcing over a piece of 2 to 20 ms, all drawn from rng. `swing` > 0 adds to each q_i a random
// deformation up to swing and a velocity up to swing times its pinned-base frequency: with mode
// shapes of both directions (Gamma far from 0) the moment's quadratic term Gamma^T q . q'' then
// counts in the bounds.
struct RandomPiece {
  using Dyn = Dynamics<Eigen::Dynamic, 16>;
  using State = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 64, 1>;

  RandomPiece(int modes, unsigned body_seed, std::mt19937& rng, double vertical_scale = 0.02,
              double swing = 0.0)
      : n(modes),
        hz(frequencies(modes, rng)),
        body(damped(hz, body_seed, rng, vertical_scale)),
        dyn(body),
        motion(random_record(1u, 0.1, 1.0, true)),
        prop(dyn, motion, 4, 0.01, true),
        x(State::Zero(2 * modes + 11)) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const VectorX q0 = body.static_deformation();
    for (int i = 0; i < n; ++i) {
      const double w = 2.0 * std::numbers::pi * hz[static_cast<std::size_t>(i)];
      x(1 + i) = q0(i) * (1.0 + 0.5 * u(rng));
      x(n + 2 + i) = 0.05 * u(rng) * std::abs(q0(i)) * w;
      if (swing > 0.0) {
        x(1 + i) += swing * u(rng);
        x(n + 2 + i) += swing * w * u(rng);
      }
    }
    h = 0.002 + 0.018 * (0.5 + 0.5 * u(rng));
    a0 = {0.3 * g * u(rng), 0.2 * g * u(rng)};
    slope = {20.0 * g * u(rng), 10.0 * g * u(rng)};
  }
  /// The propagator's piece from x over h under a0 + slope tau.
  void walk() {
    prop.walk_start(x);
    prop.walk_piece(h, a0, slope, false);
  }

  int n;
  std::vector<double> hz;
  Body body;
  Dyn dyn;
  GroundMotion motion;
  detail::ContactPropagator<Eigen::Dynamic, 16, State> prop;
  State x;
  double h = 0.0;
  BaseAcceleration a0, slope;

 private:
  static std::vector<double> frequencies(int n, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> hz;
    for (int i = 0; i < n; ++i) hz.push_back(std::pow(10.0, 0.3 + 2.4 * (0.5 + 0.5 * u(rng))));
    std::sort(hz.begin(), hz.end());
    return hz;
  }
  static Body damped(const std::vector<double>& hz, unsigned seed, std::mt19937& rng,
                     double vertical_scale) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    BodyParameters p = test::random_coupled(hz, seed, vertical_scale).params();
    p.damping.kind = DampingKind::kModal;
    p.damping.modal_ratios =
        VectorX::Constant(static_cast<Eigen::Index>(hz.size()), 0.5 * (0.5 + 0.5 * u(rng)) * 0.2);
    return Body(p);
  }
};

// The swing of the tests' last 20 pieces, on bodies whose vertical mode shapes are 0.3 of the
// horizontal ones: large enough that the bounds without the moment's Gamma term fail there (both
// tests fail with it dropped; at 0.1 neither does).
constexpr double kSwing = 3.0;

TEST(FullContactWalk, ExcursionBoundsHoldAtEveryPointOfRandomPieces) {
  // the walk's claim itself: over a piece, each full-contact function (floor reaction, uplift
  // functions, moment) and each q_j stays within the bound of its chord between the piece's ends.
  // Random coupled bodies (slow to stiff modes), random states and linear forcing; the functions
  // by Dynamics at 4001 points of the exact solution.
  std::mt19937 rng(77u);
  int tight = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 1 + trial % 3;
    const bool swinging = trial >= 40;  // the last 20: Gamma's term counts
    RandomPiece piece(n, 500u + static_cast<unsigned>(trial), rng, swinging ? 0.3 : 0.02,
                      swinging ? kSwing : 0.0);
    ASSERT_TRUE(piece.prop.available());
    piece.walk();
    const RandomPiece::Dyn& dyn = piece.dyn;
    const auto& prop = piece.prop;
    const RandomPiece::State& x = piece.x;
    const double h = piece.h;
    const BaseAcceleration a0 = piece.a0, slope = piece.slope;
    const double ax = std::max(std::abs(a0.x), std::abs(a0.x + slope.x * h)) / g;
    const double ay = std::max(std::abs(1.0 + a0.y / g), std::abs(1.0 + (a0.y + slope.y * h) / g));
    const auto e = prop.walk_excursion(h, ax, ay, std::abs(slope.x) / g, std::abs(slope.y) / g);
    // the functions at tau: F_I, F_J, U1, U2, the moment, then q
    auto functions = [&](double tau) {
      const PieceReaction pr = reaction_at(dyn, prop, x, n, a0, slope, tau);
      VectorX f(5 + n);
      f << pr.r(0), pr.r(1), pr.uplift(0), pr.uplift(1), pr.moment, pr.q;
      return f;
    };
    const VectorX f0 = functions(0.0), f1 = functions(h);
    VectorX bound(5 + n);
    bound << e.fi, e.fj, e.u1, e.u2, e.moment, VectorX::Zero(n);
    for (int j = 0; j < n; ++j) bound(5 + j) = prop.walk_q_excursion(j, h);
    VectorX worst = VectorX::Zero(5 + n);
    for (int k = 1; k < 4000; ++k) {
      const double tau = h * k / 4000.0;
      const VectorX chord = f0 + (f1 - f0) * (tau / h);
      worst = worst.cwiseMax((functions(tau) - chord).cwiseAbs());
    }
    SCOPED_TRACE("trial " + std::to_string(trial));
    for (int j = 0; j < 5 + n; ++j) {
      EXPECT_LE(worst(j), bound(j) * (1.0 + 1e-9) + 1e-14) << "function " << j;
      if (worst(j) > 0.05 * bound(j)) ++tight;
    }
  }
  // and the bounds are not vacuous: most are within a factor 20 of the true excursion
  EXPECT_GT(tight, 40 * 6 / 2);
}

TEST(FullContactWalk, ReachBoundsHoldAtEveryPointOfRandomPieces) {
  // the claim that lets the walk skip a piece's evaluation (Simulator::walk_quiet): over a piece,
  // |F_I|, F_J, |R(0)| and each |q_j| stay within the bounds on the values themselves, and the
  // uplift functions above alpha_k min F_J - max|R(0)|. The bodies, states and forcing of the
  // excursion test; the functions by Dynamics at 4001 points of the exact solution.
  std::mt19937 rng(78u);
  int tight = 0, checks = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 1 + trial % 3;
    const bool swinging = trial >= 40;  // the last 20: Gamma's term counts
    RandomPiece piece(n, 600u + static_cast<unsigned>(trial), rng, swinging ? 0.3 : 0.02,
                      swinging ? kSwing : 0.0);
    ASSERT_TRUE(piece.prop.available());
    piece.walk();
    const Body& body = piece.body;
    const RandomPiece::Dyn& dyn = piece.dyn;
    const auto& prop = piece.prop;
    const RandomPiece::State& x = piece.x;
    const double h = piece.h;
    const BaseAcceleration a0 = piece.a0, slope = piece.slope;
    const double ax = std::max(std::abs(a0.x), std::abs(a0.x + slope.x * h)) / g;
    const double ay0 = 1.0 + a0.y / g, ay1 = 1.0 + (a0.y + slope.y * h) / g;
    const auto r = prop.walk_reach(ax, std::min(ay0, ay1), std::max(ay0, ay1));
    // the largest |F_I|, F_J, -F_J, |R(0)|, -U1, -U2 and |q_j| over the piece, and their bounds
    VectorX worst = VectorX::Constant(6 + n, -std::numeric_limits<double>::infinity());
    VectorX bound(6 + n);
    bound << r.fi, r.fj_hi, -r.fj_lo, r.moment, r.moment - body.alpha1() * r.fj_lo,
        r.moment - body.alpha2() * r.fj_lo, VectorX::Zero(n);
    for (int j = 0; j < n; ++j) bound(6 + j) = prop.walk_q_reach(j);
    for (int k = 0; k <= 4000; ++k) {
      const PieceReaction pr = reaction_at(dyn, prop, x, n, a0, slope, h * k / 4000.0);
      VectorX f(6 + n);
      f << std::abs(pr.r(0)), pr.r(1), -pr.r(1), std::abs(pr.moment), -pr.uplift(0), -pr.uplift(1),
          pr.q.cwiseAbs();
      worst = worst.cwiseMax(f);
    }
    SCOPED_TRACE("trial " + std::to_string(trial));
    for (int j = 0; j < 6 + n; ++j) {
      EXPECT_LE(worst(j), bound(j) + 1e-9 * (1.0 + std::abs(bound(j)))) << "function " << j;
      // not vacuous: the value's reach within twice its true one (about the forcing's level)
      ++checks;
      if (std::abs(bound(j)) < 2.0 * std::abs(worst(j)) + 1e-3) ++tight;
    }
  }
  EXPECT_GT(tight, checks / 2);
}

TEST(FullContactWalk, StiffModesWalkedAWholeIntervalAtATimeMatchTheSteppedPath) {
  // modes up to 500 Hz: 31 rad of the fastest mode's phase per 10 ms piece of the walk (20 steps
  // of the stepped path, whose phase cap is 1.5 rad). The guards' bound then takes the fast
  // modes by their amplitude, not their curvature; the energies come from the pieces' ends.
  for (int n : {2, 3}) {
    for (double amplitude : {0.02, 0.6}) {
      const unsigned seed = 4100u + static_cast<unsigned>(n) + (amplitude > 0.1 ? 7u : 0u);
      std::vector<double> hz{3.0, 500.0};
      if (n == 3) hz = {1.5, 40.0, 500.0};
      BodyParameters p = test::random_coupled(hz, seed).params();
      p.damping.kind = DampingKind::kModal;
      p.damping.modal_ratios = VectorX::LinSpaced(n, 0.02, 0.05);
      const Body body(p);
      const GroundMotion m = random_record(seed, amplitude, 3.0, true);
      SCOPED_TRACE("n = " + std::to_string(n) + ", amplitude " + std::to_string(amplitude));
      const SimulationResult wk = walk::run(body, m, 0, 0.0137), st = walk::run(body, m, 1, 0.0137);
      ASSERT_EQ(wk.status, st.status);
      EXPECT_NEAR(wk.extremes.first_uplift_time, st.extremes.first_uplift_time, 1e-12);
      EXPECT_EQ(wk.extremes.first_uplift_edge, st.extremes.first_uplift_edge);
      const double t_end =
          st.extremes.first_uplift_time > 0.0 ? st.extremes.first_uplift_time - 1e-6 : -1.0;
      const SimulationResult wkc = walk::run(body, m, 0, 0.0137, {}, t_end),
                             stc = walk::run(body, m, 1, 0.0137, {}, t_end);
      // below uplift, one piece per record interval against ~20 steps
      if (amplitude < 0.1) {
        ASSERT_EQ(st.extremes.first_uplift_time, -1.0);
        EXPECT_LT(wkc.steps * 10, stc.steps);
      }
      compare_walk_with_steps(body, wkc, stc);
    }
  }
}

TEST(FullContactWalk, LocatedExtremesBoundEverySampleOfTheExactSolution) {
  // rows every 0.1 ms are the exact solution at those times: the located max|q| is above every
  // one of them, and within the rows' spacing of the largest. Under a random record the reactions
  // of one mode peak at its samples, the kinks of the forcing, where the walk evaluates anyway;
  // an undamped body vibrating on a floor at rest (an all-zero record, from a deformed and moving
  // start) has its peaks inside the record's intervals, which only the search
  // (Simulator::largest_near) finds: with the search skipped, n = 1 fails here on the shear, the
  // moment and the friction demand, and under the random record on max|q| alone. A wrong rate
  // sends the search to its fallback on the values, which finds the same peaks: the rates
  // themselves are ReactionRatesAreTheRatesOfTheReactionAlongTheMotion's to check
  for (const int n : {1, 3, -1, -3}) {
    const bool vibrating = n < 0;
    const int modes = std::abs(n);
    SCOPED_TRACE(std::string(vibrating ? "free vibration" : "random record") + ", n " +
                 std::to_string(modes));
    const Body body = damped_body(modes, 900u + static_cast<unsigned>(modes), vibrating ? 0 : 1);
    const std::vector<double> rest(201, 0.0);  // 2 s at 0.01 s
    const GroundMotion m = vibrating
                               ? GroundMotion::uniform(0.01, rest, rest)
                               : random_record(910u + static_cast<unsigned>(n), 0.02, 2.0, true);
    InitialState init;
    if (vibrating) {
      const VectorX q0 = body.static_deformation();
      init.q = 1.5 * q0;
      init.q_dot = 0.5 * q0.cwiseAbs() * body.natural_frequencies()(0);
    }
    const SimulationResult wk = walk::run(body, m, 0, 1e-4, init);
    ASSERT_EQ(wk.extremes.first_uplift_time, -1.0);
    const double qs = wk.extremes.max_abs_q.maxCoeff();
    for (int i = 0; i < modes; ++i) {
      double rows = 0.0;
      for (std::size_t k = static_cast<std::size_t>(i); k < wk.history.q.size();
           k += static_cast<std::size_t>(modes))
        rows = std::max(rows, std::abs(wk.history.q[k]));
      EXPECT_GE(wk.extremes.max_abs_q(i), rows - 1e-13 * qs);
      const double w = body.natural_frequencies().maxCoeff();
      EXPECT_LE(wk.extremes.max_abs_q(i) - rows, 0.5 * std::pow(w * 1e-4, 2) * qs);
    }
    // and so are the base shear, the moment about the c.g. projection and the friction demand:
    // above every row, and within what the rows' spacing can miss of the largest (the forcing
    // is linear between the record's samples, so these have kinks there: a first-order miss)
    const History& hs = wk.history;
    double shear = 0.0, moment = 0.0, demand = 0.0;
    for (std::size_t k = 0; k < hs.size(); ++k) {
      shear = std::max(shear, std::abs(hs.reaction_x[k]));
      moment = std::max(moment, std::abs(hs.resultant[k] * hs.reaction_y[k]));
      demand = std::max(demand, hs.friction_demand[k]);
    }
    const Extremes& ex = wk.extremes;
    EXPECT_GE(ex.max_base_shear, shear * (1.0 - 1e-13));
    EXPECT_GE(ex.max_overturning_moment, moment * (1.0 - 1e-13));
    EXPECT_GE(ex.max_friction_demand, demand * (1.0 - 1e-13));
    EXPECT_LE(ex.max_base_shear, shear * (1.0 + 1e-3));
    EXPECT_LE(ex.max_overturning_moment, moment * (1.0 + 1e-3));
    EXPECT_LE(ex.max_friction_demand, demand * (1.0 + 1e-3));
  }
}

TEST(FullContactWalk, DerivativesOfQAreTheExactSolutionsRates) {
  // q', q'', q''' and q'''' at a point of a piece (ContactPropagator::walk_q_derivatives, from
  // the modes' equation) against central differences of the exact q, q' and q'' there; q and q'
  // themselves against the piece's dense output
  using Dyn = Dynamics<Eigen::Dynamic, 16>;
  using State = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 64, 1>;
  for (int n : {1, 3}) {
    const Body body = damped_body(n, 1200u + static_cast<unsigned>(n), n == 1 ? 1 : 2);
    const Dyn dyn(body);
    const GroundMotion motion = random_record(1210u + static_cast<unsigned>(n), 0.1, 1.0, true);
    detail::ContactPropagator<Eigen::Dynamic, 16, State> prop(dyn, motion, 4, 0.01, true);
    ASSERT_TRUE(prop.available());
    State x = State::Zero(2 * n + 11);
    const VectorX q0 = body.static_deformation();
    for (int i = 0; i < n; ++i) {
      x(1 + i) = 1.3 * q0(i);
      x(n + 2 + i) = 0.4 * std::abs(q0(i)) * body.natural_frequencies()(0);
    }
    const double h = 0.02;
    prop.walk_start(x);
    prop.walk_piece(h, {0.2 * g, -0.1 * g}, {5.0 * g, 3.0 * g}, false);
    std::array<Dyn::Vec, 5> d, dm, dp;
    for (auto* a : {&d, &dm, &dp})
      for (Dyn::Vec& v : *a) v.setZero(n);
    // inside the piece; at a kept point, its start and its end, where the piece's own steps
    // and end state give s (the neighbours at +-e are computed)
    for (const double tau : {0.37 * h, 3.0 * h / 8.0, 0.0, h}) {
      const double e = 1e-5 * h;
      prop.walk_q_derivatives(tau, d);
      prop.walk_q_derivatives(tau - e, dm);
      prop.walk_q_derivatives(tau + e, dp);
      State xs = x;
      prop.walk_dense(tau, xs);
      for (int i = 0; i < n; ++i) {
        SCOPED_TRACE("n " + std::to_string(n) + " tau/h " + std::to_string(tau / h) + " i " +
                     std::to_string(i));
        EXPECT_NEAR(d[0](i), xs(1 + i), 1e-12 * std::abs(xs(1 + i)));
        EXPECT_NEAR(d[1](i), xs(n + 2 + i), 1e-12 * d[1].cwiseAbs().maxCoeff());
        for (std::size_t k = 1; k < 5; ++k) {
          const double fd = (dp[k - 1](i) - dm[k - 1](i)) / (2.0 * e);
          EXPECT_NEAR(d[k](i), fd, 1e-6 * d[k].cwiseAbs().maxCoeff()) << "derivative " << k;
        }
      }
    }
  }
}

TEST(FullContactWalk, ReactionRatesAreTheRatesOfTheReactionAlongTheMotion) {
  // Dynamics::full_contact_reaction_rates along the exact motion of a piece: its values are
  // full_contact_reaction and contact_moments at (q, q'' of the equations of motion), its first
  // derivatives their central differences, its second derivatives those of its first. Coupled
  // bodies (Gamma != 0 from two modes on), so every term of the moment's rates counts
  using Dyn = Dynamics<Eigen::Dynamic, 16>;
  using State = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 64, 1>;
  for (int n : {1, 2, 3}) {
    std::vector<double> hz{2.0, 9.0, 31.0};
    hz.resize(static_cast<std::size_t>(n));
    BodyParameters p = test::random_coupled(hz, 1300u + static_cast<unsigned>(n), 0.02).params();
    p.damping.kind = DampingKind::kModal;
    p.damping.modal_ratios = VectorX::Constant(n, 0.05);
    const Body body(p);
    const Dyn dyn(body);
    if (n > 1) {
      ASSERT_GT(dyn.gamma().norm(), 0.0);
    }
    const GroundMotion motion = random_record(1310u + static_cast<unsigned>(n), 0.1, 1.0, true);
    detail::ContactPropagator<Eigen::Dynamic, 16, State> prop(dyn, motion, 4, 0.01, true);
    ASSERT_TRUE(prop.available());
    State x = State::Zero(2 * n + 11);
    const VectorX q0 = body.static_deformation();
    for (int i = 0; i < n; ++i) {
      x(1 + i) = (1.5 - 0.4 * i) * q0(i);
      x(n + 2 + i) = 3.0 * std::abs(q0(i)) * body.natural_frequencies()(0);
    }
    const double h = 0.02;
    const BaseAcceleration a0{0.3 * g, -0.2 * g}, rate{8.0 * g, 5.0 * g};
    prop.walk_start(x);
    prop.walk_piece(h, a0, rate, false);
    std::array<Dyn::Vec, 5> d;
    for (Dyn::Vec& v : d) v.setZero(n);
    auto rates = [&](double tau) {
      prop.walk_q_derivatives(tau, d);
      return dyn.full_contact_reaction_rates(d, prop.walk_base(tau), rate);
    };
    // F_I, F_J, R(0) at tau from the state, as evaluate() forms them
    auto direct = [&](double tau) {
      const PieceReaction pr = reaction_at(dyn, prop, x, n, a0, rate, tau);
      return Eigen::Vector3d(pr.r(0), pr.r(1), pr.moment);
    };
    for (double f : {0.13, 0.5, 0.91}) {
      const double tau = f * h, e = 1e-5 * h;
      const auto r = rates(tau), rm = rates(tau - e), rp = rates(tau + e);
      const Eigen::Vector3d v = direct(tau), fd = (direct(tau + e) - direct(tau - e)) / (2.0 * e);
      const std::array<std::array<double, 3>, 3> jet{r.fi, r.fj, r.moment},
          jm{rm.fi, rm.fj, rm.moment}, jp{rp.fi, rp.fj, rp.moment};
      for (int k = 0; k < 3; ++k) {
        SCOPED_TRACE("n " + std::to_string(n) + " tau/h " + std::to_string(f) + " quantity " +
                     std::to_string(k));
        const auto kk = static_cast<std::size_t>(k);
        const double fd2 = (jp[kk][1] - jm[kk][1]) / (2.0 * e);
        EXPECT_NEAR(jet[kk][0], v(k), 1e-12 * (1.0 + std::abs(v(k))));
        EXPECT_NEAR(jet[kk][1], fd(k), 1e-6 * (std::abs(fd(k)) + std::abs(jet[kk][0]) / h));
        EXPECT_NEAR(jet[kk][2], fd2, 1e-6 * (std::abs(fd2) + std::abs(jet[kk][1]) / h));
      }
    }
  }
}

TEST(FullContactWalk, FindsAnUpliftBetweenSamplesThatTheSamplesDoNotShow) {
  // an oscillator (8 Hz) on a slab, thrown from its static state by q_dot0 under a record of
  // zero acceleration sampled every 20 ms (one walk piece, 1 rad of the mode's phase): the
  // uplift function dips to its minimum at 1/4 period, 31 ms, between the samples at 20 and
  // 40 ms where it is well positive. The walk's bound must see the dip; the crossing is where
  // the tight integration puts it.
  const Body body(oscillator_on_slab(1000.0, 8.0, 500.0, 2.0, 0.8, 0.0));
  const std::vector<double> zero(11, 0.0);
  const GroundMotion m = GroundMotion::uniform(0.02, zero, zero);
  auto start = [&](double v) {
    InitialState init;
    init.q = body.static_deformation();
    init.q_dot = VectorX::Constant(1, v);
    return init;
  };
  auto uplifts = [&](double v) {
    const SimulationResult r = walk::run(body, m, 2, 0.0, start(v), 0.05);
    return r.extremes.first_uplift_time > 0.0;
  };
  // the least q_dot0 that uplifts within 50 ms, by bisection on the tight integration
  double lo = 0.0, hi = 1.0;
  while (!uplifts(hi)) hi *= 2.0;
  for (int k = 0; k < 50; ++k) (uplifts(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
  const double v_up = hi * (1.0 + 1e-4), v_down = lo * (1.0 - 1e-4);
  // just below: no uplift, and at the samples the resultant is well inside the base
  const SimulationResult below = walk::run(body, m, 0, 0.02, start(v_down), 0.05);
  ASSERT_EQ(below.extremes.first_uplift_time, -1.0);
  const double h = body.params().height, a1 = body.alpha1(), a2 = body.alpha2();
  for (std::size_t k = 0; k < below.history.size(); ++k) {
    const double r = below.history.resultant[k] / h;
    EXPECT_GT(r + a1, 0.02 * (a1 + a2)) << "t = " << below.history.time[k];
    EXPECT_GT(a2 - r, 0.02 * (a1 + a2)) << "t = " << below.history.time[k];
  }
  // just above: the walk finds the uplift between the samples, where the integration does
  const SimulationResult wk = walk::run(body, m, 0, 0.0, start(v_up), 0.05);
  const SimulationResult in = walk::run(body, m, 2, 0.0, start(v_up), 0.05);
  ASSERT_GT(in.extremes.first_uplift_time, 0.02);
  ASSERT_LT(in.extremes.first_uplift_time, 0.04);
  EXPECT_NEAR(wk.extremes.first_uplift_time, in.extremes.first_uplift_time, 1e-6);
  EXPECT_EQ(wk.extremes.first_uplift_edge, in.extremes.first_uplift_edge);
}

}  // namespace
}  // namespace flexrock
