// SPDX-License-Identifier: BSD-3-Clause
// One simulation of a rigid body of revolution on a floor shaken in three components
// (docs/theory.md §27): full contact, rocking-rolling on the rim without slip, landing,
// overturning. Modes this engine does not model (flight, rim slip, full sliding) are detected and
// END the run, named in its status with their magnitude. Outcomes are returned, never thrown.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/model/axisymmetric_body.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock {

/// The floor's motion in three components: `h1` carries H1 along x (its horizontal) and the
/// vertical (its vertical), `h2` (may be null) H2 along y, 90 degrees from H1 toward which
/// azimuths are measured. Both must outlive the run.
struct FloorMotion {
  const GroundMotion* h1 = nullptr;
  const GroundMotion* h2 = nullptr;
};

/// The contact modes of the 3D automaton, in docs/theory.md §27's table.
enum class RimMode : int {
  kFullContact = 0,  // the base flat on the floor, sticking
  kRolling = 1,      // on the rim, rolling without slip: the contact is the lowest rim point
  kPivoting = 2,     // within kPivotZone of upright: pivoting on one material rim point
};

/// [rad] Within this tilt of upright the body pivots on one rim point instead of rolling (the
/// lowest rim point is undefined upright and races round the rim near it: docs/theory.md §27).
/// A pass by upright closer than this lands; in one plane pivoting and rolling are one motion.
inline constexpr double kPivotZone = 1e-12;

enum class RimStatus {
  kCompleted,   // reached the end time
  kOverturned,  // the tilt reached the overturning angle
  kUnmodelled,  // a mode this engine does not model began (flight, rim slip, full sliding)
  kStopped,     // the run could not go on (step collapse, step limit)
};

enum class RimEventKind {
  kUplift,       // full contact -> rolling on the rim point toward -a_h
  kLanding,      // pivoting, the tilt passed through upright: the landing map, pivoting on the
                 // opposite rim point
  kRest,         // a landing left no tilting rate toward the new contact, or the chatter
                 // criterion: full contact
  kOverturn,     // the tilt reached the overturning angle
  kLiftOff,      // the normal force reached zero: flight (not modelled, the run ends)
  kRimSlip,      // rolling: the friction demand reached mu (not modelled, the run ends)
  kFullSliding,  // full contact: the friction demand reached mu (not modelled, the run ends)
  kStopped,      // step collapse or step limit
};

const char* to_string(RimStatus s);
const char* to_string(RimEventKind k);
const char* to_string(RimMode m);

/// Where the body starts: upright at rest (full contact) unless tilted or moving. With a tilt or
/// rates it starts rolling on the rim point toward `azimuth`.
struct RimInitialState {
  double tilt = 0.0;         // theta [rad]
  double azimuth_deg = 0.0;  // phi [deg] the azimuth toward which the axis leans (the contact's),
                             // from x (H1) toward y (H2)
  double tilt_rate = 0.0;    // theta_dot [rad/s]
  double precession = 0.0;   // phi_dot [rad/s]
  double spin = 0.0;         // psi_dot [rad/s] spin relative to the tilt frame (Euler angles
                             // Rz(phi) Ry(theta) Rz(psi)): omega = phi_dot e_z + theta_dot e2 +
                             // psi_dot k
};

struct RimOptions {
  double t_end = -1.0;  // [s] < 0: the end of the motion
  double rtol = 1e-10;
  double atol = 1e-12;
  double max_step = 0.01;  // [s]
  int event_samples = 4;   // points per step where guards are checked
  double output_dt = 0.0;  // [s] 0: no history
  OverturnCriterion overturn = OverturnCriterion::kHalfPi;
  double chatter_ratio = 1e-4;  // landings closer than this times 2 pi / p end rocking
  double friction_coefficient = std::numeric_limits<double>::infinity();  // mu
  long max_steps = 50'000'000;
  // [rad] the pivot zone round upright (kPivotZone); for convergence checks: the answers do not
  // depend on it (tests/unit/axisymmetric_test.cpp)
  double pivot_zone = kPivotZone;
};

struct RimEvent {
  double time = 0.0;  // [s]
  RimEventKind kind = RimEventKind::kUplift;
  double tilt = 0.0;         // [rad]
  double azimuth = 0.0;      // [rad] of the contact (the new one after a landing)
  double rate_before = 0.0;  // [rad/s] |omega| before a landing
  double rate_after = 0.0;   // [rad/s] |omega| after
  double energy_loss = 0.0;  // [J]
  double value = 0.0;        // the magnitude: normal force over M g (lift-off), friction demand
                             // (slip), tilt (overturn)
};

struct RimHistory {
  std::vector<double> time;           // [s]
  std::vector<int> mode;              // RimMode
  std::vector<double> tilt, azimuth;  // theta [rad], phi [rad] (unwrapped)
  std::vector<double> contact_angle;  // [rad] the contact's angle on the base circle, body frame
                                      // (unwrapped: the rolling angle)
  std::vector<double> x, y;           // [m] base centre's offset on the floor from where it stood
  std::vector<double> reaction_x, reaction_y, reaction_z;           // [N] floor on body
  std::vector<double> friction_demand;                              // |F_h| / F_z [-]
  std::vector<double> kinetic, potential, input_work, impact_loss;  // [J]
  std::size_t size() const { return time.size(); }
};

struct RimResult {
  RimStatus status = RimStatus::kCompleted;
  std::string message;
  double t_end = 0.0;
  RimMode final_mode = RimMode::kFullContact;
  double final_tilt = 0.0;
  RimHistory history;
  std::vector<RimEvent> events;
  double max_tilt = 0.0;             // [rad]
  double max_tilt_azimuth = 0.0;     // [rad] azimuth of the contact at the largest tilt
  double max_offset = 0.0;           // [m] largest horizontal offset of the base centre
  double max_friction_demand = 0.0;  // [-] while in contact
  double min_normal_force = std::numeric_limits<double>::infinity();  // [N] while rolling
  // [rad] the smallest local minimum of the sampled tilt: a pass by upright that rolled round it
  // instead of landing (inf: none); where the response is sensitive (docs/theory.md §27)
  double closest_pass = std::numeric_limits<double>::infinity();
  long landings = 0;
  long uplifts = 0;
  EnergyBalance energy;
  long steps = 0, rhs_evaluations = 0;
};

/// The 3D engine's options from a planar run's (the [options] keys a case file gives both; the
/// pivot zone keeps its default): what `flexrock run` and the Python module run a case with.
RimOptions rim_options(const SimulationOptions& options);

/// Simulates `body` on a floor moving with `motion`. Bad options or bodies throw InputError.
RimResult simulate_axisymmetric(const AxisymmetricBody& body, const FloorMotion& motion,
                                const RimInitialState& initial = {},
                                const RimOptions& options = {});

}  // namespace flexrock
