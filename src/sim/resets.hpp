// SPDX-License-Identifier: BSD-3-Clause
// The resets: what each guard's crossing does to the state and the mode (uplift, impact, lift-off,
// landing, overturning, slip and stick, impacts with friction), each ending in a request for the
// next mode's entry. Part of the event loop (simulator.hpp), included at its end.
#pragma once

#include "flexrock/contact/flight_maps.hpp"
#include "flexrock/contact/friction_impact.hpp"
#include "simulator.hpp"

namespace flexrock::detail {

// a resetting guard of the current mode fired at (t, x); false when the run ends
template <int N, int MaxN>
bool Simulator<N, MaxN>::fire(int slot, double t, State& x) {
  if (sliding()) ledger_.offset = x(isd());  // events name where the base is
  const GuardSpec& g = guard_spec(mode_spec(eq_.mode).guards[static_cast<std::size_t>(slot)]);
  switch (g.reset) {
    case Reset::kUplift: {
      // U1 + U2 = (alpha1 + alpha2) F_J / M g: when the floor also stops pressing, both uplift
      // guards and the lift-off guard cross together, and the body flies (theory §15)
      GuardSample now;
      eq_.evaluate(t, x, now);
      const int lift = guard_slot(eq_.mode, Guard::kLiftOff);
      if (!latch_.tension && lift >= 0 && now.v[static_cast<std::size_t>(lift)] <= 0.0)
        return lift_off(t, x);
      return uplift(t, x, g.edge);
    }
    case Reset::kLiftOff:
      return lift_off(t, x);
    case Reset::kImpact:
      return impact(t, x);
    case Reset::kOverturn:
      return overturned(t, x);
    case Reset::kLanding:
      return land(t, x, g.edge);
    case Reset::kSlip:
      return start_slip(t, x);
    case Reset::kStick:
      return stick(t, x);
    case Reset::kRecord:
      break;
  }
  return true;
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::uplift(double t, State& x, int e) {
  Event ev = make_event(t, EventKind::kUplift, e);
  rec_.event(ev);
  if (res_.extremes.first_uplift_time < 0.0) {
    res_.extremes.first_uplift_time = t;
    res_.extremes.first_uplift_edge = e;
  }
  // a sliding base goes on sliding under the new pivot (no impulse: d_dot is continuous)
  switch_mode(contact_mode(e, slip()), t, x);
  x(0) = 0.0;
  x(ithd()) = 0.0;
  ledger_.last_contact_change = t;
  // theta = 0 and it must grow: the impact and peak functions start at zero, known to turn
  // positive
  latch_.zero_start.fill(false);
  latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kImpact))] = true;
  latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kPeak))] = true;
  // a slide that began at this instant has not yet any slip velocity: it too starts at zero
  if (sliding() && x(isv()) == 0.0)
    latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kSlipStop))] = true;
  return request_entry();
}

template <int N, int MaxN>
void Simulator<N, MaxN>::law_fallback(double t, int e) {
  ++res_.extremes.impact_law_fallbacks;
  rec_.event(make_event(t, EventKind::kImpactLawFallback, e));
}

template <int N, int MaxN>
void Simulator<N, MaxN>::count_impact(const Event& impact, double impulse_y, double loss,
                                      bool chatter) {
  // the force a contact of the assumed duration would carry: a half-sine pulse of this impulse
  Event ev = impact;
  // (the impulse's size by sqrt, not hypot: no impulse comes near the range where x^2 overflows)
  ev.force_estimate = 0.5 * std::numbers::pi *
                      std::sqrt(ev.impulse_x * ev.impulse_x + ev.impulse_y * ev.impulse_y) /
                      opt_.impact_duration;
  rec_.event(ev);
  Extremes& ex = res_.extremes;
  ex.max_impact_force = std::max(ex.max_impact_force, ev.force_estimate);
  ++ex.impacts;
  if (chatter) {
    ++ex.chatter_cutoffs;
    res_.chatter_cut_off = true;
    ledger_.chatter_loss += loss;
  } else {
    ledger_.impact_loss += loss;
  }
  ex.max_impulse = std::max(ex.max_impulse, impulse_y);
  ex.max_impact_energy_loss = std::max(ex.max_impact_energy_loss, loss);
  // the cut-off is a numerical device on a vanishing impulse (its ratio is 1/alpha for a rigid
  // block whatever the speed): it sets no friction demand
  if (!chatter && impulse_y > 0.0)
    ex.max_friction_demand = std::max(ex.max_friction_demand, ev.friction_demand);
  if (loss < -1e-12 * std::max(1.0, rec_.energy_scale())) {
    res_.impact_gained_energy = true;
    Event ge = ev;
    ge.kind = EventKind::kImpactGainedEnergy;
    rec_.event(ge);
  }
}

