// SPDX-License-Identifier: BSD-3-Clause
// One simulation: a body on a moving base, from an initial state to the end of the motion or an
// outcome (overturned, stopped). Outcomes are returned, never thrown.
#pragma once

#include <atomic>
#include <limits>
#include <string>
#include <vector>

#include "flexrock/contact/compliant.hpp"
#include "flexrock/contact/impact.hpp"
#include "flexrock/core/types.hpp"
#include "flexrock/excitation/ground_motion.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/model/dynamics.hpp"

namespace flexrock {

/// When a run counts as overturned, in every contact mode (rocking or flight).
enum class OverturnCriterion {
  kHalfPi,             // |theta| reaches pi/2 (default: a body past its static overturning angle
                       // can still be brought back by a base motion that reverses)
  kStaticInstability,  // |theta| reaches the static overturning angle (paper eq. 5)
};

/// The contact modes of the hybrid automaton (docs/theory.md, "Contact modes and transitions").
enum class ContactMode : int {
  kFullContact = 0,   // theta = 0, both edges down
  kRockingEdge1 = 1,  // theta > 0, pivot on the left tipping point
  kRockingEdge2 = 2,  // theta < 0, pivot on the right tipping point
  kFlight = 3,        // no contact: the c.g. is ballistic relative to the base
  // with a finite friction coefficient the base can slide (docs/theory.md, "Sliding"): the slip
  // velocity d_dot of the base along I is positive (plus) or negative (minus)
  kSlidingPlus = 4,               // full contact, the base sliding along +I
  kSlidingMinus = 5,              // full contact, the base sliding along -I
  kRockingEdge1SlidingPlus = 6,   // rocking on edge 1, its pivot sliding along +I
  kRockingEdge1SlidingMinus = 7,  // rocking on edge 1, its pivot sliding along -I
  kRockingEdge2SlidingPlus = 8,   // rocking on edge 2, its pivot sliding along +I
  kRockingEdge2SlidingMinus = 9,  // rocking on edge 2, its pivot sliding along -I
};
using Phase = ContactMode;

enum class Status {
  kCompleted,   // reached the end time
  kOverturned,  // |theta| reached the overturning angle (OverturnCriterion), rocking or flying
  kStopped,     // the run could not go on; `message` says why
};

enum class EventKind {
  kUplift,              // full contact -> rocking on `edge`
  kImpact,              // rocking -> rocking on the landing `edge`
  kRockingEnded,        // an impact left both edges on the floor (the both-edges rule)
  kChatterCutoff,       // impacts came faster than the chatter criterion: set to full contact
  kPeak,                // a rocking amplitude: theta_dot = 0 while rocking
  kOverturn,            // overturning criterion met about `edge`
  kLiftOff,             // the vertical reaction reached zero: the body leaves the floor (flight)
  kLanding,             // a tipping point (`edge`; 0: both, flat) lands after a flight
  kFrictionExceeded,    // an impulse needed more friction than the coefficient: the sliding
                        // impact law applied (docs/theory.md, "Impacts with friction")
  kImpactGainedEnergy,  // an impact (with a restitution factor) added kinetic energy
  kStopped,             // step collapse, step or event limit
  kTensileLanding,      // a plastic landing needed a pulling impulse (`impulse_y` < 0): the
                        // sticking model breaks
  kPivotTension,        // the vertical reaction vanished but the body cannot fly off its sticking
                        // pivot (it would have to slide): the floor is let pull until it presses
                        // (`force_estimate`: the episode's most negative F_J [N])
  kEnergyUnbalanced,    // at the end: |energy residual| above its bound (`energy_loss`: residual)
  kSlipStart,           // the friction demand reached the static coefficient: the base slides
  kStick,               // the slip velocity reached zero and friction holds: sliding ends
  kSlipReversal,        // the slip velocity reached zero but friction cannot hold: it reverses
  kImpactLawFallback,   // the chosen impact law would have added energy: rigid_body (the modes
                        // move fast against theta_dot) took the paper's law, restitution the
                        // elastic ratio (docs/theory.md, "Impact laws")
};

/// The bound on the energy balance's residual that runs at the default tolerances meet
/// (docs/reliability.md): |residual| <= kEnergyResidualRelative * scale + kEnergyResidualFloor *
/// M g h. A run above it is flagged (`energy_unbalanced`, an `energy_unbalanced` event), not
/// stopped: its numbers are suspect (a loose rtol/atol, or a defect).
inline constexpr double kEnergyResidualRelative = 1e-5;
inline constexpr double kEnergyResidualFloor = 1e-10;

const char* to_string(Status s);
const char* to_string(EventKind k);
const char* to_string(ContactMode m);

/// Where the body starts. theta > 0 rocks on edge 1, theta < 0 on edge 2; theta = 0 with a
/// nonzero theta_dot rocks on the edge its sign lifts off; otherwise full contact.
struct InitialState {
  double theta = 0.0;      // [rad]
  double theta_dot = 0.0;  // [rad/s]
  VectorX q;               // [-] empty: the static deformation under gravity
  VectorX q_dot;           // [1/s] empty: zero
};

/// How the engine steps, kept for tests and comparisons: each switch picks between two methods
/// that give the same answer within the tolerances (the tests check that they do), at different
/// cost. The defaults are the engine's; no file sets them and Python exposes them as
/// SimulationOptions.methods.
struct SimulationMethods {
  // a flexible body in full contact under a sampled record is propagated exactly between the
  // samples (docs/theory.md, "Exact propagation in full contact"); false: integrated by DOPRI5
  bool exact_full_contact = true;
  // how the compliant contact is integrated: kAuto switches between DOPRI5 and a Rosenbrock
  // method as the springs' stiffness would hold the explicit step (tests force either)
  ContactIntegrator contact_integrator = ContactIntegrator::kAuto;
  // how a flexible body's rocking is integrated (docs/theory.md, "Stiff rocking"): kAuto switches
  // between DOPRI5 and the Rosenbrock method as the body's stiffest rocking motion would hold the
  // explicit step (tests force either)
  ContactIntegrator rocking_integrator = ContactIntegrator::kAuto;
  // factor on that motion's rate where the switch is decided (tests: the switch changes the
  // cost, not the answer)
  double stiff_switch_scale = 1.0;
  // with exact_full_contact, under a sampled record: the record is walked one exact update per
  // sample interval, the guards checked between samples by a bound on their excursion and the
  // extremes located there (docs/theory.md, "Walking the record"); false: every step of the
  // exact propagation is sampled at event_samples points, within a phase cap of the fastest mode
  bool full_contact_walk = true;
  // a rigid body's rocking under a sampled record, a pulse of sinusoids (GroundMotion::sinusoids)
  // or none is stepped by the Taylor series of its motion (docs/theory.md, "Rocking of a rigid body
  // by its Taylor series"); false: by DOPRI5
  bool series_rocking = true;
  // a flexible body's rocking, while its step is set by accuracy, is stepped by DOP853 (8th order,
  // dense output of order 7: about a quarter of DOPRI5's steps at the engine's tolerances;
  // docs/theory.md, "Stiff rocking"); false: by DOPRI5
  bool high_order_rocking = true;
  // a rigid body rocking freely on a floor at rest (after a record or a pulse, or with none) is
  // advanced by the closed form of its arcs, one step from one impact to the next (docs/theory.md,
  // "Free rocking in closed form"); false: by the Taylor series as under the record
  bool closed_form_free_rocking = true;
};

struct SimulationOptions {
  double t_end = -1.0;  // [s] end time; < 0: the end of the motion
  double rtol = 1e-9;   // relative tolerance of the integrator
  double atol = 1e-11;  // absolute tolerance (rad, -, rad/s, 1/s)
  // [s] cap on the step where events are sought by samples within each step (not on a rigid
  // body's rocking by its series, whose events are bounded over the whole step)
  double max_step = 0.01;
  int event_samples = 4;   // points per step where event functions are checked
  double output_dt = 0.0;  // [s] time-history spacing; 0: no time history
  OverturnCriterion overturn = OverturnCriterion::kHalfPi;
  // impacts closer than this times the shortest period end rocking (docs/theory.md, "Chatter")
  double chatter_ratio = 1e-4;
  double restitution_factor = 1.0;  // factor on theta_dot after an impact (1: the law's own)
  // how impacts and landings are resolved (docs/theory.md, "Impact laws")
  ImpactLaw impact_law = ImpactLaw::kPaper;
  // restitution law: theta_dot+/theta_dot- at an impact landing on edge 1, on edge 2 (0 to 1)
  double restitution_ratio_edge1 = 1.0;
  double restitution_ratio_edge2 = 1.0;
  // [s] the contact duration assumed to turn an impulse I into a force estimate: the peak of a
  // half-sine pulse, pi |I| / (2 duration)
  double impact_duration = 0.002;
  // Coulomb friction at the base (docs/theory.md, "Sliding"): the static coefficient mu_s; inf: the
  // floor holds whatever the demand (the paper's assumption; no sliding)
  double friction_coefficient = std::numeric_limits<double>::infinity();
  // the kinetic coefficient mu_k while sliding; inf: equal to the static one (mu_k <= mu_s)
  double kinetic_friction_coefficient = std::numeric_limits<double>::infinity();
  long max_steps = 50'000'000;              // integrator steps before the run stops
  long max_impacts = 10'000'000;            // impacts before the run stops
  std::atomic<double>* progress = nullptr;  // if set: the time reached [s], after every step
  // the floor (docs/theory.md, "Compliant contact"): impulsive (a rigid floor and the impact law)
  // or compliant (a no-tension spring-dashpot at each tipping point)
  ContactModel contact_model = ContactModel::kImpulsive;
  ContactForceLaw contact_force_law = ContactForceLaw::kLinear;
  double contact_stiffness = 0.0;  // [N/m^p] k of each tipping point's spring (compliant: > 0)
  double contact_exponent = 1.0;   // p: F ~ delta^p (linear: 1; Hertz-like: 1.5)
  // linear: the dashpot as a damping ratio of the body bouncing on both springs (1: critical)
  double contact_damping_ratio = 1.0;
  // the restitution of a free bounce (linear: sets the damping ratio; hunt_crossley: its
  // damping); < 0: not given
  double contact_restitution = -1.0;
  // [N/m] the sticking tipping point's horizontal spring at rest under half the weight (it scales
  // with the normal spring's force: docs/theory.md, "Compliant contact"), > 0; -1: not given, the
  // normal spring's secant stiffness there
  double contact_tangential_stiffness = -1.0;
  // how the engine steps: for tests and comparisons only (SimulationMethods)
  SimulationMethods methods;
};

/// Something that happened, in time order. Fields not meaningful for a kind are zero.
struct Event {
  double time = 0.0;  // [s]
  EventKind kind = EventKind::kUplift;
  int edge = 0;                   // 1 or 2: the pivot after uplift/impact, or the overturn side
  double theta = 0.0;             // [rad] (peaks)
  double theta_dot_before = 0.0;  // [rad/s] (impacts)
  double theta_dot_after = 0.0;   // [rad/s] (impacts)
  double energy_loss = 0.0;       // [J] (impacts, chatter cut-off)
  double impulse_x = 0.0;         // [N s] horizontal impulse of the floor (impacts)
  double impulse_y = 0.0;         // [N s] vertical impulse of the floor (impacts)
  double friction_demand = 0.0;   // |F_I|/F_J or |impulse_x|/impulse_y
  double offset = 0.0;            // [m] horizontal offset of the base from where it stood
  double force_estimate = 0.0;    // [N] impacts: pi |impulse| / (2 impact_duration)
};

/// Time history at the requested output times.
struct History {
  int modes = 0;
  std::vector<double> time;  // [s]
  std::vector<int>
      phase;  // contact mode: 0 full contact, 1 rocking on edge 1, 2 on edge 2, 3 flight
  std::vector<double> theta, theta_dot;        // [rad], [rad/s]
  std::vector<double> q, q_dot;                // [-], [1/s]; row-major, `modes` values a row
  std::vector<double> base_acc_x, base_acc_y;  // [m/s^2]
  std::vector<double> reaction_x, reaction_y;  // [N] floor on body, inertial I and J
  std::vector<double> resultant;        // [m] from the c.g. projection (full contact; else pivot)
  std::vector<double> friction_demand;  // |F_I|/F_J [-]
  std::vector<double> kinetic, potential;  // [J] relative kinetic; gravity + strain
  std::vector<double> input_work, damping_loss, impact_loss;  // [J] cumulative
  std::vector<double> offset;  // [m] horizontal offset of the base centre from where it stood
  std::vector<double> lift;    // [m] height of the lower tipping point above the floor
  std::size_t size() const { return time.size(); }
};

struct Extremes {
  double max_theta_edge1 = 0.0;  // [rad] largest tilt on edge 1 (theta > 0)
  double max_theta_edge2 = 0.0;  // [rad] largest tilt on edge 2, as a positive number
  double max_uplift = 0.0;       // [m] height of the lifted tipping point, (b1+b2) sin|theta|
  long impacts = 0;              // impacts, chatter cut-offs and landings included
  long chatter_cutoffs = 0;      // impacts ended by the chatter criterion
  double max_impulse = 0.0;      // [N s] largest vertical impulse
  double max_impact_energy_loss = 0.0;  // [J]
  VectorX max_abs_q;                    // [-] largest |q_i|
  double max_base_shear = 0.0;          // [N] largest |F_I|
  double max_overturning_moment =
      0.0;  // [N m] largest |moment of the reaction about the c.g. projection|
  double max_friction_demand = 0.0;  // [-] largest |F_I|/F_J while the floor presses, impulses
                                     // included (docs/theory.md, "Friction demand")
  double first_uplift_time = -1.0;   // [s] -1: never
  int first_uplift_edge = 0;
  double overturn_time = -1.0;  // [s] -1: did not overturn
  int overturn_edge = 0;
  long lift_offs = 0;              // times the body left the floor (flight)
  double flight_time = 0.0;        // [s] total time in flight
  double max_flight_height = 0.0;  // [m] largest height of the lower tipping point in flight
  double max_offset = 0.0;         // [m] largest |horizontal offset| of the base centre
  double sliding_time = 0.0;       // [s] total time with the base sliding
  long slips = 0;                  // times sliding started (from sticking or at an impulse)
  double max_impact_force = 0.0;   // [N] largest force estimate of an impact (impact_duration)
  long impact_law_fallbacks = 0;   // impacts where the chosen law would have added energy
  double max_contact_force = 0.0;  // [N] compliant contact: the largest normal force of a tipping
                                   // point (resolved, not estimated)
  // where the sticking-contact model breaks without a friction limit (docs/theory.md §15, §16):
  // the floor pulling on a held pivot (F_J < 0) and landings that need a pulling impulse
  long tension_episodes = 0;         // pivot_tension events: the floor began to pull
  double max_pivot_pull = 0.0;       // [N] largest pull on a held pivot, -min F_J (>= 0)
  double tension_time = 0.0;         // [s] total time with the floor pulling (F_J < 0 held)
  long tensile_landings = 0;         // landings and impacts that needed a pulling impulse
  double max_tensile_impulse = 0.0;  // [N s] largest pulling vertical impulse, -min I_y (>= 0)
};

/// Energy balance relative to the base [J]: residual = input_work - (kinetic_change +
/// potential_change + damping_loss + impact_loss + chatter_loss + friction_loss). Zero up to
/// integration error.
struct EnergyBalance {
  double input_work = 0.0;
  double kinetic_change = 0.0;
  double potential_change = 0.0;
  double damping_loss = 0.0;
  double impact_loss = 0.0;
  double chatter_loss = 0.0;
  double friction_loss = 0.0;  // work of friction while sliding (impulses' losses are impact_loss)
  double residual = 0.0;
  double scale = 0.0;  // largest energy magnitude seen, for a relative residual
};

struct SimulationResult {
  Status status = Status::kCompleted;
  std::string message;  // why it stopped, in words
  double t_end = 0.0;   // [s] time reached
  ContactMode final_phase = ContactMode::kFullContact;
  double final_theta = 0.0, final_theta_dot = 0.0;
  double final_offset = 0.0;  // [m] horizontal offset of the base centre at the end
  VectorX final_q, final_q_dot;
  bool friction_exceeded = false;     // the base slid (the demand reached the coefficient)
  bool chatter_cut_off = false;       // the chatter criterion ended rocking at least once
  bool impact_gained_energy = false;  // some impact added energy (restitution factor)
  bool pivot_tension = false;         // the floor pulled on a sticking pivot (no sliding modelled)
  History history;
  Extremes extremes;
  EnergyBalance energy;
  std::vector<Event> events;
  long steps = 0, rejected_steps = 0, rhs_evaluations = 0;
  bool energy_unbalanced = false;  // |energy.residual| above energy_residual_bound
};

/// The largest |energy residual| [J] a run of `body` with this energy scale may have
/// (kEnergyResidualRelative, kEnergyResidualFloor); a NaN residual is above any bound.
double energy_residual_bound(const Body& body, double scale);

/// The one overturning rule of every entry point (run, sweep, spectrum, Python): the engine's
/// status, set when |theta| reaches the criterion's angle in any contact mode.
inline bool overturned(const SimulationResult& r) { return r.status == Status::kOverturned; }

/// Simulates `body` on a base moving with `motion`. Invalid options or initial state throw
/// InputError; the physical outcome is in the result's status and events.
SimulationResult simulate(const Body& body, const GroundMotion& motion,
                          const InitialState& initial = {}, const SimulationOptions& options = {});

/// The checks simulate() makes of its options and initial state before it starts, alone: throws
/// the same InputError (naming the option). For callers that refuse bad options before any run.
void validate_options(const Body& body, const InitialState& initial,
                      const SimulationOptions& options);

/// The first reported output of `r` that is not finite, in words ("energy.input_work = inf");
/// empty when all are finite. Friction demands may be +inf (no normal force), never NaN.
/// simulate() ends a run with such an output as stopped, naming it; io writes no file of it.
std::string non_finite_output(const SimulationResult& r);

}  // namespace flexrock
