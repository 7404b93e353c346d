// SPDX-License-Identifier: BSD-3-Clause
// A rigid block on a support that moves with it (docs/theory.md §24), against independent
// references: the rigid floor's engine as the support stiffens, the closed-form SDOF when the
// block never uplifts, the transmissibility's uplift threshold, the energy balance, mirror
// symmetry, and the refusals of what is not modelled.
#include "flexrock/sim/support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "flexrock/contact/support_impact.hpp"
#include "flexrock/core/error.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {
namespace {

constexpr double kPi = std::numbers::pi;

// a one-sine pulse of amplitude a [m/s^2] and period tp [s], then rest until `duration`
GroundMotion one_sine(double a, double tp, double duration, bool vertical_too = false,
                      double ay = 0.0) {
  return GroundMotion::analytic(
      [=](double t) {
        BaseAcceleration b;
        if (t >= 0.0 && t <= tp) b.x = a * std::sin(2.0 * kPi * t / tp);
        if (vertical_too) b.y = ay;
        return b;
      },
      duration, {tp});
}

GroundMotion harmonic(double a, double f, double duration) {
  return GroundMotion::analytic(
      [=](double t) {
        return BaseAcceleration{a * std::sin(2.0 * kPi * f * t), 0.0};
      },
      duration);
}

const Event* first_of(const SimulationResult& r, EventKind k) {
  for (const Event& e : r.events)
    if (e.kind == k) return &e;
  return nullptr;
}

// the largest tilt before the first impact
double peak_before_impact(const SimulationResult& r) {
  for (const Event& e : r.events) {
    if (e.kind == EventKind::kPeak) return std::abs(e.theta);
    if (e.kind == EventKind::kImpact) break;
  }
  return -1.0;
}

// uplift, rocking and a first impact under a one-sine pulse; then the first impact's ratio
TEST(Support, StiffeningSupportConvergesToTheRigidFloorUntilTheFirstImpact) {
  const Body body(BodyParameters::rectangular_block(1000.0, 0.2, 0.8));
  SimulationOptions o;
  o.rtol = 1e-11;
  o.atol = 1e-13;
  const GroundMotion m = one_sine(0.5 * 9.80665, 0.5, 3.0);
  const SimulationResult floor = simulate(body, m, {}, o);
  const Event* fi = first_of(floor, EventKind::kImpact);
  ASSERT_NE(fi, nullptr);
  ASSERT_GE(floor.extremes.first_uplift_time, 0.0);
  const double peak0 = peak_before_impact(floor);
  ASSERT_GT(peak0, 0.0);
  const double housner = fi->theta_dot_after / fi->theta_dot_before;
  std::printf("rigid floor: uplift %.12f s, peak %.12f rad, first impact %.12f s, ratio %.9f\n",
              floor.extremes.first_uplift_time, peak0, fi->time, housner);
  std::printf("%10s %12s %12s %12s %14s %14s\n", "f_h [Hz]", "d uplift", "d peak/peak", "d impact",
              "ratio-Housner", "ratio-coupled");
  std::vector<double> e_up, e_peak, e_imp, e_ratio;
  const double ms = 1000.0;
  for (const double f : {10.0, 30.0, 100.0, 300.0, 1000.0, 3000.0}) {
    const SupportParameters s = SupportParameters::from_frequency(ms, 1000.0, f, 0.05);
    const SupportRunResult r = simulate(body, s, m, {}, o);
    ASSERT_NE(r.body.status, Status::kStopped) << r.body.message;
    const Event* ri = first_of(r.body, EventKind::kImpact);
    ASSERT_NE(ri, nullptr);
    const double ratio = ri->theta_dot_after / ri->theta_dot_before;
    const double coupled =
        support_impact(1000.0, ms, body.params().zeta2, body.alpha2(), -body.alpha1()).ratio;
    e_up.push_back(std::abs(r.body.extremes.first_uplift_time - floor.extremes.first_uplift_time));
    e_peak.push_back(std::abs(peak_before_impact(r.body) - peak0) / peak0);
    e_imp.push_back(std::abs(ri->time - fi->time));
    e_ratio.push_back(std::abs(ratio - coupled));
    std::printf("%10g %12.3e %12.3e %12.3e %14.6f %14.3e\n", f, e_up.back(), e_peak.back(),
                e_imp.back(), ratio - housner, e_ratio.back());
  }
  // each quantity before the first impact converges, at second order in 1/f (1/k): a decade of
  // f gains about two of accuracy
  for (std::size_t i = 2; i < e_up.size(); ++i) {
    EXPECT_LT(e_up[i], 0.3 * e_up[i - 1]) << i;
    EXPECT_LT(e_peak[i], 0.3 * e_peak[i - 1]) << i;
    EXPECT_LT(e_imp[i], 0.3 * e_imp[i - 1]) << i;
  }
  EXPECT_LT(e_up.back(), 1e-6);
  EXPECT_LT(e_peak.back(), 1e-5);
  EXPECT_LT(e_imp.back(), 1e-5);
  // the impact does not converge to Housner's: the support's velocity jumps at any stiffness
  // (its spring gives no impulse), so the ratio is the coupled map's with m_s, whatever k
  for (const double er : e_ratio) EXPECT_LT(er, 1e-9);
  const double coupled =
      support_impact(1000.0, ms, body.params().zeta2, body.alpha2(), -body.alpha1()).ratio;
  EXPECT_GT(std::abs(coupled - housner), 1e-2);
}

// m_s -> 0 and a block that never uplifts: M u'' + c u' + k u = -M a(t), in closed form
TEST(Support, MasslessSupportUnderAStandingBlockIsTheClosedFormOscillator) {
  const Body body(BodyParameters::rectangular_block(500.0, 0.5, 0.5));  // wide: alpha = 1
  const double f = 1.3, z = 0.07, a = 0.2 * 9.80665, w = 2.0 * kPi * 2.1;
  const SupportParameters s = SupportParameters::from_frequency(0.0, 500.0, f, z);
  SimulationOptions o;
  o.rtol = 1e-13;
  o.atol = 1e-16;
  o.output_dt = 0.01;
  const SupportRunResult r = simulate(body, s, harmonic(a, 2.1, 6.0), {}, o);
  ASSERT_EQ(r.body.status, Status::kCompleted);
  ASSERT_LT(r.body.extremes.first_uplift_time, 0.0);
  // the closed form from rest: particular C sin + D cos, homogeneous damped free vibration
  const double wn = 2.0 * kPi * f, wd = wn * std::sqrt(1.0 - z * z);
  const double a11 = wn * wn - w * w, a12 = -2.0 * z * wn * w;
  const double det = a11 * a11 + a12 * a12;
  const double c_ = -a * a11 / det, d_ = -a * (2.0 * z * wn * w) / det * -1.0;
  // check the particular solution's equations: a11 C + a12 D = -a, -a12 C + a11 D = 0
  ASSERT_NEAR(a11 * c_ + a12 * d_, -a, 1e-12 * a);
  ASSERT_NEAR(-a12 * c_ + a11 * d_, 0.0, 1e-12 * a);
  const double e_ = -d_, f_ = (z * wn * e_ - c_ * w) / wd;
  double umax = 0.0, err = 0.0;
  const auto& h = r.body.history;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double t = h.time[i];
    const double u = c_ * std::sin(w * t) + d_ * std::cos(w * t) +
                     std::exp(-z * wn * t) * (e_ * std::cos(wd * t) + f_ * std::sin(wd * t));
    umax = std::max(umax, std::abs(u));
    err = std::max(err, std::abs(r.history.displacement[i] - u));
  }
  std::printf("massless support: max |u| = %.6e m, max error %.3e m\n", umax, err);
  EXPECT_LT(err, 1e-9 * umax);
  EXPECT_NEAR(r.support.max_displacement, umax, 1e-3 * umax);  // at samples and peaks
}

