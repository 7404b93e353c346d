// SPDX-License-Identifier: BSD-3-Clause
// Restraints of a rigid body on its floor (docs/theory.md, §26 "Restraints: tendons and anchors"):
// ties between a point of the foundation and a point of the body that pull (never push), elastic
// with a prestress or a slack, elastic-perfectly plastic past a yield force, and broken past a
// fracture elongation. Their forces enter the rocking equations as a generalised force from their
// potential; yield, unloading and fracture are events located like uplift.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "flexrock/sim/simulate.hpp"

namespace flexrock {

/// What a restraint is: one law (a tension-only elastic-plastic tie) with two sets of defaults.
enum class RestraintKind {
  kTendon,  // a post-tensioning tendon: prestressed, from the foundation to a point of the body
  kAnchor,  // an anchor bolt at a point of the base: a slack before it engages, a capacity
};

struct RestraintKindInfo {
  RestraintKind kind;
  const char* name;         // as written in case files and Python
  const char* description;  // one line, for `flexrock keys` and the docs
  const char* yielded;      // the damage state of one that yielded (sweeps, summaries)
  const char* fractured;    // the damage state of one that broke
};

inline constexpr RestraintKindInfo kRestraintKinds[] = {
    {RestraintKind::kTendon, "tendon",
     "a prestressed tie from the foundation to a point of the body (central by default)",
     "tendon yielded", "tendon fractured"},
    {RestraintKind::kAnchor, "anchor",
     "an anchor bolt at a point of the base, with a slack, a tension capacity and a fracture "
     "elongation",
     "anchor yielded", "anchor fractured"},
};

inline const RestraintKindInfo& restraint_kind_info(RestraintKind k) {
  return kRestraintKinds[k == RestraintKind::kTendon ? 0 : 1];
}

/// One tie from the floor point F to the body point P. Body axes: x along the base from the point
/// under the undeformed c.g., y up from the base; F in the same axes at rest (the floor's).
struct Restraint {
  RestraintKind kind = RestraintKind::kTendon;
  double body_x = 0.0;     // [m] P along the base
  double body_y = 0.0;     // [m] P above the base (>= 0)
  double floor_x = 0.0;    // [m] F along the floor
  double floor_y = 0.0;    // [m] F's height (<= 0: in the foundation); P != F at rest
  double stiffness = 0.0;  // [N/m] k (>= 0)
  double prestress = 0.0;  // [N] P_0: tension at rest (>= 0; tendons)
  double slack = 0.0;      // [m] s: elongation before it pulls (>= 0; anchors; not with P_0)
  double yield_force = std::numeric_limits<double>::infinity();  // [N] F_y > P_0; inf: elastic
  // [m] elongation past the slack at which it breaks; inf: never
  double fracture_elongation = std::numeric_limits<double>::infinity();
};

enum class RestraintEventKind {
  kYield,     // the force reached F_y: plastic flow begins
  kUnload,    // the elongation's rate reached zero while yielding: elastic again, e_p kept
  kFracture,  // the elongation past the slack reached the fracture elongation: the tie is gone
};
const char* to_string(RestraintEventKind k);

struct RestraintEvent {
  double time = 0.0;  // [s]
  int restraint = 0;  // index into the run's restraints (0-based)
  RestraintEventKind kind = RestraintEventKind::kYield;
  double force = 0.0;               // [N] just before the event
  double elongation = 0.0;          // [m] e = |P - F| - |P_0 - F|
  double plastic_elongation = 0.0;  // [m] e_p after the event
  double energy = 0.0;              // [J] fracture: the elastic energy released; otherwise 0
};

/// What one restraint did over a run.
struct RestraintSummary {
  double max_force = 0.0;           // [N]
  double max_elongation = 0.0;      // [m] largest e
  double final_force = 0.0;         // [N]
  double plastic_elongation = 0.0;  // [m] e_p at the end
  double plastic_work = 0.0;        // [J] F_y times the plastic elongation's growth
  double fracture_work = 0.0;       // [J] elastic energy released at fracture
  double yield_time = -1.0;         // [s] first yield; -1: never
  double fracture_time = -1.0;      // [s] -1: never
  bool yielded = false, fractured = false;
};

/// A run with restraints: the body's result (its energy balance with the ties' stored energy in
/// potential_change and their plastic and fracture work in the residual's sum) and the ties'.
struct RestrainedResult {
  SimulationResult result;
  std::vector<RestraintSummary> restraints;
  std::vector<RestraintEvent> events;
  // time history at result.history.time, row-major: restraints.size() values a row
  std::vector<double> force;          // [N]
  std::vector<double> elongation;     // [m]
  std::vector<double> energy;         // [J] elastic energy stored in each tie
  double stored_energy_change = 0.0;  // [J] the ties' elastic energy, end minus start
  double plastic_work = 0.0;          // [J] all ties
  double fracture_work = 0.0;         // [J] all ties
};

/// The checks simulate_restrained makes of the restraints (InputError naming the restraint,
/// 1-based, and its key): a rigid body, the impulsive floor without sliding, ties that make sense.
void validate_restraints(const Body& body, const std::vector<Restraint>& restraints,
                         const SimulationOptions& options);

/// Simulates a rigid body (no modes) tied down by `restraints` on a base moving with `motion`,
/// on the rigid floor with the chosen impact law. Flight (the floor's reaction reaching zero) is
/// not modelled with restraints: a run that reaches it stops and says so with the reaction.
RestrainedResult simulate_restrained(const Body& body, const std::vector<Restraint>& restraints,
                                     const GroundMotion& motion, const InitialState& initial = {},
                                     const SimulationOptions& options = {});

/// Statics of the restrained rigid body (docs/theory.md §26), with every tie elastic and intact.
/// The elongation e(theta) of `r` rocking on `edge` (1: theta >= 0) and its first two derivatives.
struct TieGeometry {
  double e, de, d2e;  // [m], [m/rad], [m/rad^2]
};
TieGeometry tie_geometry(const Body& body, const Restraint& r, int edge, double theta);
/// The tie's force [N] at elongation e (elastic, no plastic elongation, tension only).
double tie_force(const Restraint& r, double e);
/// The restoring moment about the pivot of `edge` at rotation theta (theta >= 0 on edge 1,
/// <= 0 on edge 2), gravity and ties, positive when it pushes the body back [N m].
double restoring_moment(const Body& body, const std::vector<Restraint>& restraints, int edge,
                        double theta);
/// The horizontal base acceleration [m/s^2, magnitude] that holds the body at theta (pushover).
double pushover_acceleration(const Body& body, const std::vector<Restraint>& restraints, int edge,
                             double theta);
/// The uplift threshold [m/s^2, magnitude] on `edge`: pushover_acceleration at theta = 0.
double uplift_acceleration(const Body& body, const std::vector<Restraint>& restraints, int edge);
/// The tie stiffness [N/m] above which the restoring moment stops softening after uplift on
/// `edge`: (M g h - T_0 e''(0) - sum of the others' T_0 e''(0)) / e'(0)^2 (the others as given).
double critical_stiffness(const Body& body, const std::vector<Restraint>& restraints, int which,
                          int edge);
/// The post-uplift rotational stiffness [N m/rad] on `edge`: dM_r/dtheta at 0+ (negative:
/// softening, as a free block's -M g h).
double self_centring_stiffness(const Body& body, const std::vector<Restraint>& restraints,
                               int edge);
/// The rigid body's angular acceleration [rad/s^2] rocking on `edge` at (theta, theta_dot) under
/// `base`, the ties elastic and intact: the engine's equation (tests).
double restrained_rocking_acceleration(const Body& body, const std::vector<Restraint>& restraints,
                                       int edge, double theta, BaseAcceleration base);

}  // namespace flexrock
