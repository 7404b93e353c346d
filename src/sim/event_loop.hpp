// SPDX-License-Identifier: BSD-3-Clause
// The loop: entering a mode (the same-instant transitions as a loop), choosing and starting its
// stepper, the one dispatch to it, the sampled step of the integrators with its guards and
// extremes, the state within the last step, and the run's outputs (events, history rows, the
// result). Part of the event loop (simulator.hpp), included at its end.
#pragma once

#include "simulator.hpp"

namespace flexrock::detail {

// enters the current mode at (t, x) and every mode the resets at that instant lead to; false when
// the run ends here
template <int N, int MaxN>
bool Simulator<N, MaxN>::enter_mode(double t, State& x) {
  bool running = true;
  do {
    latch_.entry_pending = false;
    running = start_mode(t, x);
  } while (running && latch_.entry_pending);
  return running;
}

// starts the current mode at (t, x); false when the run ends here. A guard already at or below
// zero on entry fires at once (an uplift or lift-off that the entry state already calls for): its
// reset requests the next entry.
template <int N, int MaxN>
bool Simulator<N, MaxN>::start_mode(double t, State& x) {
  // every reset's new mode starts here, those a mode's entry state calls for at once included:
  // contact changes piling up at one instant would loop forever, so they stop the run
  if (t - ledger_.zeno_time < 1e-9 * std::max(1.0, t)) {
    if (++ledger_.same_time_events > kSameInstantEntries) {
      return stop(t, "contact changes accumulate at t = " + short_number(t) +
                         " s without time advancing (Zeno behaviour) in " + to_string(eq_.mode) +
                         (opt_.chatter_ratio <= 0.0 ? " with the chatter cut-off disabled "
                                                      "(chatter_ratio = 0); set chatter_ratio > 0"
                                                    : ""));
    }
  } else {
    ledger_.zeno_time = t;
    ledger_.same_time_events = 0;
  }
  if (full_contact()) {
    x(0) = 0.0;
    x(ithd()) = 0.0;
  }
  step_stop_ = std::numeric_limits<double>::infinity();
  stepper_ = choose_stepper();
  // quadratures steer no step of a sticking contact mode; a slide's d, d_dot come after them
  ctl_.controlled = flying() ? 2 * n_ + 8 : (sliding() ? -1 : 2 * n_ + 2);
  on_stepper([&](auto& s) { s.start(*this, t, x); });
  // an arc from the floor (after an impact) knows its reaction there
  bool arc_from_floor = false;
  if constexpr (N == 0) {
    arc_from_floor = std::holds_alternative<Arc*>(stepper_) && x(0) == 0.0;
    if (arc_from_floor)
      eq_.arc_sample(arc_.arc, t, x, arc_.arc.floor_sin(), arc_.arc.floor_cos(), s0_);
  }
  if (!arc_from_floor) eq_.evaluate(t, x, s0_);
  const ModeSpec& spec = mode_spec(eq_.mode);
  for (int j = 0; j < spec.count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    if (latch_.friction_tie && spec.guards[k] == Guard::kFrictionLimit) continue;
    if (latch_.zero_start[k] && s0_.v[k] != 0.0) latch_.zero_start[k] = false;
  }
  latch_.friction_tie = false;
  auto at_or_below = [&](Guard g) {
    const int j = guard_slot(eq_.mode, g);
    return j >= 0 && !latch_.zero_start[static_cast<std::size_t>(j)] &&
           s0_.v[static_cast<std::size_t>(j)] <= 0.0;
  };
  const int lift = guard_slot(eq_.mode, Guard::kLiftOff);
  if (lift < 0) latch_.hold_tension = false;
  if (lift < 0 || (s0_.v[static_cast<std::size_t>(lift)] > 0.0 && !latch_.hold_tension))
    latch_.tension = false;
  if (at_or_below(Guard::kOverturn)) return overturned(t, x);
  if (!latch_.tension && at_or_below(Guard::kLiftOff)) return lift_off(t, x);
  // an uplift is tried before a slip (theory §20): rocking on a sticking pivot if its friction
  // holds, else rocking with the pivot sliding if that turns the body up, else sliding flat
  if (full_contact() && !latch_.suppress_uplift_at_start) {
    const bool up1 = at_or_below(Guard::kUpliftEdge1), up2 = at_or_below(Guard::kUpliftEdge2);
    if (up1 || up2) {
      const int e = up1 && (!up2 || s0_.v[0] <= s0_.v[1]) ? 1 : 2;
      if (!sliding() && !uplift_holds(t, e)) {
        latch_.suppress_uplift_at_start = true;  // the body slides flat instead
        return start_slip(t, x);
      }
      return uplift(t, x, e);
    }
  }
  latch_.suppress_uplift_at_start = false;
  if (at_or_below(Guard::kFrictionLimit)) return start_slip(t, x);
  if (at_or_below(Guard::kSlipStop)) return stick(t, x);
  if (flying()) {
    for (int e : {1, 2}) {
      if (at_or_below(e == 1 ? Guard::kLandingEdge1 : Guard::kLandingEdge2)) return land(t, x, e);
    }
  }
  // observed only now that the mode holds: an entry state that a reset leaves at once is no state
  // of this mode (a landing whose sticking contact would need more than mu_s slips at that
  // instant; the demand that made it slip is the slip_start event's, not a sticking contact's)
  observe(s0_, x);
  return true;
}

// the stepper of the current mode: the cheapest that is exact or accurate for its equations (theory
// §17)
template <int N, int MaxN>
auto Simulator<N, MaxN>::choose_stepper() -> ActiveStepper {
  if (flying()) return &flight_;
  if (sliding()) return &slide_;
  if constexpr (N == 0) {
    // a rigid body in full contact does not move: no integration until it uplifts
    if (eq_.mode == ContactMode::kFullContact) return &still_;
    // the series needs a base acceleration it can expand between the steps' ends: a record's
    // (linear), sinusoids' (a pulse's), or none
    if (opt_.methods.series_rocking &&
        (eq_.motion.is_sampled() || eq_.motion.is_none() || eq_.motion.is_sinusoidal()))
      return &series_;
  } else {
    // a flexible body in full contact under a record: exact steps between its samples (the
    // propagator is available for a sampled motion only)
    if (eq_.mode == ContactMode::kFullContact && exact_.prop.available()) return &exact_;
  }
  return &rocking_;
}

// the rigid body's rocking: the closed-form arc where the floor is at rest, else the series
template <int N, int MaxN>
void Simulator<N, MaxN>::start_series(double t, const State& x) requires(N == 0) {
  series_.buf = x.head(2 * n_ + 4);
  if (start_arc(t, series_.buf)) return;  // the arc needs no series
  const int e = edge();
  const double a = eq_.dyn.alpha(e);
  series_.integ.set_pivot(a, eq_.dyn.g_over_h() / eq_.dyn.inertia(a, eq_.scratch.q),
                          eq_.dyn.mass() * eq_.dyn.height() * eq_.dyn.g(), eq_.dyn.g());
  series_.integ.start([](double, const ContactState&, ContactState&) {}, ctl_, t, series_.buf);
}

template <int N, int MaxN>
void Simulator<N, MaxN>::start_rocking(double t, const State& x) {
  rocking_.buf = x.head(2 * n_ + 4);
  configure_rocking_integrator();
  rocking_.integ.start(
      [this](double tt, const ContactState& xx, ContactState& dd) { eq_.contact_rhs(tt, xx, dd); },
      ctl_, t, rocking_.buf);
}

// flight and the sliding modes: DOPRI5 on the mode's own equations and state
template <int N, int MaxN>
template <class Ode>
void Simulator<N, MaxN>::start_ode(Ode& ode, double t, const State& x) {
  if constexpr (std::is_same_v<Ode, Flight>) {
    ode.buf = x.head(2 * n_ + 8);
  } else {
    ode.buf.head(2 * n_ + 4) = x.head(2 * n_ + 4);
    ode.buf.tail(3) = x.segment(isd(), 3);
  }
  ode.integ.start(ode_rhs(ode), ctl_, t, ode.buf);
}

template <int N, int MaxN>
template <class Ode>
StepEnd Simulator<N, MaxN>::advance_ode(Ode& ode, double& t, State& x) {
  return advance_with(ode.integ, ode_rhs(ode), ode.buf, t, x);
}

template <int N, int MaxN>
template <class Ode>
auto Simulator<N, MaxN>::ode_rhs(Ode&) {
  if constexpr (std::is_same_v<Ode, Flight>)
    return
        [this](double tt, const FlightState& xx, FlightState& dd) { eq_.flight_rhs(tt, xx, dd); };
  else
    return [this](double tt, const SlideState& xx, SlideState& dd) { eq_.slide_rhs(tt, xx, dd); };
}

template <int N, int MaxN>
double Simulator<N, MaxN>::stepped_until() const {
  return on_stepper([](const auto& s) { return s.stepped_until(); });
}

// a flexible body's rocking may be stiff: the explicit method's stability bound on the rocking
// equations about the pivot (once per edge and run) lets the stepper see when stability, not
// accuracy, holds its step. Its explicit method is DOP853 (high_order_rocking): the modes'
// oscillation, resolved to rtol, sets the step, and the 8th order takes about a quarter of
// DOPRI5's steps for that. Full contact and a rigid body keep DOPRI5.
template <int N, int MaxN>
void Simulator<N, MaxN>::configure_rocking_integrator() {
  const auto method = static_cast<StiffMethod>(opt_.methods.rocking_integrator);
  if (n_ == 0 || !rocking()) {
    rocking_.integ.configure(std::numeric_limits<double>::infinity(), StiffMethod::kExplicit);
    return;
  }
  const ExplicitMethod explicit_method =
      opt_.methods.high_order_rocking ? ExplicitMethod::kDop853 : ExplicitMethod::kDopri5;
  double& h = rocking_.h_stable[static_cast<std::size_t>(edge() - 1)];
  if (h < 0.0 && method == StiffMethod::kAuto)
    h = rocking_stable_step(body_, edge(), explicit_method) / opt_.methods.stiff_switch_scale;
  rocking_.integ.configure(h, method, explicit_method);
}

// one accepted step plus whatever happens in it: the stepper stops at the step's end or at the
// guard that crossed in it, and a guard's reset is applied here; false when the run ends
template <int N, int MaxN>
bool Simulator<N, MaxN>::advance(double& t, State& x) {
  const StepEnd end = on_stepper([&](auto& s) {
    static_assert(LoopStepper<std::remove_cvref_t<decltype(s)>, Simulator, Eq, State>);
    return s.advance(*this, t, x);
  });
  if (end.why == StepEnd::Why::kGuard) return fire(end.slot, t, x);
  return end.why == StepEnd::Why::kStepped;
}

template <int N, int MaxN>
StepEnd Simulator<N, MaxN>::advance_rocking(double& t, State& x) {
  auto sys = [this](double tt, const ContactState& xx, ContactState& dd) {
    eq_.contact_rhs(tt, xx, dd);
  };
  return advance_with(rocking_.integ, sys, rocking_.buf, t, x);
}

template <int N, int MaxN>
StepEnd Simulator<N, MaxN>::advance_exact(double& t, State& x) requires(N != 0) {
  // the exact propagator takes no right-hand side
  if (t >= step_stop_) step_stop_ = std::numeric_limits<double>::infinity();
  if (can_walk(t)) return StepEnd::ran(advance_walk(t, x));
  return advance_with(
      exact_.prop, [](double, const State&, State&) {}, exact_.buf, t, x);
}

template <int N, int MaxN>
StepEnd Simulator<N, MaxN>::advance_series_step(double& t, State& x) requires(N == 0) {
  if (series_bounded()) return advance_series(t, x);
  series_.integ.set_max_step(ctl_.max_step);
  return advance_with(
      series_.integ, [](double, const ContactState&, ContactState&) {}, series_.buf, t, x);
}

// the earliest crossing of a resetting guard among the step's samples, after recording the
// non-resetting ones before it; false when none
template <int N, int MaxN>
bool Simulator<N, MaxN>::step_guards(int samples, double t1, double& t_hit, int& slot_hit) {
  const ModeSpec& spec = mode_spec(eq_.mode);
  t_hit = std::numeric_limits<double>::infinity();
  slot_hit = -1;
  std::array<double, kMaxGuards> when;
  when.fill(std::numeric_limits<double>::infinity());
  for (int j = 0; j < spec.count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const GuardSpec& g = guard_spec(spec.guards[k]);
    if (g.guard == Guard::kPeak && !rocking()) continue;
    if (g.guard == Guard::kLiftOff && latch_.tension) continue;
    // without a friction limit its guard is the constant 1 (evaluate): it never crosses
    if (g.guard == Guard::kFrictionLimit && !std::isfinite(eq_.mu_s)) continue;
    when[k] = first_crossing(j, points_.samples.data(), samples, latch_.zero_start[k],
                             g.fires_if_unresolved, *this);
    if (g.reset != Reset::kRecord && when[k] < t_hit) {
      t_hit = when[k];
      slot_hit = j;
    }
  }
  for (int j = 0; j < spec.count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    if (guard_spec(spec.guards[k]).reset == Reset::kRecord && when[k] <= std::min(t_hit, t1))
      record(when[k]);
  }
  return slot_hit >= 0;
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::count_step(double t) {
  if (++res_.steps <= opt_.max_steps) return true;
  return stop(t,
              "step limit reached (" + std::to_string(opt_.max_steps) + " steps; raise max_steps)");
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::step_collapsed(double t) {
  // the step limit is relative (min_step x max(1 s, t)); while rocking the usual cause is
  // impacts accumulating with the chatter cut-off disabled, so the message says so
  const double h_min = ctl_.min_step * std::max(1.0, std::abs(t));
  const std::string cause =
      rocking() && opt_.chatter_ratio <= 0.0
          ? "impacts accumulating while rocking with the chatter cut-off disabled "
            "(chatter_ratio = 0); set chatter_ratio > 0"
          : "the equations became too stiff or singular; loosen rtol/atol or check the body";
  return stop(t, "integration step collapsed below " + short_number(h_min) + " s near t = " +
                     short_number(t) + " s in " + to_string(eq_.mode) + " (" + cause + ")");
}

// the step of `integ` (the integrator, or the exact propagator in full contact)
template <int N, int MaxN>
template <class Stepper, class System, class Buffer>
StepEnd Simulator<N, MaxN>::advance_with(Stepper& integ, System&& sys, Buffer& buf, double& t,
                                         State& x) {
  const double t_stop =
      std::min({setup_.t_end, eq_.motion.next_breakpoint(t, eq_.cursor.brk), step_stop_});
  if (!count_step(t)) return StepEnd::ended();
  const auto status = integ.step(sys, t_stop);
  if (status != std::remove_cv_t<decltype(status)>::kAccepted)
    return StepEnd::ran(step_collapsed(t));
  if (eq_.slide_inconsistent)
    return StepEnd::ran(
        stop(t, "no consistent slide near t = " + short_number(t) + " s in " + to_string(eq_.mode) +
                    ": Coulomb friction with this coefficient would need the floor to push the "
                    "slip forward (Painleve's paradox; docs/theory.md, \"Sliding\")"));
  const double t0 = integ.t0(), t1 = integ.t1();
  if (opt_.progress) opt_.progress->store(t1, std::memory_order_relaxed);
  // sample the guards across the step, keeping the states for the extremes
  auto& smp = points_.samples;
  smp[0] = s0_;
  for (int k = 1; k <= samples_; ++k) {
    const double tk = k == samples_ ? t1 : t0 + (t1 - t0) * k / samples_;
    State& xk = points_.states[static_cast<std::size_t>(k)];
    if (k == samples_) {
      put(integ.x1(), xk);
    } else {
      integ.dense(tk, buf);
      put(buf, xk);
    }
    eq_.evaluate(tk, xk, smp[static_cast<std::size_t>(k)]);
  }
  double t_hit = 0.0;
  int slot_hit = -1;
  const bool hit = step_guards(samples_, t1, t_hit, slot_hit);
  // extremes from the samples that precede any state change and from the state just before it,
  // then located between them
  if (n_ > 0) eq_.scratch.qu.noalias() = Dyn::mv(eq_.to_user, x.segment(iq(), n_));
  keep_point(0, t0, s0_, eq_.scratch.qu);
  int points = 1;
  for (int k = 1; k <= samples_; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    if (smp[kk].t >= t_hit) break;
    observe(smp[kk], points_.states[kk]);  // leaves u in eq_.scratch.qu
    keep_point(points++, smp[kk].t, smp[kk], eq_.scratch.qu);
  }
  if (hit && t_hit > points_.t[static_cast<std::size_t>(points - 1)]) {
    GuardSample before;
    state_at(t_hit, scratch_.xr);
    eq_.evaluate(t_hit, scratch_.xr, before);
    observe(before, scratch_.xr);
    keep_point(points++, t_hit, before, eq_.scratch.qu);
  }
  locate_step_extremes(points);
  // an analytic motion may jump at a breakpoint: start the next step from its right limit
  if (!hit && t1 == t_stop && t1 < setup_.t_end && !eq_.motion.is_sampled())
    integ.refresh_derivative(sys, std::nextafter(t1, setup_.t_end));
  return end_step(integ, sys, slot_hit, t_hit, smp[static_cast<std::size_t>(samples_)], t, x);
}

// a step's end: with no event (slot_hit < 0) the state moves to the step's end, whose guards are
// s_end; else the step is cut at the event, whose guard the stepper returns for the loop to fire
template <int N, int MaxN>
template <class Stepper, class System>
StepEnd Simulator<N, MaxN>::end_step(Stepper& integ, System&& sys, int slot_hit, double t_hit,
                                     const GuardSample& s_end, double& t, State& x) {
  if (slot_hit < 0) {
    emit_rows_until(integ.t1());
    t = integ.t1();
    put(integ.x1(), x);
    s0_ = s_end;
    latch_.zero_start.fill(false);
    release_latches(s0_);
    return StepEnd::stepped();
  }
  // land exactly on the event: the loop applies its reset
  const bool inside = t_hit > integ.t0();
  if (inside) integ.restep_to(sys, t_hit);
  emit_rows_until(t_hit);
  t = t_hit;
  put(inside ? integ.x1() : integ.x0(), x);
  return StepEnd::guard(slot_hit);
}

template <int N, int MaxN>
void Simulator<N, MaxN>::keep_point(int p, double t, const GuardSample& s, const Vec& u) {
  const auto pp = static_cast<std::size_t>(p);
  points_.t[pp] = t;
  Quantities& v = points_.vals[pp];
  if constexpr (N == Eigen::Dynamic)
    v.head(n_) = u.array().abs();
  else if constexpr (N != 0)
    v.template head<N>() = u.array().abs();
  v(n_) = std::abs(s.fi);
  v(n_ + 1) = std::abs(s.moment);
  v(n_ + 2) = friction_demand(s);
  v(n_ + 3) = pull_of(s);
  points_.pressing[pp] = s.fj >= kPressingFraction;
  points_.fj[pp] = s.fj;
}

template <int N, int MaxN>
inline double Simulator<N, MaxN>::point_quantity(int k, const GuardSample& s,
                                                 const State& x) const {
  if (k < n_) {
    if constexpr (N != 0) return std::abs(eq_.to_user.row(k).dot(x.segment(iq(), n_)));
  }
  if (k == n_) return std::abs(s.fi);
  if (k == n_ + 1) return std::abs(s.moment);
  if (k == n_ + 2) return friction_demand(s);
  return pull_of(s);
}

template <int N, int MaxN>
double Simulator<N, MaxN>::step_quantity(int k, double t) {
  state_at(t, scratch_.xr);
  GuardSample s;
  if (k >= n_) eq_.evaluate(t, scratch_.xr, s);  // a deformation needs the state alone
  return point_quantity(k, s, scratch_.xr);
}

// A step's quantities (|u_j|, |F_I|, |moment|, friction demand) peak between its observed points:
// located by locate_peaks_between (step_extremes.hpp), each value through the guards' own
// evaluation and each peak observed (evaluate() there, every quantity folded)
template <int N, int MaxN>
void Simulator<N, MaxN>::locate_step_extremes(int points) {
  // the time the floor pulls on the held pivot, its sign changes between the points located
  if (latch_.tension) {
    GuardSample s;
    res_.extremes.tension_time +=
        time_negative(points_.t.data(), points_.fj.data(), points, [&](double t) {
          state_at(t, scratch_.xr);
          eq_.evaluate(t, scratch_.xr, s);
          return s.fj;
        });
  }
  // the friction demand counts only while the floor presses with kPressingFraction of the weight,
  // and rises toward that limit before the floor lets go: its peak lies at the switch
  for (int p = 1; p < points; ++p) {
    const auto pp = static_cast<std::size_t>(p);
    const bool pressed_before = points_.pressing[pp - 1];
    if (pressed_before == points_.pressing[pp]) continue;
    GuardSample s;
    observe_at(bisect_switch(points_.t[pp - 1], points_.t[pp], pressed_before, [&](double t) {
      state_at(t, scratch_.xr);
      eq_.evaluate(t, scratch_.xr, s);
      return s.fj >= kPressingFraction;
    }));
  }
  if (points < 3) return;
  const Extremes& ex = res_.extremes;
  const double mg = eq_.dyn.mass() * eq_.dyn.g(), mgh = mg * eq_.dyn.height();
  if constexpr (N != 0) points_.extreme.head(n_) = ex.max_abs_q.array();
  points_.extreme(n_) = ex.max_base_shear / mg;
  points_.extreme(n_ + 1) = ex.max_overturning_moment / mgh;
  points_.extreme(n_ + 2) = ex.max_friction_demand;
  points_.extreme(n_ + 3) = ex.max_pivot_pull / mg;
  locate_peaks_between(
      points_.t.data(), points_.vals.data(), points, points_.extreme,
      [this](int k, double t) { return step_quantity(k, t); }, [this](double t) { observe_at(t); });
}

// the state at t within the last step (or the still state)
template <int N, int MaxN>
void Simulator<N, MaxN>::state_at(double t, State& out) const {
  on_stepper([&](const auto& s) { s.state_at(eq_, t, out); });
}

template <int N, int MaxN>
double Simulator<N, MaxN>::guard_value(int slot, double t) {
  GuardSample s;
  state_at(t, scratch_.xr);
  eq_.evaluate(t, scratch_.xr, s);
  return s.v[static_cast<std::size_t>(slot)];
}

// the rocking series' impact guard (s theta) and peak guard (s theta_dot) are polynomials on the
// step: their crossings are found on the polynomial; every other guard by TOMS 748
template <int N, int MaxN>
double Simulator<N, MaxN>::crossing(int slot, double tl, double tr, double gl, double gr) {
  if constexpr (N == 0) {
    if (std::holds_alternative<Series*>(stepper_)) {
      const Guard g = mode_spec(eq_.mode).guards[static_cast<std::size_t>(slot)];
      const double sg = edge_sign(edge());
      const double* c = series_.integ.theta_coefficients();
      const double* dc = series_.integ.theta_rate_coefficients();  // k c[k]
      const int degree = series_.integ.order();  // theta's; theta_dot's is one less
      if (g == Guard::kImpact)
        return polynomial_crossing(c, dc, degree, sg, series_.integ.t0(), tl, tr, gl, gr);
      if (g == Guard::kPeak) {
        // theta_dot's coefficients d[k] = dc[k + 1], and k d[k]
        const double* d = dc + 1;
        std::array<double, RockingSeries<ContactState>::kMaxOrder + 2> dd;
        for (int k = 1; k < degree; ++k) dd[static_cast<std::size_t>(k)] = k * d[k];
        return polynomial_crossing(d, dd.data(), degree - 1, sg, series_.integ.t0(), tl, tr, gl,
                                   gr);
      }
    }
  }
  return locate_crossing(slot, tl, tr, gl, gr, *this);
}

// a non-resetting guard crossed at t: record it
template <int N, int MaxN>
void Simulator<N, MaxN>::record(double t) {
  state_at(t, scratch_.xr);
  GuardSample s;
  eq_.evaluate(t, scratch_.xr, s);
  record_sample(s, scratch_.xr);
}

template <int N, int MaxN>
void Simulator<N, MaxN>::record_sample(const GuardSample& s, const State& x) {
  // the only recording guard is the peak (the friction limit resets: the base slides)
  Event e = make_event(s.t, EventKind::kPeak, edge());
  e.theta = x(0);
  e.offset = offset_of(x);
  rec_.event(e);
  observe(s, x);
}

template <int N, int MaxN>
void Simulator<N, MaxN>::emit_rows_until(double t_cut) {
  if (opt_.output_dt <= 0.0) return;
  for (;;) {
    const double to = static_cast<double>(ledger_.next_output) * opt_.output_dt;
    if (to > t_cut || to > setup_.t_end * (1.0 + 1e-14)) break;
    state_at(std::min(to, stepped_until()), scratch_.xr);
    emit_row(to, scratch_.xr);
    ++ledger_.next_output;
  }
}

template <int N, int MaxN>
void Simulator<N, MaxN>::emit_row(double t, const State& x) {
  GuardSample s;
  eq_.evaluate(t, x, s);
  const BaseAcceleration a = eq_.motion.at(t, eq_.cursor.event);
  Observation o = eq_.observation(t, x, s, ledger_.offset);
  if (n_ > 0) eq_.scratch.qdu.noalias() = Dyn::mv(eq_.to_user, x.segment(iqd(), n_));
  o.q_dot = eq_.scratch.qdu.data();
  // the resultant's distance from the c.g. projection [m]: at the pivot while rocking
  double resultant = 0.0;
  if (rocking()) {
    resultant = eq_.dyn.height() * eq_.dyn.alpha(edge());
  } else if (full_contact()) {
    resultant = eq_.dyn.height() * s.moment / s.fj;
  }
  rec_.row(o, a, eq_.kinetic_energy(x), eq_.potential_energy(x), resultant,
           ledger_.impact_loss + ledger_.chatter_loss);
}

template <int N, int MaxN>
void Simulator<N, MaxN>::finish(double t, const State& x) {
  res_.t_end = t;
  if (opt_.progress) opt_.progress->store(t, std::memory_order_relaxed);
  if (opt_.output_dt > 0.0 && (res_.history.time.empty() || res_.history.time.back() < t - 1e-12)) {
    emit_row(t, x);
  }
  if (flying() && res_.status != Status::kOverturned)
    res_.extremes.flight_time += t - ledger_.flight_start;
  if (sliding() && res_.status != Status::kOverturned)
    res_.extremes.sliding_time += t - ledger_.slide_start;
  res_.final_phase = eq_.mode;
  res_.final_theta = x(0);
  res_.final_theta_dot = x(ithd());
  res_.final_q = eq_.to_user * x.segment(iq(), n_);
  res_.final_q_dot = eq_.to_user * x.segment(iqd(), n_);
  res_.final_offset = offset_of(x);
  EnergyBalance& e = res_.energy;
  const double kin = eq_.kinetic_energy(x);
  const double pot = eq_.potential_energy(x);
  e.input_work = x(iw());
  e.damping_loss = x(id());
  e.impact_loss = ledger_.impact_loss;
  e.chatter_loss = ledger_.chatter_loss;
  e.friction_loss = x(ifr());
  e.kinetic_change = kin - ledger_.kinetic0;
  e.potential_change = pot - (ledger_.energy0 - ledger_.kinetic0);
  e.residual = e.input_work - (e.kinetic_change + e.potential_change + e.damping_loss +
                               e.impact_loss + e.chatter_loss + e.friction_loss);
  e.scale =
      std::max({rec_.energy_scale(), std::abs(ledger_.energy0 - pot), std::abs(kin),
                ledger_.kinetic0, ledger_.impact_loss + ledger_.chatter_loss + e.friction_loss});
  res_.rejected_steps = rocking_.integ.rejected_steps() + flight_.integ.rejected_steps() +
                        slide_.integ.rejected_steps();
  res_.rhs_evaluations = rocking_.integ.rhs_evaluations() + flight_.integ.rhs_evaluations() +
                         slide_.integ.rhs_evaluations();
  if (res_.status == Status::kCompleted) res_.message = "completed";
}

}  // namespace flexrock::detail
