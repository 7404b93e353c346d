// SPDX-License-Identifier: BSD-3-Clause
#include "flexrock/excitation/pulses.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "flexrock/core/error.hpp"
#include "flexrock/core/format.hpp"

namespace flexrock {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// shortest round-trip text of a double, so messages show the value the user gave
std::string show(double v) { return format_number(v); }

// "pulse: argument 'name' = value, expected ..."
void require(bool ok, const char* pulse, const char* name, double value, const char* expected) {
  FLEXROCK_THROW_UNLESS(ok, std::string(pulse) + ": argument '" + name + "' = " + show(value) +
                                ", expected " + expected);
}

void require_finite(const char* pulse, const char* name, double value) {
  require(std::isfinite(value), pulse, name, value, "a finite number");
}

void require_positive(const char* pulse, const char* name, double value) {
  require(std::isfinite(value) && value > 0.0, pulse, name, value, "a positive finite number");
}

// duration must be positive and cover the pulse of length t_end. A duration short of t_end by
// rounding only (2 pi/omega computed by the caller vs here) is accepted, and the pulse is cut at
// the duration so that no breakpoint lies beyond the motion.
void require_duration(const char* pulse, double duration, double& t_end) {
  require_positive(pulse, "duration", duration);
  if (duration < t_end && duration >= t_end * (1.0 - 16.0 * kEpsilon)) t_end = duration;
  FLEXROCK_THROW_UNLESS(duration >= t_end,
                        std::string(pulse) + ": argument 'duration' = " + show(duration) +
                            " s, expected at least the pulse " + "length " + show(t_end) + " s");
}

// a scalar acceleration history a(t) on [0, t_end] (zero after), placed on one component
template <class F>
GroundMotion make_pulse(F a, double t_end, double duration, Component component,
                        std::vector<double> breakpoints) {
  const bool vertical = component == Component::kVertical;
  auto f = [a = std::move(a), t_end, vertical](double t) -> BaseAcceleration {
    const double v = (t >= 0.0 && t <= t_end) ? a(t) : 0.0;
    return vertical ? BaseAcceleration{0.0, v} : BaseAcceleration{v, 0.0};
  };
  return GroundMotion::analytic(std::move(f), duration, std::move(breakpoints));
}

// the same pulse described as amplitude sin(omega t + phase) on [0, t_end]: its function stays
// the one the guards and the integrators read; the description lets a rigid body's rocking series
// expand it (GroundMotion::with_sinusoids)
GroundMotion described(const GroundMotion& m, double amplitude, double omega, double phase,
                       double t_end, Component component) {
  return m.with_sinusoids(
      {SinusoidPiece{0.0, t_end, amplitude, omega, phase, component == Component::kVertical}});
}

// common checks of the sinusoidal pulses
void check_sine_args(const char* pulse, double a_p, double omega_p) {
  require_finite(pulse, "a_p", a_p);
  require_positive(pulse, "omega_p", omega_p);
}

}  // namespace

GroundMotion harmonic(double amplitude, double omega, double duration, double phase,
                      Component component) {
  const char* name = "harmonic";
  require_finite(name, "amplitude", amplitude);
  require_positive(name, "omega", omega);
  require_positive(name, "duration", duration);
  require_finite(name, "phase", phase);
  return described(make_pulse([=](double t) { return amplitude * std::sin(omega * t + phase); },
                              duration, duration, component, {}),
                   amplitude, omega, phase, duration, component);
}

GroundMotion harmonic_cycles(double amplitude, double omega, double cycles, double duration,
                             double phase, Component component) {
  const char* name = "harmonic_cycles";
  require_finite(name, "amplitude", amplitude);
  require_positive(name, "omega", omega);
  require_positive(name, "cycles", cycles);
  require_finite(name, "phase", phase);
  double t_end = cycles * 2.0 * kPi / omega;
  require_duration(name, duration, t_end);
  return described(make_pulse([=](double t) { return amplitude * std::sin(omega * t + phase); },
                              t_end, duration, component, {t_end}),
                   amplitude, omega, phase, t_end, component);
}

namespace {
// a_p sin(omega_p t) over `half_periods` half periods; `name` is the caller's, for messages
GroundMotion sine_pulse(const char* name, double a_p, double omega_p, double half_periods,
                        double duration, Component component) {
  check_sine_args(name, a_p, omega_p);
  double t_end = half_periods * kPi / omega_p;
  require_duration(name, duration, t_end);
  return described(make_pulse([=](double t) { return a_p * std::sin(omega_p * t); }, t_end,
                              duration, component, {t_end}),
                   a_p, omega_p, 0.0, t_end, component);
}
}  // namespace

GroundMotion one_sine_pulse(double a_p, double omega_p, double duration, Component component) {
  return sine_pulse("one_sine_pulse", a_p, omega_p, 2.0, duration, component);
}

GroundMotion half_sine_pulse(double a_p, double omega_p, double duration, Component component) {
  return sine_pulse("half_sine_pulse", a_p, omega_p, 1.0, duration, component);
}

