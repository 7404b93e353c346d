// SPDX-License-Identifier: BSD-3-Clause
// An explicit method (DOPRI5 or DOP853) while accuracy sets the step, the Rosenbrock method while
// stability would: a stepper that switches between the two at step boundaries, as LSODA switches
// between its methods. Generic over an Eigen vector state (fixed, bounded or dynamic size); knows
// nothing of bodies or contacts.
#pragma once

#include <algorithm>
#include <limits>

#include "flexrock/integrate/dop853.hpp"
#include "flexrock/integrate/dopri5.hpp"
#include "flexrock/integrate/rosenbrock4.hpp"

namespace flexrock {

/// Which method a StiffSwitching stepper uses.
enum class StiffMethod {
  kAuto = 0,      // DOPRI5 while accuracy sets the step, Rosenbrock while stability would
  kExplicit = 1,  // DOPRI5 only
  kImplicit = 2,  // the Rosenbrock method only
};

/// The explicit method of a StiffSwitching stepper.
enum class ExplicitMethod {
  kDopri5,  // Dormand-Prince 5(4), 6 evaluations a step, dense output of order 4
  kDop853,  // Dormand-Prince 8(5,3), 14 evaluations a step with its dense output of order 7
};

// The caller gives the explicit method's stability bound h_stable [s]: the longest step it takes
// stably on the system's fastest motion, whatever accuracy allows (DOPRI5: 3.3 / lambda for a
// decaying motion of rate lambda, about 1 / omega for an undamped oscillation; DOP853: about
// 6 / lambda; dopri5_stable_step, dop853_stable_step). Explicit steps that
// keep near it say stability holds the step: the Rosenbrock method, L-stable, takes the steps
// accuracy allows. Rosenbrock steps that become short enough that DOPRI5, stable up to h_stable
// and cheaper a step by the ratio of their right-hand-side evaluations, would do the same work
// for less say the stiff phase is over. Both meet the same tolerances, so the switch changes the
// cost, not the answer; a wrong h_stable costs time only.
template <class State>
class StiffSwitching {
 public:
  enum class Status { kAccepted, kStepCollapsed };

  explicit StiffSwitching(double h_stable = std::numeric_limits<double>::infinity(),
                          StiffMethod method = StiffMethod::kAuto)
      : h_stable_(h_stable), method_(method), stiff_(method == StiffMethod::kImplicit) {}

  /// Sets the stability bound (of `explicit_method`), the method and the explicit method for the
  /// next start(): kExplicit and kImplicit fix the method; kAuto keeps the one in use.
  void configure(double h_stable, StiffMethod method,
                 ExplicitMethod explicit_method = ExplicitMethod::kDopri5) {
    h_stable_ = h_stable;
    method_ = method;
    eighth_ = explicit_method == ExplicitMethod::kDop853;
    if (method != StiffMethod::kAuto) stiff_ = method == StiffMethod::kImplicit;
  }

  /// Starts at (t, x) with the method in use (a first step `h` > 0, or the method's own).
  template <class System>
  void start(System&& sys, const StepControl& ctl, double t, const State& x, double h = 0.0) {
    ctl_ = ctl;
    // a Rosenbrock step: a Jacobian by differences of the controlled components, six stages, an
    // LU; a DOPRI5 step: six stages; a DOP853 step: fourteen
    const double m = ctl.controlled < 0 ? static_cast<double>(x.size()) : ctl.controlled;
    cost_ratio_ = (m + 7.0) / (eighth_ ? 14.0 : 6.0);
    count_ = 0;
    if (stiff_) {
      ros_.start(sys, ctl, t, x, h);
    } else {
      start_explicit(sys, t, x, h);
    }
  }

  /// One accepted step from the current point, ending at or before t_stop (exactly at t_stop
  /// when it is reached). Afterwards the dense output covers [t0(), t1()].
  template <class System>
  Status step(System&& sys, double t_stop) {
    if (method_ == StiffMethod::kAuto) switch_if_due(sys);
    const bool ok = stiff_    ? ros_.step(sys, t_stop) == Rosenbrock4<State>::Status::kAccepted
                    : eighth_ ? dop8_.step(sys, t_stop) == Dop853<State>::Status::kAccepted
                              : dop_.step(sys, t_stop) == Dopri5<State>::Status::kAccepted;
    if (!ok) return Status::kStepCollapsed;
    const double h = t1() - t0();
    const bool full = h < t_stop - t0() || t1() < t_stop;  // not a step cut short by t_stop
    ++dwell_steps_;
    if (stiff_) {
      // accuracy now asks for steps short enough that the explicit method, stable up to
      // h_stable and cost_ratio times cheaper a step, does the same work for less
      count_ = full && h < 0.5 * cost_ratio_ * h_stable_ ? count_ + 1 : 0;
    } else {
      // the explicit steps are at the stability bound: stability, not accuracy, holds them
      count_ = full && h > 0.25 * h_stable_ ? count_ + 1 : (full ? 0 : count_);
    }
    return Status::kAccepted;
  }

