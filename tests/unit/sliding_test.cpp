// SPDX-License-Identifier: BSD-3-Clause
// Coulomb friction at the base (docs/theory.md, "Sliding"), each against something independent:
// closed-form slip distances, the exact piecewise solution under a half-sine pulse, an event-exact
// sliding block written here under a sampled record, the regime at initiation on both sides of its
// thresholds, and the energy balance with the friction work.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/excitation/pulses.hpp"
#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

constexpr double g = kStandardGravity;

SimulationOptions with_friction(double mu_s,
                                double mu_k = std::numeric_limits<double>::infinity()) {
  SimulationOptions o;
  o.friction_coefficient = mu_s;
  o.kinetic_friction_coefficient = mu_k;
  return o;
}

long count(const SimulationResult& r, EventKind k) {
  return std::count_if(r.events.begin(), r.events.end(),
                       [&](const Event& e) { return e.kind == k; });
}

double first_time(const SimulationResult& r, EventKind k) {
  for (const Event& e : r.events)
    if (e.kind == k) return e.time;
  return -1.0;
}

// a squat block (b/h = 2): it cannot uplift below 2 g, so it only slides
Body squat_block() { return Body(BodyParameters::rectangular_block(100.0, 1.0, 0.5)); }

// Rectangular pulse A over t1: the base leaves the block behind at A - mu g, then friction stops
// the slip at mu g: |d| = A (A - mu g) t1^2 / (2 mu g), over t1 A / (mu g), friction work mu M g
// |d|.
TEST(Sliding, RectangularPulseSlidesTheClosedFormDistance) {
  const Body body = squat_block();
  const double t1 = 0.5;
  for (double A_g : {0.35, 0.6, 1.2}) {
    for (auto [mu_s, mu_k] : {std::pair{0.3, 0.3}, std::pair{0.3, 0.2}}) {
      const double A = A_g * g;
      const auto r = simulate(body, rectangular_pulse(A, t1, 4.0), {}, with_friction(mu_s, mu_k));
      ASSERT_EQ(r.status, Status::kCompleted) << r.message;
      const double d = A * (A - mu_k * g) * t1 * t1 / (2.0 * mu_k * g);
      EXPECT_NEAR(r.final_offset, -d, 1e-12 * d) << A_g << " " << mu_k;
      EXPECT_NEAR(r.extremes.max_offset, d, 1e-12 * d);
      EXPECT_NEAR(r.extremes.sliding_time, t1 * A / (mu_k * g), 1e-12);
      EXPECT_NEAR(r.energy.friction_loss, mu_k * 100.0 * g * d, 1e-9 * d);
      EXPECT_LT(std::abs(r.energy.residual), 1e-9 * r.energy.scale);
      EXPECT_EQ(count(r, EventKind::kSlipStart), 1);
      EXPECT_EQ(count(r, EventKind::kStick), 1);
      EXPECT_EQ(r.final_phase, ContactMode::kFullContact);
    }
  }
  // below the static coefficient nothing moves
  const auto still = simulate(body, rectangular_pulse(0.29 * g, t1, 2.0), {}, with_friction(0.3));
  EXPECT_EQ(still.final_offset, 0.0);
  EXPECT_EQ(count(still, EventKind::kSlipStart), 0);
}