// rocking reaches theta = 0: the impact law of theory §8-§10
template <int N, int MaxN>
bool Simulator<N, MaxN>::impact(double t, State& x) {
  const int landing = edge() == 1 ? 2 : 1;
  eq_.unpack(x);
  const double thd_minus = x(ithd());
  const bool chatter = t - ledger_.last_contact_change < setup_.chatter_interval;
  const auto out = resolve_impact(eq_.dyn, landing, eq_.scratch.q, thd_minus, eq_.scratch.qd,
                                  setup_.rule, chatter);
  // with friction: a sliding pivot, or an impulse outside the friction cone, needs the impact law
  // with Coulomb friction (theory §19); the paper's law is its sticking case. A chatter cut-off of
  // a sticking pivot is a numerical device on a vanishing impulse whose ratio |I_x|/I_y says
  // nothing about sliding (§10): it stays the sticking both-edges stop.
  if (std::isfinite(eq_.mu_s) &&
      (sliding() ||
       (!chatter && !inside_friction_cone(out.impulse(0), out.impulse(1), eq_.mu_s)))) {
    Eigen::Vector2d r, v_c;
    eq_.dyn.cg_from_pivot(edge(), 0.0, 1.0, eq_.scratch.q, thd_minus, eq_.scratch.qd, r, v_c);
    if (sliding()) v_c(0) += x(isv());
    x(0) = 0.0;  // located at theta = 0 up to rounding
    return impact_with_friction(t, x, {.edge = landing, .flat = chatter, .grazing = chatter}, v_c,
                                chatter ? EventKind::kChatterCutoff : EventKind::kImpact);
  }
  if (out.law_fallback) law_fallback(t, landing);
  Event ev = make_event(t,
                        chatter ? EventKind::kChatterCutoff
                                : (out.both_edges ? EventKind::kRockingEnded : EventKind::kImpact),
                        landing);
  ev.theta_dot_before = thd_minus;
  ev.theta_dot_after = out.theta_dot;
  ev.energy_loss = out.energy_loss;
  ev.impulse_x = out.impulse(0);
  ev.impulse_y = out.impulse(1);
  ev.friction_demand = friction_ratio(out.impulse(0), out.impulse(1));
  count_impact(ev, out.impulse(1), out.energy_loss, chatter);
  x(0) = 0.0;
  x(ithd()) = out.theta_dot;
  x.segment(iqd(), n_) = out.q_dot;
  switch_mode(out.both_edges
                  ? ContactMode::kFullContact
                  : (landing == 1 ? ContactMode::kRockingEdge1 : ContactMode::kRockingEdge2),
              t, x);
  // a degenerate excursion (no time since uplift) must not uplift again at once
  if (out.both_edges && t == ledger_.last_contact_change) latch_.suppress_uplift_at_start = true;
  ledger_.last_contact_change = t;
  latch_.zero_start.fill(false);
  if (!out.both_edges)
    latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kImpact))] = true;
  if (res_.extremes.impacts > opt_.max_impacts)
    return stop(t, "impact limit reached (" + std::to_string(opt_.max_impacts) + ")");
  return request_entry();
}

