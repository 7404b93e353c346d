// SPDX-License-Identifier: BSD-3-Clause
// Intensity measures of an acceleration record: peak ground acceleration, velocity and
// displacement, Arias intensity, cumulative absolute velocity, significant duration, and the
// elastic pseudo-spectral acceleration of a damped single-degree-of-freedom oscillator, computed
// exactly for the record taken as piecewise linear between its samples (Nigam & Jennings 1969,
// "Calculation of response spectra from strong-motion earthquake records", BSSA 59(2)).
// kIntensityMeasures lists them once: the sweep columns, the fragility intensity measures, the
// docs and the Python bindings are written from it.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "flexrock/excitation/ground_motion.hpp"

namespace flexrock {

/// The largest |Xddot| and |Yddot| of a motion [m/s^2]: over the samples of a sampled motion;
/// for an analytic one at 20001 even times over [0, duration] and at every breakpoint (where
/// pulses start, end and kink). The one statement of a motion's peak (summary JSON, Python,
/// the studies' overflow checks).
BaseAcceleration peak_acceleration(const GroundMotion& motion);

/// Largest |a| over the samples [units of `a`].
double peak_ground_acceleration(const std::vector<double>& a);

/// Largest |v| of v(t) = integral of a from the first sample (v = 0 there), a piecewise linear
/// between the samples at times `t` [s]; v is then piecewise quadratic and its extrema inside a
/// step (where a changes sign) are included. No baseline correction. [units of a times s]
double peak_ground_velocity(const std::vector<double>& t, const std::vector<double>& a);

/// Largest |v| over the samples, v the trapezoidal integral of a from 0 at the first sample (the
/// velocity at the samples of a piecewise-linear a; a peak between two samples is not sought):
/// the PGV a sweep writes. [units of a times s]
double peak_sampled_velocity(const std::vector<double>& t, const std::vector<double>& a);

/// Largest |d| of d(t), the double integral of a from rest (d = v = 0 at the first sample), a
/// piecewise linear: d is piecewise cubic and its extrema inside a step (where v changes sign)
/// are included. No baseline correction. [units of a times s^2]
double peak_ground_displacement(const std::vector<double>& t, const std::vector<double>& a);

/// Arias intensity pi/(2 g) integral of a^2 dt, exact for a piecewise linear, `a` in m/s^2 and
/// `g` [m/s^2]. [m/s]
double arias_intensity(const std::vector<double>& t, const std::vector<double>& a);

/// Cumulative absolute velocity: integral of |a| dt, exact for a piecewise linear (a step where
/// a changes sign is split at its zero). No threshold. [units of a times s]
double cumulative_absolute_velocity(const std::vector<double>& t, const std::vector<double>& a);

/// Significant duration: the time between the instants at which the integral of a^2 reaches
/// `from` and `to` of its total (Trifunac & Brady 1975: 5 % and 95 %), exact for a piecewise
/// linear (the integral is a cubic in each step). 0 for a record of zeros. [s]
double significant_duration(const std::vector<double>& t, const std::vector<double>& a,
                            double from = 0.05, double to = 0.95);

/// Relative displacement u at every sample of the oscillator u'' + 2 zeta omega u' + omega^2 u
/// = -a(t), at rest at the first sample, a piecewise linear between the samples: each step is
/// the exact solution (the particular solution of the linear segment plus the free vibration
/// that matches the state at its start), so the result has no discretisation error.
/// `omega` [rad/s] > 0, 0 <= `zeta` < 1. [units of a times s^2]
std::vector<double> sdof_displacement(const std::vector<double>& t, const std::vector<double>& a,
                                      double omega, double zeta);

/// The shortest period a spectral acceleration takes [s]: a 1 MHz oscillator follows any record
/// (Sa is its PGA); far below it omega^2 and omega^3 overflow.
inline constexpr double kMinSpectralPeriod = 1e-6;

/// Throws InputError naming `key` unless `period` is finite and >= kMinSpectralPeriod.
void require_spectral_period(double period, const std::string& key);

/// The largest |u| of the oscillator's free vibration from (u0, v0) sampled at s = k h, k = 1,
/// 2, ..., ceil(period / h) (one natural period), in closed form from the extrema of u (wd s =
/// atan2(v0 q, w u0 + z v0) mod pi, q = sqrt(1 - z^2)): its cost does not grow with the period.
double free_vibration_peak(double u0, double v0, double omega, double zeta, double h,
                           double period);

/// Pseudo-spectral acceleration omega^2 max |u| of the oscillator of natural `period` [s] and
/// damping ratio `zeta`, over the record and one natural period of free vibration after it (the
/// peak of a long-period oscillator may come after the shaking), sampled at the record's steps.
/// Any period >= kMinSpectralPeriod, in a time that does not depend on it. As the period grows
/// the mass stays still (u -> minus the ground displacement) and, when the record ends with a
/// ground velocity v_end != 0, Sa tends to omega |v_end| e^(-zeta acos(zeta) / sqrt(1 -
/// zeta^2)), the peak of the free vibration that brings the oscillator back: to 0 as 1/T.
/// [units of a]
double spectral_acceleration(const std::vector<double>& t, const std::vector<double>& a,
                             double period, double zeta = 0.05);

/// Orientation-independent spectral accelerations of two orthogonal horizontal components (Boore
/// 2010, "Orientation-independent, nongeometric-mean measures of seismic intensity from two
/// horizontal components of motion", BSSA 100(4)): for each rotation angle theta = 0, 1, ...,
/// 179 degrees the oscillator's peak response to the rotated component a1 cos(theta) + a2
/// sin(theta), as spectral_acceleration() computes it (over the record and one period of free
/// vibration after it, sampled at the record's steps). The oscillator is linear, so the rotated
/// response is u1 cos(theta) + u2 sin(theta) of the two responses, computed once.
struct RotD {
  double rotd50 = 0.0;   // median over the 180 angles (mean of the two middle values) [units of a]
  double rotd100 = 0.0;  // largest over the angles [units of a]
  std::vector<double> by_angle;  // Sa at theta = 0, 1, ..., 179 degrees [units of a]
};

/// RotD50 and RotD100 of the peak acceleration of the pair (a1, a2) [units of a]: for each angle
/// theta = 0, 1, ..., 179 degrees the largest |a1 cos(theta) + a2 sin(theta)| over the samples
/// (exact on the samples, no oscillator). Throws InputError when the two differ in length.
RotD rotd_peak_acceleration(const std::vector<double>& a1, const std::vector<double>& a2);

/// RotD50 and RotD100 of the pair (a1, a2) sampled at the same times `t` [s], at natural
/// `period` [s] and damping ratio `zeta`. Throws InputError when the two differ in length.
RotD rotd_spectral_acceleration(const std::vector<double>& t, const std::vector<double>& a1,
                                const std::vector<double>& a2, double period, double zeta = 0.05);

/// One intensity measure of the table: its name (as `flexrock fragility --im`, a sweep manifest's
/// [intensity] measures and Python give it), the sweep CSV column it is written to, its unit and
/// meaning, how it grows with a scale factor s on the record (value(s a) = s^power value(a)), and
/// the function that computes it in SI units from a record in m/s^2 (`period` [s] and `zeta`
/// only for the spectral acceleration, whose column is named for them: spectral_column()).
struct IntensityMeasure {
  const char* name;
  const char* column;  // sweep CSV column ("" for sa: spectral_column names it)
  const char* unit;
  const char* doc;
  int scale_power;      // [-] 1, 2 (Arias) or 0 (durations, ratios)
  bool needs_period;    // sa: a period and a damping ratio
  bool always_written;  // pga, pgv: every sweep row has them
  double (*compute)(const std::vector<double>& t, const std::vector<double>& a, double period,
                    double zeta);
};

/// Every intensity measure, in the order of the sweep columns and of the docs.
std::span<const IntensityMeasure> intensity_measures();

/// The measure of that name, or nullptr.
const IntensityMeasure* find_intensity_measure(std::string_view name);

/// The sweep CSV column of Sa at `period` [s] and damping ratio `zeta`:
/// "sa_T<period>_z<zeta>_m_per_s2", numbers as their shortest round-trip text (e.g.
/// sa_T0.5_z0.05_m_per_s2).
std::string spectral_column(double period, double zeta);

}  // namespace flexrock
