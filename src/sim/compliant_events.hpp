// SPDX-License-Identifier: BSD-3-Clause
// The compliant contact's event bookkeeping: corners that touch, leave, slip and stick, the
// events they write and the touches' transfers (compliant.hpp's table). Internal header.
#pragma once

#include "compliant_sim.hpp"

namespace flexrock::detail {

template <int MaxN>
inline bool CompliantSim<MaxN>::stop(double t, const std::string& why) {
  res_.status = Status::kStopped;
  res_.message = why;
  Event ev;
  ev.time = t;
  ev.kind = EventKind::kStopped;
  rec_.event(ev);
  return false;
}

// closes the open touch: theta_dot after, the floor's impulse and the dissipation since
template <int MaxN>
inline void CompliantSim<MaxN>::close_transfer(const State& x) {
  if (transfer_.event < 0) return;
  Event& ev = res_.events[static_cast<std::size_t>(transfer_.event)];
  ev.theta_dot_after = x(iv() + 2);
  ev.impulse_x = x(iw() + 4) - transfer_.ix;
  ev.impulse_y = x(iw() + 5) - transfer_.iy;
  ev.energy_loss = contact_loss(x) - transfer_.loss;
  Extremes& ex = res_.extremes;
  ex.max_impulse = std::max(ex.max_impulse, std::abs(ev.impulse_y));
  ex.max_impact_energy_loss = std::max(ex.max_impact_energy_loss, ev.energy_loss);
  transfer_.event = -1;
}

// the peak normal force of corner j's contact, written to its touch event
template <int MaxN>
inline void CompliantSim<MaxN>::close_contact(std::size_t j) {
  Corner& k = corner_[j];
  if (k.touch >= 0) {
    double& estimate = res_.events[static_cast<std::size_t>(k.touch)].force_estimate;
    estimate = std::max(estimate, k.peak);  // a landing on both corners: the larger
    res_.extremes.max_impact_force = std::max(res_.extremes.max_impact_force, k.peak);
  }
  k.touch = -1;
  k.peak = 0.0;
}

// mode-time bookkeeping around a change of the corners' states
template <int MaxN>
inline void CompliantSim<MaxN>::before_change() {
  mode_before_ = mode();
}

template <int MaxN>
inline void CompliantSim<MaxN>::after_change(double t) {
  const ContactMode now = mode();
  const bool flew = mode_before_ == ContactMode::kFlight, flies = now == ContactMode::kFlight;
  const bool slid = mode_spec(mode_before_).slip != 0, slides = mode_spec(now).slip != 0;
  if (!flew && flies) flight_start_ = t;
  if (flew && !flies) res_.extremes.flight_time += t - flight_start_;
  if (!slid && slides) {
    slide_start_ = t;
    ++res_.extremes.slips;
    res_.friction_exceeded = true;
  }
  if (slid && !slides) res_.extremes.sliding_time += t - slide_start_;
}

template <int MaxN>
inline Event CompliantSim<MaxN>::event_at(double t, EventKind kind, int edge, const State& x) {
  Event ev;
  ev.time = t;
  ev.kind = kind;
  ev.edge = edge;
  ev.theta = x(2);
  ev.theta_dot_before = x(iv() + 2);
  ev.theta_dot_after = x(iv() + 2);
  GuardSample gs;
  evaluate(t, x, gs);
  ev.offset = observation(gs, x).offset;
  ev.friction_demand = gs.fj > 0.0 ? std::abs(gs.fi) / gs.fj : 0.0;
  return ev;
}

// a corner whose sticking force already needs more than mu_s F_n slips at once
template <int MaxN>
inline void CompliantSim<MaxN>::resolve_stick(int e, State& x) {
  Corner& k = corner_[static_cast<std::size_t>(e - 1)];
  if (!std::isfinite(mu_s_) || k.state != CornerState::kStick) return;
  unpack(x);
  Eigen::Vector2d f, ve;
  corner_force(e, std::sin(x(2)), std::cos(x(2)), x, f, ve);
  if (std::abs(f(0)) <= mu_s_ * f(1)) return;
  start_slip(e, f, ve, x);
}

// a sticking corner starts to slip: its tangential spring lets go through the slider, so the
// energy it held is the slip's work (the floor's springs give it to friction)
template <int MaxN>
inline void CompliantSim<MaxN>::start_slip(int e, const Eigen::Vector2d& f,
                                           const Eigen::Vector2d& ve, State& x) {
  const std::size_t j = static_cast<std::size_t>(e - 1);
  Corner& k = corner_[j];
  const double s = std::sin(x(2)), c = std::cos(x(2));
  const double u = dyn_.corner_x(e, s, c, q_, x(0)) - k.anchor;
  const double delta = -dyn_.corner_height(e, s, c, q_, x(1));
  const double held = 0.5 * cc_.k_t * tangential_scale(cc_, f_ref_, delta) * u * u;
  x(iw() + 2) -= held;
  x(iw() + 3) += held;
  released_ += held;
  k.state = CornerState::kSlip;
  k.slip = ve(0) != 0.0 ? (ve(0) > 0.0 ? 1 : -1) : (f(0) > 0.0 ? -1 : 1);
  zero_start_[j + 2] = true;
}

// The guards that cross at one instant fire together (advance): an overturn ends the run;
// corners that touch come down together (one touch event: a landing on both corners when both
// were free), corners that leave the floor leave together (one lift_off when none is left),
// then the friction switches of corners that neither touched nor left.
template <int MaxN>
inline bool CompliantSim<MaxN>::fire(const std::array<bool, kMaxGuards>& fires, double t,
                                     State& x) {
  unpack(x);
  if (fires[4]) {
    const int edge = x(2) > 0.0 ? 1 : 2;
    res_.status = Status::kOverturned;
    res_.message = "overturned";
    res_.extremes.overturn_time = t;
    res_.extremes.overturn_edge = edge;
    rec_.event(event_at(t, EventKind::kOverturn, edge, x));
    return false;
  }
  before_change();
  const std::array<CornerState, 2> was = {corner_[0].state, corner_[1].state};
  const std::array<bool, 2> touch = {fires[0] && was[0] == CornerState::kFree,
                                     fires[1] && was[1] == CornerState::kFree};
  const std::array<bool, 2> release = {fires[0] && was[0] != CornerState::kFree,
                                       fires[1] && was[1] != CornerState::kFree};
  if ((touch[0] || touch[1]) && !touch_down(touch, t, x)) return false;
  if (release[0] || release[1]) release_corners(release, t, x);
  for (int e = 1; e <= 2; ++e) {
    const std::size_t j = static_cast<std::size_t>(e - 1);
    if (fires[j + 2] && corner_[j].state == was[j]) friction_switch(e, t, x);
  }
  after_change(t);
  return true;
}

// corners touching the floor: an impact when the other corner presses, a landing when it flies
// (on both corners, edge 0, when both come down at once)
template <int MaxN>
inline bool CompliantSim<MaxN>::touch_down(const std::array<bool, 2>& touch, double t, State& x) {
  close_transfer(x);
  if (++res_.extremes.impacts > opt_.max_impacts)
    return stop(
        t, "more than max_impacts = " + std::to_string(opt_.max_impacts) + " touches of the floor");
  const bool both = touch[0] && touch[1];
  const int single = touch[0] ? 1 : 2;
  const bool impact =
      !both && corner_[static_cast<std::size_t>(2 - single)].state != CornerState::kFree;
  const double s = std::sin(x(2)), c = std::cos(x(2));
  const long index = static_cast<long>(res_.events.size());
  for (int e = 1; e <= 2; ++e) {
    const std::size_t j = static_cast<std::size_t>(e - 1);
    if (!touch[j]) continue;
    Corner& k = corner_[j];
    const Eigen::Vector2d vb = dyn_.corner_velocity_body(e, s, c, q_, x(iv() + 2), qd_,
                                                         Eigen::Vector2d(x(iv()), x(iv() + 1)));
    k.state = CornerState::kStick;
    k.anchor = dyn_.corner_x(e, s, c, q_, x(0));
    k.v_in = std::max(-(s * vb(0) + c * vb(1)), 0.0);
    k.peak = 0.0;
    k.touch = index;
    zero_start_[j] = true;
  }
  rec_.event(event_at(t, impact ? EventKind::kImpact : EventKind::kLanding, both ? 0 : single, x));
  transfer_.event = index;
  transfer_.ix = x(iw() + 4);
  transfer_.iy = x(iw() + 5);
  transfer_.loss = contact_loss(x);
  transfer_.theta_dot = x(iv() + 2);
  for (int e = 1; e <= 2; ++e)
    if (touch[static_cast<std::size_t>(e - 1)]) resolve_stick(e, x);
  return true;
}

// corners leaving the floor: the end of an impact's transfer, an uplift, or a lift-off (one,
// edge 0, when no corner is left pressing)
template <int MaxN>
inline void CompliantSim<MaxN>::release_corners(const std::array<bool, 2>& release, double t,
                                                const State& x) {
  // a transfer opened at this very instant (a corner touched as the other left) stays open
  const bool opened_now =
      transfer_.event >= 0 && res_.events[static_cast<std::size_t>(transfer_.event)].time == t;
  const bool closes = transfer_.event >= 0 && !opened_now;
  if (closes) close_transfer(x);
  for (std::size_t j = 0; j < 2; ++j) {
    if (!release[j]) continue;
    close_contact(j);
    corner_[j].state = CornerState::kFree;
    zero_start_[j] = true;
  }
  if (corner_[0].state == CornerState::kFree && corner_[1].state == CornerState::kFree) {
    rec_.event(event_at(t, EventKind::kLiftOff, 0, x));
    ++res_.extremes.lift_offs;
  } else if (!closes && !opened_now) {
    const int pivot = corner_[0].state != CornerState::kFree ? 1 : 2;
    rec_.event(event_at(t, EventKind::kUplift, pivot, x));
    if (res_.extremes.first_uplift_time < 0.0) {
      res_.extremes.first_uplift_time = t;
      res_.extremes.first_uplift_edge = pivot;
    }
  }
}

// corner e's friction guard: a sticking corner slips, a slipping one sticks where it is
template <int MaxN>
inline void CompliantSim<MaxN>::friction_switch(int e, double t, State& x) {
  const std::size_t j = static_cast<std::size_t>(e - 1);
  Corner& k = corner_[j];
  unpack(x);
  const double s = std::sin(x(2)), c = std::cos(x(2));
  if (k.state == CornerState::kStick) {
    Eigen::Vector2d f, ve;
    corner_force(e, s, c, x, f, ve);
    start_slip(e, f, ve, x);
    rec_.event(event_at(t, EventKind::kSlipStart, e, x));
  } else if (k.state == CornerState::kSlip) {
    k.state = CornerState::kStick;
    k.anchor = dyn_.corner_x(e, s, c, q_, x(0));
    rec_.event(event_at(t, EventKind::kStick, e, x));
    resolve_stick(e, x);
  }
}

}  // namespace flexrock::detail
