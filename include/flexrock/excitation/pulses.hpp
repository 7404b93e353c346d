// SPDX-License-Identifier: BSD-3-Clause
// Synthetic ground motions: harmonic excitation and the idealized pulses of the rocking literature.
//
// Every function returns GroundMotion::analytic(...) lasting `duration` [s] (free vibration, zero
// acceleration, after the pulse), with the pulse end as a breakpoint so that a simulation ends a
// step exactly there. Accelerations are in m/s^2, frequencies in rad/s, times in s, phases in rad.
// The motion acts along the horizontal (Xddot) unless `component` is Component::kVertical (Yddot).
//
// Value at a jump: a pulse is active on the closed interval [0, t_e]. At t = 0 the motion returns
// the pulse's value (the right limit), at the pulse end t_e its left limit, so a step ending at
// t_e integrates the pulse exactly. A step that starts at t_e and needs the right limit (zero)
// should sample at std::nextafter(t_e, +inf).
//
// Arguments are checked: amplitudes and phases must be finite, frequencies, durations and cycle
// counts positive and finite, and `duration` at least the pulse length (pulses that end).
// Violations throw flexrock::InputError naming the argument, its value and what is expected.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flexrock/excitation/ground_motion.hpp"

namespace flexrock {

/// Which base acceleration a synthetic motion drives.
enum class Component {
  kHorizontal,  // Xddot
  kVertical,    // Yddot
};

/// Steady harmonic excitation over the whole duration:
///   a(t) = amplitude * sin(omega * t + phase),   0 <= t <= duration.
/// \param amplitude [m/s^2]  \param omega [rad/s] > 0  \param duration [s] > 0  \param phase [rad]
/// \param component the base acceleration it drives (horizontal or vertical)
GroundMotion harmonic(double amplitude, double omega, double duration, double phase = 0.0,
                      Component component = Component::kHorizontal);

/// `cycles` cycles of harmonic excitation, then free vibration:
///   a(t) = amplitude * sin(omega * t + phase)   for 0 <= t <= t_e = cycles * 2 pi / omega,
///   a(t) = 0                                    for t_e < t <= duration.
/// `cycles` may be fractional. With phase = 0 and whole cycles the ground velocity returns to zero
/// at t_e. Breakpoint: t_e.
GroundMotion harmonic_cycles(double amplitude, double omega, double cycles, double duration,
                             double phase = 0.0, Component component = Component::kHorizontal);

/// One-sine acceleration pulse (Housner 1963; Zhang & Makris 2001):
///   a(t) = a_p * sin(omega_p * t)   for 0 <= t <= T_p = 2 pi / omega_p, then 0.
/// Ground velocity v(t) = a_p/omega_p (1 - cos omega_p t) returns to zero at T_p; the ground
/// displacement ends at u(T_p) = 2 pi a_p / omega_p^2 (a forward pulse). Breakpoint: T_p.
GroundMotion one_sine_pulse(double a_p, double omega_p, double duration,
                            Component component = Component::kHorizontal);

/// Half-sine acceleration pulse:
///   a(t) = a_p * sin(omega_p * t)   for 0 <= t <= pi / omega_p, then 0.
/// The ground velocity ends at 2 a_p / omega_p (not zero). Breakpoint: pi / omega_p.
GroundMotion half_sine_pulse(double a_p, double omega_p, double duration,
                             Component component = Component::kHorizontal);

/// Makris & Roussos (2000) cycloidal pulse type A, the "forward" pulse:
///   a(t) = a_p * sin(omega_p * t)   for 0 <= t <= T_p = 2 pi / omega_p, then 0,
/// with a_p = omega_p v_p / 2 (v_p the peak ground velocity). The ground velocity
/// v(t) = v_p/2 (1 - cos omega_p t) returns to zero at T_p; the displacement does not: it ends at
/// u(T_p) = v_p T_p / 2 = 2 pi a_p / omega_p^2 (permanent "fling" displacement). The acceleration
/// is the same as one_sine_pulse(); this name states the intent. Breakpoint: T_p.
GroundMotion cycloidal_pulse_a(double a_p, double omega_p, double duration,
                               Component component = Component::kHorizontal);

/// Makris & Roussos (2000) cycloidal pulse type B, the "forward-and-back" one-cosine pulse:
///   a(t) = a_p * cos(omega_p * t)   for 0 <= t <= T_p = 2 pi / omega_p, then 0,
/// with a_p = omega_p v_p. Ground velocity v(t) = a_p/omega_p sin(omega_p t) and displacement
/// u(t) = a_p/omega_p^2 (1 - cos omega_p t) both return to zero at T_p. The acceleration jumps
/// from 0 to a_p at t = 0 and from a_p to 0 at T_p. Breakpoint: T_p.
GroundMotion cycloidal_pulse_b(double a_p, double omega_p, double duration,
                               Component component = Component::kHorizontal);

/// Phase phi [rad] of the type-C_n cycloidal pulse: the root in (0, pi/2) of
///   2 cos(phi) = ((2n + 1) pi - 2 phi) sin(phi),
/// which makes the ground displacement return to zero at the pulse end (the velocity returns to
/// zero for any phi, by the choice of the pulse length). n = 1 gives phi = 0.0697 pi = 0.2190 rad,
/// n = 2 gives 0.0410 pi (Makris & Roussos 2000, Table 1). Requires n >= 1.
double cycloidal_c_phase(int n);

/// Makris & Roussos (2000) cycloidal pulse type C_n (n >= 1, default 1), the "forward-and-back-
/// and-forward" pulse with n main cycles:
///   a(t) = a_p * cos(omega_p * t + phi)   for 0 <= t <= t_e = (n + 1/2 - phi/pi) 2 pi / omega_p,
/// then 0, with a_p = omega_p v_p and phi = cycloidal_c_phase(n). The ground velocity
///   v(t) = a_p/omega_p (sin(omega_p t + phi) - sin(phi))
/// returns to zero at t_e because omega_p t_e + phi = (2n + 1) pi - phi; the displacement
///   u(t) = a_p/omega_p^2 (cos(phi) - cos(omega_p t + phi)) - a_p/omega_p sin(phi) t
/// returns to zero at t_e by the choice of phi. Breakpoint: t_e.
GroundMotion cycloidal_pulse_c(double a_p, double omega_p, double duration, int n = 1,
                               Component component = Component::kHorizontal);

/// Ricker wavelet (the "Mexican hat", second derivative of a Gaussian) centred at t_c:
///   a(t) = a_p (1 - omega_p^2 tau^2 / 2) exp(-omega_p^2 tau^2 / 4),   tau = t - t_c,
/// on the whole duration, where omega_p = 2 pi f_p is the peak (characteristic) frequency of its
/// Fourier amplitude spectrum. The peak a(t_c) = a_p; the side lobes reach -2 a_p exp(-3/2) at
/// tau = +-sqrt(6)/omega_p. The velocity v(t) = a_p (tau e^{-omega_p^2 tau^2/4} + t_c
/// e^{-omega_p^2 t_c^2/4}) returns to (almost) zero once tau >> 2/omega_p, if also
/// t_c >> 2/omega_p (choose t_c >= 3 sqrt(6)/omega_p so the motion starts from rest). Requires
/// 0 <= t_c <= duration. The centre is a breakpoint (not a kink, but it places a step end on the
/// peak).
GroundMotion ricker_wavelet(double a_p, double omega_p, double t_c, double duration,
                            Component component = Component::kHorizontal);

/// Rectangular acceleration pulse:
///   a(t) = a_p   for 0 <= t <= t_1, then 0.
/// The ground velocity ends at a_p t_1. Breakpoint: t_1.
GroundMotion rectangular_pulse(double a_p, double t_1, double duration,
                               Component component = Component::kHorizontal);

// ---------------------------------------------------------------------------------------------
// The table of pulse types: one entry a synthetic motion type, read by the case loader
// (excitation.*.type), the spectrum loader ([spectrum] pulse), the Python keywords and the
// generated key reference of docs/case-file.md. A new pulse type is one entry here and its
// function above.

/// How an extra key of a pulse type is checked.
enum class PulseKeyRule {
  kFinite,       // any finite number
  kPositive,     // a finite number > 0
  kNonnegative,  // a finite number >= 0
  kCount,        // an integer >= 1
};

/// One key of a pulse type besides amplitude, units, frequency_hz/period and duration.
struct PulseKey {
  const char* name;      // key in a case file and keyword in Python
  const char* argument;  // the pulse function's argument it becomes
  const char* unit;      // "rad", "s", "-"
  PulseKeyRule rule;
  bool required;  // no default: the key must be given
  double fixed;   // default when not required; NaN: the function decides (`default_text`)
  const char* default_text;  // the default as the docs state it
  const char* doc;           // one line: what the key means
};

/// The values a pulse type is made from, in SI units (amplitude m/s^2, omega rad/s, times s).
struct PulseArgs {
  double a_p = 0.0;       // [m/s^2] peak acceleration
  double omega_p = 0.0;   // [rad/s] circular frequency; 0 for a type without one
  double duration = 0.0;  // [s] length of the motion
  Component component = Component::kHorizontal;
  std::map<std::string, double, std::less<>> keys;  // extra keys given or defaulted
  /// The value of extra key `name`, if given or defaulted.
  std::optional<double> key(std::string_view name) const;
};

/// One synthetic motion type.
struct PulseKind {
  const char* name;      // type name in case files and spectrum specs ("one_sine")
  const char* function;  // the function of this header that makes it ("one_sine_pulse")
  bool frequency;        // takes frequency_hz or period (omega_p)
  std::vector<PulseKey> keys;
  GroundMotion (*make)(const PulseArgs& args);
  /// [s] length of the pulse at omega_p with default keys, where spectra start the free motion;
  /// nullptr: not a spectrum family (no frequency, or no end).
  double (*length)(double omega_p);
  const char* length_text;  // the length as the docs state it ("" without a length)
  bool ends;                // false: never quite ends (Ricker): nonzero up to the end of the motion
  const char* doc;          // one line: the acceleration
};

/// [s] the range of a pulse's period 2 pi/omega_p (or 1/frequency_hz): no ground or shake-table
/// motion is faster than 10 kHz, and one with a period of hours is a static tilt. make_pulse
/// refuses a period outside, naming it (a period of 1e-300 s would end in an overflow).
inline constexpr double kMinPulsePeriod = 1e-4;
inline constexpr double kMaxPulsePeriod = 1e4;

/// Every pulse type, in the order the docs list them.
const std::vector<PulseKind>& pulse_kinds();

/// The pulse type of a name; throws InputError listing the known names (and the closest one).
const PulseKind& pulse_kind(std::string_view name);

/// The names of the pulse types that spectra sweep (those with a length).
std::vector<std::string> spectrum_pulse_names();

/// Makes a pulse type from `args`, filling the fixed defaults of keys not given and refusing
/// keys the type does not have. Throws InputError as the pulse functions do.
GroundMotion make_pulse(const PulseKind& kind, PulseArgs args);

}  // namespace flexrock