// the floor stops pressing: the body flies, with no impulse (theory "Flight", lift-off map)
template <int N, int MaxN>
bool Simulator<N, MaxN>::lift_off(double t, State& x) {
  eq_.unpack(x);
  const int e = edge();
  // a free body must move its touching tipping points up: otherwise the sticking pivot is pulled
  // sideways as its force vanishes and the body could only leave it by sliding, which is not
  // modelled here; the floor is let pull (flagged) until it presses again (theory "Lift-off")
  const LiftOffState<Vec> at{.pivot = mode_spec(eq_.mode).pivot,
                             .theta = x(0),
                             .q = eq_.scratch.q,
                             .theta_dot = x(ithd()),
                             .q_dot = eq_.scratch.qd,
                             .offset = offset_of(x),
                             .sliding = sliding(),
                             .slip_velocity = sliding() ? x(isv()) : 0.0};
  if (lift_off_pulls(eq_.dyn, at, eq_.motion.at(t, eq_.cursor.event))) {
    latch_.tension = true;
    res_.pivot_tension = true;
    Event ev = make_event(t, EventKind::kPivotTension, rocking() ? e : 0);
    ev.theta = x(0);
    ev.theta_dot_before = ev.theta_dot_after = x(ithd());
    rec_.event(ev);
    // the episode's largest pull goes into this event as the floor pulls (fold_pull)
    latch_.tension_event = static_cast<long>(res_.events.size()) - 1;
    ++res_.extremes.tension_episodes;
    return request_entry();
  }
  const FlightStart f = lift_off_map(eq_.dyn, at);
  x(ixc()) = f.r_c(0);
  x(ixc() + 1) = f.r_c(1);
  x(ixc() + 2) = f.v_c(0);
  x(ixc() + 3) = f.v_c(1);
  Event ev = make_event(t, EventKind::kLiftOff, full_contact() ? 0 : e);
  ev.theta = x(0);
  ev.theta_dot_before = ev.theta_dot_after = x(ithd());
  rec_.event(ev);
  ++res_.extremes.lift_offs;
  const ContactMode from = eq_.mode;
  switch_mode(ContactMode::kFlight, t, x);
  ledger_.flight_start = t;
  ledger_.last_contact_change = t;
  // the tipping points that touched the floor start at zero height and rise
  latch_.zero_start.fill(false);
  if (mode_spec(from).pivot != 2)
    latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kLandingEdge1))] = true;
  if (mode_spec(from).pivot != 1)
    latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kLandingEdge2))] = true;
  return request_entry();
}

