// SPDX-License-Identifier: BSD-3-Clause
// Synthetic pulses against their closed forms: peaks, ground velocity and displacement at the
// pulse end (by quadrature of the motion itself), breakpoints, zero free vibration, checks.
#include "flexrock/excitation/pulses.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <numbers>
#include <string>
#include <vector>

#include "flexrock/core/error.hpp"
#include "support/expect_error.hpp"

namespace flexrock {
namespace {

constexpr double kPi = std::numbers::pi;

using test::expect_input_error;

// ground velocity and displacement at T from rest at 0: v = int_0^T a, u = int_0^T (T - s) a(s) ds
// (composite Simpson; the pulses are smooth on [0, T] when T is the pulse end)
struct Kinematics {
  double v;  // [m/s]
  double u;  // [m]
};

Kinematics integrate(const GroundMotion& m, double T, bool vertical = false) {
  constexpr int kN = 20000;  // even
  const double h = T / kN;
  double v = 0.0, u = 0.0;
  for (int i = 0; i <= kN; ++i) {
    const double t = i * h;
    const BaseAcceleration a = m.at(t);
    const double ai = vertical ? a.y : a.x;
    const double w = (i == 0 || i == kN) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    v += w * ai;
    u += w * (T - t) * ai;
  }
  return {v * h / 3.0, u * h / 3.0};
}

// the breakpoints after 0, in order
std::vector<double> breakpoints(const GroundMotion& m) {
  std::vector<double> out;
  GroundMotion::Cursor c;
  for (double t = m.next_breakpoint(0.0, c); std::isfinite(t); t = m.next_breakpoint(t, c)) {
    out.push_back(t);
  }
  return out;
}

constexpr double kAp = 2.5;       // [m/s^2]
constexpr double kOmega = 4.0;    // [rad/s]
constexpr double kDuration = 10;  // [s]

TEST(OneSinePulse, PeaksVelocityReturnsToZeroDisplacementIsForward) {
  const GroundMotion m = one_sine_pulse(kAp, kOmega, kDuration);
  const double tp = 2.0 * kPi / kOmega;
  EXPECT_DOUBLE_EQ(m.duration(), kDuration);
  EXPECT_NEAR(m.at(0.25 * tp).x, kAp, 1e-14);
  EXPECT_NEAR(m.at(0.75 * tp).x, -kAp, 1e-14);
  EXPECT_DOUBLE_EQ(m.at(0.3).y, 0.0);
  const Kinematics k = integrate(m, tp);
  EXPECT_NEAR(k.v, 0.0, 1e-12);
  EXPECT_NEAR(k.u, 2.0 * kPi * kAp / (kOmega * kOmega), 1e-10);
  EXPECT_EQ(breakpoints(m), (std::vector<double>{tp, kDuration}));
  EXPECT_EQ(m.at(tp + 1e-9).x, 0.0);
  EXPECT_EQ(m.at(7.0).x, 0.0);
}

TEST(HalfSinePulse, EndsWithVelocityTwoApOverOmega) {
  const GroundMotion m = half_sine_pulse(kAp, kOmega, kDuration);
  const double te = kPi / kOmega;
  EXPECT_NEAR(m.at(0.5 * te).x, kAp, 1e-14);
  EXPECT_NEAR(integrate(m, te).v, 2.0 * kAp / kOmega, 1e-12);
  EXPECT_EQ(breakpoints(m), (std::vector<double>{te, kDuration}));
  EXPECT_EQ(m.at(te + 1e-9).x, 0.0);
}

TEST(CycloidalPulseA, ForwardPulseEndsAtRestWithPermanentDisplacement) {
  // a_p = omega_p v_p / 2
  const double vp = 0.4;
  const GroundMotion m = cycloidal_pulse_a(kOmega * vp / 2.0, kOmega, kDuration);
  const double tp = 2.0 * kPi / kOmega;
  // v(t) = v_p/2 (1 - cos omega_p t): peak v_p at T_p/2
  EXPECT_NEAR(integrate(m, 0.5 * tp).v, vp, 1e-12);
  const Kinematics k = integrate(m, tp);
  EXPECT_NEAR(k.v, 0.0, 1e-12);
  EXPECT_NEAR(k.u, vp * tp / 2.0, 1e-10);
  EXPECT_EQ(breakpoints(m), (std::vector<double>{tp, kDuration}));
}

TEST(CycloidalPulseB, VelocityAndDisplacementReturnToZero) {
  const GroundMotion m = cycloidal_pulse_b(kAp, kOmega, kDuration);
  const double tp = 2.0 * kPi / kOmega;
  EXPECT_DOUBLE_EQ(m.at(0.0).x, kAp);  // jumps to a_p at the start
  EXPECT_NEAR(m.at(0.5 * tp).x, -kAp, 1e-14);
  EXPECT_NEAR(m.at(tp).x, kAp, 1e-13);              // left limit at the end
  EXPECT_EQ(m.at(std::nextafter(tp, 1e9)).x, 0.0);  // right limit
  const Kinematics k = integrate(m, tp);
  EXPECT_NEAR(k.v, 0.0, 1e-12);
  EXPECT_NEAR(k.u, 0.0, 1e-12);
  // peak velocity a_p / omega_p at T_p/4, peak displacement 2 a_p / omega_p^2 at T_p/2
  EXPECT_NEAR(integrate(m, 0.25 * tp).v, kAp / kOmega, 1e-12);
  EXPECT_NEAR(integrate(m, 0.5 * tp).u, 2.0 * kAp / (kOmega * kOmega), 1e-10);
  EXPECT_EQ(breakpoints(m), (std::vector<double>{tp, kDuration}));
}

TEST(CycloidalPulseC, PhaseMatchesMakrisRoussosTable) {
  EXPECT_NEAR(cycloidal_c_phase(1) / kPi, 0.0697, 5e-5);
  EXPECT_NEAR(cycloidal_c_phase(2) / kPi, 0.0410, 5e-5);
  // the defining equation holds to rounding
  for (int n : {1, 2, 3}) {
    const double phi = cycloidal_c_phase(n);
    EXPECT_NEAR(2.0 * std::cos(phi), ((2.0 * n + 1.0) * kPi - 2.0 * phi) * std::sin(phi), 1e-14);
  }
}

TEST(CycloidalPulseC, VelocityAndDisplacementReturnToZero) {
  for (int n : {1, 2}) {
    const GroundMotion m = cycloidal_pulse_c(kAp, kOmega, kDuration, n);
    const double phi = cycloidal_c_phase(n);
    const double te = (n + 0.5 - phi / kPi) * 2.0 * kPi / kOmega;
    EXPECT_NEAR(m.at(0.0).x, kAp * std::cos(phi), 1e-14);
    const Kinematics k = integrate(m, te);
    EXPECT_NEAR(k.v, 0.0, 1e-12) << "n = " << n;
    EXPECT_NEAR(k.u, 0.0, 1e-11) << "n = " << n;
    // mid-pulse, the closed forms of pulses.hpp
    const double t = 0.37 * te;
    const Kinematics mid = integrate(m, t);
    EXPECT_NEAR(mid.v, kAp / kOmega * (std::sin(kOmega * t + phi) - std::sin(phi)), 1e-12);
    EXPECT_NEAR(mid.u,
                kAp / (kOmega * kOmega) * (std::cos(phi) - std::cos(kOmega * t + phi)) -
                    kAp / kOmega * std::sin(phi) * t,
                1e-11);
    EXPECT_EQ(breakpoints(m), (std::vector<double>{te, kDuration}));
    EXPECT_EQ(m.at(std::nextafter(te, 1e9)).x, 0.0);
  }
}

TEST(RickerWavelet, PeakSideLobesAndVelocityClosedForm) {
  const double tc = 3.0;
  const GroundMotion m = ricker_wavelet(kAp, kOmega, tc, kDuration);
  EXPECT_DOUBLE_EQ(m.at(tc).x, kAp);
  const double lobe = std::sqrt(6.0) / kOmega;
  EXPECT_NEAR(m.at(tc + lobe).x, -2.0 * kAp * std::exp(-1.5), 1e-14);
  EXPECT_NEAR(m.at(tc - lobe).x, -2.0 * kAp * std::exp(-1.5), 1e-14);
  // a zero crossing at tau = sqrt(2)/omega_p
  EXPECT_NEAR(m.at(tc + std::sqrt(2.0) / kOmega).x, 0.0, 1e-14);
  const double k = 0.25 * kOmega * kOmega;
  for (double t : {2.0, 3.0, 3.7, kDuration}) {
    const double tau = t - tc;
    EXPECT_NEAR(integrate(m, t).v,
                kAp * (tau * std::exp(-k * tau * tau) + tc * std::exp(-k * tc * tc)), 1e-10)
        << "t = " << t;
  }
  EXPECT_EQ(breakpoints(m), (std::vector<double>{tc, kDuration}));
}

TEST(RectangularPulse, ConstantThenZero) {
  const GroundMotion m = rectangular_pulse(-kAp, 0.8, kDuration);
  EXPECT_DOUBLE_EQ(m.at(0.0).x, -kAp);
  EXPECT_DOUBLE_EQ(m.at(0.8).x, -kAp);
  EXPECT_EQ(m.at(std::nextafter(0.8, 1.0)).x, 0.0);
  EXPECT_NEAR(integrate(m, 0.8).v, -kAp * 0.8, 1e-12);
  EXPECT_EQ(breakpoints(m), (std::vector<double>{0.8, kDuration}));
}

TEST(Harmonic, SteadyOverTheWholeDuration) {
  const GroundMotion m = harmonic(kAp, kOmega, kDuration, 0.3);
  for (double t : {0.0, 1.1, 9.99, kDuration}) {
    EXPECT_NEAR(m.at(t).x, kAp * std::sin(kOmega * t + 0.3), 1e-14);
  }
  EXPECT_EQ(m.at(kDuration + 0.1).x, 0.0);
  EXPECT_EQ(breakpoints(m), (std::vector<double>{kDuration}));
}

TEST(Harmonic, CyclesEndAtRestAndThenStop) {
  const GroundMotion m = harmonic_cycles(kAp, kOmega, 3.0, kDuration);
  const double te = 3.0 * 2.0 * kPi / kOmega;
  EXPECT_NEAR(integrate(m, te).v, 0.0, 1e-12);
  EXPECT_NEAR(m.at(te - 0.25 * 2.0 * kPi / kOmega).x, -kAp, 1e-13);
  EXPECT_EQ(m.at(std::nextafter(te, 1e9)).x, 0.0);
  EXPECT_EQ(breakpoints(m), (std::vector<double>{te, kDuration}));
}

TEST(Pulses, VerticalComponentDrivesOnlyYddot) {
  const GroundMotion m = one_sine_pulse(kAp, kOmega, kDuration, Component::kVertical);
  const double tp = 2.0 * kPi / kOmega;
  EXPECT_NEAR(m.at(0.25 * tp).y, kAp, 1e-14);
  EXPECT_EQ(m.at(0.25 * tp).x, 0.0);
  EXPECT_NEAR(integrate(m, tp, true).v, 0.0, 1e-12);
  const GroundMotion r = ricker_wavelet(kAp, kOmega, 2.0, kDuration, Component::kVertical);
  EXPECT_DOUBLE_EQ(r.at(2.0).y, kAp);
  EXPECT_EQ(r.at(2.0).x, 0.0);
}

TEST(Pulses, ScaledPulseScalesAcceleration) {
  const GroundMotion m = cycloidal_pulse_b(kAp, kOmega, kDuration).scaled(-2.0);
  EXPECT_DOUBLE_EQ(m.at(0.0).x, -2.0 * kAp);
}

TEST(Pulses, RejectNonPositiveFrequencyNamingArgumentAndValue) {
  expect_input_error([] { one_sine_pulse(1.0, -3.0, 5.0); },
                     {"one_sine_pulse", "'omega_p' = -3", "expected a positive finite number"});
  expect_input_error([] { harmonic(1.0, 0.0, 5.0); }, {"harmonic", "'omega' = 0", "positive"});
}

TEST(Pulses, RejectNonFiniteAmplitude) {
  expect_input_error([] { cycloidal_pulse_b(std::nan(""), 3.0, 5.0); },
                     {"cycloidal_pulse_b", "'a_p' = nan", "expected a finite number"});
  expect_input_error([] { harmonic(INFINITY, 3.0, 5.0); }, {"'amplitude' = inf", "finite"});
}

TEST(Pulses, RejectDurationShorterThanThePulse) {
  expect_input_error([] { one_sine_pulse(1.0, kPi, 1.5); },
                     {"one_sine_pulse", "'duration' = 1.5 s", "at least the pulse length 2 s"});
  expect_input_error([] { rectangular_pulse(1.0, 2.0, -1.0); },
                     {"rectangular_pulse", "'duration' = -1", "positive"});
}

TEST(Pulses, AcceptDurationShortOfThePulseByRoundingOnly) {
  // the caller's 2 pi/omega may round one ulp below ours: that is the pulse length, not an error
  const double omega = 2.0 * kPi / 3.0;
  const double t_pulse = 2.0 * kPi / omega;
  const double just_short = std::nextafter(t_pulse, 0.0);
  const GroundMotion m = one_sine_pulse(1.0, omega, just_short);
  EXPECT_EQ(m.duration(), just_short);
  EXPECT_NEAR(m.at(0.25 * t_pulse).x, 1.0, 1e-12);
  // a shortfall beyond rounding is still refused
  expect_input_error([&] { one_sine_pulse(1.0, omega, t_pulse * (1.0 - 1e-9)); },
                     {"one_sine_pulse", "at least the pulse length"});
}

TEST(Pulses, RejectBadShapeArguments) {
  expect_input_error([] { harmonic_cycles(1.0, 1.0, 0.0, 100.0); }, {"'cycles' = 0", "positive"});
  expect_input_error([] { rectangular_pulse(1.0, -0.5, 5.0); }, {"'t_1' = -0.5", "positive"});
  expect_input_error([] { cycloidal_pulse_c(1.0, 1.0, 100.0, 0); },
                     {"cycloidal_pulse_c", "'n' = 0", "integer >= 1"});
  expect_input_error([] { ricker_wavelet(1.0, 1.0, 6.0, 5.0); },
                     {"ricker_wavelet", "'t_c' = 6", "[0, duration]"});
  expect_input_error([] { harmonic(1.0, 1.0, 5.0, std::nan("")); }, {"'phase' = nan"});
}

// every pulse type but the Ricker wavelet is described also as sinusoids (which a rigid body's
// rocking series expands): their sum is the pulse's own function everywhere, on either component
// and scaled; a piece holds on [begin, end), the function at a pulse end its left limit
TEST(Pulses, SinusoidsDescribeEveryPulseButTheRickerWavelet) {
  int described = 0;
  for (const PulseKind& kind : pulse_kinds()) {
    for (Component c : {Component::kHorizontal, Component::kVertical}) {
      PulseArgs args{1.7, kind.frequency ? 3.0 : 0.0, 8.0, c, {}};
      for (const PulseKey& k : kind.keys)
        if (k.required) args.keys[k.name] = 1.3;
      const GroundMotion m = make_pulse(kind, args).scaled(-0.6);
      const std::string name = kind.name;
      if (name == "ricker") {
        EXPECT_FALSE(m.is_sinusoidal());
        continue;
      }
      ASSERT_TRUE(m.is_sinusoidal()) << name;
      ++described;
      auto sum = [&m](double t) {
        BaseAcceleration a;
        for (const SinusoidPiece& p : m.sinusoids()) {
          if (!(p.begin <= t && t < p.end)) continue;
          (p.vertical ? a.y : a.x) += p.amplitude * std::sin(p.omega * t + p.phase);
        }
        return a;
      };
      std::vector<double> ts;
      for (int i = 0; i <= 4000; ++i) ts.push_back(8.0 * i / 4000.0);
      for (const SinusoidPiece& p : m.sinusoids()) {
        ts.push_back(p.begin);
        ts.push_back(std::nextafter(p.end, 0.0));
        ts.push_back(std::nextafter(p.end, 10.0));
      }
      for (double t : ts) {
        if (t >= 8.0) continue;
        const bool at_end = std::any_of(m.sinusoids().begin(), m.sinusoids().end(),
                                        [t](const SinusoidPiece& p) { return t == p.end; });
        if (at_end) continue;  // the function's left limit there, the pieces' right one
        const BaseAcceleration f = m.at(t), d = sum(t);
        EXPECT_NEAR(d.x, f.x, 2e-15 * 1.7) << name << " t = " << t;
        EXPECT_NEAR(d.y, f.y, 2e-15 * 1.7) << name << " t = " << t;
      }
      // the pieces' ends are breakpoints, where steps end
      GroundMotion::Cursor cur;
      for (const SinusoidPiece& p : m.sinusoids()) {
        if (p.end < m.duration()) {
          EXPECT_EQ(m.next_breakpoint(std::nextafter(p.end, 0.0), cur), p.end) << name;
        }
      }
    }
  }
  EXPECT_GE(described, 14);  // seven types, two components
}

TEST(Pulses, QuietFromIsWherePulsesThatEndEnd) {
  // the motion is zero after quiet_from() (read from its own function, not the pieces), and a
  // pulse that ends is quiet from its end: the engine lets a rigid body at rest skip the rest
  for (const PulseKind& kind : pulse_kinds()) {
    PulseArgs args{1.7, kind.frequency ? 3.0 : 0.0, 8.0, Component::kHorizontal, {}};
    for (const PulseKey& k : kind.keys)
      if (k.required) args.keys[k.name] = 1.3;
    const GroundMotion m = make_pulse(kind, args);
    const std::string name = kind.name;
    const double quiet = m.quiet_from();
    EXPECT_LE(quiet, m.duration()) << name;
    for (int i = 1; i <= 400; ++i) {
      const double t = quiet + (m.duration() - quiet) * i / 400.0;
      if (!(t > quiet)) continue;  // at quiet_from() itself a pulse may hold its left limit
      EXPECT_EQ(m.at(t).x, 0.0) << name << " t = " << t;
    }
    if (kind.length && kind.ends) {
      EXPECT_NEAR(quiet, kind.length(3.0), 1e-14) << name;
    } else if (!kind.ends) {
      EXPECT_EQ(quiet, m.duration()) << name;
    }
  }
  EXPECT_NEAR(half_sine_pulse(2.0, 4.0, 6.0).quiet_from(), kPi / 4.0, 1e-15);
  EXPECT_EQ(GroundMotion::none(5.0).quiet_from(), 0.0);
  EXPECT_EQ(GroundMotion::uniform(0.01, {0.0, 1.0, 0.0}).quiet_from(), 0.02);
  // an analytic motion known only by its function may move up to its end
  EXPECT_EQ(GroundMotion::analytic([](double) { return BaseAcceleration{}; }, 7.0).quiet_from(),
            7.0);
}

}  // namespace
}  // namespace flexrock
