// SPDX-License-Identifier: BSD-3-Clause
// The classical hand estimates a reviewer sets beside a numerical qualification of an unanchored
// body: the quasi-static uplift and sliding thresholds, Housner's (1963) rectangular-pulse and
// energy (velocity-pulse) overturning estimates for a rigid body, and Newmark's (1965) rigid
// sliding block. Each is a closed form or an exact integration written independently of the
// engine, with its validity range stated where it is returned. No files here.
#pragma once

#include <span>

#include "flexrock/model/body.hpp"

namespace flexrock::study {

/// The rigid-body constants of rocking about one edge: the pivot-to-c.g. distance R, the angle
/// alpha between R and the vertical, p^2 = M g R / I_O and I_O = I_cg + M R^2 about the pivot.
/// For a body with modes, those of the body taken rigid (its modes dropped).
struct RockingConstants {
  double R = 0.0;      // [m] pivot to c.g.
  double alpha = 0.0;  // [rad] atan(b/h)
  double p = 0.0;      // [rad/s] sqrt(M g R / I_O)
  double I_O = 0.0;    // [kg m^2] rotary inertia about the pivot
};
RockingConstants rocking_constants(const BodyParameters& body, int edge);

/// Quasi-static uplift threshold onto `edge` [m/s^2]: g b/h with b the c.g.'s distance to the
/// other edge's side, i.e. g b1/h lifts onto edge 1 (exact for a rigid body at rest on a rigid
/// floor under a steady acceleration; a flexible body's dynamic threshold differs).
double uplift_threshold(const BodyParameters& body, int edge);

/// Quasi-static sliding threshold mu_s g [m/s^2] (exact for a rigid body in full contact under a
/// steady acceleration, when mu_s < b/h: else it uplifts first).
double sliding_threshold(double mu_s, double g);

/// Housner (1963), linearized rocking theta'' = p^2 (theta - alpha + a/g) of a rigid body at
/// rest under a rectangular acceleration pulse of duration t1: the smallest amplitude that
/// overturns it, a_min = g alpha / (1 - exp(-p t1)) [m/s^2]. Exact for the linearized equation;
/// the nonlinear body differs by O(alpha^2) (slender bodies: alpha <~ 0.25).
double housner_rectangular_min_amplitude(const RockingConstants& c, double g, double t1);
/// Its inverse: the shortest rectangular pulse of amplitude a [m/s^2] that overturns the body,
/// t1 = -ln(1 - g alpha / a) / p [s]; +inf when a <= g alpha (no pulse length suffices).
double housner_rectangular_min_duration(const RockingConstants& c, double g, double a);

/// Housner's energy criterion for an impulsive base velocity change V: the c.g.'s pivot
/// angular momentum M h V gives the kinetic energy (M h V)^2 / (2 I_O), which overturns the body
/// when it exceeds the barrier M g R (1 - cos alpha). Returns the critical V [m/s]. Exact for
/// an impulse (a pulse much shorter than 1/p); a longer single pulse gives less energy (the
/// estimate is on the safe side for one pulse), repeated pulses in phase can give more.
double housner_critical_velocity(const RockingConstants& c, double mass, double height, double g);

/// Newmark (1965) rigid sliding block under a rectangular pulse A over t1 (A > mu g, mu_s =
/// mu_k = mu): the relative displacement |d| = A (A - mu g) t1^2 / (2 mu g) [m]; 0 if A <= mu g.
double newmark_rectangular_displacement(double A, double t1, double mu, double g);

/// What a two-way Newmark sliding block did under a record.
struct NewmarkResult {
  double max_offset = 0.0;    // [m] largest |d|, d the block's displacement relative to the floor
  double final_offset = 0.0;  // [m] d at the end (signed, along +x)
  double sliding_time = 0.0;  // [s]
  long slips = 0;             // times sliding started, a reversal included (as the engine counts)
};

/// Newmark's rigid block on a floor with Coulomb friction (static mu_s, kinetic mu_k <= mu_s),
/// sliding both ways (d'' = -a - mu_k g sgn(d') while sliding; it sticks when d' = 0 and |a| <=
/// mu_s g), integrated exactly for the acceleration a(t) [m/s^2] piecewise linear between the
/// samples (t_i, a_i) (times non-decreasing; two equal times make a jump). No rocking: valid for
/// a body that does not uplift (peak a < g b/h).
NewmarkResult newmark_sliding(std::span<const double> t, std::span<const double> a, double mu_s,
                              double mu_k, double g);

}  // namespace flexrock::study