// the steady harmonic threshold of uplift: g alpha / |T(r)| (the transmissibility), found by the
// engine by bisection on the amplitude, started on the steady state
TEST(Support, UpliftThresholdInSteadyHarmonicMotionIsTheTransmissibilitys) {
  const Body body(BodyParameters::rectangular_block(800.0, 0.25, 1.0));
  const double m_s = 300.0, fs = 2.0, z = 0.1;
  SimulationOptions o;
  o.rtol = 1e-12;
  o.atol = 1e-15;
  for (const double f : {0.8, 1.9, 3.5}) {
    SupportParameters s = SupportParameters::from_frequency(m_s, 800.0, fs, z);
    const double wn = 2.0 * kPi * fs, w = 2.0 * kPi * f;
    // independent closed form: X'' = A sin(w t); the support's absolute acceleration has the
    // amplitude |1 + 2 i z r| / |1 - r^2 + 2 i z r| A
    const double r = f / fs;
    const std::complex<double> tr =
        std::complex<double>(1.0, 2.0 * z * r) / std::complex<double>(1.0 - r * r, 2.0 * z * r);
    const double a_star = 9.80665 * 0.25 / std::abs(tr);
    auto uplifts = [&](double a) {
      // the steady state: u = C sin + D cos with (wn^2 - w^2) C - 2 z wn w D = -a, ...
      const double a11 = wn * wn - w * w, a12 = -2.0 * z * wn * w, det = a11 * a11 + a12 * a12;
      const double c_ = -a * a11 / det, d_ = -a * a12 / det;
      s.displacement = d_;
      s.velocity = c_ * w;
      const SupportRunResult run = simulate(body, s, harmonic(a, f, 3.0 / f), {}, o);
      return run.body.extremes.first_uplift_time >= 0.0;
    };
    double lo = 0.9 * a_star, hi = 1.1 * a_star;
    ASSERT_FALSE(uplifts(lo));
    ASSERT_TRUE(uplifts(hi));
    for (int i = 0; i < 40; ++i) {
      const double mid = 0.5 * (lo + hi);
      (uplifts(mid) ? hi : lo) = mid;
    }
    std::printf("f = %.2f Hz: threshold engine %.12f, closed form %.12f m/s^2 (rel %.2e)\n", f, hi,
                a_star, (hi - a_star) / a_star);
    EXPECT_NEAR(hi, a_star, 1e-8 * a_star);
    EXPECT_NEAR(support_uplift_amplitude(body, s, f), a_star, 1e-12 * a_star);
  }
}

