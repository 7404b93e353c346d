// SPDX-License-Identifier: BSD-3-Clause
// The modes' equations: each contact mode's right-hand side (full contact and rocking, flight,
// sliding), its guard functions and their crossings, and what a run observes of the state
// (energies, reactions, history rows, the result at the end). Every stepper reads the guards
// through evaluate(). Part of the event loop (simulator.hpp), included at its end.
#pragma once

#include "simulator.hpp"

namespace flexrock::detail {

// full contact (theory §4, theta = 0) and rocking (theory §4); writes every entry
template <int N, int MaxN>
void Simulator<N, MaxN>::contact_rhs(double t, const ContactState& x, ContactState& dx) {
  const BaseAcceleration a = motion_.at(t, cursor_.rhs);
  dx.resize(x.size());
  if (rocking()) {
    // from the state to its derivative in place, every shared sum formed once
    double sn = 0.0, cs = 0.0;
    sin_cos(x(0), sn, cs);
    typename Dyn::RockingRates r;
    dyn_.rocking_rates_sc(edge(), sn, cs, x.data() + iq(), x(ithd()), x.data() + iqd(), a,
                          dx.data() + iqd(), r);
    dx(0) = x(ithd());
    dx.segment(iq(), n_) = x.segment(iqd(), n_);
    dx(ithd()) = r.theta_ddot;
    dx(iw()) = r.input_power;
    dx(id()) = r.damping_power;
    return;
  }
  unpack(x);
  dyn_.full_contact_acceleration(scratch_.q, scratch_.qd, a, scratch_.qdd);
  dx(0) = 0.0;
  dx.segment(iq(), n_) = scratch_.qd;
  dx(ithd()) = 0.0;
  dx.segment(iqd(), n_) = scratch_.qdd;
  dx(iw()) = dyn_.input_power(0.0, 0.0, scratch_.q, 0.0, scratch_.qd, a);
  dx(id()) = dyn_.damping_power(scratch_.qd);
}

// theory "Flight": the c.g. is ballistic relative to the base, the rest feels no gravity
template <int N, int MaxN>
void Simulator<N, MaxN>::flight_rhs(double t, const FlightState& x, FlightState& dx) {
  const BaseAcceleration a = motion_.at(t, cursor_.rhs);
  unpack(x);
  dx.resize(x.size());
  double thdd = 0.0;
  dyn_.flight_acceleration(scratch_.q, x(ithd()), scratch_.qd, thdd, scratch_.qdd);
  dx(0) = x(ithd());
  dx.segment(iq(), n_) = scratch_.qd;
  dx(ithd()) = thdd;
  dx.segment(iqd(), n_) = scratch_.qdd;
  dx(iw()) = dyn_.flight_input_power(cg_velocity(x), a);
  dx(id()) = dyn_.damping_power(scratch_.qd);
  dx(ixc()) = x(ixc() + 2);
  dx(ixc() + 1) = x(ixc() + 3);
  dx(ixc() + 2) = -a.x;
  dx(ixc() + 3) = -dyn_.g() - a.y;
}

// theory §18: with the base sliding, the body moves as in the mode without slip on a base that
// accelerates at a + d_ddot I, so the accelerations and the floor reaction are affine in d_ddot,
// and Coulomb's F_I = -s mu_k F_J is one linear equation for it
template <int N, int MaxN>
double Simulator<N, MaxN>::slide_acceleration(double sn, double cs, double theta_dot,
                                              BaseAcceleration a, double& theta_ddot,
                                              Eigen::Vector2d& reaction) {
  const BaseAcceleration a1{a.x + 1.0, a.y};  // a unit slip acceleration [m/s^2]
  Eigen::Vector2d r0, r1;
  double thdd0 = 0.0, thdd1 = 0.0;
  if (rocking()) {
    const int e = edge();
    dyn_.rocking_acceleration_sc(e, sn, cs, scratch_.q, theta_dot, scratch_.qd, a, thdd0,
                                 scratch_.qdd);
    r0 = dyn_.rocking_reaction_sc(e, sn, cs, scratch_.q, theta_dot, scratch_.qd, thdd0,
                                  scratch_.qdd, a);
    dyn_.rocking_acceleration_sc(e, sn, cs, scratch_.q, theta_dot, scratch_.qd, a1, thdd1,
                                 scratch_.qdd1);
    r1 = dyn_.rocking_reaction_sc(e, sn, cs, scratch_.q, theta_dot, scratch_.qd, thdd1,
                                  scratch_.qdd1, a1);
  } else {
    dyn_.full_contact_acceleration(scratch_.q, scratch_.qd, a, scratch_.qdd);
    r0 = dyn_.full_contact_reaction(scratch_.qdd, a);
    dyn_.full_contact_acceleration(scratch_.q, scratch_.qd, a1, scratch_.qdd1);
    r1 = dyn_.full_contact_reaction(scratch_.qdd1, a1);
  }
  const double s = slip();
  const Eigen::Vector2d dr = r1 - r0;  // the reaction's change per m/s^2 of d_ddot
  // k > 0: friction opposing the slip decelerates it; k <= 0 has no consistent slide (Painleve)
  const double k = dr(0) + s * setup_.mu_k * dr(1);
  if (!(k > 0.0)) latch_.slide_inconsistent = true;
  const double dd = -(r0(0) + s * setup_.mu_k * r0(1)) / k;
  theta_ddot = thdd0 + dd * (thdd1 - thdd0);
  scratch_.qdd += dd * (scratch_.qdd1 - scratch_.qdd);
  reaction = r0 + dd * dr;
  return dd;
}

// the sliding modes (theory §18): the contact mode's equations in the sliding frame, the slip, and
// the powers relative to the base: input -M a.(v_cm + d_dot I), friction dissipation -F_I d_dot
template <int N, int MaxN>
void Simulator<N, MaxN>::slide_rhs(double t, const SlideState& x, SlideState& dx) {
  const BaseAcceleration a = motion_.at(t, cursor_.rhs);
  unpack(x);
  dx.resize(x.size());
  double sn = 0.0, cs = 0.0;
  sin_cos(x(0), sn, cs);
  const double v = x(jsd() + 1);
  double thdd = 0.0;
  Eigen::Vector2d r;
  const double dd = slide_acceleration(sn, cs, x(ithd()), a, thdd, r);
  const double al = rocking() ? dyn_.alpha(edge()) : 0.0;
  dx(0) = rocking() ? x(ithd()) : 0.0;
  dx.segment(iq(), n_) = scratch_.qd;
  dx(ithd()) = thdd;
  dx.segment(iqd(), n_) = scratch_.qdd;
  dx(iw()) = dyn_.input_power_sc(al, sn, cs, scratch_.q, x(ithd()), scratch_.qd, a) -
             dyn_.mass() * a.x * v;
  dx(id()) = dyn_.damping_power(scratch_.qd);
  dx(jsd()) = v;
  dx(jsd() + 1) = dd;
  dx(jsd() + 2) = -dyn_.mass() * dyn_.g() * r(0) * v;
}

template <int N, int MaxN>
void Simulator<N, MaxN>::evaluate(double t, const State& x, GuardSample& s) {
  // after the motion's end (GroundMotion::quiet_from) the floor is at rest
  const BaseAcceleration a =
      t > setup_.quiet_from ? BaseAcceleration{} : motion_.at(t, cursor_.event);
  unpack(x);
  s.t = t;
  // each value goes to its guard's slot in the mode's list, which the table fixes at compile time
  auto& v = s.v;
  const double mu = opt_.friction_coefficient;
  switch (mode_) {
    case ContactMode::kFullContact: {
      constexpr ContactMode m = ContactMode::kFullContact;
      dyn_.full_contact_acceleration(scratch_.q, scratch_.qd, a, scratch_.qdd);
      const Eigen::Vector2d r = dyn_.full_contact_reaction(scratch_.qdd, a);
      Eigen::Vector2d u;
      s.fi = r(0);
      s.fj = r(1);
      s.moment = dyn_.contact_moments(scratch_.q, scratch_.qdd, a, u);
      v[kSlot<m, Guard::kUpliftEdge1>] = u(0);
      v[kSlot<m, Guard::kUpliftEdge2>] = u(1);
      v[kSlot<m, Guard::kLiftOff>] = s.fj;
      v[kSlot<m, Guard::kFrictionLimit>] = std::isfinite(mu) ? mu * s.fj - std::abs(s.fi) : 1.0;
      break;
    }
    case ContactMode::kRockingEdge1:
    case ContactMode::kRockingEdge2: {
      const int e = edge();
      double thdd = 0.0;
      double sn = 0.0, cs = 0.0;
      sin_cos(x(0), sn, cs);
      dyn_.rocking_acceleration_sc(e, sn, cs, scratch_.q, x(ithd()), scratch_.qd, a, thdd,
                                   scratch_.qdd);
      const Eigen::Vector2d r = dyn_.rocking_reaction_sc(e, sn, cs, scratch_.q, x(ithd()),
                                                         scratch_.qd, thdd, scratch_.qdd, a);
      s.fi = r(0);
      s.fj = r(1);
      // reaction at the pivot, moment about the c.g. projection: alpha h F_j(body)
      s.moment = dyn_.alpha(e) * (-r(0) * sn + r(1) * cs);
      rocking_guards(e, x, s);
      break;
    }
    case ContactMode::kSlidingPlus:
    case ContactMode::kSlidingMinus: {
      constexpr ContactMode m = ContactMode::kSlidingPlus;  // both directions list the same guards
      static_assert(mode_spec(ContactMode::kSlidingPlus).guards ==
                    mode_spec(ContactMode::kSlidingMinus).guards);
      double thdd = 0.0;
      Eigen::Vector2d r;
      const double dd = slide_acceleration(0.0, 1.0, 0.0, a, thdd, r);
      const BaseAcceleration as{a.x + dd, a.y};  // the sliding base's acceleration
      Eigen::Vector2d u;
      s.fi = r(0);
      s.fj = r(1);
      s.moment = dyn_.contact_moments(scratch_.q, scratch_.qdd, as, u);
      v[kSlot<m, Guard::kUpliftEdge1>] = u(0);
      v[kSlot<m, Guard::kUpliftEdge2>] = u(1);
      v[kSlot<m, Guard::kLiftOff>] = s.fj;
      v[kSlot<m, Guard::kSlipStop>] = slip() * x(isv());
      break;
    }
    case ContactMode::kRockingEdge1SlidingPlus:
    case ContactMode::kRockingEdge1SlidingMinus:
    case ContactMode::kRockingEdge2SlidingPlus:
    case ContactMode::kRockingEdge2SlidingMinus: {
      constexpr ContactMode m = ContactMode::kRockingEdge1SlidingPlus;
      static_assert(
          mode_spec(m).guards == mode_spec(ContactMode::kRockingEdge2SlidingMinus).guards &&
          mode_spec(m).guards == mode_spec(ContactMode::kRockingEdge1SlidingMinus).guards &&
          mode_spec(m).guards == mode_spec(ContactMode::kRockingEdge2SlidingPlus).guards);
      const int e = edge();
      const double sg = edge_sign(e);
      double sn = 0.0, cs = 0.0;
      sin_cos(x(0), sn, cs);
      double thdd = 0.0;
      Eigen::Vector2d r;
      slide_acceleration(sn, cs, x(ithd()), a, thdd, r);
      s.fi = r(0);
      s.fj = r(1);
      s.moment = dyn_.alpha(e) * (-r(0) * sn + r(1) * cs);
      v[kSlot<m, Guard::kImpact>] = sg * x(0);
      v[kSlot<m, Guard::kOverturn>] =
          setup_.overturn_limit[static_cast<std::size_t>(e - 1)] - sg * x(0);
      v[kSlot<m, Guard::kLiftOff>] = s.fj;
      v[kSlot<m, Guard::kSlipStop>] = slip() * x(isv());
      v[kSlot<m, Guard::kPeak>] = sg * x(ithd());
      break;
    }
    case ContactMode::kFlight: {
      constexpr ContactMode m = ContactMode::kFlight;
      double sn = 0.0, cs = 0.0;
      sin_cos(x(0), sn, cs);
      const double h = dyn_.height();
      s.fi = s.fj = s.moment = 0.0;
      v[kSlot<m, Guard::kLandingEdge1>] =
          dyn_.corner_height(1, sn, cs, scratch_.q, x(ixc() + 1)) / h;
      v[kSlot<m, Guard::kLandingEdge2>] =
          dyn_.corner_height(2, sn, cs, scratch_.q, x(ixc() + 1)) / h;
      v[kSlot<m, Guard::kOverturn>] =
          std::min(setup_.overturn_limit[0] - x(0), setup_.overturn_limit[1] + x(0));
      break;
    }
  }
}

template <int N, int MaxN>
void Simulator<N, MaxN>::rocking_guards(int e, const State& x, GuardSample& s) const {
  constexpr ContactMode m = ContactMode::kRockingEdge1;  // both edges list the same guards
  static_assert(mode_spec(ContactMode::kRockingEdge1).guards ==
                mode_spec(ContactMode::kRockingEdge2).guards);
  const double sg = edge_sign(e), mu = opt_.friction_coefficient;
  auto& v = s.v;
  v[kSlot<m, Guard::kImpact>] = sg * x(0);
  v[kSlot<m, Guard::kOverturn>] =
      setup_.overturn_limit[static_cast<std::size_t>(e - 1)] - sg * x(0);
  v[kSlot<m, Guard::kLiftOff>] = s.fj;
  v[kSlot<m, Guard::kFrictionLimit>] = std::isfinite(mu) ? mu * s.fj - std::abs(s.fi) : 1.0;
  v[kSlot<m, Guard::kPeak>] = sg * x(ithd());
}

template <int N, int MaxN>
void Simulator<N, MaxN>::arc_sample(double t, const State& x, double sp, double cp,
                                    GuardSample& s) const requires(N == 0) {
  s.t = t;
  s.fi = arc_.arc.fi(sp, cp);
  s.fj = arc_.arc.press(cp);
  s.moment = arc_.arc.signed_moment(sp, cp);
  rocking_guards(edge(), x, s);
}

template <int N, int MaxN>
double Simulator<N, MaxN>::guard_value(int slot, double t) {
  GuardSample s;
  state_at(t, scratch_.xr);
  evaluate(t, scratch_.xr, s);
  return s.v[static_cast<std::size_t>(slot)];
}

// the rocking series' impact guard (s theta) and peak guard (s theta_dot) are polynomials on the
// step: their crossings are found on the polynomial; every other guard by TOMS 748
template <int N, int MaxN>
double Simulator<N, MaxN>::crossing(int slot, double tl, double tr, double gl, double gr) {
  if constexpr (N == 0) {
    if (std::holds_alternative<Series*>(stepper_)) {
      const Guard g = mode_spec(mode_).guards[static_cast<std::size_t>(slot)];
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
  evaluate(t, scratch_.xr, s);
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
double Simulator<N, MaxN>::kinetic_energy(const State& x) {
  unpack(x);
  if (flying())
    return dyn_.flight_kinetic_energy(scratch_.q, x(ithd()), scratch_.qd, cg_velocity(x));
  const double a = rocking() ? dyn_.alpha(edge()) : 0.0;
  const double t_pivot = dyn_.kinetic_energy(a, scratch_.q, x(ithd()), scratch_.qd);
  if (!sliding()) return t_pivot;
  // theory §18: T = T_pivot + M d_dot v_cm,x + 1/2 M d_dot^2
  Eigen::Vector2d r, v;
  dyn_.cg_from_pivot(edge(), std::sin(x(0)), std::cos(x(0)), scratch_.q, x(ithd()), scratch_.qd, r,
                     v);
  const double vd = x(isv());
  return t_pivot + dyn_.mass() * vd * (v(0) + 0.5 * vd);
}

template <int N, int MaxN>
double Simulator<N, MaxN>::potential_energy(const State& x) {
  unpack(x);
  if (flying()) return dyn_.flight_potential_energy(x(ixc() + 1), scratch_.q);
  const double a = rocking() ? dyn_.alpha(edge()) : 0.0;
  return dyn_.potential_energy(a, x(0), scratch_.q);
}

// the horizontal offset of the base centre from where the body stood [m]
template <int N, int MaxN>
double Simulator<N, MaxN>::offset_of(const State& x) {
  if (sliding()) return x(isd());
  if (!flying()) return ledger_.offset;
  unpack(x);
  // the base centre is the tipping-point line's point at alpha = 0
  const double sn = std::sin(x(0)), cs = std::cos(x(0)), h = dyn_.height();
  return x(ixc()) +
         h * (-cs * dyn_.psi_x().dot(scratch_.q) + sn * (1.0 + dyn_.psi_y().dot(scratch_.q)));
}

template <int N, int MaxN>
inline Observation Simulator<N, MaxN>::observation(double t, const State& x, const GuardSample& s) {
  Observation o;
  o.t = t;
  o.mode = mode_;
  o.theta = x(0);
  o.theta_dot = x(ithd());
  // u only: the extremes need no u_dot, which emit_row adds for a history row
  if (n_ > 0) scratch_.qu.noalias() = Dyn::mv(to_user_, x.segment(iq(), n_));
  o.q = scratch_.qu.data();
  o.fi = s.fi;
  o.fj = s.fj;
  o.moment = s.moment;
  o.input_work = x(iw());
  o.damping_loss = x(id());
  if (flying()) {
    flight_heights(x, o);
  } else {
    o.high = setup_.base_width * std::sin(std::abs(x(0)));
    o.offset = sliding() ? x(isd()) : ledger_.offset;
  }
  return o;
}

template <int N, int MaxN>
void Simulator<N, MaxN>::flight_heights(const State& x, Observation& o) {
  unpack(x);
  const double sn = std::sin(x(0)), cs = std::cos(x(0));
  const double y1 = dyn_.corner_height(1, sn, cs, scratch_.q, x(ixc() + 1));
  const double y2 = dyn_.corner_height(2, sn, cs, scratch_.q, x(ixc() + 1));
  o.lift = std::min(y1, y2);
  o.high = std::max(y1, y2);
  o.offset = offset_of(x);
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
  evaluate(t, x, s);
  const BaseAcceleration a = motion_.at(t, cursor_.event);
  Observation o = observation(t, x, s);
  if (n_ > 0) scratch_.qdu.noalias() = Dyn::mv(to_user_, x.segment(iqd(), n_));
  o.q_dot = scratch_.qdu.data();
  // the resultant's distance from the c.g. projection [m]: at the pivot while rocking
  double resultant = 0.0;
  if (rocking()) {
    resultant = dyn_.height() * dyn_.alpha(edge());
  } else if (full_contact()) {
    resultant = dyn_.height() * s.moment / s.fj;
  }
  rec_.row(o, a, kinetic_energy(x), potential_energy(x), resultant,
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
  res_.final_phase = mode_;
  res_.final_theta = x(0);
  res_.final_theta_dot = x(ithd());
  res_.final_q = to_user_ * x.segment(iq(), n_);
  res_.final_q_dot = to_user_ * x.segment(iqd(), n_);
  res_.final_offset = offset_of(x);
  EnergyBalance& e = res_.energy;
  const double kin = kinetic_energy(x);
  const double pot = potential_energy(x);
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