// tipping point e lands after a flight: the plastic corner impact (theory "Landing", landing_map
// or friction_impact in contact/); at theta = 0 with the body turning into the floor about e, the
// other tipping point may land instead, or both (flat)
template <int N, int MaxN>
bool Simulator<N, MaxN>::land(double t, State& x, int e) {
  eq_.unpack(x);
  const double th = x(0), thd_minus = x(ithd());
  const double sn = std::sin(th), cs = std::cos(th), h = eq_.dyn.height();
  const Eigen::Vector2d v_c = eq_.cg_velocity(x);
  if (std::isfinite(eq_.mu_s)) {
    res_.extremes.flight_time += t - ledger_.flight_start;
    const bool chatter = t - ledger_.last_contact_change < setup_.chatter_interval;
    if (chatter) {
      latch_.tension = latch_.hold_tension = true;  // as below: grazing hops cannot accumulate
      latch_.tension_event = -1;
    }
    return impact_with_friction(t, x, {.edge = e, .from_flight = true, .grazing = chatter}, v_c,
                                chatter ? EventKind::kChatterCutoff : EventKind::kLanding);
  }
  const auto out = landing_map(eq_.dyn, e,
                               ImpactState<Vec>{.theta = th,
                                                .q = eq_.scratch.q,
                                                .theta_dot = thd_minus,
                                                .q_dot = eq_.scratch.qd,
                                                .v_c = v_c},
                               setup_.rule);
  if (out.law_fallback) law_fallback(t, e);
  const double x_corner = eq_.dyn.corner_x(out.edge, sn, cs, eq_.scratch.q, x(ixc()));
  x(ithd()) = out.theta_dot;
  x.segment(iqd(), n_) = out.q_dot;
  ledger_.offset = x_corner - h * eq_.dyn.alpha(out.edge);
  switch_mode(out.flat ? ContactMode::kFullContact
                       : (out.edge == 1 ? ContactMode::kRockingEdge1 : ContactMode::kRockingEdge2),
              t, x);
  Event ev = make_event(t, EventKind::kLanding, out.flat ? 0 : out.edge);
  ev.theta = th;
  ev.theta_dot_before = thd_minus;
  ev.theta_dot_after = out.theta_dot;
  ev.energy_loss = out.energy_loss;
  ev.impulse_x = out.impulse(0);
  ev.impulse_y = out.impulse(1);
  ev.friction_demand = friction_ratio(out.impulse(0), out.impulse(1));
  res_.extremes.flight_time += t - ledger_.flight_start;
  // a flight shorter than the chatter interval is below what the model resolves (a tipping point
  // grazing the floor): the landing is a chatter cut-off, and the floor may pull until it presses
  // again, so that such hops cannot accumulate without end
  const bool chatter = t - ledger_.last_contact_change < setup_.chatter_interval;
  if (chatter) {
    ev.kind = EventKind::kChatterCutoff;
    latch_.tension = true;
    latch_.tension_event = -1;
  }
  count_impact(ev, out.impulse(1), ev.energy_loss, chatter);
  return after_impulse(t, ev, th, eq_.dyn.mass() * (v_c.norm() + out.v_c.norm()));
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::overturned(double t, State& x) {
  const int side = flying() ? (x(0) >= 0.0 ? 1 : 2) : edge();
  res_.status = Status::kOverturned;
  // the run ends here: every extreme (tilt, uplift, reaction, modes) takes this state too, not
  // only the samples before it
  GuardSample now;
  eq_.evaluate(t, x, now);
  observe(now, x);
  res_.extremes.overturn_time = t;
  res_.extremes.overturn_edge = side;
  if (sliding()) res_.extremes.sliding_time += t - ledger_.slide_start;
  if (flying()) res_.extremes.flight_time += t - ledger_.flight_start;
  Event ev = make_event(t, EventKind::kOverturn, side);
  ev.theta = x(0);
  ev.offset = offset_of(x);
  rec_.event(ev);
  res_.message = std::string("overturned about edge ") + std::to_string(side) +
                 " at t = " + short_number(t) + " s" + (flying() ? " (in flight)" : "");
  return false;
}

template <int N, int MaxN>
void Simulator<N, MaxN>::switch_mode(ContactMode m, double t, State& x) {
  const bool was = sliding(), flew = flying();
  eq_.mode = m;
  if (was && !sliding()) {
    res_.extremes.sliding_time += t - ledger_.slide_start;
    ledger_.offset = x(isd());
    x(isv()) = 0.0;
  } else if (!was && sliding()) {
    ledger_.slide_start = t;
    if (!flew) x(isd()) = ledger_.offset;  // a landing sets ledger_.offset first
  }
  if (flew && sliding()) x(isd()) = ledger_.offset;
}

// the friction limit of a sticking contact mode is reached: the base slides the way the floor
// cannot hold it, starting from rest (theory §18)
template <int N, int MaxN>
bool Simulator<N, MaxN>::start_slip(double t, State& x) {
  GuardSample now;
  eq_.evaluate(t, x, now);
  // the floor cannot push along F_I as hard as sticking needs: the base slips the other way
  const int s = slip_direction(now.fi);
  Event ev = make_event(t, EventKind::kSlipStart, rocking() ? edge() : 0);
  ev.theta = x(0);
  ev.friction_demand = friction_ratio(now.fi, now.fj);
  rec_.event(ev);
  res_.friction_exceeded = true;
  ++res_.extremes.slips;
  x(isv()) = 0.0;
  switch_mode(contact_mode(mode_spec(eq_.mode).pivot, s), t, x);
  ledger_.last_contact_change = t;
  if (rocking() && x(0) == 0.0 && x(ithd()) == 0.0) {
    // just uplifted: with its pivot sliding the body must still turn up, else it slides flat
    eq_.unpack(x);
    double thdd = 0.0;
    Eigen::Vector2d r;
    eq_.slide_acceleration(0.0, 1.0, 0.0, eq_.motion.at(t, eq_.cursor.event), thdd, r);
    if (!(edge_sign(edge()) * thdd > 0.0)) {
      switch_mode(contact_mode(0, s), t, x);
      latch_.suppress_uplift_at_start = true;
    }
  }
  // the slip velocity starts at zero and grows; an uplift at this instant leaves theta = 0
  latch_.zero_start.fill(false);
  latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kSlipStop))] = true;
  if (rocking() && x(0) == 0.0) {
    latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kImpact))] = true;
    latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kPeak))] = true;
  }
  return request_entry();
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::uplift_holds(double t, int e) {
  if (!std::isfinite(eq_.mu_s)) return true;
  const ContactMode was = eq_.mode;
  const BaseAcceleration a = eq_.motion.at(t, eq_.cursor.event);
  double thdd = 0.0;
  eq_.dyn.rocking_acceleration_sc(e, 0.0, 1.0, eq_.scratch.q, 0.0, eq_.scratch.qd, a, thdd,
                                  eq_.scratch.qdd);
  const Eigen::Vector2d r = eq_.dyn.rocking_reaction_sc(e, 0.0, 1.0, eq_.scratch.q, 0.0,
                                                        eq_.scratch.qd, thdd, eq_.scratch.qdd, a);
  if (eq_.mu_s * r(1) - std::abs(r(0)) > 0.0) return true;
  eq_.mode = contact_mode(e, r(0) > 0.0 ? -1 : 1);
  Eigen::Vector2d rs;
  const bool inconsistent = eq_.slide_inconsistent;
  eq_.slide_acceleration(0.0, 1.0, 0.0, a, thdd, rs);
  eq_.slide_inconsistent = inconsistent;  // a probe, not the motion
  eq_.mode = was;
  return edge_sign(e) * thdd > 0.0;
}