// the energy balance with the support's kinetic and spring energy, the dashpot and the impacts
TEST(Support, EnergyBalancesAndNoImpactGainsEnergy) {
  const Body body(BodyParameters::rectangular_block(1000.0, 0.2, 0.8));
  SimulationOptions o;
  o.output_dt = 0.005;
  for (const double zeta : {0.0, 0.1}) {
    const SupportParameters s = SupportParameters::from_frequency(400.0, 1000.0, 2.5, zeta);
    const SupportRunResult r = simulate(body, s, one_sine(0.35 * 9.80665, 0.6, 6.0), {}, o);
    ASSERT_NE(r.body.status, Status::kStopped) << r.body.message;
    EXPECT_GT(r.body.extremes.impacts, 3);
    const EnergyBalance& e = r.body.energy;
    EXPECT_FALSE(r.body.energy_unbalanced);
    EXPECT_LT(std::abs(e.residual), 1e-7 * e.scale) << e.residual;
    if (zeta == 0.0) {
      EXPECT_EQ(e.damping_loss, 0.0);
    }
    for (const Event& ev : r.body.events) {
      if (ev.kind == EventKind::kImpact) {
        EXPECT_GE(ev.energy_loss, 0.0) << ev.time;
      }
      EXPECT_NE(ev.kind, EventKind::kImpactGainedEnergy);
    }
  }
  // no damping and no excitation: kinetic + potential + impact losses stay the starting energy
  SupportParameters s = SupportParameters::from_frequency(400.0, 1000.0, 2.5, 0.0);
  s.displacement = 0.01;
  InitialState init;
  init.theta = 0.1;
  o.rtol = 1e-12;
  o.atol = 1e-14;
  const SupportRunResult r = simulate(body, s, GroundMotion::none(4.0), init, o);
  const History& h = r.body.history;
  const double e0 = h.kinetic[0] + h.potential[0];
  double worst = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i)
    worst = std::max(worst, std::abs(h.kinetic[i] + h.potential[i] + h.impact_loss[i] - e0));
  EXPECT_GT(r.body.extremes.impacts, 2);
  EXPECT_LT(worst, 1e-9 * e0) << worst;
}

// mirrored input gives the mirrored response (a symmetric block)
TEST(Support, MirroredInputGivesTheMirroredResponse) {
  const Body body(BodyParameters::rectangular_block(1000.0, 0.2, 0.8));
  const SupportParameters s = SupportParameters::from_frequency(400.0, 1000.0, 2.5, 0.05);
  SimulationOptions o;
  o.output_dt = 0.01;
  const SupportRunResult a = simulate(body, s, one_sine(0.35 * 9.80665, 0.6, 4.0), {}, o);
  const SupportRunResult b = simulate(body, s, one_sine(-0.35 * 9.80665, 0.6, 4.0), {}, o);
  ASSERT_EQ(a.body.history.size(), b.body.history.size());
  ASSERT_GT(a.body.extremes.impacts, 1);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.body.history.size(); ++i) {
    worst = std::max(worst, std::abs(a.body.history.theta[i] + b.body.history.theta[i]));
    worst = std::max(worst, std::abs(a.history.displacement[i] + b.history.displacement[i]));
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_EQ(a.body.extremes.impacts, b.body.extremes.impacts);
  EXPECT_DOUBLE_EQ(a.body.extremes.max_theta_edge1, b.body.extremes.max_theta_edge2);
  EXPECT_DOUBLE_EQ(a.support.max_displacement, b.support.max_displacement);
}