// Half-sine pulse A sin(w t), t <= pi/w: the slip starts at sin(w ts) = mu g / A; with the slip
// negative, d'' = mu g - a(t), integrated in closed form; it stops where d' = 0 (found here by
// bisection on the closed form), possibly after the pulse, where d'' = mu g.
TEST(Sliding, HalfSinePulseMatchesTheExactPiecewiseSolution) {
  const Body body = squat_block();
  const double w = 2.0 * M_PI, te = M_PI / w;
  for (double A_g : {0.4, 0.8, 1.5}) {
    const double mu = 0.25, A = A_g * g, mg = mu * g;
    const double ts = std::asin(mg / A) / w;
    auto v_in = [&](double t) {  // during the pulse
      return mg * (t - ts) + A / w * (std::cos(w * t) - std::cos(w * ts));
    };
    auto d_in = [&](double t) {
      return 0.5 * mg * (t - ts) * (t - ts) + A / (w * w) * (std::sin(w * t) - std::sin(w * ts)) -
             A / w * std::cos(w * ts) * (t - ts);
    };
    double d_end = 0.0, t_stop = 0.0;
    if (v_in(te) < 0.0) {
      // still sliding when the pulse ends: uniform deceleration at mu g
      const double v = v_in(te);
      t_stop = te - v / mg;
      d_end = d_in(te) - v * v / (2.0 * mg);
    } else {
      // stops within the pulse: the first root of v_in after the slip started
      double lo = ts + 1e-9, hi = te;
      while (!(v_in(lo) < 0.0)) lo = ts + 2.0 * (lo - ts);
      for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (v_in(mid) < 0.0 ? lo : hi) = mid;
      }
      t_stop = 0.5 * (lo + hi);
      d_end = d_in(t_stop);
    }
    const auto r = simulate(body, half_sine_pulse(A, w, 4.0), {}, with_friction(mu));
    ASSERT_EQ(r.status, Status::kCompleted) << r.message;
    EXPECT_NEAR(first_time(r, EventKind::kSlipStart), ts, 1e-12) << A_g;
    EXPECT_NEAR(first_time(r, EventKind::kStick), t_stop, 1e-9) << A_g;
    EXPECT_NEAR(r.final_offset, d_end, 1e-10 * std::abs(d_end)) << A_g;
  }
}

// The nine pulses of docs/theory.md §20, whose final offsets the derivation script computes from
// the exact piecewise solution (tools/derive/derive.py, `sliding_pulses`; values to 9 digits).
TEST(Sliding, PulsesMatchTheDerivationsPiecewiseSolution) {
  const Body body = squat_block();
  struct Case {
    int pulse;  // 0 rectangular, 1 half-sine (omega = pi / t1), 2 one-sine (omega = 2 pi / t1)
    double a_g, t1, mu_s, mu_k, d;
  };
  const Case cases[] = {
      {0, 0.5, 0.5, 0.2, 0.2, -0.919373438},   {0, 0.5, 0.5, 0.2, 0.15, -1.43013646},
      {0, 0.3, 1.0, 0.1, 0.1, -2.941995},      {1, 0.5, 0.5, 0.2, 0.2, -0.28084858},
      {1, 0.5, 0.5, 0.2, 0.15, -0.470931988},  {1, 0.3, 1.0, 0.1, 0.1, -0.951890693},
      {2, 0.5, 0.5, 0.2, 0.2, -0.00510400575}, {2, 0.5, 0.5, 0.2, 0.15, -0.0237802786},
      {2, 0.3, 1.0, 0.1, 0.1, -0.0401884643}};
  for (const Case& c : cases) {
    const double A = c.a_g * g, duration = 8.0;
    const GroundMotion m = c.pulse == 0   ? rectangular_pulse(A, c.t1, duration)
                           : c.pulse == 1 ? half_sine_pulse(A, M_PI / c.t1, duration)
                                          : one_sine_pulse(A, 2 * M_PI / c.t1, duration);
    const auto r = simulate(body, m, {}, with_friction(c.mu_s, c.mu_k));
    ASSERT_EQ(r.status, Status::kCompleted) << r.message;
    // the references are printed to 9 significant digits
    EXPECT_NEAR(r.final_offset, c.d, 1e-10 + 2e-9 * std::abs(c.d)) << c.pulse << " " << c.mu_k;
  }
}

// An event-exact sliding block written independently of the engine: under a record linear between
// samples the slip acceleration -a(t) - s mu_k g is linear, so the slip velocity is quadratic and
// the offset cubic in each interval; slip starts where |a| crosses mu_s g (linear), stops at the
// first root of the quadratic, and then sticks if |a| < mu_s g there, else reverses.
struct SlidingBlock {
  double mu_s, mu_k;
  double d = 0.0, v = 0.0, max_abs_d = 0.0;
  int s = 0;  // slip sign, 0 sticking
  long slips = 0;