// the slip velocity reached zero: the base sticks if static friction can hold it (a strictly
// positive margin), else it slides the way the floor cannot hold (theory §18). A slide that began
// here from rest and could not be resolved as growing (its slip_stop fired where it started) has
// already shown that the floor holds: the margin is zero to rounding, and the base sticks
template <int N, int MaxN>
bool Simulator<N, MaxN>::stick(double t, State& x) {
  const bool never_grew =
      latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kSlipStop))] &&
      t == ledger_.slide_start;
  ledger_.offset = x(isd());
  x(isv()) = 0.0;
  const int pivot = mode_spec(eq_.mode).pivot, was = slip();
  const double th = x(0);
  switch_mode(contact_mode(pivot, 0), t, x);
  GuardSample now;
  eq_.evaluate(t, x, now);
  const int limit = guard_slot(eq_.mode, Guard::kFrictionLimit);
  const double margin = now.v[static_cast<std::size_t>(limit)];
  const StickOrSlip after = stick_or_slip(now.fi, margin, never_grew);
  Event ev = make_event(t, after.sticks ? EventKind::kStick : EventKind::kSlipReversal,
                        rocking() ? edge() : 0);
  ev.theta = th;
  ev.friction_demand = friction_ratio(now.fi, now.fj);
  rec_.event(ev);
  latch_.zero_start.fill(false);
  if (after.tie) {
    // the friction limit starts at zero and fires only where the margin falls below it later
    latch_.zero_start[static_cast<std::size_t>(limit)] = true;
    latch_.friction_tie = true;
  }
  if (after.slip != 0) {
    if (after.slip != was) ++res_.extremes.slips;
    switch_mode(contact_mode(pivot, after.slip), t, x);
    latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kSlipStop))] = true;
  }
  if (rocking() && th == 0.0) {
    latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kImpact))] = true;
    latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kPeak))] = true;
  }
  return request_entry();
}