// the answers do not depend on the numerical devices: the tolerance and the guards' samples
TEST(Support, AnswersConvergeWithTheToleranceAndDoNotDependOnTheSamples) {
  const Body body(BodyParameters::rectangular_block(1000.0, 0.2, 0.8));
  const SupportParameters s = SupportParameters::from_frequency(400.0, 1000.0, 2.5, 0.05);
  const GroundMotion m = one_sine(0.35 * 9.80665, 0.6, 6.0);
  auto run = [&](double rtol, int samples) {
    SimulationOptions o;
    o.rtol = rtol;
    o.atol = 1e-2 * rtol;
    o.event_samples = samples;
    return simulate(body, s, m, {}, o);
  };
  const SupportRunResult ref = run(1e-13, 8);
  ASSERT_GT(ref.body.extremes.impacts, 10);
  for (const auto& [rtol, samples, tol] :
       {std::tuple{1e-9, 4, 1e-6}, std::tuple{1e-11, 4, 1e-8}, std::tuple{1e-11, 2, 1e-8},
        std::tuple{1e-11, 16, 1e-8}}) {
    const SupportRunResult r = run(rtol, samples);
    EXPECT_EQ(r.body.status, ref.body.status);
    EXPECT_EQ(r.body.extremes.impacts, ref.body.extremes.impacts) << rtol << " " << samples;
    EXPECT_NEAR(r.body.extremes.max_theta_edge1, ref.body.extremes.max_theta_edge1,
                tol * ref.body.extremes.max_theta_edge1);
    EXPECT_NEAR(r.body.extremes.max_theta_edge2, ref.body.extremes.max_theta_edge2,
                tol * ref.body.extremes.max_theta_edge2);
    EXPECT_NEAR(r.support.max_displacement, ref.support.max_displacement,
                tol * ref.support.max_displacement);
    const Event* a = first_of(r.body, EventKind::kImpact);
    const Event* b = first_of(ref.body, EventKind::kImpact);
    ASSERT_TRUE(a && b);
    EXPECT_NEAR(a->time, b->time, tol);
  }
}

// under a sampled record full contact is walked one exact update per sample interval; stepped by
// the integrator instead, the run is the same
TEST(Support, ExactFullContactWalkAgreesWithTheIntegrator) {
  const Body body(BodyParameters::rectangular_block(1000.0, 0.2, 0.8));
  // a record of 8 s at 0.01 s: a burst of three sines, strong enough to rock the block
  std::vector<double> a;
  for (int i = 0; i <= 800; ++i) {
    const double t = 0.01 * i;
    a.push_back(t < 5.0 ? 3.3 * std::sin(2.0 * kPi * 1.7 * t) * std::sin(kPi * t / 5.0) +
                              0.8 * std::sin(2.0 * kPi * 4.3 * t + 0.4) +
                              0.5 * std::sin(2.0 * kPi * 0.6 * t + 1.1)
                        : 0.0);
  }
  const GroundMotion m = GroundMotion::uniform(0.01, a);
  for (const double f : {0.7, 2.5, 12.0}) {
    for (const double zeta : {0.0, 0.08, 1.5}) {
      const SupportParameters s = SupportParameters::from_frequency(700.0, 1000.0, f, zeta);
      SimulationOptions o;
      o.rtol = 1e-12;
      o.atol = 1e-14;
      o.output_dt = 0.02;
      const SupportRunResult walk = simulate(body, s, m, {}, o);
      o.methods.full_contact_walk = false;
      const SupportRunResult dopri = simulate(body, s, m, {}, o);
      ASSERT_EQ(walk.body.status, dopri.body.status) << f << " " << zeta;
      EXPECT_EQ(walk.body.extremes.impacts, dopri.body.extremes.impacts) << f << " " << zeta;
      const double umax = walk.support.max_displacement;
      ASSERT_GT(umax, 0.0);
      double du = 0.0, dth = 0.0;
      for (std::size_t i = 0; i < walk.body.history.size(); ++i) {
        du = std::max(du, std::abs(walk.history.displacement[i] - dopri.history.displacement[i]));
        dth = std::max(dth, std::abs(walk.body.history.theta[i] - dopri.body.history.theta[i]));
      }
      // the undamped 12 Hz support with 82 impacts amplifies the integrator's own error to
      // 5e-7 of max |u| (it shrinks with rtol: below); the other runs agree to 1e-10
      EXPECT_LT(du, 1e-6 * umax) << f << " " << zeta;
      EXPECT_LT(dth, 1e-6) << f << " " << zeta;
      EXPECT_NEAR(walk.body.energy.damping_loss, dopri.body.energy.damping_loss,
                  1e-8 * walk.body.energy.scale);
      EXPECT_NEAR(walk.body.energy.input_work, dopri.body.energy.input_work,
                  1e-8 * walk.body.energy.scale);
      EXPECT_FALSE(walk.body.energy_unbalanced);
      EXPECT_LT(std::abs(walk.body.energy.residual), 1e-9 * walk.body.energy.scale);
      std::printf(
          "f %5.1f Hz zeta %4.2f: %s, %ld impacts, uplift %d, steps walk %ld / "
          "integrator %ld, |du| %.2e m of %.3e\n",
          f, zeta, to_string(walk.body.status), walk.body.extremes.impacts,
          walk.body.extremes.first_uplift_time >= 0.0 ? 1 : 0, walk.body.steps, dopri.body.steps,
          du, umax);
    }
  }
}