  void run(const std::vector<double>& t, const std::vector<double>& a) {
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
      double t0 = t[i];
      const double k = (a[i + 1] - a[i]) / (t[i + 1] - t[i]);
      auto acc = [&](double tt) { return a[i] + k * (tt - t[i]); };
      while (t0 < t[i + 1]) {
        if (s == 0) {
          // the first time in [t0, t1] where |a| >= mu_s g
          const double lim = mu_s * g;
          double tc = -1.0;
          if (std::abs(acc(t0)) >= lim) {
            tc = t0;
          } else if (k != 0.0) {
            for (double target : {lim, -lim}) {
              const double tt = t[i] + (target - a[i]) / k;
              if (tt > t0 && tt <= t[i + 1] && (tc < 0.0 || tt < tc)) tc = tt;
            }
          }
          if (tc < 0.0) break;
          s = acc(tc) > 0.0 ? -1 : 1;
          ++slips;
          t0 = tc;
          continue;
        }
        // slipping: v(tau) = v0 + c1 tau + c2 tau^2, c1 = -(a(t0) + s mu_k g), c2 = -k / 2
        const double c1 = -(acc(t0) + s * mu_k * g), c2 = -0.5 * k;
        const double h = t[i + 1] - t0;
        double tau = h;
        bool stops = false;
        // smallest root in (0, h] of s v(tau) = 0
        std::vector<double> roots;
        if (c2 == 0.0) {
          if (c1 != 0.0) roots.push_back(-v / c1);
        } else {
          const double disc = c1 * c1 - 4.0 * c2 * v;
          if (disc >= 0.0) {
            const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
            if (q != 0.0) roots.push_back(q / c2);
            if (q != 0.0) roots.push_back(v / q);
          }
        }
        for (double rt : roots) {
          if (rt > 1e-15 && rt <= tau) {
            tau = rt;
            stops = true;
          }
        }
        d += v * tau + 0.5 * c1 * tau * tau + c2 * tau * tau * tau / 3.0;
        max_abs_d = std::max(max_abs_d, std::abs(d));
        v = stops ? 0.0 : v + c1 * tau + c2 * tau * tau;
        t0 += tau;
        if (stops) {
          const double at = acc(t0);
          if (std::abs(at) < mu_s * g) {
            s = 0;
          } else {
            const int ns = at > 0.0 ? -1 : 1;
            if (ns != s) ++slips;
            s = ns;
          }
        }
      }
    }
  }
};

TEST(Sliding, SampledRecordMatchesAnEventExactSlidingBlock) {
  const Body body = squat_block();
  for (unsigned seed : {1u, 2u, 3u}) {
    // a random record: 12 s at 100 Hz, a sum of sines with a random-walk envelope, PGA ~ 0.6 g
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double dt = 0.01;
    std::vector<double> t, a;
    std::vector<double> f(6), ph(6), amp(6);
    for (int j = 0; j < 6; ++j) {
      f[static_cast<std::size_t>(j)] = 0.3 + 6.0 * u(rng);
      ph[static_cast<std::size_t>(j)] = 2 * M_PI * u(rng);
      amp[static_cast<std::size_t>(j)] = 0.1 + 0.2 * u(rng);
    }
    for (int i = 0; i <= 1200; ++i) {
      const double ti = i * dt;
      double ai = 0.0;
      for (std::size_t j = 0; j < 6; ++j) ai += amp[j] * std::sin(2 * M_PI * f[j] * ti + ph[j]);
      t.push_back(ti);
      a.push_back(g * ai * std::sin(M_PI * ti / 12.0));
    }
    for (auto [mu_s, mu_k] : {std::pair{0.2, 0.2}, std::pair{0.3, 0.22}}) {
      SlidingBlock ref{mu_s, mu_k};
      ref.run(t, a);
      const auto r = simulate(body, GroundMotion::sampled(t, a, {}), {}, with_friction(mu_s, mu_k));
      ASSERT_EQ(r.status, Status::kCompleted) << r.message;
      ASSERT_GT(ref.slips, 3) << "the record must make the block slide";
      EXPECT_NEAR(r.final_offset, ref.d, 1e-9 * std::max(1.0, ref.max_abs_d)) << seed;
      EXPECT_NEAR(r.extremes.max_offset, ref.max_abs_d, 1e-9 * std::max(1.0, ref.max_abs_d));
      EXPECT_EQ(r.extremes.slips, ref.slips) << seed;
      EXPECT_LT(std::abs(r.energy.residual), 1e-9 * r.energy.scale);
    }
  }
}