// the impact of a tipping point with Coulomb friction (friction_impact in contact/, theory §19):
// its outcome into the state, the mode, the events and the ledger; false when the run ends
template <int N, int MaxN>
bool Simulator<N, MaxN>::impact_with_friction(double t, State& x, const CornerImpactCase& c,
                                              const Eigen::Vector2d& v_c, EventKind kind) {
  eq_.unpack(x);
  const double th = x(0), thd_minus = x(ithd());
  const auto out = friction_impact(eq_.dyn,
                                   ImpactState<Vec>{.theta = th,
                                                    .q = eq_.scratch.q,
                                                    .theta_dot = thd_minus,
                                                    .q_dot = eq_.scratch.qd,
                                                    .v_c = v_c},
                                   c, setup_.rule, CoulombFriction{eq_.mu_s, eq_.mu_k});
  if (out.law_fallback) law_fallback(t, c.edge);
  if (!out.consistent)
    return stop(t, "no consistent impact with friction at t = " + short_number(t) +
                       " s (no outcome of the impact law with Coulomb friction fits; "
                       "docs/theory.md, \"Impacts with friction\")");
  // the contact point's place: the landing tipping point, or the base centre when flat
  const double d_now = offset_of(x);
  if (c.from_flight) {
    const double x_corner =
        eq_.dyn.corner_x(out.edge, std::sin(th), std::cos(th), eq_.scratch.q, x(ixc()));
    ledger_.offset = x_corner - eq_.dyn.height() * eq_.dyn.alpha(out.edge);
  } else {
    ledger_.offset = d_now;
  }
  x(ithd()) = out.theta_dot;
  x.segment(iqd(), n_) = out.q_dot;
  switch_mode(contact_mode(out.flat ? 0 : out.edge, out.slip), t, x);
  x(isd()) = ledger_.offset;
  x(isv()) = out.slip_velocity;
  Event ev = make_event(t, out.flat && kind == EventKind::kImpact ? EventKind::kRockingEnded : kind,
                        c.from_flight && out.flat ? 0 : out.edge);
  ev.theta = th;
  ev.theta_dot_before = thd_minus;
  ev.theta_dot_after = x(ithd());
  ev.energy_loss = out.energy_loss;
  ev.impulse_x = out.impulse(0);
  ev.impulse_y = out.impulse(1);
  ev.friction_demand = friction_ratio(out.impulse(0), out.impulse(1));
  count_impact(ev, out.impulse(1), out.energy_loss, c.grazing);
  if (out.slid) {
    // the impulse needed more friction than the floor has: a sliding impact
    res_.friction_exceeded = true;
    ++res_.extremes.slips;
    Event fe = ev;
    fe.kind = EventKind::kFrictionExceeded;
    fe.friction_demand = out.sticking_demand;
    rec_.event(fe);
  }
  return after_impulse(t, ev, th, eq_.dyn.mass() * (v_c.norm() + out.v_c.norm()));
}

// the end of a landing or an impact with friction, recorded as `ev` at tilt th: a tensile impulse
// is said, and the new mode starts (theta = 0 and rocking: the impact guard starts at zero)
template <int N, int MaxN>
bool Simulator<N, MaxN>::after_impulse(double t, const Event& ev, double th, double momentum) {
  // (a grazing landing's impulse vanishes: its sign within the rounding of M (v+ - v-) says
  // nothing, and such a landing pulls on nothing)
  if (ev.impulse_y < -kTensileRounding * momentum) {
    // the sticking tipping point would need the floor to pull: say so
    Event te = ev;
    te.kind = EventKind::kTensileLanding;
    rec_.event(te);
    Extremes& ex = res_.extremes;
    ++ex.tensile_landings;
    ex.max_tensile_impulse = std::max(ex.max_tensile_impulse, -ev.impulse_y);
  }
  ledger_.last_contact_change = t;
  latch_.zero_start.fill(false);
  if (rocking() && th == 0.0)
    latch_.zero_start[static_cast<std::size_t>(guard_slot(eq_.mode, Guard::kImpact))] = true;
  if (res_.extremes.impacts > opt_.max_impacts)
    return stop(t, "impact limit reached (" + std::to_string(opt_.max_impacts) + ")");
  return request_entry();
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::stop(double t, std::string why) {
  res_.status = Status::kStopped;
  Event ev;
  ev.time = t;
  ev.kind = EventKind::kStopped;
  rec_.event(ev);
  res_.message = std::move(why);
  return false;
}

}  // namespace flexrock::detail
