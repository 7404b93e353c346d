// SPDX-License-Identifier: BSD-3-Clause
// Intensity measures of an acceleration record: peak ground acceleration and velocity, and the
// elastic pseudo-spectral acceleration of a damped single-degree-of-freedom oscillator, computed
// exactly for the record taken as piecewise linear between its samples (Nigam & Jennings 1969,
// "Calculation of response spectra from strong-motion earthquake records", BSSA 59(2)).
#pragma once

#include <vector>

namespace flexrock {

/// Largest |a| over the samples [units of `a`].
double peak_ground_acceleration(const std::vector<double>& a);

/// Largest |v| of v(t) = integral of a from the first sample (v = 0 there), a piecewise linear
/// between the samples at times `t` [s]; v is then piecewise quadratic and its extrema inside a
/// step (where a changes sign) are included. No baseline correction. [units of a times s]
double peak_ground_velocity(const std::vector<double>& t, const std::vector<double>& a);

/// Relative displacement u at every sample of the oscillator u'' + 2 zeta omega u' + omega^2 u
/// = -a(t), at rest at the first sample, a piecewise linear between the samples: each step is
/// the exact solution (the particular solution of the linear segment plus the free vibration
/// that matches the state at its start), so the result has no discretisation error.
/// `omega` [rad/s] > 0, 0 <= `zeta` < 1. [units of a times s^2]
std::vector<double> sdof_displacement(const std::vector<double>& t, const std::vector<double>& a,
                                      double omega, double zeta);

/// Pseudo-spectral acceleration omega^2 max |u| of the oscillator of natural `period` [s] and
/// damping ratio `zeta`, over the record and one natural period of free vibration after it (the
/// peak of a long-period oscillator may come after the shaking), sampled at the record's steps.
/// [units of a]
double spectral_acceleration(const std::vector<double>& t, const std::vector<double>& a,
                             double period, double zeta = 0.05);

}  // namespace flexrock