// A rigid block under a step of acceleration a g (a long rectangular pulse), a_y = 1, against the
// regimes at initiation of docs/theory.md §20: rest for a <= min(mu, alpha); a slide for mu < alpha
// < ... and a > mu; for mu >= alpha and a > alpha, rocking on a sticking pivot up to a* = (mu (1 +
// zeta^2) - alpha) / (zeta^2 + alpha^2 - mu alpha) (always when mu >= (zeta^2 + alpha^2) / alpha),
// rocking with the pivot sliding above it.
TEST(Sliding, RegimeAtInitiationOnBothSidesOfItsThresholds) {
  for (double alpha : {0.25, 0.5, 1.0}) {
    const Body body(BodyParameters::rectangular_block(100.0, alpha * 0.5, 0.5));
    const double z2 = (1.0 + alpha * alpha) / 3.0;  // uniform block
    for (double mu : {0.5 * alpha, 0.9 * alpha, 1.1 * alpha, 1.6 * alpha}) {
      const double a_star = (mu * (1.0 + z2) - alpha) / (z2 + alpha * alpha - mu * alpha);
      const bool always_rocks = mu >= (z2 + alpha * alpha) / alpha;
      std::vector<double> levels = {0.9 * std::min(mu, alpha), 1.05 * mu, 1.05 * alpha,
                                    0.95 * alpha + 0.05 * mu, 1.5 * std::max(mu, alpha)};
      if (!always_rocks && a_star > alpha) {
        levels.push_back(0.98 * a_star);
        levels.push_back(1.02 * a_star);
      }
      for (double a : levels) {
        const auto r = simulate(body, rectangular_pulse(a * g, 0.02, 0.02), {}, with_friction(mu));
        ASSERT_NE(r.status, Status::kStopped) << r.message;
        const bool rest = a <= std::min(mu, alpha);
        const bool slide = mu < alpha && a > mu;
        const bool rock = mu >= alpha && a > alpha && (always_rocks || a <= a_star);
        const bool slide_rock = mu >= alpha && a > alpha && !always_rocks && a > a_star;
        const std::string what = "alpha " + std::to_string(alpha) + " mu " + std::to_string(mu) +
                                 " a " + std::to_string(a);
        const double up = first_time(r, EventKind::kUplift),
                     slip = first_time(r, EventKind::kSlipStart);
        if (rest) {
          EXPECT_TRUE(r.events.empty()) << what;
        }
        if (slide) {
          EXPECT_EQ(slip, 0.0) << what;
          EXPECT_EQ(up, -1.0) << what;
        }
        if (rock) {
          EXPECT_EQ(up, 0.0) << what;
          EXPECT_EQ(slip, -1.0) << what;
        }
        if (slide_rock) {
          EXPECT_EQ(up, 0.0) << what;
          EXPECT_EQ(slip, 0.0) << what;
          EXPECT_TRUE(r.final_phase != ContactMode::kFullContact) << what;
        }
      }
    }
  }
}

// The friction work closes the balance, with no energy gained at any event, for rigid blocks that
// rock and slide and for flexible bodies that slide, rock and fly.
TEST(Sliding, EnergyBalanceClosesWithFrictionWork) {
  std::vector<Body> bodies;
  bodies.emplace_back(BodyParameters::rectangular_block(1000.0, 0.25, 1.0));
  bodies.emplace_back(oscillator_on_slab(500.0, 3.0, 500.0, 2.0, 1.0, 0.02));
  bodies.emplace_back(uniform_cantilever(6.0, 2.0, 2000.0, 7.5e7, 2, 2000.0, 0.02));
  for (const Body& body : bodies) {
    for (double mu : {0.1, 0.2, 0.3}) {
      for (double ag : {0.3, 0.6}) {
        const auto r = simulate(body, one_sine_pulse(ag * g, 2 * M_PI * 2.0, 3.0), {},
                                with_friction(mu, 0.8 * mu));
        EXPECT_NE(r.status, Status::kStopped) << r.message;
        EXPECT_FALSE(r.energy_unbalanced)
            << body.modes() << " " << mu << " " << ag << " " << r.energy.residual;
        EXPECT_FALSE(r.impact_gained_energy);
        EXPECT_GE(r.energy.friction_loss, 0.0);
        for (const Event& e : r.events) EXPECT_GE(e.energy_loss, -1e-9 * r.energy.scale);
        if (ag > mu) {
          EXPECT_GT(r.extremes.slips, 0);
          EXPECT_GT(r.energy.friction_loss, 0.0);
        }
      }
    }
  }
}

