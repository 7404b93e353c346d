// SPDX-License-Identifier: BSD-3-Clause
// The resets: what each guard's crossing does to the state and the mode (uplift, impact, lift-off,
// landing, overturning, slip and stick, impacts with friction), each ending in a request for the
// next mode's entry. Part of the event loop (simulator.hpp), included at its end.
#pragma once

#include "simulator.hpp"

namespace flexrock::detail {

// a resetting guard of the current mode fired at (t, x); false when the run ends
template <int N, int MaxN>
bool Simulator<N, MaxN>::fire(int slot, double t, State& x) {
  if (sliding()) ledger_.offset = x(isd());  // events name where the base is
  const GuardSpec& g = guard_spec(mode_spec(mode_).guards[static_cast<std::size_t>(slot)]);
  switch (g.reset) {
    case Reset::kUplift: {
      // U1 + U2 = (alpha1 + alpha2) F_J / M g: when the floor also stops pressing, both uplift
      // guards and the lift-off guard cross together, and the body flies (theory §15)
      GuardSample now;
      evaluate(t, x, now);
      const int lift = guard_slot(mode_, Guard::kLiftOff);
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
      return land(t, x, g.edge, setup_.rigid_law);
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
  latch_.zero_start[static_cast<std::size_t>(guard_slot(mode_, Guard::kImpact))] = true;
  latch_.zero_start[static_cast<std::size_t>(guard_slot(mode_, Guard::kPeak))] = true;
  // a slide that began at this instant has not yet any slip velocity: it too starts at zero
  if (sliding() && x(isv()) == 0.0)
    latch_.zero_start[static_cast<std::size_t>(guard_slot(mode_, Guard::kSlipStop))] = true;
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
  unpack(x);
  const double thd_minus = x(ithd());
  const bool chatter = t - ledger_.last_contact_change < setup_.chatter_interval;
  const auto out =
      resolve_impact(dyn_, landing, scratch_.q, thd_minus, scratch_.qd, setup_.rule, chatter);
  // with friction: a sliding pivot, or an impulse outside the friction cone, needs the impact law
  // with Coulomb friction (theory §19); the paper's law is its sticking case. A chatter cut-off of
  // a sticking pivot is a numerical device on a vanishing impulse whose ratio |I_x|/I_y says
  // nothing about sliding (§10): it stays the sticking both-edges stop.
  if (std::isfinite(setup_.mu_s) &&
      (sliding() || (!chatter && !(out.impulse(1) > 0.0 &&
                                   std::abs(out.impulse(0)) <= setup_.mu_s * out.impulse(1))))) {
    Eigen::Vector2d r, v_c;
    dyn_.cg_from_pivot(edge(), 0.0, 1.0, scratch_.q, thd_minus, scratch_.qd, r, v_c);
    if (sliding()) v_c(0) += x(isv());
    return friction_impact(t, x, landing, v_c, false, chatter,
                           chatter ? EventKind::kChatterCutoff : EventKind::kImpact, chatter,
                           setup_.rigid_law);
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
  ev.friction_demand = out.impulse(1) > 0.0 ? std::abs(out.impulse(0)) / out.impulse(1)
                                            : std::numeric_limits<double>::infinity();
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
    latch_.zero_start[static_cast<std::size_t>(guard_slot(mode_, Guard::kImpact))] = true;
  if (res_.extremes.impacts > opt_.max_impacts)
    return stop(t, "impact limit reached (" + std::to_string(opt_.max_impacts) + ")");
  return request_entry();
}

// the floor stops pressing: the body flies, with no impulse (theory "Flight", lift-off map)
template <int N, int MaxN>
bool Simulator<N, MaxN>::lift_off(double t, State& x) {
  unpack(x);
  const int e = edge();  // in full contact theta = 0 and either edge gives the same c.g.
  const double sn = std::sin(x(0)), cs = std::cos(x(0));
  // a free body must move its touching tipping points up: otherwise the sticking pivot is pulled
  // sideways as its force vanishes and the body could only leave it by sliding, which is not
  // modelled here; the floor is let pull (flagged) until it presses again (theory "Lift-off")
  const BaseAcceleration a = motion_.at(t, cursor_.event);
  const int pivot = mode_spec(mode_).pivot;
  // (a sliding pivot's friction vanishes with F_J: no such case, theory "Lift-off from a sliding
  // mode"; there the corner's free acceleration is zero to rounding and its sign says nothing)
  const bool dives =
      !sliding() && ((pivot != 2 && dyn_.free_corner_acceleration(1, sn, cs, scratch_.q, x(ithd()),
                                                                  scratch_.qd, a) < 0.0) ||
                     (pivot != 1 && dyn_.free_corner_acceleration(2, sn, cs, scratch_.q, x(ithd()),
                                                                  scratch_.qd, a) < 0.0));
  if (dives) {
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
  Eigen::Vector2d r, v;
  dyn_.cg_from_pivot(e, sn, cs, scratch_.q, x(ithd()), scratch_.qd, r, v);
  const double d = offset_of(x);
  if (sliding()) v(0) += x(isv());  // the pivot's slip carries the c.g.
  x(ixc()) = d + dyn_.height() * dyn_.alpha(e) + r(0);
  x(ixc() + 1) = r(1);
  x(ixc() + 2) = v(0);
  x(ixc() + 3) = v(1);
  Event ev = make_event(t, EventKind::kLiftOff, full_contact() ? 0 : e);
  ev.theta = x(0);
  ev.theta_dot_before = ev.theta_dot_after = x(ithd());
  rec_.event(ev);
  ++res_.extremes.lift_offs;
  const ContactMode from = mode_;
  switch_mode(ContactMode::kFlight, t, x);
  ledger_.flight_start = t;
  ledger_.last_contact_change = t;
  // the tipping points that touched the floor start at zero height and rise
  latch_.zero_start.fill(false);
  if (mode_spec(from).pivot != 2)
    latch_.zero_start[static_cast<std::size_t>(guard_slot(mode_, Guard::kLandingEdge1))] = true;
  if (mode_spec(from).pivot != 1)
    latch_.zero_start[static_cast<std::size_t>(guard_slot(mode_, Guard::kLandingEdge2))] = true;
  return request_entry();
}

// tipping point e lands after a flight: the plastic corner impact (theory "Landing"); at theta = 0
// with the body turning into the floor about e, both edges land (flat)
template <int N, int MaxN>
bool Simulator<N, MaxN>::land(double t, State& x, int e, bool rigid) {
  unpack(x);
  const double th = x(0), thd_minus = x(ithd());
  const double sn = std::sin(th), cs = std::cos(th), h = dyn_.height();
  const Eigen::Vector2d v_c = cg_velocity(x);
  if (std::isfinite(setup_.mu_s)) {
    res_.extremes.flight_time += t - ledger_.flight_start;
    const bool chatter = t - ledger_.last_contact_change < setup_.chatter_interval;
    if (chatter) {
      latch_.tension = latch_.hold_tension = true;  // as below: grazing hops cannot accumulate
      latch_.tension_event = -1;
    }
    return friction_impact(t, x, e, v_c, true, false,
                           chatter ? EventKind::kChatterCutoff : EventKind::kLanding, chatter,
                           rigid);
  }
  const int e_in = e;
  const Eigen::Vector2d v_corner =
      dyn_.corner_velocity_body(e, sn, cs, scratch_.q, thd_minus, scratch_.qd, v_c);
  double thd_plus = 0.0;
  Vec qd_plus(n_);
  dyn_.corner_impact(e, scratch_.q, thd_minus, scratch_.qd, v_corner, thd_plus, qd_plus, rigid);
  bool flat = false;
  if (th == 0.0 && edge_sign(e) * thd_plus <= 0.0) {
    // level: the body rocks on the other tipping point if its map turns it up about that one,
    // else both land (both vertical impulses are then compressive; theory "Landing")
    const int o = e == 1 ? 2 : 1;
    const Eigen::Vector2d v_other =
        dyn_.corner_velocity_body(o, sn, cs, scratch_.q, thd_minus, scratch_.qd, v_c);
    double thd_o = 0.0;
    Vec qd_o(n_);
    dyn_.corner_impact(o, scratch_.q, thd_minus, scratch_.qd, v_other, thd_o, qd_o, rigid);
    if (edge_sign(o) * thd_o > 0.0) {
      e = o;
      thd_plus = thd_o;
      qd_plus = qd_o;
    } else {
      flat = true;
    }
  }
  const double x_corner = dyn_.corner_x(e, sn, cs, scratch_.q, x(ixc()));
  if (flat) {
    // both edges on the floor: theta_dot = 0, the modal momenta are conserved (rigid_body: the
    // modal velocities)
    thd_plus = 0.0;
    if (rigid) {
      qd_plus = scratch_.qd;
    } else {
      const Vec p = dyn_.flight_modal_momenta(e, scratch_.q, thd_minus, scratch_.qd, v_corner);
      qd_plus = dyn_.mu_inverse() * p;
    }
  }
  // the c.g. velocity after, for the impulse
  Eigen::Vector2d r, v_after;
  dyn_.cg_from_pivot(e, sn, cs, scratch_.q, thd_plus, qd_plus, r, v_after);
  if (flat)
    v_after = dyn_.height() * Eigen::Vector2d(dyn_.psi_x().dot(qd_plus), dyn_.psi_y().dot(qd_plus));
  const Eigen::Vector2d impulse = dyn_.mass() * (v_after - v_c);
  // a plastic impact loses the kinetic energy of the velocity jump (Carnot), which is >= 0 by
  // construction: the jump's c.g. velocity and its motion about the c.g. (theory §16). The
  // rigid_body law is no projection: its loss is the difference of the energies, and where that
  // is a gain the paper's law takes the landing
  const Vec dqd = qd_plus - scratch_.qd;
  double loss = dyn_.flight_kinetic_energy(scratch_.q, thd_plus - thd_minus, dqd, v_after - v_c);
  if (rigid) {
    const double before = dyn_.flight_kinetic_energy(scratch_.q, thd_minus, scratch_.qd, v_c);
    loss = before - dyn_.flight_kinetic_energy(scratch_.q, thd_plus, qd_plus, v_after);
    if (loss < -kImpactEnergyRounding * before) {
      law_fallback(t, e_in);
      return land(t, x, e_in, false);
    }
  }
  x(ithd()) = thd_plus;
  x.segment(iqd(), n_) = qd_plus;
  ledger_.offset = x_corner - h * dyn_.alpha(e);
  switch_mode(flat ? ContactMode::kFullContact
                   : (e == 1 ? ContactMode::kRockingEdge1 : ContactMode::kRockingEdge2),
              t, x);
  Event ev = make_event(t, EventKind::kLanding, flat ? 0 : e);
  ev.theta = th;
  ev.theta_dot_before = thd_minus;
  ev.theta_dot_after = thd_plus;
  ev.energy_loss = loss;
  ev.impulse_x = impulse(0);
  ev.impulse_y = impulse(1);
  ev.friction_demand = impulse(1) > 0.0 ? std::abs(impulse(0)) / impulse(1)
                                        : std::numeric_limits<double>::infinity();
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
  count_impact(ev, impulse(1), ev.energy_loss, chatter);
  return after_impulse(t, ev, th, dyn_.mass() * (v_c.norm() + v_after.norm()));
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::overturned(double t, State& x) {
  const int side = flying() ? (x(0) >= 0.0 ? 1 : 2) : edge();
  res_.status = Status::kOverturned;
  // the run ends here: every extreme (tilt, uplift, reaction, modes) takes this state too, not
  // only the samples before it
  GuardSample now;
  evaluate(t, x, now);
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
  mode_ = m;
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
  evaluate(t, x, now);
  // the floor cannot push along F_I as hard as sticking needs: the base slips the other way
  const int s = now.fi > 0.0 ? -1 : 1;
  Event ev = make_event(t, EventKind::kSlipStart, rocking() ? edge() : 0);
  ev.theta = x(0);
  ev.friction_demand =
      now.fj > 0.0 ? std::abs(now.fi) / now.fj : std::numeric_limits<double>::infinity();
  rec_.event(ev);
  res_.friction_exceeded = true;
  ++res_.extremes.slips;
  x(isv()) = 0.0;
  switch_mode(contact_mode(mode_spec(mode_).pivot, s), t, x);
  ledger_.last_contact_change = t;
  if (rocking() && x(0) == 0.0 && x(ithd()) == 0.0) {
    // just uplifted: with its pivot sliding the body must still turn up, else it slides flat
    unpack(x);
    double thdd = 0.0;
    Eigen::Vector2d r;
    slide_acceleration(0.0, 1.0, 0.0, motion_.at(t, cursor_.event), thdd, r);
    if (!(edge_sign(edge()) * thdd > 0.0)) {
      switch_mode(contact_mode(0, s), t, x);
      latch_.suppress_uplift_at_start = true;
    }
  }
  // the slip velocity starts at zero and grows; an uplift at this instant leaves theta = 0
  latch_.zero_start.fill(false);
  latch_.zero_start[static_cast<std::size_t>(guard_slot(mode_, Guard::kSlipStop))] = true;
  if (rocking() && x(0) == 0.0) {
    latch_.zero_start[static_cast<std::size_t>(guard_slot(mode_, Guard::kImpact))] = true;
    latch_.zero_start[static_cast<std::size_t>(guard_slot(mode_, Guard::kPeak))] = true;
  }
  return request_entry();
}

template <int N, int MaxN>
bool Simulator<N, MaxN>::uplift_holds(double t, int e) {
  if (!std::isfinite(setup_.mu_s)) return true;
  const ContactMode was = mode_;
  const BaseAcceleration a = motion_.at(t, cursor_.event);
  double thdd = 0.0;
  dyn_.rocking_acceleration_sc(e, 0.0, 1.0, scratch_.q, 0.0, scratch_.qd, a, thdd, scratch_.qdd);
  const Eigen::Vector2d r =
      dyn_.rocking_reaction_sc(e, 0.0, 1.0, scratch_.q, 0.0, scratch_.qd, thdd, scratch_.qdd, a);
  if (setup_.mu_s * r(1) - std::abs(r(0)) > 0.0) return true;
  mode_ = contact_mode(e, r(0) > 0.0 ? -1 : 1);
  Eigen::Vector2d rs;
  const bool inconsistent = latch_.slide_inconsistent;
  slide_acceleration(0.0, 1.0, 0.0, a, thdd, rs);
  latch_.slide_inconsistent = inconsistent;  // a probe, not the motion
  mode_ = was;
  return edge_sign(e) * thdd > 0.0;
}

// the slip velocity reached zero: the base sticks if static friction can hold it (a strictly
// positive margin), else it slides the way the floor cannot hold (theory §18)
template <int N, int MaxN>
bool Simulator<N, MaxN>::stick(double t, State& x) {
  ledger_.offset = x(isd());
  x(isv()) = 0.0;
  const int pivot = mode_spec(mode_).pivot, was = slip();
  const double th = x(0);
  switch_mode(contact_mode(pivot, 0), t, x);
  GuardSample now;
  evaluate(t, x, now);
  const double margin = now.v[static_cast<std::size_t>(guard_slot(mode_, Guard::kFrictionLimit))];
  const int s = now.fi > 0.0 ? -1 : 1;
  Event ev = make_event(t, margin > 0.0 ? EventKind::kStick : EventKind::kSlipReversal,
                        rocking() ? edge() : 0);
  ev.theta = th;
  ev.friction_demand =
      now.fj > 0.0 ? std::abs(now.fi) / now.fj : std::numeric_limits<double>::infinity();
  rec_.event(ev);
  latch_.zero_start.fill(false);
  if (margin <= 0.0) {
    if (s != was) ++res_.extremes.slips;
    switch_mode(contact_mode(pivot, s), t, x);
    latch_.zero_start[static_cast<std::size_t>(guard_slot(mode_, Guard::kSlipStop))] = true;
  }
  if (rocking() && th == 0.0) {
    latch_.zero_start[static_cast<std::size_t>(guard_slot(mode_, Guard::kImpact))] = true;
    latch_.zero_start[static_cast<std::size_t>(guard_slot(mode_, Guard::kPeak))] = true;
  }
  return request_entry();
}

// Moreau's impact law for one contact, plastic normally, with Coulomb friction on the impulse
// (theory §19): the moment of momentum about tipping point e and the modal momenta are conserved;
// after the impact e rests on the floor (stick) or slides along it at d_dot+ (slip), and every
// post-impact quantity is affine in d_dot+. The sticking impulse is taken if it lies in the
// friction cone; else the slip direction is the one the cone cannot hold, and d_dot+ puts the
// impulse on the cone's edge. At theta = 0 a map that turns the body into the floor about e lands
// both edges (theta_dot+ = 0, the modal momenta conserved), with the same friction rule.
template <int N, int MaxN>
bool Simulator<N, MaxN>::friction_impact(double t, State& x, int e, const Eigen::Vector2d& v_c,
                                         bool from_flight, bool flat, EventKind kind, bool chatter,
                                         bool rigid) {
  unpack(x);
  if (!from_flight) x(0) = 0.0;  // a rocking impact is located at theta = 0 up to rounding
  const double th = x(0), thd_minus = x(ithd());
  const double sn = std::sin(th), cs = std::cos(th), h = dyn_.height(), m = dyn_.mass();
  const double kinetic_before = dyn_.flight_kinetic_energy(scratch_.q, thd_minus, scratch_.qd, v_c);
  const Eigen::Vector2d unit_body(cs, -sn);  // I in body components
  // one candidate: the post-impact rates and c.g. velocity at d_dot+ = 0 and per unit d_dot+
  struct Candidate {
    double thd0 = 0.0, thd1 = 0.0;
    Vec qd0, qd1;
    Eigen::Vector2d vc0, vc1;
  };
  auto single = [&](int c, Candidate& k) {
    const Eigen::Vector2d v_corner =
        dyn_.corner_velocity_body(c, sn, cs, scratch_.q, thd_minus, scratch_.qd, v_c);
    k.qd0.resize(n_);
    k.qd1.resize(n_);
    dyn_.corner_impact(c, scratch_.q, thd_minus, scratch_.qd, v_corner, k.thd0, k.qd0, rigid);
    dyn_.corner_impact(c, scratch_.q, 0.0, Vec::Zero(n_), -unit_body, k.thd1, k.qd1, rigid);
    Eigen::Vector2d r;
    dyn_.cg_from_pivot(c, sn, cs, scratch_.q, k.thd0, k.qd0, r, k.vc0);
    dyn_.cg_from_pivot(c, sn, cs, scratch_.q, k.thd1, k.qd1, r, k.vc1);
    k.vc1(0) += 1.0;
  };
  auto both = [&](Candidate& k) {
    // theta = 0: the modal momenta p = mu q_dot + psi_x d_dot / h (over M h^2) are conserved
    const Eigen::Vector2d v_corner =
        dyn_.corner_velocity_body(e, sn, cs, scratch_.q, thd_minus, scratch_.qd, v_c);
    const Vec p = dyn_.flight_modal_momenta(e, scratch_.q, thd_minus, scratch_.qd, v_corner);
    k.thd0 = k.thd1 = 0.0;
    k.qd0 = rigid ? scratch_.qd : Vec(dyn_.mu_inverse() * p);
    // rigid_body: the slip carries the body as a whole, the modes keep their rates
    k.qd1 = rigid ? Vec(Vec::Zero(n_)) : Vec(-(dyn_.mu_inverse() * dyn_.psi_x()) / h);
    k.vc0 = h * Eigen::Vector2d(dyn_.psi_x().dot(k.qd0), dyn_.psi_y().dot(k.qd0));
    k.vc1 = Eigen::Vector2d(1.0 + h * dyn_.psi_x().dot(k.qd1), h * dyn_.psi_y().dot(k.qd1));
  };
  // Coulomb on the impulse M (v_c+ - v_c-) = L0 + d_dot+ L1: d_dot+ = 0 inside the cone, else on
  // its edge; `ok` false when the slide has no consistent solution (k_s <= 0)
  struct Resolved {
    double v = 0.0;       // d_dot+
    double demand = 0.0;  // |L0_I| / L0_J: the friction the sticking impulse needs
    bool slid = false, ok = true;
  };
  auto coulomb = [&](const Candidate& c) {
    Resolved z;
    const Eigen::Vector2d l0 = m * (c.vc0 - v_c), l1 = m * c.vc1;
    z.demand = l0(1) > 0.0 ? std::abs(l0(0)) / l0(1) : std::numeric_limits<double>::infinity();
    if (l0(1) > 0.0 && std::abs(l0(0)) <= setup_.mu_s * l0(1)) return z;
    const double sg = l0(0) > 0.0 ? -1.0 : 1.0;
    const double k_s = l1(0) + sg * setup_.mu_k * l1(1);
    z.v = -(l0(0) + sg * setup_.mu_k * l0(1)) / k_s;
    z.slid = true;
    z.ok = k_s > 0.0;
    return z;
  };
  auto turn = [](const Candidate& c, double v) { return c.thd0 + v * c.thd1; };
  Candidate k;
  Resolved z;
  int lands = e;
  if (flat) {
    both(k);
    z = coulomb(k);
  } else if (th != 0.0) {
    single(e, k);
    z = coulomb(k);
  } else {
    // theta = 0 (theory §19): corner 1, corner 2 and flat, each resolved with friction; the one
    // that is consistent (the body turns away from the other corner; flat: both corners press),
    // and where two are, the one the sticking rule of §16 names
    std::array<Candidate, 3> c;  // corner 1, corner 2, flat
    single(1, c[0]);
    single(2, c[1]);
    both(c[2]);
    std::array<Resolved, 3> r = {coulomb(c[0]), coulomb(c[1]), coulomb(c[2])};
    std::array<bool, 3> fits = {r[0].ok && turn(c[0], r[0].v) > 0.0,
                                r[1].ok && -turn(c[1], r[1].v) > 0.0,
                                r[2].ok && turn(c[0], r[2].v) <= 0.0 && -turn(c[1], r[2].v) <= 0.0};
    // the sticking rule: the landing corner if it turns the body up about itself, else (landing
    // from flight) the other one, else flat
    const int o = e == 1 ? 2 : 1;
    int pick = 2;
    if (edge_sign(e) * c[static_cast<std::size_t>(e - 1)].thd0 > 0.0) {
      pick = e - 1;
    } else if (from_flight && edge_sign(o) * c[static_cast<std::size_t>(o - 1)].thd0 > 0.0) {
      pick = o - 1;
    }
    if (!fits[static_cast<std::size_t>(pick)]) {
      for (int j = 0; j < 3; ++j)
        if (fits[static_cast<std::size_t>(j)]) pick = j;
    }
    const auto pk = static_cast<std::size_t>(pick);
    k = c[pk];
    z = r[pk];
    z.ok = z.ok && fits[pk];
    flat = pick == 2;
    lands = flat ? e : pick + 1;
  }
  if (chatter && z.slid && !((k.vc0 + z.v * k.vc1 - v_c)(1) > 0.0)) {
    // a grazing landing (below the chatter interval) whose sliding impulse would pull: the
    // sticking one, as without friction (§16: Carnot's loss, a tensile_landing said)
    z = Resolved{};
  }
  const bool ok = z.ok;
  const double v_plus = z.v;
  const bool slid = z.slid;
  const double sticking_demand = z.demand;
  if (!ok)
    return stop(t, "no consistent impact with friction at t = " + short_number(t) +
                       " s (no outcome of the impact law with Coulomb friction fits; "
                       "docs/theory.md, \"Impacts with friction\")");
  const double thd_plus = k.thd0 + v_plus * k.thd1;
  const Vec qd_plus = k.qd0 + v_plus * k.qd1;
  const Eigen::Vector2d v_after = k.vc0 + v_plus * k.vc1;
  const Eigen::Vector2d impulse = m * (v_after - v_c);
  const double loss =
      kinetic_before - dyn_.flight_kinetic_energy(scratch_.q, thd_plus, qd_plus, v_after);
  if (rigid && loss < -kImpactEnergyRounding * kinetic_before) {
    law_fallback(t, e);
    return friction_impact(t, x, e, v_c, from_flight, flat, kind, chatter, false);
  }
  // the contact point's place: the landing tipping point, or the base centre when flat
  const double d_now = offset_of(x);
  if (from_flight) {
    const double x_corner = dyn_.corner_x(lands, sn, cs, scratch_.q, x(ixc()));
    ledger_.offset = x_corner - h * dyn_.alpha(lands);
  } else {
    ledger_.offset = d_now;
  }
  x(ithd()) = flat ? 0.0 : thd_plus;
  x.segment(iqd(), n_) = qd_plus;
  const int pivot = flat ? 0 : lands;
  const int s = !slid || v_plus == 0.0 ? 0 : (v_plus > 0.0 ? 1 : -1);
  switch_mode(contact_mode(pivot, s), t, x);
  x(isd()) = ledger_.offset;
  x(isv()) = s != 0 ? v_plus : 0.0;
  Event ev = make_event(t, flat && kind == EventKind::kImpact ? EventKind::kRockingEnded : kind,
                        from_flight && flat ? 0 : lands);
  ev.theta = th;
  ev.theta_dot_before = thd_minus;
  ev.theta_dot_after = x(ithd());
  ev.energy_loss = loss;
  ev.impulse_x = impulse(0);
  ev.impulse_y = impulse(1);
  ev.friction_demand = impulse(1) > 0.0 ? std::abs(impulse(0)) / impulse(1)
                                        : std::numeric_limits<double>::infinity();
  count_impact(ev, impulse(1), loss, chatter);
  if (slid) {
    // the impulse needed more friction than the floor has: a sliding impact
    res_.friction_exceeded = true;
    ++res_.extremes.slips;
    Event fe = ev;
    fe.kind = EventKind::kFrictionExceeded;
    fe.friction_demand = sticking_demand;
    rec_.event(fe);
  }
  return after_impulse(t, ev, th, m * (v_c.norm() + v_after.norm()));
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
    latch_.zero_start[static_cast<std::size_t>(guard_slot(mode_, Guard::kImpact))] = true;
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
