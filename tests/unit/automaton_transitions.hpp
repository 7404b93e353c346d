// SPDX-License-Identifier: BSD-3-Clause
// What the automaton transition test runs and how it reads a run: a scenario (a body, a sampled
// record of a horizontal sine and a vertical step, friction, an initial state) made through the
// public API, and the transitions a run's result shows, each as the mode it left (the history row
// before the event) and the guard the event's kind names.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "flexrock/model/builders.hpp"
#include "flexrock/sim/simulate.hpp"
#include "sim/automaton.hpp"

namespace flexrock::test {

/// A run built through the public API. The record is sampled (every kRecordDt): a rigid body rocks
/// by its Taylor series under it and a flexible body in full contact is propagated exactly, the
/// default steppers of a record (docs/theory.md §17, which stepper moves a mode).
struct Scenario {
  int modes = 0;         // 0: a rigid block; 1: an oscillator on a slab
  double alpha = 0.25;   // b / h of the block, or base width / (2 x height) of the slab body
  double freq_hz = 2.0;  // the oscillator's frequency
  double ax_g = 0.0;     // horizontal: ax_g g sin(2 pi fx t) for `cycles` cycles
  double fx_hz = 1.0;
  double cycles = 1.0;
  double ay_g = 0.0;  // vertical: ay_g g on [ty0, ty1]
  double ty0 = 0.0, ty1 = 0.0;
  double mu_s = std::numeric_limits<double>::infinity();  // friction; inf: none
  double mu_k = std::numeric_limits<double>::infinity();
  double theta0 = 0.0, theta_dot0 = 0.0;  // initial state [rad], [rad/s]
  bool static_overturn = false;           // overturn at the static angle, else pi/2
  double duration = 3.0;                  // [s] of record; the run ends there
};

inline constexpr double kRecordDt = 0.002;  // [s]
inline constexpr double kRowDt = 0.0005;    // [s] history spacing: finer than any mode seen

inline Body scenario_body(const Scenario& s) {
  if (s.modes == 0) return Body(BodyParameters::rectangular_block(100.0, s.alpha, 1.0));
  return Body(oscillator_on_slab(800.0, s.freq_hz, 400.0, 2.0, 4.0 * s.alpha, 0.02));
}

/// No motion at all where both amplitudes are zero (a rigid body then rocks by the closed form of
/// its arcs), else the sampled record.
inline GroundMotion scenario_motion(const Scenario& s) {
  if (s.ax_g == 0.0 && s.ay_g == 0.0) return GroundMotion::none(s.duration);
  const double g = kStandardGravity, w = 2.0 * std::numbers::pi * s.fx_hz;
  const auto n = static_cast<std::size_t>(std::lround(s.duration / kRecordDt)) + 1;
  std::vector<double> ax(n), ay(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * kRecordDt;
    ax[k] = t * s.fx_hz <= s.cycles ? s.ax_g * g * std::sin(w * t) : 0.0;
    ay[k] = t >= s.ty0 && t <= s.ty1 ? s.ay_g * g : 0.0;
  }
  return GroundMotion::uniform(kRecordDt, std::move(ax), std::move(ay));
}

/// `finer`: rtol and atol this many times smaller than the defaults.
inline SimulationResult run_scenario(const Scenario& s, double finer = 1.0) {
  InitialState init;
  init.theta = s.theta0;
  init.theta_dot = s.theta_dot0;
  SimulationOptions opt;
  opt.output_dt = kRowDt;
  opt.rtol /= finer;
  opt.atol /= finer;
  opt.friction_coefficient = s.mu_s;
  opt.kinetic_friction_coefficient = s.mu_k;
  opt.overturn =
      s.static_overturn ? OverturnCriterion::kStaticInstability : OverturnCriterion::kHalfPi;
  return simulate(scenario_body(s), scenario_motion(s), init, opt);
}

/// One transition a run shows: the mode it left, the guard that fired, the event, and the mode
/// it led to where the history shows it (the row after the event, no other change between).
struct Seen {
  ContactMode from;
  detail::Guard guard;
  Event event;
  std::optional<ContactMode> to;
};

/// Event kinds that end a mode (a reset that selects the next one).
inline bool changes_mode(EventKind k) {
  switch (k) {
    case EventKind::kUplift:
    case EventKind::kImpact:
    case EventKind::kRockingEnded:
    case EventKind::kChatterCutoff:
    case EventKind::kLiftOff:
    case EventKind::kLanding:
    case EventKind::kSlipStart:
    case EventKind::kStick:
    case EventKind::kSlipReversal:
    case EventKind::kOverturn:
      return true;
    default:
      return false;
  }
}

/// The guard whose reset records `e` in mode `from` (the automaton's table read backwards: uplift
/// on edge e is U_e, a landing is the lower corner's height), or none for an event that no guard
/// names (a record of a reset, not a reset) or a level landing (both corners at once).
inline std::optional<detail::Guard> guard_of(ContactMode from, const Event& e) {
  using detail::Guard;
  const bool flight = from == ContactMode::kFlight;
  switch (e.kind) {
    case EventKind::kUplift:
      return e.edge == 1 ? Guard::kUpliftEdge1 : Guard::kUpliftEdge2;
    case EventKind::kLiftOff:
      return Guard::kLiftOff;
    case EventKind::kSlipStart:
      return Guard::kFrictionLimit;
    case EventKind::kImpact:
    case EventKind::kRockingEnded:
      return Guard::kImpact;
    case EventKind::kChatterCutoff:
    case EventKind::kLanding:
      if (!flight) return Guard::kImpact;
      // theta > 0 puts corner 1 lowest
      if (e.theta == 0.0) return std::nullopt;
      return e.theta > 0.0 ? Guard::kLandingEdge1 : Guard::kLandingEdge2;
    case EventKind::kOverturn:
      return Guard::kOverturn;
    case EventKind::kPeak:
      return Guard::kPeak;
    case EventKind::kStick:
    case EventKind::kSlipReversal:
      return Guard::kSlipStop;
    default:
      return std::nullopt;
  }
}

/// The transitions a run shows by crossing a guard: an event whose mode is known from the history
/// row before it, with no other mode change between that row and the event. A transition that a
/// mode's entry state calls for at the same instant as the reset before it is not counted here: it
/// is no crossing.
inline std::vector<Seen> transitions(const SimulationResult& r) {
  std::vector<Seen> out;
  const History& h = r.history;
  for (std::size_t i = 0; i < r.events.size(); ++i) {
    const Event& e = r.events[i];
    // the last row strictly before the event
    const auto it = std::lower_bound(h.time.begin(), h.time.end(), e.time);
    if (it == h.time.begin()) continue;
    const auto row = static_cast<std::size_t>(it - h.time.begin()) - 1;
    bool clear = true;
    for (std::size_t j = 0; j < i && clear; ++j)
      if (r.events[j].time > h.time[row] && changes_mode(r.events[j].kind)) clear = false;
    if (!clear) continue;
    const auto from = static_cast<ContactMode>(h.phase[row]);
    const auto g = guard_of(from, e);
    if (!g) continue;
    // the first row strictly after the event, unless another change comes first
    std::optional<ContactMode> to;
    const auto after = std::upper_bound(h.time.begin(), h.time.end(), e.time);
    if (after != h.time.end()) {
      const auto next = static_cast<std::size_t>(after - h.time.begin());
      bool alone = true;
      for (std::size_t j = i + 1; j < r.events.size() && alone; ++j)
        if (r.events[j].time <= h.time[next] && changes_mode(r.events[j].kind)) alone = false;
      if (alone) to = static_cast<ContactMode>(h.phase[next]);
    }
    out.push_back({from, *g, e, to});
  }
  return out;
}

/// Whether a transition from `from` by guard `g` may lead to `to`: the "next mode" column of
/// docs/theory.md §17, written here from the table's words (pivot 0: full contact, 1 or 2: that
/// edge, -1: flight; slip 0: sticking, +1 / -1: sliding).
inline bool leads_where_the_table_says(ContactMode from, detail::Guard g, ContactMode to) {
  using detail::Guard;
  const detail::ModeSpec& a = detail::mode_spec(from);
  const detail::ModeSpec& b = detail::mode_spec(to);
  switch (g) {
    case Guard::kUpliftEdge1:  // rocking on edge 1, the slip kept
      return b.pivot == 1 && b.slip == a.slip;
    case Guard::kUpliftEdge2:
      return b.pivot == 2 && b.slip == a.slip;
    case Guard::kLiftOff:
      return to == ContactMode::kFlight;
    case Guard::kFrictionLimit:  // the same contact, sliding
      return b.pivot == a.pivot && b.slip != 0;
    case Guard::kImpact:  // the other edge, or both (sticking or sliding)
      return b.pivot == 0 || (b.pivot > 0 && b.pivot != a.pivot);
    case Guard::kLandingEdge1:  // a corner or both down, sticking or sliding
    case Guard::kLandingEdge2:
      return b.pivot >= 0;
    case Guard::kSlipStop:  // the same contact, sticking or sliding the other way
      return b.pivot == a.pivot && (b.slip == 0 || b.slip == -a.slip);
    case Guard::kPeak:  // recorded only
      return to == from;
    case Guard::kOverturn:  // terminal: no mode follows
      return false;
  }
  return false;
}

}  // namespace flexrock::test