// A floor whose friction is never reached takes the same path as one without a limit, bit for bit:
// the friction guards, cone checks and slip bookkeeping change nothing while the base sticks. The
// one exception is physical: where the pivot force vanishes with a sideways force left
// (pivot_tension without friction) the demand grows without bound, so any finite coefficient is
// reached and the pivot slides just before.
TEST(Sliding, UnreachedFrictionChangesNothing) {
  std::vector<Body> bodies;
  bodies.emplace_back(BodyParameters::rectangular_block(1000.0, 0.25, 1.0));
  bodies.emplace_back(oscillator_on_slab(500.0, 3.0, 500.0, 2.0, 1.0, 0.02));
  bodies.emplace_back(uniform_cantilever(6.0, 2.0, 2000.0, 7.5e7, 2, 2000.0, 0.02));
  int identical = 0, tension = 0;
  for (const Body& body : bodies) {
    SimulationOptions none;
    none.output_dt = 0.01;
    SimulationOptions held = none;
    held.friction_coefficient = 1e6;
    const GroundMotion m = one_sine_pulse(0.6 * g, 2 * M_PI * 2.0, 3.0);
    const auto a = simulate(body, m, {}, none), b = simulate(body, m, {}, held);
    EXPECT_GT(a.extremes.impacts + a.extremes.lift_offs, 0) << "the run must rock";
    if (a.pivot_tension) {
      ++tension;
      const double t_tension = [&] {
        for (const Event& e : a.events)
          if (e.kind == EventKind::kPivotTension) return e.time;
        return -1.0;
      }();
      EXPECT_FALSE(b.pivot_tension);
      EXPECT_NEAR(first_time(b, EventKind::kSlipStart), t_tension, 1e-6);
      EXPECT_LE(first_time(b, EventKind::kSlipStart), t_tension);
      continue;
    }
    ++identical;
    ASSERT_EQ(a.events.size(), b.events.size());
    if (body.modes() == 0) {
      // a rigid body's rocking series bounds its guards over whole steps without a friction
      // limit and samples them at max_step with one (|F_I| is no polynomial): the same motion to
      // the integration's tolerance (rtol 1e-9 over 3 s), not to the bit
      const double mg = body.params().mass * g;
      for (std::size_t i = 0; i < a.events.size(); ++i) {
        EXPECT_EQ(a.events[i].kind, b.events[i].kind);
        EXPECT_NEAR(a.events[i].time, b.events[i].time, 1e-8);
        EXPECT_NEAR(a.events[i].theta_dot_after, b.events[i].theta_dot_after, 1e-8);
      }
      ASSERT_EQ(a.history.size(), b.history.size());
      for (std::size_t i = 0; i < a.history.size(); ++i) {
        EXPECT_NEAR(a.history.theta[i], b.history.theta[i], 1e-8);
        EXPECT_NEAR(a.history.reaction_x[i], b.history.reaction_x[i], 1e-8 * mg);
      }
      EXPECT_EQ(a.history.offset, b.history.offset);
      continue;
    }
    for (std::size_t i = 0; i < a.events.size(); ++i) {
      EXPECT_EQ(a.events[i].kind, b.events[i].kind);
      EXPECT_EQ(a.events[i].time, b.events[i].time);
      EXPECT_EQ(a.events[i].theta_dot_after, b.events[i].theta_dot_after);
    }
    EXPECT_EQ(a.history.theta, b.history.theta);
    EXPECT_EQ(a.history.q, b.history.q);
    EXPECT_EQ(a.history.reaction_x, b.history.reaction_x);
    EXPECT_EQ(a.history.offset, b.history.offset);
    EXPECT_EQ(a.energy.residual, b.energy.residual);
  }
  EXPECT_EQ(identical, 2);
  EXPECT_EQ(tension, 1);
}

TEST(Sliding, KineticAboveStaticIsRefused) {
  SimulationOptions o = with_friction(0.2, 0.3);
  EXPECT_THROW(simulate(squat_block(), GroundMotion::none(1.0), {}, o), InputError);
}

}  // namespace
}  // namespace flexrock