// the walk's and the integrator's runs differ by the integrator's error: it shrinks with rtol
TEST(Support, WalkAndIntegratorDifferByTheIntegratorsError) {
  const Body body(BodyParameters::rectangular_block(1000.0, 0.2, 0.8));
  std::vector<double> a;
  for (int i = 0; i <= 800; ++i) {
    const double t = 0.01 * i;
    a.push_back(t < 5.0 ? 3.3 * std::sin(2.0 * kPi * 1.7 * t) * std::sin(kPi * t / 5.0) +
                              0.8 * std::sin(2.0 * kPi * 4.3 * t + 0.4) +
                              0.5 * std::sin(2.0 * kPi * 0.6 * t + 1.1)
                        : 0.0);
  }
  const GroundMotion m = GroundMotion::uniform(0.01, a);
  const SupportParameters s = SupportParameters::from_frequency(700.0, 1000.0, 12.0, 0.0);
  auto diff = [&](double rtol) {
    SimulationOptions o;
    o.rtol = rtol;
    o.atol = 1e-2 * rtol;
    o.output_dt = 0.02;
    const SupportRunResult walk = simulate(body, s, m, {}, o);
    o.methods.full_contact_walk = false;
    const SupportRunResult dopri = simulate(body, s, m, {}, o);
    double du = 0.0;
    for (std::size_t i = 0; i < walk.body.history.size(); ++i)
      du = std::max(du, std::abs(walk.history.displacement[i] - dopri.history.displacement[i]));
    return du;
  };
  const double d11 = diff(1e-11), d13 = diff(1e-13);
  std::printf("walk - integrator: max |du| %.3e m at rtol 1e-11, %.3e m at 1e-13\n", d11, d13);
  EXPECT_LT(d13, 0.2 * d11);
}

// what is not modelled is refused, naming it
TEST(Support, RefusesWhatItDoesNotModel) {
  const Body rigid(BodyParameters::rectangular_block(1000.0, 0.2, 0.8));
  const SupportParameters s = SupportParameters::from_frequency(400.0, 1000.0, 2.5, 0.05);
  SimulationOptions o;
  o.friction_coefficient = 0.5;
  try {
    simulate(rigid, s, GroundMotion::none(1.0), {}, o);
    FAIL() << "sliding accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sliding on a support is not modelled"), std::string::npos)
        << e.what();
  }
  SupportParameters bad = s;
  bad.stiffness = -1.0;
  EXPECT_THROW(simulate(rigid, bad, GroundMotion::none(1.0)), InputError);
  // a base falling faster than g: the block would fly, which ends the run saying so
  const SupportRunResult r =
      simulate(rigid, s, one_sine(0.0, 0.5, 1.0, /*vertical_too=*/true, -1.2 * 9.80665));
  EXPECT_EQ(r.body.status, Status::kStopped);
  EXPECT_NE(r.body.message.find("flight on a support is not modelled"), std::string::npos)
      << r.body.message;
  EXPECT_NE(r.body.message.find("F_J = "), std::string::npos);
}