  /// Replaces the last accepted step by one from its start to `t` (within it), with no error
  /// control: used to land exactly on an event time found on the dense output.
  template <class System>
  void restep_to(System&& sys, double t) {
    if (stiff_) {
      ros_.restep_to(sys, t);
    } else if (eighth_) {
      dop8_.restep_to(sys, t);
    } else {
      dop_.restep_to(sys, t);
    }
  }
  /// The next step starts from the right-hand limit of a jump of the forcing at t1().
  template <class System>
  void refresh_derivative(System&& sys, double t_eval) {
    if (stiff_) {
      ros_.refresh_derivative(sys, t_eval);
    } else if (eighth_) {
      dop8_.refresh_derivative(sys, t_eval);
    } else {
      dop_.refresh_derivative(sys, t_eval);
    }
  }
  /// State at t in [t0(), t1()] from the continuous extension of the last step.
  void dense(double t, State& out) const {
    if (stiff_) {
      ros_.dense(t, out);
    } else if (eighth_) {
      dop8_.dense(t, out);
    } else {
      dop_.dense(t, out);
    }
  }
  double t0() const { return stiff_ ? ros_.t0() : eighth_ ? dop8_.t0() : dop_.t0(); }
  double t1() const { return stiff_ ? ros_.t1() : eighth_ ? dop8_.t1() : dop_.t1(); }
  const State& x0() const { return stiff_ ? ros_.x0() : eighth_ ? dop8_.x0() : dop_.x0(); }
  const State& x1() const { return stiff_ ? ros_.x1() : eighth_ ? dop8_.x1() : dop_.x1(); }
  double suggested_step() const {
    return stiff_    ? ros_.suggested_step()
           : eighth_ ? dop8_.suggested_step()
                     : dop_.suggested_step();
  }
  long rhs_evaluations() const {
    return ros_.rhs_evaluations() + dop_.rhs_evaluations() + dop8_.rhs_evaluations();
  }
  long rejected_steps() const {
    return ros_.rejected_steps() + dop_.rejected_steps() + dop8_.rejected_steps();
  }
  long switches() const { return switches_; }
  bool stiff() const { return stiff_; }  // the Rosenbrock method is in use

 private:
  template <class System>
  void switch_if_due(System& sys) {
    if (count_ < (stiff_ ? 4 : dwell_)) return;
    const double t = t1(), h = suggested_step();
    x_ = x1();
    // a stiff period that did not last makes the next switch to it wait longer (no ping-pong)
    if (stiff_) dwell_ = dwell_steps_ < 64 ? std::min(2 * dwell_, 4096) : std::max(dwell_ / 2, 8);
    stiff_ = !stiff_;
    count_ = 0;
    dwell_steps_ = 0;
    ++switches_;
    if (stiff_) {
      ros_.start(sys, ctl_, t, x_, 2.0 * h);
    } else {
      start_explicit(sys, t, x_, std::min(h, h_stable_));
    }
  }

  template <class System>
  void start_explicit(System& sys, double t, const State& x, double h) {
    if (eighth_) {
      dop8_.start(sys, ctl_, t, x, h);
    } else {
      dop_.start(sys, ctl_, t, x, h);
    }
  }

  double h_stable_;  // [s] the explicit method's stability bound on the system's fastest motion
  StiffMethod method_;
  double cost_ratio_ = 2.0;  // a Rosenbrock step's cost over an explicit step's
  int dwell_ = 8;            // explicit steps at the stability bound before the switch
  long dwell_steps_ = 0;     // steps since the last switch
  StepControl ctl_;
  Dopri5<State> dop_;
  Dop853<State> dop8_;
  bool eighth_ = false;  // the explicit method is DOP853
  Rosenbrock4<State> ros_;
  State x_;
  bool stiff_;
  int count_ = 0;
  long switches_ = 0;
};

}  // namespace flexrock