GroundMotion cycloidal_pulse_a(double a_p, double omega_p, double duration, Component component) {
  return sine_pulse("cycloidal_pulse_a", a_p, omega_p, 2.0, duration, component);
}

GroundMotion cycloidal_pulse_b(double a_p, double omega_p, double duration, Component component) {
  const char* name = "cycloidal_pulse_b";
  check_sine_args(name, a_p, omega_p);
  double t_end = 2.0 * kPi / omega_p;
  require_duration(name, duration, t_end);
  return described(make_pulse([=](double t) { return a_p * std::cos(omega_p * t); }, t_end,
                              duration, component, {t_end}),
                   a_p, omega_p, 0.5 * kPi, t_end, component);
}

double cycloidal_c_phase(int n) {
  FLEXROCK_THROW_UNLESS(n >= 1, "cycloidal_c_phase: argument 'n' = " + std::to_string(n) +
                                    ", expected an integer >= 1");
  // g(phi) = 2 cos(phi) - (c - 2 phi) sin(phi), c = (2n+1) pi; g(0) = 2 > 0, g(pi/2) < 0 and g is
  // decreasing on [0, pi/2]: bisection to full precision
  const double c = (2.0 * n + 1.0) * kPi;
  auto g = [c](double phi) { return 2.0 * std::cos(phi) - (c - 2.0 * phi) * std::sin(phi); };
  double lo = 0.0, hi = 0.5 * kPi;
  for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

GroundMotion cycloidal_pulse_c(double a_p, double omega_p, double duration, int n,
                               Component component) {
  const char* name = "cycloidal_pulse_c";
  check_sine_args(name, a_p, omega_p);
  FLEXROCK_THROW_UNLESS(n >= 1, std::string(name) + ": argument 'n' = " + std::to_string(n) +
                                    ", expected an integer >= 1");
  const double phi = cycloidal_c_phase(n);
  double t_end = (n + 0.5 - phi / kPi) * 2.0 * kPi / omega_p;
  require_duration(name, duration, t_end);
  return described(make_pulse([=](double t) { return a_p * std::cos(omega_p * t + phi); }, t_end,
                              duration, component, {t_end}),
                   a_p, omega_p, phi + 0.5 * kPi, t_end, component);
}

GroundMotion ricker_wavelet(double a_p, double omega_p, double t_c, double duration,
                            Component component) {
  const char* name = "ricker_wavelet";
  check_sine_args(name, a_p, omega_p);
  require_positive(name, "duration", duration);
  require(std::isfinite(t_c) && t_c >= 0.0 && t_c <= duration, name, "t_c", t_c,
          "a centre time in [0, duration]");
  const double k = 0.25 * omega_p * omega_p;
  return make_pulse(
      [=](double t) {
        const double s = k * (t - t_c) * (t - t_c);
        return a_p * (1.0 - 2.0 * s) * std::exp(-s);
      },
      duration, duration, component, {t_c});
}

GroundMotion rectangular_pulse(double a_p, double t_1, double duration, Component component) {
  const char* name = "rectangular_pulse";
  require_finite(name, "a_p", a_p);
  require_positive(name, "t_1", t_1);
  require_duration(name, duration, t_1);
  // omega = 0: the constant a_p sin(pi/2) = a_p
  return described(make_pulse([=](double) { return a_p; }, t_1, duration, component, {t_1}), a_p,
                   0.0, 0.5 * kPi, t_1, component);
}

// ---------------------------------------------------------------------------------------------
// the table of pulse types

std::optional<double> PulseArgs::key(std::string_view name) const {
  const auto it = keys.find(name);
  if (it == keys.end()) return std::nullopt;
  return it->second;
}

namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
constexpr double kTwoPi = 2.0 * kPi;

// the length of a pulse of one period
double one_period(double omega_p) { return kTwoPi / omega_p; }

const std::vector<PulseKind> kPulseKinds = {
    {"harmonic",
     "harmonic",
     true,
     {{"phase", "phase", "rad", PulseKeyRule::kFinite, false, 0.0, "0", "phase at t = 0"},
      {"cycles", "cycles", "-", PulseKeyRule::kPositive, false, kNone, "none: steady",
       "cycles, then zero (free vibration); may be fractional"}},
     [](const PulseArgs& a) {
       const double phase = *a.key("phase");
       const std::optional<double> cycles = a.key("cycles");
       return cycles ? harmonic_cycles(a.a_p, a.omega_p, *cycles, a.duration, phase, a.component)
                     : harmonic(a.a_p, a.omega_p, a.duration, phase, a.component);
     },
     nullptr,
     "",
     true,
     "a sin(omega t + phase), over `cycles` cycles then zero, or the whole duration"},
    {"one_sine",
     "one_sine_pulse",
     true,
     {},
     [](const PulseArgs& a) { return one_sine_pulse(a.a_p, a.omega_p, a.duration, a.component); },
     one_period,
     "2 pi/omega",
     true,
     "a sin(omega t) for one period"},
    {"half_sine",
     "half_sine_pulse",
     true,
     {},
     [](const PulseArgs& a) { return half_sine_pulse(a.a_p, a.omega_p, a.duration, a.component); },
     [](double omega_p) { return kPi / omega_p; },
     "pi/omega",
     true,
     "a sin(omega t) for half a period"},
    {"cycloidal_a",
     "cycloidal_pulse_a",
     true,
     {},
     [](const PulseArgs& a) {
       return cycloidal_pulse_a(a.a_p, a.omega_p, a.duration, a.component);
     },
     one_period,
     "2 pi/omega",
     true,
     "Makris & Roussos type A (= one-sine)"},
    {"cycloidal_b",
     "cycloidal_pulse_b",
     true,
     {},
     [](const PulseArgs& a) {
       return cycloidal_pulse_b(a.a_p, a.omega_p, a.duration, a.component);
     },
     one_period,
     "2 pi/omega",
     true,
     "a cos(omega t) for one period"},
    {"cycloidal_c",
     "cycloidal_pulse_c",
     true,
     {{"n", "n", "-", PulseKeyRule::kCount, false, 1.0, "1", "main cycles (type C_n)"}},
     [](const PulseArgs& a) {
       const int n = static_cast<int>(*a.key("n"));
       return cycloidal_pulse_c(a.a_p, a.omega_p, a.duration, n, a.component);
     },
     // spectra use n = 1
     [](double omega_p) { return (1.5 - cycloidal_c_phase(1) / kPi) * kTwoPi / omega_p; },
     "(1.5 - phi_1/pi) 2 pi/omega",
     true,
     "a cos(omega t + phi_n), type C_n"},
    {"ricker",
     "ricker_wavelet",
     true,
     {{"center", "t_c", "s", PulseKeyRule::kNonnegative, false, kNone, "3 sqrt(6)/omega",
       "time of the peak"}},
     [](const PulseArgs& a) {
       const double t_c = a.key("center").value_or(3.0 * std::sqrt(6.0) / a.omega_p);
       return ricker_wavelet(a.a_p, a.omega_p, t_c, a.duration, a.component);
     },
     // the centre 3 sqrt(6)/omega plus as much again
     [](double omega_p) { return 6.0 * std::sqrt(6.0) / omega_p; },
     "6 sqrt(6)/omega",
     false,
     "Ricker wavelet peaking at `center`; `frequency_hz` is its peak frequency"},
    {"rectangular",
     "rectangular_pulse",
     false,
     {{"length", "t_1", "s", PulseKeyRule::kPositive, true, kNone, "required",
       "length of the pulse"}},
     [](const PulseArgs& a) {
       return rectangular_pulse(a.a_p, *a.key("length"), a.duration, a.component);
     },
     nullptr,
     "",
     true,
     "a for 0 <= t <= length"},
};

std::string pulse_names() {
  std::string s;
  for (const PulseKind& k : kPulseKinds) s += (s.empty() ? "" : ", ") + std::string(k.name);
  return s;
}

}  // namespace