// a squat block (alpha = 1.2) whose coupled impact would turn it into the support: both edges
// stay down (theta_dot+ = 0, the block moving with the support), rocking ends
TEST(Support, SquatBlockEndsRockingAtItsImpacts) {
  const Body body(BodyParameters::rectangular_block(1000.0, 0.96, 0.8));
  const SupportParameters s = SupportParameters::from_frequency(400.0, 1000.0, 2.5, 0.05);
  // the coupled ratio is negative: 1 + zeta^2 - alpha^2 - chi < 0
  ASSERT_LT(support_impact(1000.0, 400.0, body.params().zeta2, body.alpha2(), -body.alpha1()).ratio,
            0.0);
  SimulationOptions o;
  o.output_dt = 0.001;
  const SupportRunResult r = simulate(body, s, one_sine(1.5 * 9.80665, 0.6, 3.0), {}, o);
  ASSERT_EQ(r.body.status, Status::kCompleted);
  int impacts = 0, ended = 0;
  for (const Event& e : r.body.events) {
    if (e.kind == EventKind::kImpact) {
      ++impacts;
      EXPECT_EQ(e.theta_dot_after, 0.0);
      EXPECT_GT(e.energy_loss, 0.0);
    }
    ended += e.kind == EventKind::kRockingEnded ? 1 : 0;
  }
  EXPECT_GE(impacts, 1);
  EXPECT_EQ(ended, impacts);
  EXPECT_EQ(r.body.final_phase, ContactMode::kFullContact);
  EXPECT_LT(std::abs(r.body.energy.residual), 1e-7 * r.body.energy.scale);
}

// a block toppling after the pulse: where the support's vertical force would vanish with the
// lift-off inconsistent (the corner would accelerate into the support) the pivot is held, the
// support pulling, said with its magnitude (as on the rigid floor, §15)
TEST(Support, TopplingBlockReportsThePivotTensionItNeeds) {
  const Body body(BodyParameters::rectangular_block(1000.0, 0.2, 0.8));
  const SupportParameters s = SupportParameters::from_frequency(400.0, 1000.0, 2.5, 0.0);
  const SupportRunResult r = simulate(body, s, one_sine(0.4 * 9.80665, 0.6, 6.0));
  ASSERT_EQ(r.body.status, Status::kOverturned) << r.body.message;
  EXPECT_TRUE(r.body.pivot_tension);
  EXPECT_GE(r.body.extremes.tension_episodes, 1);
  EXPECT_GT(r.body.extremes.max_pivot_pull, 0.0);
  EXPECT_GT(r.body.extremes.tension_time, 0.0);
  EXPECT_NE(first_of(r.body, EventKind::kPivotTension), nullptr);
}

// a block set rocking so fast that the support would have to pull on its pivot at once, with the
// lift-off consistent: it would fly, which ends the run saying so (as the floor's engine lifts off)
TEST(Support, FastRockingFromTheStartWouldFly) {
  const Body body(BodyParameters::rectangular_block(1000.0, 0.2, 0.8));
  InitialState init;
  init.theta_dot = 6.0;  // h theta_dot^2 = 29 m/s^2 > g
  const SimulationResult floor = simulate(body, GroundMotion::none(1.0), init);
  EXPECT_GE(floor.extremes.lift_offs, 1);
  const SupportParameters s = SupportParameters::from_frequency(400.0, 1000.0, 2.5, 0.05);
  const SupportRunResult r = simulate(body, s, GroundMotion::none(1.0), init);
  EXPECT_EQ(r.body.status, Status::kStopped);
  EXPECT_EQ(r.body.t_end, 0.0);
  EXPECT_NE(r.body.message.find("flight on a support is not modelled"), std::string::npos)
      << r.body.message;
}

// overturning on a soft support, as an outcome
TEST(Support, OverturnsAsAnOutcome) {
  const Body body(BodyParameters::rectangular_block(1000.0, 0.15, 0.9));
  const SupportParameters s = SupportParameters::from_frequency(200.0, 1000.0, 5.0, 0.05);
  const SupportRunResult r = simulate(body, s, one_sine(1.2 * 9.80665, 1.0, 4.0));
  EXPECT_EQ(r.body.status, Status::kOverturned);
  EXPECT_GT(r.body.extremes.overturn_time, 0.0);
}

}  // namespace
}  // namespace flexrock
