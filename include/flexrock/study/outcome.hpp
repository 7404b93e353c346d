// SPDX-License-Identifier: BSD-3-Clause
// The outcome of one run of a study, in the classes of the overturning-spectrum literature
// (Housner 1963; Zhang & Makris 2001): no uplift, rocking, overturned after impacts (their mode 1),
// overturned without impact (their mode 2).
#pragma once

#include "flexrock/core/enum_names.hpp"
#include "flexrock/model/body.hpp"
#include "flexrock/sim/simulate.hpp"

namespace flexrock::study {

enum class Outcome {
  kNoUplift,                 // the body never left full contact
  kRocking,                  // it uplifted (rocked) and did not overturn
  kOverturnedAfterImpacts,   // it overturned after at least one impact
  kOverturnedWithoutImpact,  // it overturned on its first uplift, with no impact before
  kStopped,                  // the run could not go on (step collapse, limits): see the message
};

/// The stable lower-case names of the outcomes, as the study CSVs write them.
inline constexpr EnumName<Outcome> kOutcomeNames[] = {
    {Outcome::kNoUplift, "no_uplift"},
    {Outcome::kRocking, "rocking"},
    {Outcome::kOverturnedAfterImpacts, "overturned_after_impacts"},
    {Outcome::kOverturnedWithoutImpact, "overturned_without_impact"},
    {Outcome::kStopped, "stopped"},
};
inline const char* to_string(Outcome o) { return name_of(kOutcomeNames, o); }

/// What the base did during a run (finite friction only): whether it slid and whether the body
/// uplifted (rocked or left the floor). An overturned body keeps its outcome; this says how it got
/// there.
enum class Regime {
  kNone,            // neither slid nor uplifted
  kSliding,         // slid, never uplifted
  kRocking,         // uplifted, never slid
  kSlidingRocking,  // both (in one mode, rocking on a sliding pivot, or in turn)
};

/// The stable lower-case names of the regimes, as the study CSVs write them.
inline constexpr EnumName<Regime> kRegimeNames[] = {
    {Regime::kNone, "none"},
    {Regime::kSliding, "sliding"},
    {Regime::kRocking, "rocking"},
    {Regime::kSlidingRocking, "sliding_rocking"},
};
inline const char* to_string(Regime r) { return name_of(kRegimeNames, r); }

/// The solver options a study starts from: the engine's, whose overturning rule (|theta| = pi/2)
/// is that of every entry point. Under a pulse or record that reverses, a body past its static
/// overturning angle (paper eq. 5) can still be brought back, so that criterion would put the
/// overturning boundary too low (some 17% low for the one-sine pulse at omega_p/p = 4,
/// alpha = 0.15: docs/validation.md).
inline SimulationOptions study_solver_defaults() { return SimulationOptions{}; }

/// True for both overturning classes.
inline bool overturned(Outcome o) {
  return o == Outcome::kOverturnedAfterImpacts || o == Outcome::kOverturnedWithoutImpact;
}

/// What a study keeps of one simulation.
struct RunSummary {
  Outcome outcome = Outcome::kNoUplift;
  Status status = Status::kCompleted;
  double max_theta_over_alpha = 0.0;  // [-] max over both edges of max|theta| / tipping angle
  double max_theta = 0.0;             // [rad] largest |theta| on either edge
  long impacts = 0;  // impacts before the end (chatter cut-offs and landings included); the
                     // run ends at an overturn, so these are the impacts before it
  double first_uplift_time = -1.0;   // [s] -1: never
  double overturn_time = -1.0;       // [s] -1: did not overturn
  int overturn_edge = 0;             // 1 or 2; 0: did not overturn
  double max_impulse = 0.0;          // [N s] largest vertical impact impulse
  double energy_lost = 0.0;          // [J] impacts + chatter cut-offs + material damping
  double max_friction_demand = 0.0;  // [-] largest |F_I|/F_J, impulses included
  double max_uplift = 0.0;           // [m] largest height of a lifted tipping point
  double t_end = 0.0;                // [s] time reached
  // sliding (zero without friction): Extremes::max_offset, SimulationResult::final_offset,
  // Extremes::sliding_time, Extremes::slips
  double max_offset = 0.0;        // [m] peak |offset| of the base from where it stood
  double final_offset = 0.0;      // [m] residual offset at the end (signed)
  double sliding_time = 0.0;      // [s] time spent sliding
  long slips = 0;                 // slip starts
  Regime regime = Regime::kNone;  // slid and/or uplifted
  // where the sticking-contact model broke (no friction limit): Extremes' fields of those names
  long tension_episodes = 0;         // pivot_tension events
  double max_pivot_pull = 0.0;       // [N] largest pull of the floor on a held pivot (-min F_J)
  double tension_time = 0.0;         // [s] time the floor pulled
  long tensile_landings = 0;         // landings/impacts that needed a pulling impulse
  double max_tensile_impulse = 0.0;  // [N s] largest such pull (-min I_y)
};

/// Classifies a finished simulation: overturned with zero impacts (Extremes::impacts, which
/// counts every impact, chatter cut-off and landing in full contact; overturning ends the run)
/// is "without impact", with one or more "after impacts"; otherwise rocking if it uplifted with a
/// tilt > 0, else no uplift (an uplift event without any tilt, where the base acceleration only
/// touches the static threshold, is no rocking). Tilts are normalised by Body::tipping_angle(edge)
/// (atan(b/h) for a rigid body). The regime: slid if the base ever slipped (Extremes::slips or
/// sliding_time > 0), uplifted by the same test as rocking above (or overturned).
RunSummary summarize(const Body& body, const SimulationResult& result);

}  // namespace flexrock::study