const std::vector<PulseKind>& pulse_kinds() { return kPulseKinds; }

const PulseKind& pulse_kind(std::string_view name) {
  for (const PulseKind& k : kPulseKinds) {
    if (name == k.name) return k;
  }
  throw InputError("expected a pulse type, one of: " + pulse_names() + "; got \"" +
                   std::string(name) + "\"");
}

std::vector<std::string> spectrum_pulse_names() {
  std::vector<std::string> v;
  for (const PulseKind& k : kPulseKinds) {
    if (k.length) v.emplace_back(k.name);
  }
  return v;
}

GroundMotion make_pulse(const PulseKind& kind, PulseArgs args) {
  for (const auto& [name, value] : args.keys) {
    bool known = false;
    std::string names;
    for (const PulseKey& k : kind.keys) {
      known = known || name == k.name;
      names += (names.empty() ? "" : ", ") + std::string(k.name);
    }
    FLEXROCK_THROW_UNLESS(known, std::string(kind.name) + ": unknown key '" + name +
                                     "'; expected " +
                                     (names.empty() ? std::string("none") : "one of: " + names));
  }
  for (const PulseKey& k : kind.keys) {
    if (args.keys.count(k.name)) continue;
    FLEXROCK_THROW_UNLESS(!k.required, std::string(kind.name) + ": key '" + k.name +
                                           "': missing; expected a number [" + k.unit + "]");
    if (!std::isnan(k.fixed)) args.keys.emplace(k.name, k.fixed);
  }
  // a period past its range, not an overflow later (omega_p <= 0 keeps the type's own message)
  if (kind.frequency && args.omega_p > 0.0) {
    const double period = 2.0 * std::numbers::pi / args.omega_p;
    FLEXROCK_THROW_UNLESS(period >= kMinPulsePeriod && period <= kMaxPulsePeriod,
                          std::string(kind.name) + ": period " + format_number(period, 6) +
                              " s (frequency_hz " + format_number(1.0 / period, 6) +
                              "), expected a period in [" + format_number(kMinPulsePeriod, 6) +
                              ", " + format_number(kMaxPulsePeriod, 6) +
                              "] s: no ground or shake-table motion is faster than 10 kHz, and a "
                              "period of hours is a static tilt");
  }
  return kind.make(args);
}

}  // namespace flexrock
