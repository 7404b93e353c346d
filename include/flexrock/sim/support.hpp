// SPDX-License-Identifier: BSD-3-Clause
// A rigid block on a support that moves with it (docs/theory.md §24): the support, of mass m_s,
// is driven by the ground through a horizontal spring and dashpot; the block's reactions and its
// impacts act back on it. Its own event loop (src/sim/support_sim.cpp), beside the single body's.
#pragma once

#include <string>
#include <vector>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {

/// The support under the body: a mass on a horizontal spring and dashpot to the ground (the
/// vertical is rigid: the support carries the ground's vertical motion).
struct SupportParameters {
  double mass = 0.0;          // m_s [kg], >= 0 (0: a massless spring-dashpot under the body)
  double stiffness = 0.0;     // k [N/m], > 0
  double damping = 0.0;       // c [N s/m], >= 0
  double displacement = 0.0;  // u(0) [m] relative to the ground at the start
  double velocity = 0.0;      // u_dot(0) [m/s] relative to the ground at the start

  /// From the coupled system's frequency and damping ratio with the body as a rigid mass
  /// `body_mass` on it: k = (m_s + M) (2 pi f)^2, c = 2 zeta sqrt(k (m_s + M)).
  static SupportParameters from_frequency(double mass, double body_mass, double frequency_hz,
                                          double damping_ratio);
};

/// The support's time history, on the body's output times.
struct SupportHistory {
  std::vector<double> displacement;  // u [m] relative to the ground
  std::vector<double> velocity;      // u_dot [m/s] relative to the ground
  std::vector<double> acceleration;  // [m/s^2] absolute (ground + u_ddot): the body's base
  std::vector<double> force;         // [N] k u + c u_dot: the spring and dashpot on the ground
};

struct SupportExtremes {
  double max_displacement = 0.0;    // [m] largest |u|
  double max_velocity = 0.0;        // [m/s] largest |u_dot| (at the samples and events)
  double max_force = 0.0;           // [N] largest |k u + c u_dot| (at the samples and events)
  double final_displacement = 0.0;  // [m]
  double final_velocity = 0.0;      // [m/s]
};

/// The body's result (its outputs as on a rigid floor: the reaction is the support's on the body,
/// the energy balance the body's and the support's together) and the support's.
struct SupportRunResult {
  SimulationResult body;
  SupportHistory history;
  SupportExtremes support;
};

/// The coupled system's frequency and damping ratio with the body as a rigid mass on the support.
struct SupportFrequencies {
  double frequency_hz = 0.0;   // sqrt(k / (m_s + M)) / 2 pi
  double damping_ratio = 0.0;  // c / (2 sqrt(k (m_s + M)))
};
SupportFrequencies support_frequencies(const Body& body, const SupportParameters& s);

/// The transmissibility |T(r)| of the support's absolute acceleration in steady harmonic motion
/// at `frequency_hz`, with the body as a rigid mass (docs/theory.md §24).
double support_transmissibility(const Body& body, const SupportParameters& s, double frequency_hz);

/// The smallest amplitude [m/s^2] of a steady harmonic ground acceleration at `frequency_hz` that
/// uplifts the block standing on the support: g min(alpha_1, alpha_2) / |T(r)|.
double support_uplift_amplitude(const Body& body, const SupportParameters& s, double frequency_hz);

/// Throws InputError when the run cannot be made on a support: bad support parameters, or a
/// configuration the support's engine does not model (a flexible body, the compliant contact,
/// sliding: a finite friction coefficient), naming it.
void validate_support(const Body& body, const SupportParameters& s, const InitialState& initial,
                      const SimulationOptions& options);

/// Simulates the rigid `body` standing on the support under the ground motion. Full contact,
/// rocking on either edge, impacts (the block's moment of momentum about the landing corner and the
/// linear momentum of block and support) and overturning are modelled; a run whose block would
/// leave the support (its vertical reaction reaching zero) ends as stopped, saying so.
SupportRunResult simulate(const Body& body, const SupportParameters& support,
                          const GroundMotion& motion, const InitialState& initial = {},
                          const SimulationOptions& options = {});

}  // namespace flexrock
