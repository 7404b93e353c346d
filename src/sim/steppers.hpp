// SPDX-License-Identifier: BSD-3-Clause
// The steppers of the event loop: each owns the integrator and the scratch it keeps between steps,
// and the loop holds the one stepping the current mode in a std::variant, with one dispatch
// (Simulator::on_stepper). Which stepper steps which mode, body and motion is the table in
// docs/theory.md §17. The still path, the Taylor series and the closed-form arc exist only in the
// rigid body's loop (N = 0), the exact propagation and its record walk only in a flexible body's:
// a loop compiles the steppers it can run and no other. Internal header.
#pragma once

#include <array>
#include <concepts>
#include <limits>
#include <vector>

#include "contact_propagator.hpp"
#include "flexrock/integrate/dopri5.hpp"
#include "flexrock/integrate/stiff_switching.hpp"
#include "free_rocking_arc.hpp"
#include "rocking_series.hpp"
#include "series_guards.hpp"

namespace flexrock::detail {

// where and why a stepper stopped: at the end of a step with the run going on (kStepped), at a
// resetting guard's crossing (kGuard: the loop applies the reset of mode_spec(mode).guards[slot];
// a stepper never fires one), or where the run ends (kEnded: the step limit, a collapsed step, an
// inconsistent slide, the status says which). The time and state it stopped at are advance()'s t
// and x.
struct StepEnd {
  enum class Why : unsigned char { kStepped, kGuard, kEnded };
  Why why = Why::kStepped;
  int slot = -1;  // the guard's slot in the mode's list (kGuard)
  static StepEnd stepped() { return {}; }
  static StepEnd guard(int slot) { return {Why::kGuard, slot}; }
  static StepEnd ended() { return {Why::kEnded, -1}; }
  // from a step that either went on (true) or ended the run (false)
  static StepEnd ran(bool running) { return running ? stepped() : ended(); }
};

// What the loop asks of a stepper (the loop is the step context: the mode's equations and guards,
// the recorder, the options, the end time):
//   start(loop, t, x)              take the current mode's motion from the state x at t
//   advance(loop, t, x) -> StepEnd advance toward the next stop time (the step's end, the end
//                                  time, the motion's next breakpoint) and return where (t, x) and
//                                  why it stopped: a guard that crossed is returned, not reset
//   stepped_until() -> double      [s] the end of the last step taken
//   state_at(eq, t, out)           the state at t within the last step, from the stepper's own
//                                  dense output and the equations' state layout (ModeEquations)
template <class S, class Loop, class Eq, class State>
concept LoopStepper = requires(S& s, const S& cs, Loop& loop, const Eq& eq, double& t, double tt,
                               State& x) {
  { s.start(loop, tt, x) } -> std::same_as<void>;
  { s.advance(loop, t, x) } -> std::same_as<StepEnd>;
  { cs.stepped_until() } -> std::same_as<double>;
  { cs.state_at(eq, tt, x) } -> std::same_as<void>;
};

// a stepper a loop of this body size never runs: nothing, whatever it is built from
struct AbsentStepper {
  AbsentStepper() = default;
  template <class... A>
  explicit AbsentStepper(A&&...) {}
};

// a rigid body in full contact: nothing integrates, the state stays x until a guard crosses
// (Simulator::advance_still)
template <class State>
struct StillStepper {
  State x;
  double t1 = 0.0;  // [s] the end of the span checked last
  template <class Loop>
  void start(Loop&, double t, State& s) {
    x = s;
    t1 = t;
  }
  template <class Loop>
  StepEnd advance(Loop& loop, double& t, State& s) {
    return loop.advance_still(t, s);
  }
  double stepped_until() const { return t1; }
  template <class Eq>
  void state_at(const Eq&, double, State& out) const {
    out = x;
  }
};

// a flexible body in full contact under a record or none: the exact propagation between the
// record's samples, walked sample to sample where no guard can cross (Simulator::advance_walk)
template <int N, int MaxN, class State>
struct ExactStepper {
  using Vec = typename Dynamics<N, MaxN>::Vec;
  ExactStepper(const Dynamics<N, MaxN>& dyn, const GroundMotion& motion, int samples,
               double max_step, bool exact)
      : prop(dyn, motion, samples, max_step, exact) {}
  ContactPropagator<N, MaxN, State> prop;
  State buf;                 // scratch: the propagation's dense output
  State xw, xe;              // the walk's state at its piece's start and end
  double fine_until = -1.0;  // [s] the walk resumes once the stepped propagation reaches it
  Vec ua, ub;                // scratch: u at a walk's piece's start and end
  std::array<Vec, 5> qjet;   // scratch: q and its first four derivatives in a walk's piece
  std::vector<int> wanted;   // the walk's extremes search: the quantities sought
  std::vector<double> best, best_at;  // their largest values found, and where [s]
  std::array<double, 4> forcing{};    // the piece's max |a_x|, |a_y|, |a_x'|, |a_y'|
  template <class Loop>
  void start(Loop&, double t, State& x) {
    prop.start(t, x);
  }
  template <class Loop>
  StepEnd advance(Loop& loop, double& t, State& x) {
    return loop.advance_exact(t, x);
  }
  double stepped_until() const { return prop.t1(); }
  template <class Eq>
  void state_at(const Eq&, double t, State& out) const {
    prop.dense(t, out);
  }
};

// a rigid body rocking under a record, sinusoids or none: its Taylor series, guards bounded over
// the step (Simulator::advance_series); the guards and observed quantities as polynomials in tau
template <class ContactState>
struct SeriesStepper {
  explicit SeriesStepper(const GroundMotion& motion) : integ(motion) {}
  RockingSeries<ContactState> integ;
  mutable ContactState buf;  // the series' start, and scratch for the dense output
  StepPolynomial sp_impact, sp_overturn, sp_peak, sp_fi, sp_fj, sp_moment, sp_work;
  template <class Loop, class State>
  void start(Loop& loop, double t, State& x) {
    loop.start_series(t, x);
  }
  template <class Loop, class State>
  StepEnd advance(Loop& loop, double& t, State& x) {
    return loop.advance_series_step(t, x);
  }
  double stepped_until() const { return integ.t1(); }
  template <class Eq, class State>
  void state_at(const Eq& eq, double t, State& out) const {
    integ.dense(t, buf);
    eq.put(buf, out);
  }
};

// a rigid body rocking freely on a floor at rest: the arc in closed form (Simulator::advance_arc)
template <class ContactState>
struct ArcStepper {
  FreeRockingArc<ContactState> arc;
  mutable ContactState buf;  // scratch for the dense output
  template <class Loop, class State>
  void start(Loop&, double, State&) {}  // started by the series, which found the floor at rest
  template <class Loop, class State>
  StepEnd advance(Loop& loop, double& t, State& x) {
    return loop.advance_arc(t, x);
  }
  double stepped_until() const { return arc.t1(); }
  template <class Eq, class State>
  void state_at(const Eq& eq, double t, State& out) const {
    arc.dense(t, buf);
    eq.put(buf, out);
  }
};

// any other sticking contact mode (rocking, or full contact under pulses): DOPRI5, DOP853 or the
// Rosenbrock method while a flexible body's stiffest rocking motion would hold the explicit step
template <class ContactState>
struct RockingStepper {
  StiffSwitching<ContactState> integ;
  mutable ContactState buf;                    // the mode's start, and scratch for the dense output
  std::array<double, 2> h_stable{-1.0, -1.0};  // [s] per edge, once known (< 0: not yet)
  template <class Loop, class State>
  void start(Loop& loop, double t, State& x) {
    loop.start_rocking(t, x);
  }
  template <class Loop, class State>
  StepEnd advance(Loop& loop, double& t, State& x) {
    return loop.advance_rocking(t, x);
  }
  double stepped_until() const { return integ.t1(); }
  template <class Eq, class State>
  void state_at(const Eq& eq, double t, State& out) const {
    integ.dense(t, buf);
    eq.put(buf, out);
  }
};

// flight (Sys: FlightState) or a sliding mode (SlideState): DOPRI5 on the mode's own state
template <class SubState, int Kind>
struct OdeStepper {
  Dopri5<SubState> integ;
  mutable SubState buf;  // the mode's state, and scratch for the dense output
  template <class Loop, class State>
  void start(Loop& loop, double t, State& x) {
    loop.start_ode(*this, t, x);
  }
  template <class Loop, class State>
  StepEnd advance(Loop& loop, double& t, State& x) {
    return loop.advance_ode(*this, t, x);
  }
  double stepped_until() const { return integ.t1(); }
  template <class Eq, class State>
  void state_at(const Eq& eq, double t, State& out) const {
    integ.dense(t, buf);
    eq.put(buf, out);
  }
};

}  // namespace flexrock::detail
